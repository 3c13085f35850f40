#include "anim/timelineevaluator.h"
#include "face/averageface.h"
#include "face/fapu.h"
#include "face/pointtable.h"
#include "speech/audiomouth.h"
#include "testmain.h"
#include "track/livepose.h"
#include "track/retarget.h"

#include <QtTest>

#include <cmath>

using namespace toonface;

namespace {

FaceModel testFace()
{
    return averageFace(QRectF(100, 150, 200, 240), QSize(400, 500));
}

// A tracked frame with motion everywhere live mode shows it.
TrackedFrame movingFrame(double time, double amount)
{
    TrackedFrame f;
    f.time = time;
    f.confidence = 1;
    for (const char *id : {"8.9", "8.2", "8.4", "8.3", "4.6", "4.4a", "4.4", "4.2", "4.1", "4.3", "4.3a", "4.5"})
        f.motion.displacementEs0[pt::idx(id)] = QPointF(0.01 * amount, 0.02 * amount) * (id[0] == '8' ? 3 : 1);
    f.motion.displacementEs0[pt::idx("8.2")] = QPointF(0, 0.15 * amount); // the jaw drops
    f.motion.rotationDeg = 4 * amount;
    f.motion.translationEs0 = QPointF(0.05, -0.02) * amount;
    f.motion.scale = 1 + 0.03 * amount;
    f.motion.gazeEs0 = QPointF(0.04, 0.01) * amount;
    f.motion.leftEyeOpen = 1 - 0.3 * amount;
    f.motion.rightEyeOpen = 1 - 0.2 * amount;
    return f;
}

bool near(QPointF a, QPointF b)
{
    return std::abs(a.x() - b.x()) < 1e-6 && std::abs(a.y() - b.y()) < 1e-6;
}

} // namespace

class TestLivePose : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void liveShowsWhatARecordingPlays();
    void soundMouthReplacesTheTrackedMouth();
    void chooseMouthFollowsTheMode();
    void takeReplacesItsSpanOnly();
    void takeWithSoundMouth();
    void heardOnlyTakeKeepsTheMotion();
    void importedTrackReplacesItsSpanOnly();
    void takeWithSoundWhileLost();
};

void TestLivePose::liveShowsWhatARecordingPlays()
{
    const FaceModel face = testFace();
    const MouthShapeSet shapes;
    QVector<TrackedFrame> frames;
    for (int i = 0; i < 5; ++i)
        frames.append(movingFrame(i * 0.04, i / 4.0));
    Timeline timeline;
    RetargetOptions options;
    options.mouthKeysFromShapes = false;
    addTrackToTimeline(frames, 25, &timeline, options);
    const TimelineEvaluator evaluator(timeline, face, shapes);
    for (const TrackedFrame &f : frames) {
        const Pose live = livePose(f, face, shapes);
        const Pose played = evaluator.evaluate(f.time);
        for (int i = 0; i < kPointCount; ++i)
            QVERIFY2(near(live.offset[i], played.offset[i]), qPrintable(pointId(i)));
        QVERIFY(std::abs(live.head.rotationDeg - played.head.rotationDeg) < 1e-9);
        QVERIFY(near(live.head.translation, played.head.translation));
        QVERIFY(std::abs(live.head.scale - played.head.scale) < 1e-9);
        // Lids: live follows each eye; a recording makes blinks of them instead.
        QCOMPARE(live.leftEyeOpen, f.motion.leftEyeOpen);
        QCOMPARE(live.rightEyeOpen, f.motion.rightEyeOpen);
    }
    // The motion is really there: the jaw dropped by 0.15 ES0 at the last frame.
    const double es0 = face.fapu().es0;
    const Pose last = livePose(frames.last(), face, shapes);
    const Pose rest = livePose(TrackedFrame {}, face, shapes);
    QVERIFY(std::abs((last.offset[pt::idx("8.2")] - rest.offset[pt::idx("8.2")]).y() - 0.15 * es0) < 1e-6);
    QCOMPARE(rest.head, HeadPose {});
}

