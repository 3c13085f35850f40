// A project file (.toonface) as loadProject reads it. A project it accepts must save, load back
// equal (project.h promises lossless round trips), draw, and play at any time; the layers it
// holds are the cleaned copies (a cleaned layer cleans to itself).

#include "fuzzinput.h"

#include "anim/timelineevaluator.h"
#include "io/project.h"
#include "render/svgface.h"
#include "render/svglayer.h"

using namespace toonface;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QString path = fuzz::scratchFile(data, size, QStringLiteral("input.toonface"));
    QString error;
    const auto project = loadProject(path, &error);
    if (!project) {
        TOONFACE_FUZZ_CHECK(!error.isEmpty());
        return 0;
    }
    for (const StyleLayer &layer : project->style.layers) {
        QByteArray cleaned;
        TOONFACE_FUZZ_CHECK(cleanLayerSvg(layer.svg, &cleaned, &error) && cleaned == layer.svg);
    }
    const QString again = path + QStringLiteral(".saved.toonface");
    TOONFACE_FUZZ_CHECK(saveProject(*project, again, &error));
    const auto reloaded = loadProject(again, &error);
    TOONFACE_FUZZ_CHECK(reloaded && *reloaded == *project);

    if (project->face.isValid()) {
        const SvgFace face(project->face, project->style);
        const TimelineEvaluator evaluator(project->timeline, project->face, project->mouthShapes);
        for (const double t : {0.0, evaluator.duration() / 2, evaluator.duration()})
            TOONFACE_FUZZ_CHECK(!face.svg(evaluator.evaluate(t)).isEmpty());
    }
    return 0;
}
