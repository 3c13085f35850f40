#include "benchmark.h"

#include "anim/timeline.h"
#include "anim/timelineevaluator.h"
#include "face/averageface.h"
#include "face/mouthshape.h"
#include "face/pose.h"

#include <random>

using namespace toonface;

namespace {

// Ten minutes of speech as lip sync would give it: syllables of 0.15-0.35 s holding one to
// four shapes at the thesis' fractions (ch. 5.3), a pause every dozen syllables, with emotions,
// blinks, gaze and head motion over the whole length.
Timeline tenMinuteTimeline()
{
    constexpr double length = 600.0;
    static const double fractions[4][4] = {{0}, {0, 0.8095}, {0, 0.4337, 0.8312}, {0, 0.245, 0.4565, 0.7153}};
    std::mt19937 rng(1);
    auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    QVector<MouthCue> cues;
    double t = 0.5;
    int syllable = 0;
    while (t < length - 1.0) {
        const double duration = uniform(0.15, 0.35);
        const int shapes = 1 + int(rng() % 4);
        for (int k = 0; k < shapes; ++k) {
            const double start = t + fractions[shapes - 1][k] * duration;
            const double end = k + 1 < shapes ? t + fractions[shapes - 1][k + 1] * duration : t + duration;
            cues.append({start, end, kAllMouthShapes[1 + rng() % 8]});
        }
        t += duration;
        if (++syllable % 12 == 0)
            t += uniform(0.3, 0.9);
    }
    Timeline timeline;
    timeline.addMouthCues(cues);
    for (double s = 0; s < length; s += 30.0)
        timeline.addEmotionClip({s + 2.0, s + 20.0, kAllEmotions[1 + int(s / 30) % 4], 0.8, 0.5, 0.5});
    timeline.generateBlinks(7, length);
    for (double s = 0; s < length; s += 2.0)
        timeline.addGazeKey({s, {uniform(-0.05, 0.05), uniform(-0.02, 0.02)}});
    for (double s = 10; s < length; s += 40.0) {
        timeline.addShake(s, s + 1.0);
        timeline.addNod(s + 20.0, s + 21.0);
    }
    timeline.setAudio(AudioClip {QStringLiteral("speech.wav"), 0.0, length});
    return timeline;
}

QJsonObject benchEvaluate()
{
    const FaceModel face = averageFace(QRectF(100, 100, 300, 360), QSize(512, 512));
    const MouthShapeSet shapes;
    const Timeline timeline = tenMinuteTimeline();

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
