#include "anim/timeline.h"
#include "anim/timelineevaluator.h"
#include "face/averageface.h"
#include "face/mouthshape.h"
#include "testmain.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QTest>

#include <cmath>

using namespace toonface;

namespace {

// A timeline using every field, with values that are not round in binary.
Timeline fullTimeline()
{
    Timeline t;
    t.setFrameRate(29.97);
    t.setSmoothing({0.05, 0.11, 0.27});
    t.addMouthCues({{0.1, 0.3, MouthShape::I}, {0.3, 0.41, MouthShape::N}, {0.7, 0.7 + 1.0 / 3.0, MouthShape::A}});
    t.addMouthKey({1.7, MouthShape::O, 0.6, std::nullopt});
    t.addMouthKey({2.2, MouthShape::F, 1.0, 0.1});
    t.addEmotionClip({0.2, 3.1, Emotion::Smile, 0.7, 0.25, 0.4});
    t.addEmotionClip({1.0, 2.0, Emotion::Surprise, 1.0 / 7.0, 0.0, 0.1});
    t.generateBlinks(42, 12.0);
    t.addGazeKey({0.5, {0.1 / 3.0, -0.02}});
    t.addGazeKey({1.5, {-0.05, 0.0}});
    t.addHeadKey({0.0, 0.0, {}, 1.0});
    t.addHeadKey({2.0, 3.5, {0.01, -0.02}, 1.05});
    t.addShake(3.0, 4.0);
    t.addNod(5.0, 6.0);
    t.addPoseKey({0.04, {{QStringLiteral("8.2"), {0.0, 0.125}}, {QStringLiteral("8.4"), {-0.01 / 3.0, 0.0}}}});
    t.addPoseKey({0.08, {{QStringLiteral("3.2"), {0.0, 0.05}}}});
    t.setAudioClips({AudioClip {QStringLiteral("/tmp/speech (1).wav"), 0.125, 11.9}});
    return t;
}

double rotationAt(const Timeline &t, double time)
{
    return t.headAt(time).rotationDeg;
}

} // namespace

