// A project's timeline (Timeline::fromJson): mouth, emotion, blink, gaze, head and pose tracks,
// sound and video clips. A timeline it accepts must write and read back equal (timeline.h:
// lossless) and play at any time on the average face.

#include "fuzzinput.h"

#include "anim/timeline.h"
#include "anim/timelineevaluator.h"
#include "face/averageface.h"
#include "face/mouthshape.h"

#include <QJsonDocument>
#include <QJsonObject>

using namespace toonface;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QJsonDocument doc = QJsonDocument::fromJson(fuzz::bytes(data, size));
    if (!doc.isObject())
        return 0;
    QString error;
    const auto timeline = Timeline::fromJson(doc.object(), &error);
    if (!timeline) {
        TOONFACE_FUZZ_CHECK(!error.isEmpty());
        return 0;
    }
    const auto again = Timeline::fromJson(timeline->toJson(), &error);
    TOONFACE_FUZZ_CHECK(again && *again == *timeline);

    static const FaceModel face = averageFace(QRectF(100, 100, 200, 260), QSize(400, 480));
    const TimelineEvaluator evaluator(*timeline, face, MouthShapeSet());
    for (const double t : {-1.0, 0.0, evaluator.duration() / 3, evaluator.duration(), evaluator.duration() + 1})
        evaluator.evaluate(t);
    evaluator.exportKeys();
    return 0;
}
