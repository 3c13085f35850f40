// A user's SVG layer (clothing, accessories) added to a face. Whatever the file holds, the
// drawing written is well-formed XML and inert: every element is an SVG element of drawing
// (no script, foreign content, animation, link or other namespace), every attribute one of
// drawing or a link inside the file (or to a raster picture inside it), and every value CSS
// with no escape, at-rule or url() of anything outside the file. Cleaning is done once: the
// cleaned layer cleans to itself.

#include "fuzzinput.h"

#include "face/averageface.h"
#include "render/svgallowlist.h"
#include "render/svgface.h"
#include "render/svglayer.h"

#include <QXmlStreamReader>

using namespace toonface;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const FaceModel face = averageFace(QRectF(100, 100, 200, 260), QSize(400, 480));
    const QByteArray input = fuzz::bytes(data, size);
    SvgFace drawing(face, Style());
    drawing.addLayer(input);
    QXmlStreamReader reader(drawing.svg());
    while (!reader.atEnd()) {
        if (reader.readNext() != QXmlStreamReader::StartElement)
            continue;
        TOONFACE_FUZZ_CHECK(reader.namespaceUri() == QLatin1StringView("http://www.w3.org/2000/svg"));
        TOONFACE_FUZZ_CHECK(svgallow::isDrawingElement(reader.name()));
        const bool picture
            = reader.name() == QLatin1StringView("image") || reader.name() == QLatin1StringView("feImage");
        for (const QXmlStreamAttribute &a : reader.attributes()) {
            if (a.name() == QLatin1StringView("href")) {
                TOONFACE_FUZZ_CHECK(svgallow::isInternalLink(a.value(), picture));
                continue;
            }
            if (a.namespaceUri() == QLatin1StringView("http://www.w3.org/XML/1998/namespace"))
                continue;
            TOONFACE_FUZZ_CHECK(a.namespaceUri().isEmpty());
            TOONFACE_FUZZ_CHECK(svgallow::isDrawingAttribute(a.name()));
            TOONFACE_FUZZ_CHECK(a.name() == QLatin1StringView("id") || svgallow::isInertCss(a.value()));
        }
        if (reader.name() == QLatin1StringView("style"))
            TOONFACE_FUZZ_CHECK(svgallow::isInertCss(reader.readElementText()));
    }
    TOONFACE_FUZZ_CHECK(!reader.hasError());
    QByteArray once, twice;
    QString error;
    if (cleanLayerSvg(input, &once, &error)) {
        TOONFACE_FUZZ_CHECK(cleanLayerSvg(once, &twice, &error));
        TOONFACE_FUZZ_CHECK(twice == once);
    }
    return 0;
}