void TestLivePose::soundMouthReplacesTheTrackedMouth()
{
    const FaceModel face = testFace();
    const MouthShapeSet shapes;
    const TrackedFrame f = movingFrame(0, 1);
    const Pose tracked = livePose(f, face, shapes);
    const Pose sound = livePose(f, face, shapes, WeightedShape {MouthShape::A, 0.5});
    const std::array<QPointF, 4> a = shapes.displacements(MouthShape::A, face);
    for (int k = 0; k < 4; ++k)
        QVERIFY(near(sound.offset[pt::idx(kMouthControlIds[k])], a[k] * 0.5));
    // Everything else still follows the camera.
    for (const char *id : {"4.2", "4.1", "3.6", "3.5"})
        QVERIFY(near(sound.offset[pt::idx(id)], tracked.offset[pt::idx(id)]));
    QCOMPARE(sound.head, tracked.head);
}

void TestLivePose::chooseMouthFollowsTheMode()
{
    const WeightedShape s {MouthShape::O, 0.7};
    QVERIFY(!chooseMouth(LiveMouth::Camera, false, s));
    QVERIFY(!chooseMouth(LiveMouth::Camera, true, s));
    QCOMPARE(chooseMouth(LiveMouth::Microphone, false, s)->shape, MouthShape::O);
    QCOMPARE(chooseMouth(LiveMouth::Microphone, true, s)->weight, 0.7);
    QVERIFY(!chooseMouth(LiveMouth::Both, false, s));
    QCOMPARE(chooseMouth(LiveMouth::Both, true, s)->shape, MouthShape::O);
}

void TestLivePose::takeReplacesItsSpanOnly()
{
    Timeline timeline;
    for (double t : {0.5, 3.5, 6.0}) {
        PoseKey key;
        key.time = t;
        key.offsetsEs0.insert(QStringLiteral("4.2"), QPointF(0, -0.1));
        timeline.addPoseKey(key);
        timeline.addHeadKey({t, 5.0, {}, 1.0});
    }
    timeline.addPoseKey(PoseKey {2.5, {{QStringLiteral("4.1"), QPointF(0, 0.1)}}});
    timeline.setMouthKeys(
        {{0.2, MouthShape::A, 1.0, 0.3}, {2.4, MouthShape::E, 1.0, 0.2}, {6.0, MouthShape::O, 1.0, 0.2}});
    timeline.setBlinks({{1.0, 0.18}, {2.2, 0.18}, {4.0, 0.18}});

    // A take of one second: the eyes shut in its middle.
    QVector<TrackedFrame> take;
    for (int i = 0; i < 25; ++i) {
        TrackedFrame f = movingFrame(i * 0.04, 0.5);
        const double closed = (i >= 11 && i <= 13) ? 0.05 : 1.0;
        f.motion.leftEyeOpen = f.motion.rightEyeOpen = closed;
        take.append(f);
    }
    addTakeToTimeline(take, 25, 1.0, {}, &timeline, 2.0);

    QVector<double> poseTimes;
    for (const PoseKey &k : timeline.poseKeys())
        poseTimes.append(k.time);
    QCOMPARE(poseTimes.size(), 3 + 25);
    QCOMPARE(poseTimes.first(), 0.5);
    QCOMPARE(poseTimes[1], 2.0);
    QVERIFY(std::abs(poseTimes[25] - 2.96) < 1e-9);
    QCOMPARE(poseTimes[26], 3.5);
    QVERIFY(std::is_sorted(poseTimes.cbegin(), poseTimes.cend()));
    QVERIFY(timeline.poseKeys()[1].offsetsEs0.contains(QStringLiteral("8.2"))); // the tracked mouth
    QCOMPARE(timeline.headKeys().size(), 3 + 25);
    QCOMPARE(timeline.gazeKeys().size(), 25);
    // Blinks: the ones outside kept, the one inside replaced by the take's.
    QCOMPARE(timeline.blinks().size(), 3);
    QCOMPARE(timeline.blinks()[0].time, 1.0);
    QVERIFY(timeline.blinks()[1].time > 2.2 && timeline.blinks()[1].time < 2.6);
    QCOMPARE(timeline.blinks()[2].time, 4.0);
    // Mouth: the key inside is gone, a shut key stops the one before from sounding on.
    QCOMPARE(timeline.mouthKeys().size(), 3);
    QCOMPARE(timeline.mouthKeys()[1].time, 2.0);
    QCOMPARE(timeline.mouthKeys()[1].shape, MouthShape::M);
    QCOMPARE(timeline.mouthKeys()[2].shape, MouthShape::O);
}