class TestTimeline : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void defaults()
    {
        const Timeline t;
        QCOMPARE(t.frameRate(), 25.0);
        QCOMPARE(t.duration(), 0.0);
        QCOMPARE(t.frameCount(), 0);
        QVERIFY(t.audioClips().isEmpty());
        QCOMPARE(t.smoothing().minHold, 0.06);
        QCOMPARE(t.smoothing().silenceHold, 0.3);
    }

    void tracksStaySortedAndLaterEqualTimeWins()
    {
        Timeline t;
        t.addMouthKey({2.0, MouthShape::A, 1.0, {}});
        t.addMouthKey({1.0, MouthShape::E, 1.0, {}});
        t.addMouthKey({2.0, MouthShape::O, 1.0, {}});
        QCOMPARE(t.mouthKeys().size(), 3);
        QCOMPARE(t.mouthKeys()[0].shape, MouthShape::E);
        QCOMPARE(t.mouthKeys()[1].shape, MouthShape::A);
        QCOMPARE(t.mouthKeys()[2].shape, MouthShape::O);
        // The evaluator shows the later of two keys at the same time.
        const FaceModel face = averageFace(QRectF(100, 150, 200, 240), QSize(400, 500));
        const MouthShapeSet shapes;
        const auto o = shapes.displacements(MouthShape::O, face);
        QCOMPARE(TimelineEvaluator(t, face, shapes).mouthAt(2.0), o);

        t.setBlinks({{5.0, 0.2}, {1.0, 0.2}});
        QCOMPARE(t.blinks().first().time, 1.0);
        t.setHeadKeys({{3.0, 1, {}, 1}, {0.5, 2, {}, 1}});
        QCOMPARE(t.headKeys().first().time, 0.5);
    }

    // Issue 26: the audio track keeps its clips in order of where they are heard, round-trips
    // through JSON, and reads a version-1 file's one clip.
    void audioTrack()
    {
        Timeline t;
        AudioClip late {QStringLiteral("b.wav"), 5.0, 3.0};
        late.trimIn = 0.5;
        late.trimOut = 0.25;
        late.script = QStringLiteral("bye");
        late.language = QStringLiteral("en");
        AudioClip early {QStringLiteral("a.wav"), 0.0, 4.0};
        QCOMPARE(t.addAudioClip(late), 0);
        QCOMPARE(t.addAudioClip(early), 0);
        QCOMPARE(t.audioClips()[1], late);
        QCOMPARE(late.start(), 5.5);
        QCOMPARE(late.end(), 7.75);
        QCOMPARE(t.audioClipAt(2.0), 0);
        QCOMPARE(t.audioClipAt(5.2), -1); // trimmed away
        QCOMPARE(t.audioClipAt(6.0), 1);
        QCOMPARE(t.duration(), 7.75);

        QString error;
        const QJsonObject json = t.toJson();
        QCOMPARE(json.value(QStringLiteral("version")).toInt(), 2);
        QCOMPARE(json.value(QStringLiteral("audio")).toArray().size(), 2);
        const std::optional<Timeline> back = Timeline::fromJson(json, &error);
        QVERIFY2(back, qPrintable(error));
        QCOMPARE(*back, t);

        QJsonObject v1;
        v1.insert(QStringLiteral("version"), 1);
        v1.insert(QStringLiteral("audio"),
            QJsonObject {{QStringLiteral("path"), QStringLiteral("x.wav")}, {QStringLiteral("offset"), 0.5},
                {QStringLiteral("duration"), 2.0}});
        const std::optional<Timeline> old = Timeline::fromJson(v1, &error);
        QVERIFY2(old, qPrintable(error));
        QCOMPARE(old->audioClips(), QVector<AudioClip> {AudioClip(QStringLiteral("x.wav"), 0.5, 2.0)});

        // Bad clips are named.
        QJsonObject bad = json;
        QJsonArray clips = json.value(QStringLiteral("audio")).toArray();
        QJsonObject c = clips[1].toObject();
        c.insert(QStringLiteral("trimIn"), 2.9);
        clips[1] = c;
        bad.insert(QStringLiteral("audio"), clips);
        QVERIFY(!Timeline::fromJson(bad, &error));
        QVERIFY2(error.startsWith(QStringLiteral("audio[1].trimOut")), qPrintable(error));
        c.insert(QStringLiteral("trimIn"), 0.0);
        c.insert(QStringLiteral("offset"), Timeline::kMaxSeconds - 1);
        clips[1] = c;
        bad.insert(QStringLiteral("audio"), clips);
        QVERIFY(!Timeline::fromJson(bad, &error));
        QVERIFY2(error.startsWith(QStringLiteral("audio[1].duration")), qPrintable(error));
    }

    void durationFollowsAudioOrLastKey()
    {
        Timeline t;
        t.addMouthCues({{1.0, 2.5, MouthShape::A}});
        QCOMPARE(t.duration(), 2.5);
        t.addBlink({2.4, 0.2});
        QCOMPARE(t.duration(), 2.6);
        t.setAudioClips({AudioClip {QStringLiteral("a.wav"), 0.5, 10.0}});
        QCOMPARE(t.duration(), 10.5);
        QCOMPARE(t.frameCount(), 263); // ceil(10.5 * 25)
        t.setAudioClips({AudioClip {QStringLiteral("a.wav"), 0.0, 10.0}});
        QCOMPARE(t.frameCount(), 250);
        t.setFrameRate(30);
        QCOMPARE(t.frameCount(), 300);
    }

    void mouthCuesBecomeKeysWithDurations()
    {
        Timeline t;
        t.addMouthKey({0.5, MouthShape::E, 1.0, {}});
        t.addMouthKey({1.2, MouthShape::E, 1.0, {}}); // inside the cues' span: replaced
        t.addMouthKey({9.0, MouthShape::O, 1.0, {}});
        const QVector<MouthCue> cues = {{1.5, 1.9, MouthShape::U}, {1.0, 1.3, MouthShape::A}};
        t.addMouthCues(cues);
        QCOMPARE(t.mouthKeys().size(), 4);
        QCOMPARE(t.mouthKeys()[1].time, 1.0);
        QCOMPARE(t.mouthKeys()[1].shape, MouthShape::A);
        QCOMPARE(t.mouthKeys()[1].weight, 1.0);
        QVERIFY(std::abs(*t.mouthKeys()[1].duration - 0.3) < 1e-12);
        QCOMPARE(t.mouthKeys()[2].shape, MouthShape::U);
        QVERIFY(std::abs(*t.mouthKeys()[2].duration - 0.4) < 1e-12);

        const QVector<MouthCue> back = t.mouthCues();
        QCOMPARE(back.size(), 4);
        QCOMPARE(back[0], (MouthCue {0.5, 1.0, MouthShape::E})); // until the next key
        QCOMPARE(back[1], (MouthCue {1.0, 1.0 + (1.3 - 1.0), MouthShape::A}));
        QCOMPARE(back[3], (MouthCue {9.0, 9.3, MouthShape::O})); // last: silenceHold

        Timeline fromCues;
        fromCues.addMouthCues(cues);
        Timeline again;
        again.addMouthCues(fromCues.mouthCues());
        QCOMPARE(again, fromCues);
    }

    void blinksAreDeterministicForASeed()
    {
        const auto a = Timeline::randomBlinks(7, 120.0);
        const auto b = Timeline::randomBlinks(7, 120.0);
        const auto c = Timeline::randomBlinks(8, 120.0);
        QVERIFY(!a.isEmpty());
        QCOMPARE(a, b);
        QVERIFY(a != c);
        Timeline t;
        t.generateBlinks(7, 120.0);
        QCOMPARE(t.blinks(), a);
        QVERIFY(Timeline::randomBlinks(7, 0.0).isEmpty());
    }

    void blinksAreHumanLike_data()
    {
        QTest::addColumn<quint32>("seed");
        for (quint32 seed : {0u, 1u, 42u, 2024u, 0xdeadbeefu})
            QTest::addRow("seed %u", seed) << seed;
    }

    void blinksAreHumanLike()
    {
        QFETCH(quint32, seed);
        const double duration = 600.0;
        const auto blinks = Timeline::randomBlinks(seed, duration);
        int doubles = 0;
        for (qsizetype i = 0; i < blinks.size(); ++i) {
            const BlinkEvent &b = blinks[i];
            QVERIFY(b.time >= 0);
            QVERIFY(b.time + b.duration <= duration);
            QVERIFY2(b.duration >= Timeline::kBlinkDurationMin && b.duration <= Timeline::kBlinkDurationMax,
                qPrintable(QString::number(b.duration)));
            if (i == 0)
                continue;
            const double gap = b.time - (blinks[i - 1].time + blinks[i - 1].duration);
            const bool single = gap >= Timeline::kBlinkGapMin - 1e-12 && gap <= Timeline::kBlinkGapMax + 1e-12;
            const bool second
                = gap >= Timeline::kDoubleBlinkGapMin - 1e-12 && gap <= Timeline::kDoubleBlinkGapMax + 1e-12;
            QVERIFY2(single || second, qPrintable(QStringLiteral("gap %1 before blink %2").arg(gap).arg(i)));
            doubles += second;
        }
        // 15-20 blinks a minute: a mean start-to-start interval of 3-4 s (here about 3.5 s).
        const double meanInterval = (blinks.last().time - blinks.first().time) / double(blinks.size() - 1);
        QVERIFY2(meanInterval > 3.0 && meanInterval < 4.0, qPrintable(QString::number(meanInterval)));
        // Occasional double blinks: about one in ten.
        const double doubleShare = double(doubles) / blinks.size();
        QVERIFY2(doubleShare > 0.02 && doubleShare < 0.2, qPrintable(QString::number(doubleShare)));
        // Variability: intervals are not all alike.
        double shortest = 1e9, longest = 0;
        for (qsizetype i = 1; i < blinks.size(); ++i) {
            const double d = blinks[i].time - blinks[i - 1].time;
            shortest = std::min(shortest, d);
            longest = std::max(longest, d);
        }
        QVERIFY(shortest < 1.0);
        QVERIFY(longest > 6.0);
    }

    void shakeOscillatesSideToSide()
    {
        Timeline t;
        t.addHeadKey({0.0, 2.0, {}, 1.0});
        t.addHeadKey({1.5, 2.0, {}, 1.0}); // inside the shake: replaced
        t.addHeadKey({10.0, 2.0, {}, 1.0});
        const double amplitude = 8.0;
        t.addShake(1.0, 2.0, amplitude, 5.0);
        const auto &keys = t.headKeys();
        // start + 5 extremes + end, plus the keys outside.
        QCOMPARE(keys.size(), 9);
        QCOMPARE(rotationAt(t, 1.0), 2.0);
        QCOMPARE(rotationAt(t, 2.0), 2.0);
        for (int j = 0; j < 5; ++j) {
            const double tj = 1.0 + (2 * j + 1) / 10.0;
            const double swing = rotationAt(t, tj) - 2.0;
            QCOMPARE(swing > 0, j % 2 == 0);
            QVERIFY(std::abs(swing) <= amplitude + 1e-9);
            QVERIFY(std::abs(swing) >= 0.7 * amplitude - 1e-9);
            if (j > 0)
                QVERIFY(std::abs(swing) < std::abs(rotationAt(t, tj - 0.2) - 2.0)); // damping
        }
        // The swings pass through the rest pose between extremes: 4 crossings.
        int crossings = 0;
        double previous = 0;
        for (double time = 1.0; time <= 2.0; time += 0.005) {
            const double swing = rotationAt(t, time) - 2.0;
            if (std::abs(swing) > 1e-6) {
                crossings += previous != 0 && (swing > 0) != (previous > 0);
                previous = swing;
            }
        }
        QCOMPARE(crossings, 4);
        QCOMPARE(t.headAt(1.5).translationEs0, QPointF()); // a shake does not move the head up or down
    }

    void nodGoesDownAndUp()
    {
        Timeline t;
        const double amplitude = 0.06;
        t.addNod(0.0, 1.0, amplitude, 4.0);
        QCOMPARE(t.headKeys().size(), 6);
        for (int j = 0; j < 4; ++j) {
            const double y = t.headAt((2 * j + 1) / 8.0).translationEs0.y();
            if (j % 2 == 0)
                QVERIFY(y > 0.7 * amplitude - 1e-9 && y <= amplitude + 1e-9); // down (y grows downward)
            else
                QVERIFY(y < 0 && y >= -0.25 * amplitude - 1e-9); // up a little
            QCOMPARE(t.headAt((2 * j + 1) / 8.0).rotationDeg, 0.0);
        }
        QCOMPARE(t.headAt(0.0).translationEs0, QPointF());
        QCOMPARE(t.headAt(1.0).translationEs0, QPointF());
        // At least two extremes however short the interval.
        Timeline brief;
        brief.addNod(0.0, 0.05);
        QCOMPARE(brief.headKeys().size(), 4);
    }

    void jsonRoundTripIsLossless()
    {
        const Timeline original = fullTimeline();
        const QJsonObject json = original.toJson();
        QString error;
        const auto back = Timeline::fromJson(json, &error);
        QVERIFY2(back, qPrintable(error));
        QCOMPARE(*back, original);

        // Through text, as the project file stores it.
        const QByteArray text = QJsonDocument(json).toJson(QJsonDocument::Compact);
        const auto fromText = Timeline::fromJson(QJsonDocument::fromJson(text).object(), &error);
        QVERIFY2(fromText, qPrintable(error));
        QCOMPARE(*fromText, original);
        QCOMPARE(fromText->toJson(), json);
    }

    void poseKeysStaySortedAndReplaceAtEqualTime()
    {
        Timeline t;
        const PoseKey open {2.0, {{QStringLiteral("8.2"), {0.0, 0.3}}}};
        const PoseKey wide {1.0, {{QStringLiteral("8.4"), {-0.1, 0.0}}, {QStringLiteral("8.3"), {0.1, 0.0}}}};
        t.addPoseKey(open);
        t.addPoseKey(wide);
        QCOMPARE(t.poseKeys().size(), 2);
        QCOMPARE(t.poseKeys()[0], wide);
        QCOMPARE(t.poseKeys()[1], open);
        QCOMPARE(t.duration(), 2.0);

        // A key at the same time (within the tolerance) replaces the old one.
        PoseKey shut = open;
        shut.time = 2.0 + Timeline::kPoseTimeTolerance / 2;
        shut.offsetsEs0[QStringLiteral("8.2")] = {0.0, 0.0};
        t.addPoseKey(shut);
        QCOMPARE(t.poseKeys().size(), 2);
        QCOMPARE(t.poseKeys()[1], shut);
        // Further apart it is a key of its own, in time order.
        t.addPoseKey({1.5, {}});
        QCOMPARE(t.poseKeys().size(), 3);
        QCOMPARE(t.poseKeys()[1].time, 1.5);

        t.setPoseKeys({open, wide});
        QCOMPARE(t.poseKeys()[0], wide);
    }

    void oldFilesLoadWithAnEmptyPoseTrack()
    {
        QJsonObject json = fullTimeline().toJson();
        QVERIFY(json.value(QStringLiteral("pose")).isArray());
        QCOMPARE(json.value(QStringLiteral("pose")).toArray().size(), 2);
        const QJsonArray offsets = json.value(QStringLiteral("pose"))
                                       .toArray()[0]
                                       .toObject()
                                       .value(QStringLiteral("offsets"))
                                       .toObject()
                                       .value(QStringLiteral("8.2"))
                                       .toArray();
        QCOMPARE(offsets.size(), 2);
        QCOMPARE(offsets[0].toDouble(), 0.0);
        QCOMPARE(offsets[1].toDouble(), 0.125);
        json.remove(QStringLiteral("pose"));
        QString error;
        const auto t = Timeline::fromJson(json, &error);
        QVERIFY2(t, qPrintable(error));
        QVERIFY(t->poseKeys().isEmpty());
        QCOMPARE(t->mouthKeys(), fullTimeline().mouthKeys());

        const QByteArray unsorted = R"({"pose": [{"time": 2, "offsets": {"8.9": [0, -0.1]}}, {"time": 1}]})";
        const auto u = Timeline::fromJson(QJsonDocument::fromJson(unsorted).object(), &error);
        QVERIFY2(u, qPrintable(error));
        QCOMPARE(u->poseKeys().size(), 2);
        QCOMPARE(u->poseKeys()[0], (PoseKey {1.0, {}}));
        QCOMPARE(u->poseKeys()[1].offsetsEs0.value(QStringLiteral("8.9")), QPointF(0, -0.1));
    }

    void jsonDefaultsAndOrder()
    {
        QString error;
        const auto empty = Timeline::fromJson(QJsonObject(), &error);
        QVERIFY2(empty, qPrintable(error));
        QCOMPARE(*empty, Timeline());

        const QByteArray text = R"({"mouth": [{"time": 2, "shape": "o"}, {"time": 1, "shape": "a", "weight": 0.5}],
                                    "audio": null})";
        const auto t = Timeline::fromJson(QJsonDocument::fromJson(text).object(), &error);
        QVERIFY2(t, qPrintable(error));
        QCOMPARE(t->mouthKeys().size(), 2);
        QCOMPARE(t->mouthKeys()[0], (MouthKey {1.0, MouthShape::A, 0.5, std::nullopt}));
        QVERIFY(t->audioClips().isEmpty());
    }

    void jsonErrorsNameThePath_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("error");
        QTest::newRow("unknown shape") << QByteArray(R"({"mouth": [{"time": 0, "shape": "a"}, {"time": 1, "shape": "i"},
                                       {"time": 2, "shape": "u"}, {"time": 3, "shape": "x"}]})")
                                       << QStringLiteral("mouth[3].shape: unknown mouth shape 'x'");
        QTest::newRow("missing time") << QByteArray(R"({"mouth": [{"shape": "a"}]})")
                                      << QStringLiteral("mouth[0].time: missing");
        QTest::newRow("time not a number") << QByteArray(R"({"mouth": [{"time": "1", "shape": "a"}]})")
                                           << QStringLiteral("mouth[0].time: expected a number");
        QTest::newRow("shape not a string") << QByteArray(R"({"mouth": [{"time": 1, "shape": 3}]})")
                                            << QStringLiteral("mouth[0].shape: expected a string");
        QTest::newRow("negative weight") << QByteArray(R"({"mouth": [{"time": 1, "shape": "a", "weight": -1}]})")
                                         << QStringLiteral("mouth[0].weight: must not be negative");
        QTest::newRow("track not an array")
            << QByteArray(R"({"mouth": {}})") << QStringLiteral("mouth: expected an array");
        QTest::newRow("key not an object")
            << QByteArray(R"({"blink": [{"time": 1}, 3]})") << QStringLiteral("blink[1]: expected an object");
        QTest::newRow("clip ends first") << QByteArray(R"({"emotion": [{"start": 1, "end": 0.5, "emotion": "smile"}]})")
                                         << QStringLiteral("emotion[0].end: must not be before start");
        QTest::newRow("unknown emotion") << QByteArray(R"({"emotion": [{"start": 0, "end": 1, "emotion": "bored"}]})")
                                         << QStringLiteral("emotion[0].emotion: unknown emotion 'bored'");
        QTest::newRow("intensity above 1")
            << QByteArray(R"({"emotion": [{"start": 0, "end": 1, "emotion": "sad", "intensity": 1.5}]})")
            << QStringLiteral("emotion[0].intensity: must be between 0 and 1");
        QTest::newRow("zero blink") << QByteArray(R"({"blink": [{"time": 1, "duration": 0}]})")
                                    << QStringLiteral("blink[0].duration: must be positive");
        QTest::newRow("gaze x") << QByteArray(R"({"gaze": [{"time": 0, "x": "left"}]})")
                                << QStringLiteral("gaze[0].x: expected a number");
        QTest::newRow("head scale") << QByteArray(R"({"head": [{"time": 0}, {"time": 1, "scale": -1}]})")
                                    << QStringLiteral("head[1].scale: must be positive");
        QTest::newRow("pose time") << QByteArray(R"({"pose": [{"offsets": {}}]})")
                                   << QStringLiteral("pose[0].time: missing");
        QTest::newRow("pose offsets type") << QByteArray(R"({"pose": [{"time": 0, "offsets": [1, 2]}]})")
                                           << QStringLiteral("pose[0].offsets: expected an object");
        QTest::newRow("pose unknown point")
            << QByteArray(R"({"pose": [{"time": 0}, {"time": 1, "offsets": {"99.1": [0, 1]}}]})")
            << QStringLiteral("pose[1].offsets.99.1: unknown point ID");
        QTest::newRow("pose offset shape") << QByteArray(R"({"pose": [{"time": 0, "offsets": {"8.2": [1]}}]})")
                                           << QStringLiteral("pose[0].offsets.8.2: expected [dx, dy], two numbers");
        QTest::newRow("pose offset number") << QByteArray(R"({"pose": [{"time": 0, "offsets": {"8.2": [1, "a"]}}]})")
                                            << QStringLiteral("pose[0].offsets.8.2: expected [dx, dy], two numbers");
        QTest::newRow("fps") << QByteArray(R"({"fps": 0})") << QStringLiteral("fps: must be positive");
        QTest::newRow("newer version") << QByteArray(R"({"version": 3})")
                                       << QStringLiteral("version: 3 is newer than this Toonface reads (2)");
        QTest::newRow("smoothing field") << QByteArray(R"({"smoothing": {"minHold": -0.1}})")
                                         << QStringLiteral("smoothing.minHold: must not be negative");
        QTest::newRow("smoothing type") << QByteArray(R"({"smoothing": []})")
                                        << QStringLiteral("smoothing: expected an object");
        QTest::newRow("audio path") << QByteArray(R"({"audio": {"offset": 1}})")
                                    << QStringLiteral("audio.path: missing");
        QTest::newRow("audio type") << QByteArray(R"({"audio": "a.wav"})")
                                    << QStringLiteral("audio: expected an array of clips");
        QTest::newRow("video path") << QByteArray(R"({"video": {"offset": 1}})")
                                    << QStringLiteral("video.path: missing");
        QTest::newRow("video fps") << QByteArray(R"({"video": {"path": "a.mpg", "fps": -25}})")
                                   << QStringLiteral("video.fps: must not be negative");
        QTest::newRow("video type") << QByteArray(R"({"video": 3})") << QStringLiteral("video: expected an object");
    }

    void videoClipRoundTrips()
    {
        Timeline t = fullTimeline();
        QVERIFY(!t.video());
        t.setVideo(VideoClip {QStringLiteral("/clips/talk.mpg"), 0.25, 3.0, 25.0});
        QString error;
        const auto back = Timeline::fromJson(t.toJson(), &error);
        QVERIFY2(back, qPrintable(error));
        QVERIFY(back->video());
        QCOMPARE(*back->video(), *t.video());
        QCOMPARE(*back, t);
        // Without a clip nothing is written, and older files (no "video") load without one.
        QVERIFY(!fullTimeline().toJson().contains(QStringLiteral("video")));
    }

    void jsonErrorsNameThePath()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, error);
        QJsonParseError parse;
        const QJsonDocument doc = QJsonDocument::fromJson(json, &parse);
        QVERIFY2(parse.error == QJsonParseError::NoError, qPrintable(parse.errorString()));
        QString message;
        const auto t = Timeline::fromJson(doc.object(), &message);
        QVERIFY(!t);
        QCOMPARE(message, error);
        // A null error pointer is allowed.
        QVERIFY(!Timeline::fromJson(doc.object(), nullptr));
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestTimeline)
#include "tst_timeline.moc"
