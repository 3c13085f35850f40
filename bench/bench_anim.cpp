#include "benchmark.h"
#include "benchtimeline.h"

#include "anim/timeline.h"
#include "anim/timelineevaluator.h"
#include "face/averageface.h"
#include "face/mouthshape.h"
#include "face/pose.h"

#include <random>

using namespace toonface;

namespace {

QJsonObject benchEvaluate()
{
    const FaceModel face = averageFace(QRectF(100, 100, 300, 360), QSize(512, 512));
    const MouthShapeSet shapes;
    const Timeline timeline = bench::tenMinuteTimeline();

    double buildMs = bench::medianMs([&] { TimelineEvaluator e(timeline, face, shapes); });
    const TimelineEvaluator evaluator(timeline, face, shapes);

    // Random times (the cost of a seek) and every frame in order (the cost of playback).
    std::mt19937 rng(3);
    QVector<double> randomTimes(1000);
    for (double &time : randomTimes)
        time = std::uniform_real_distribution<double>(0, timeline.duration())(rng);
    double sink = 0;
    const double randomMs = bench::medianMs([&] {
        for (double time : randomTimes)
            sink += evaluator.evaluate(time).offset[pt::idx("8.2")].y();
    });
    const int frames = timeline.frameCount();
    const double allFramesMs = bench::medianMs(
        [&] {
            for (int f = 0; f < frames; ++f)
                sink += evaluator.evaluate(f / timeline.frameRate()).leftEyeOpen;
        },
        3);
    const double exportKeysMs = bench::medianMs([&] { sink += evaluator.exportKeys().times.size(); }, 3);
    // Key times per animated element, as an SMIL exporter would ask for them.
    QJsonObject perElement;
    const std::pair<const char *, Tracks> elements[] = {{"all", kAllTracks}, {"mouth", Track::Mouth | Track::Emotion},
        {"lids", Track::Blink | Track::Emotion}, {"eyeballs", Tracks(Track::Gaze)}, {"head", Tracks(Track::Head)}};
    for (const auto &[name, tracks] : elements) {
        const auto keys = evaluator.exportKeys(tracks);
        int mixed = 0;
        for (auto segment : keys.segments)
            mixed += segment == TimelineEvaluator::Segment::Mixed;
        QJsonObject o;
        o.insert(QStringLiteral("times"), keys.times.size());
        o.insert(QStringLiteral("mixedSegments"), mixed);
        perElement.insert(QString::fromLatin1(name), o);
    }
    const double jsonMs = bench::medianMs([&] { sink += timeline.toJson().size(); }, 3);

    QJsonObject r;
    r.insert(QStringLiteral("durationS"), timeline.duration());
    r.insert(QStringLiteral("mouthKeys"), timeline.mouthKeys().size());
    r.insert(QStringLiteral("blinks"), timeline.blinks().size());
    r.insert(QStringLiteral("headKeys"), timeline.headKeys().size());
    r.insert(QStringLiteral("frames"), frames);
    r.insert(QStringLiteral("buildMs"), buildMs);
    r.insert(QStringLiteral("evaluateRandomUs"), randomMs); // 1000 calls: ms per run == µs per call
    r.insert(QStringLiteral("evaluatePerFrameUs"), allFramesMs * 1000.0 / frames);
    r.insert(QStringLiteral("evaluateAllFramesMs"), allFramesMs);
    r.insert(QStringLiteral("exportKeysMs"), exportKeysMs);
    r.insert(QStringLiteral("exportKeys"), perElement);
    r.insert(QStringLiteral("toJsonMs"), jsonMs);
    r.insert(QStringLiteral("targetUs"), 100);
    r.insert(QStringLiteral("checksum"), sink != 0);
    return r;
}

} // namespace

TOONFACE_BENCHMARK("anim.evaluate", benchEvaluate);