void TestLivePose::takeWithSoundMouth()
{
    Timeline timeline;
    QVector<TrackedFrame> take;
    for (int i = 0; i < 10; ++i)
        take.append(movingFrame(i * 0.04, 1));
    const QVector<MouthKey> sound
        = {{0.0, MouthShape::M, 1.0, 0.1}, {0.1, MouthShape::A, 0.8, 0.2}, {0.3, MouthShape::M, 1.0, 0.1}};
    addTakeToTimeline(take, 25, 0.4, sound, &timeline, 5.0);
    QCOMPARE(timeline.mouthKeys().size(), 3);
    QCOMPARE(timeline.mouthKeys()[1].time, 5.1);
    QCOMPARE(timeline.mouthKeys()[1].shape, MouthShape::A);
    QCOMPARE(timeline.mouthKeys()[1].weight, 0.8);
    for (const PoseKey &k : timeline.poseKeys()) {
        for (const char *id : kMouthControlIds)
            QVERIFY(!k.offsetsEs0.contains(QString::fromLatin1(id)));
        QVERIFY(k.offsetsEs0.contains(QStringLiteral("4.2")));
    }
}

// A take heard only (the microphone alone, no frames) puts its mouth in the span and leaves the
// pose, head, gaze and blinks there as they were.
void TestLivePose::heardOnlyTakeKeepsTheMotion()
{
    Timeline timeline;
    for (const double t : {1.0, 2.5, 4.0}) {
        timeline.addPoseKey(PoseKey {t, {{QStringLiteral("4.1"), QPointF(0, 0.1)}}});
        timeline.addHeadKey({t, 5.0, {}, 1.0});
        timeline.addGazeKey({t, QPointF(0.1, 0)});
    }
    timeline.setBlinks({{2.2, 0.18}});
    timeline.setMouthKeys({{0.2, MouthShape::A, 1.0, 0.3}, {2.4, MouthShape::E, 1.0, 0.2}});
    const Timeline before = timeline;
    const QVector<MouthKey> sound
        = {{0.0, MouthShape::M, 1.0, 0.1}, {0.3, MouthShape::O, 0.7, 0.2}, {0.9, MouthShape::M, 1.0, 0.1}};
    addTakeToTimeline({}, 30, 1.2, sound, &timeline, 2.0);
    QCOMPARE(timeline.poseKeys(), before.poseKeys());
    QCOMPARE(timeline.headKeys(), before.headKeys());
    QCOMPARE(timeline.gazeKeys(), before.gazeKeys());
    QCOMPARE(timeline.blinks(), before.blinks());
    // The mouth: the key before kept, the one inside replaced by the sound's.
    QCOMPARE(timeline.mouthKeys().size(), 4);
    QCOMPARE(timeline.mouthKeys()[0].shape, MouthShape::A);
    QCOMPARE(timeline.mouthKeys()[1].time, 2.0);
    QCOMPARE(timeline.mouthKeys()[2].time, 2.3);
    QCOMPARE(timeline.mouthKeys()[2].shape, MouthShape::O);
    QCOMPARE(timeline.mouthKeys()[2].weight, 0.7);
}

// An imported video's track lands on its own span of the timeline: what the animation held
// before and after it (lip sync, blinks, head keys) stays; inside, the tracked motion replaces
// it, and the lip-synced mouth there gives way to the tracked one.
void TestLivePose::importedTrackReplacesItsSpanOnly()
{
    Timeline timeline;
    for (const double t : {0.5, 1.5, 4.0}) {
        timeline.addPoseKey(PoseKey {t, {{QStringLiteral("4.1"), QPointF(0, 0.1)}}});
        timeline.addHeadKey({t, 5.0, {}, 1.0});
        timeline.addGazeKey({t, QPointF(0.1, 0)});
    }
    timeline.setMouthKeys(
        {{0.2, MouthShape::A, 1.0, 0.3}, {1.6, MouthShape::E, 1.0, 0.2}, {4.2, MouthShape::O, 1.0, 0.2}});
    timeline.setBlinks({{0.8, 0.18}, {1.8, 0.18}, {4.5, 0.18}});

    // Ten frames of a clip placed at 1.2 s: the span is [1.2, 1.6).
    QVector<TrackedFrame> frames;
    for (int i = 0; i < 10; ++i)
        frames.append(movingFrame(i * 0.04, 0.5));
    RetargetOptions options;
    options.mouthKeysFromShapes = false;
    addTrackToTimeline(frames, 25, &timeline, options, 1.2);

    auto times = [](const auto &keys) {
        QVector<double> out;
        for (const auto &k : keys)
            out.append(k.time);
        return out;
    };
    for (const QVector<double> &t :
        {times(timeline.poseKeys()), times(timeline.headKeys()), times(timeline.gazeKeys())}) {
        QCOMPARE(t.size(), 2 + 10); // 0.5 and 4.0 kept, 1.5 replaced by the ten frames
        QCOMPARE(t.first(), 0.5);
        QCOMPARE(t[1], 1.2);
        QCOMPARE(t.last(), 4.0);
        QVERIFY(std::is_sorted(t.cbegin(), t.cend()));
    }
    QCOMPARE(timeline.headKeys()[1].rotationDeg, frames[0].motion.rotationDeg);
    // Blinks outside kept (the clip has none: the eyes stay open).
    QCOMPARE(times(timeline.blinks()), (QVector<double> {0.8, 1.8, 4.5}));
    // Mouth: the lip-synced key in the span is gone and a shut key stops the one before it
    // there; the tracked mouth is in the pose keys.
    QCOMPARE(timeline.mouthKeys().size(), 3);
    QCOMPARE(timeline.mouthKeys()[1].time, 1.2);
    QCOMPARE(timeline.mouthKeys()[1].shape, MouthShape::M);
    QCOMPARE(timeline.mouthKeys()[2].shape, MouthShape::O);
    QVERIFY(timeline.poseKeys()[1].offsetsEs0.contains(QStringLiteral("8.2")));
}

// Live mode's "camera, microphone when the lips are lost", recorded: the camera's mouth where
// it saw the face, the sound's where it lost it, as live mode showed them.
void TestLivePose::takeWithSoundWhileLost()
{
    // One second at 25 fps; the face lost from 0.4 s to 0.6 s.
    QVector<TrackedFrame> take;
    for (int i = 0; i < 25; ++i) {
        TrackedFrame f = movingFrame(i * 0.04, 0.5);
        f.lost = i >= 10 && i < 15;
        take.append(f);
    }
    // The sound says a (from 0.3 s), o (0.5 s), e (0.8 s).
    const QVector<MouthKey> sound = {{0.3, MouthShape::A, 0.8, std::nullopt}, {0.5, MouthShape::O, 0.9, std::nullopt},
        {0.8, MouthShape::E, 0.7, std::nullopt}};
    Timeline timeline;
    addTakeToTimeline(take, 25, 1.0, sound, &timeline, 2.0, true);

    // A pose key per frame, lost ones included: they hold the last pose, mouth at rest.
    QCOMPARE(timeline.poseKeys().size(), 25);
    const PoseKey &seen = timeline.poseKeys()[9];
    const PoseKey &lost = timeline.poseKeys()[12];
    QVERIFY(seen.offsetsEs0.value(QStringLiteral("8.2")).y() > 0.05); // the camera's mouth
    QCOMPARE(lost.offsetsEs0.value(QStringLiteral("8.2")), QPointF());
    QCOMPARE(lost.offsetsEs0.value(QStringLiteral("4.1")), seen.offsetsEs0.value(QStringLiteral("4.1")));
    QCOMPARE(timeline.headKeys()[12].rotationDeg, timeline.headKeys()[9].rotationDeg);
    // The sound's mouth only while lost: a (sounding since 0.3 s) from 0.4 s, o at 0.5 s, shut
    // at 0.6 s where the camera has the face again; e (0.8 s) is the camera's time.
    const QVector<MouthKey> &mouth = timeline.mouthKeys();
    QCOMPARE(mouth.size(), 3);
    QVERIFY(std::abs(mouth[0].time - 2.4) < 1e-9);
    QCOMPARE(mouth[0].shape, MouthShape::A);
    QCOMPARE(mouth[0].weight, 0.8);
    QVERIFY(std::abs(mouth[1].time - 2.5) < 1e-9);
    QCOMPARE(mouth[1].shape, MouthShape::O);
    QVERIFY(std::abs(mouth[2].time - 2.6) < 1e-9);
    QCOMPARE(mouth[2].shape, MouthShape::M);
}

TOONFACE_TEST_GUILESS_MAIN(TestLivePose)
#include "tst_livepose.moc"
