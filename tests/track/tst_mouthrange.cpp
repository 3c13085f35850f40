#include "media/mediareader.h"
#include "testmain.h"
#include "track/mouthrange.h"
#include "track/trackaccuracy.h"
#include "track/trackvideo.h"

#include <QFileInfo>
#include <QJsonObject>
#include <QTest>

#include <algorithm>
#include <set>

using namespace toonface;

namespace {

const QString kPortrait = QStringLiteral("/usr/lib/python3/dist-packages/skimage/data/astronaut.png");
const QString kVideoDir = QStringLiteral(TOONFACE_SHARED_DATA "/video");
constexpr double kFps = 25.0;

// A frame whose mouth controls 8.9, 8.2, 8.4, 8.3 are displaced by `mouth` (ES0).
TrackedFrame frameWith(int index, const std::array<QPointF, 4> &mouth, bool lost = false)
{
    TrackedFrame f;
    f.index = index;
    f.time = index / kFps;
    f.lost = lost;
    for (int k = 0; k < 4; ++k)
        f.motion.displacementEs0[pt::idx(kMouthControlIds[k])] = mouth[k];
    return f;
}

// The outer lips parted by `open` ES0 from `base` (the lower lip down, the upper up a quarter).
std::array<QPointF, 4> parted(const std::array<QPointF, 4> &base, double open)
{
    std::array<QPointF, 4> m = base;
    m[Up] += QPointF(0, -0.25 * open);
    m[Down] += QPointF(0, 0.75 * open);
    return m;
}

std::array<QPointF, 4> plus(const std::array<QPointF, 4> &a, const std::array<QPointF, 4> &b, double times = 1.0)
{
    std::array<QPointF, 4> m;
    for (int k = 0; k < 4; ++k)
        m[k] = a[k] + b[k] * times;
    return m;
}

double partingOf(const std::array<QPointF, 4> &m)
{
    return m[Down].y() - m[Up].y();
}

} // namespace

class TestMouthRange : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // The closed mouth is the clip's most closed frames, not its neutral frame; the gain brings
    // the clip's wide openings (95th percentile) to the table's widest.
    void measuresTheClipsClosedMouthAndRange()
    {
        // The neutral frame caught the lips apart: shut, the lower lip sits 0.04 ES0 higher and
        // the upper 0.01 lower than on it. 20 of 100 frames shut, the others open up to 0.12.
        const std::array<QPointF, 4> shut
            = {QPointF(0.0, 0.01), QPointF(0.0, -0.04), QPointF(0.003, 0), QPointF(-0.003, 0)};
        QVector<TrackedFrame> frames;
        for (int i = 0; i < 100; ++i) {
            const double open = i % 5 == 0 ? 0.0 : 0.12 * (i % 20) / 19.0;
            frames.append(frameWith(i, parted(shut, open)));
        }
        frames.append(frameWith(100, parted(shut, 3.0), true)); // lost: not measured
        const double widest = 0.4;
        const MouthRange range = measureMouthRange(frames, widest);
        QCOMPARE(range.framesMeasured, 100);
        for (int k = 0; k < 4; ++k) {
            QVERIFY2(QLineF(range.closedEs0[k], shut[k]).length() < 1e-9,
                qPrintable(QStringLiteral("control %1: (%2, %3)")
                               .arg(k)
                               .arg(range.closedEs0[k].x())
                               .arg(range.closedEs0[k].y())));
        }
        // The 95th percentile of the openings (0.12 * 18/19 is the 95th of these).
        QVector<double> openings;
        for (int i = 0; i < 100; ++i)
            openings.append(partingOf(parted(shut, i % 5 == 0 ? 0.0 : 0.12 * (i % 20) / 19.0)) - partingOf(shut));
        std::sort(openings.begin(), openings.end());
        QVERIFY(std::abs(range.wideOpeningEs0 - openings[94]) < 1e-9);
        QVERIFY(std::abs(range.gain - widest / openings[94]) < 1e-9);
    }

    // A still face is not blown up: its jitter stays jitter.
    void aStillMouthIsNotEnlargedBeyondTheCap()
    {
        QVector<TrackedFrame> frames;
        for (int i = 0; i < 50; ++i)
            frames.append(frameWith(i, parted({}, 0.004 * ((i * 7) % 5) / 4.0)));
        const MouthRange range = measureMouthRange(frames, 0.4);
        QCOMPARE(range.gain, kMaxMouthGain);
        // No frames: the identity.
        const MouthRange none = measureMouthRange({frameWith(0, parted({}, 0.2), true)}, 0.4);
        QCOMPARE(none.framesMeasured, 0);
        QCOMPARE(none.gain, 1.0);
        QCOMPARE(none.closedEs0[Down], QPointF());
    }

    // On a real neutral face: a speaker who makes the table's shapes at a third of their size,
    // from lips shut lower than the neutral frame's, is snapped to those very shapes over the
    // clip; frame by frame (relative to the neutral frame, unscaled) the same frames fall to
    // the few shapes nearest to shut, and the closures to `f`.
    void snapsAScaledSpeakerToTheTablesShapes()
    {
        if (!QFileInfo::exists(kPortrait))
            QSKIP("astronaut.png is not installed (package python3-skimage)");
        Tracker tracker;
        QString error;
        QVERIFY2(tracker.setNeutral(QImage(kPortrait), &error), qPrintable(error));
        const std::array<QPointF, 4> shut = {QPointF(0, 0.01), QPointF(0, -0.05), QPointF(), QPointF()};
        // A sentence between pauses, two frames a shape (`f` parts the outer lips less than `m`
        // does: a few frames of it must not become the closed mouth).
        QVector<MouthShape> spoken(10, MouthShape::M);
        for (MouthShape s : {MouthShape::A, MouthShape::M, MouthShape::E, MouthShape::O, MouthShape::M, MouthShape::I,
                 MouthShape::A, MouthShape::M, MouthShape::H, MouthShape::F})
            spoken << s << s;
        spoken += QVector<MouthShape>(10, MouthShape::M);
        QVector<TrackedFrame> frames;
        for (MouthShape s : std::as_const(spoken))
            frames.append(frameWith(int(frames.size()), plus(shut, tracker.mouthShapeEs0(s), 1.0 / 3.0)));
        frames.append(frameWith(int(frames.size()), {}, true)); // lost after the last `m`
        const MouthRange range = measureMouthRange(frames, widestMouthOpeningEs0(tracker));
        QVERIFY2(std::abs(range.gain - 3.0) < 0.3, qPrintable(QString::number(range.gain)));

        QVector<TrackedFrame> clip = frames;
        snapClipMouth(&clip, tracker, range);
        for (qsizetype i = 0; i + 1 < clip.size(); ++i) {
            QVERIFY(clip[i].mouthShape);
            QCOMPARE(mouthShapeName(*clip[i].mouthShape), mouthShapeName(spoken[i]));
            // The controls hold the shape's own displacements.
            QCOMPARE(clip[i].motion.displacementEs0[pt::idx("8.2")], tracker.mouthShapeEs0(spoken[i])[Down]);
        }
        QCOMPARE(clip.last().mouthShape, std::optional<MouthShape>(MouthShape::M)); // held over the lost frame

        QVector<TrackedFrame> byFrame = frames;
        snapClipMouth(&byFrame, tracker, MouthRange {});
        std::set<MouthShape> wholeClip, frameByFrame;
        for (qsizetype i = 0; i + 1 < frames.size(); ++i) {
            wholeClip.insert(*clip[i].mouthShape);
            frameByFrame.insert(*byFrame[i].mouthShape);
        }
        QCOMPARE(wholeClip.size(), size_t(7));
        QVERIFY2(frameByFrame.size() < wholeClip.size(), qPrintable(QString::number(frameByFrame.size())));
        QCOMPARE(mouthShapeName(*byFrame[0].mouthShape), QStringLiteral("f")); // a closure read as `f`
    }

    // The frames in silence snap to `m` however far apart the lips stand there; the others as
    // before.
    void silenceSnapsToTheClosedMouth()
    {
        if (!QFileInfo::exists(kPortrait))
            QSKIP("astronaut.png is not installed (package python3-skimage)");
        Tracker tracker;
        QString error;
        QVERIFY2(tracker.setNeutral(QImage(kPortrait), &error), qPrintable(error));
        // Lips held at `a` in a pause (frames 0-4), then speech.
        QVector<TrackedFrame> frames;
        for (MouthShape s : {MouthShape::A, MouthShape::A, MouthShape::A, MouthShape::A, MouthShape::A, MouthShape::O,
                 MouthShape::M, MouthShape::A})
            frames.append(frameWith(int(frames.size()), tracker.mouthShapeEs0(s)));
        frames.append(frameWith(int(frames.size()), {}, true)); // lost after the `a`
        QVector<bool> silent(frames.size(), false);
        std::fill(silent.begin(), silent.begin() + 5, true);
        QVector<TrackedFrame> snapped = frames;
        snapClipMouth(&snapped, tracker, MouthRange {}, silent);
        QString shapes;
        for (const TrackedFrame &f : std::as_const(snapped))
            shapes += mouthShapeName(*f.mouthShape);
        QCOMPARE(shapes, QStringLiteral("mmmmmomaa"));
        QCOMPARE(snapped[0].motion.displacementEs0[pt::idx("8.2")], tracker.mouthShapeEs0(MouthShape::M)[Down]);
        // Without the silence the pause is the `a` it looks like.
        snapClipMouth(&frames, tracker, MouthRange {});
        QCOMPARE(mouthShapeName(*frames[0].mouthShape), QStringLiteral("a"));
    }

    // The GRID clips (a speaker each, English): the snapped mouth uses more of the nine shapes
    // than frame by frame, and its opening follows the clip's own sound.
    void gridClipsUseTheShapesAndFollowTheSound_data()
    {
        QTest::addColumn<QString>("clip");
        for (const char *name : {"bbaf2n.mpg", "lbax4n.mpg", "pwij3p.mpg", "id2_vcd_swwp2s.mpg"})
            QTest::newRow(name) << QString::fromLatin1(name);
    }

    void gridClipsUseTheShapesAndFollowTheSound()
    {
        QFETCH(QString, clip);
        const QString path = kVideoDir + QLatin1Char('/') + clip;
        if (!QFileInfo::exists(path))
            QSKIP("the GRID clips of shared/data/video are absent");
        TrackVideoOptions options;
        options.tracker.snapMouth = true;
        const TrackResult track = trackVideo(path, options);
        QVERIFY2(track.status == TrackStatus::Ok, qPrintable(track.error));
        QVERIFY(track.mouthRange);
        QVERIFY(trackToJson(track).contains(QStringLiteral("mouthRange")));
        // The sentence comes after a silence (a GRID speaker waits about half a second, the
        // lips apart): the mouth is at rest there, and the speech is not silence.
        QCOMPARE(track.silentFrames.size(), track.frames.size());
        qsizetype leading = 0;
        while (leading < track.silentFrames.size() && track.silentFrames[leading])
            ++leading;
        QVERIFY2(leading >= 5 && leading < track.frames.size() / 2, qPrintable(QString::number(leading)));
        for (qsizetype i = 0; i < leading; ++i)
            QCOMPARE(track.frames[i].mouthShape, std::optional<MouthShape>(MouthShape::M));
        QVERIFY(std::count(track.silentFrames.cbegin(), track.silentFrames.cend(), false) >= track.frames.size() / 3);
        QCOMPARE(trackToJson(track)
                     .value(QStringLiteral("mouthRange"))
                     .toObject()
                     .value(QStringLiteral("silentFrames"))
                     .toInt(),
            int(std::count(track.silentFrames.cbegin(), track.silentFrames.cend(), true)));
        std::set<MouthShape> used;
        QString shapes;
        for (const TrackedFrame &f : track.frames) {
            QVERIFY(f.mouthShape);
            used.insert(*f.mouthShape);
            shapes += mouthShapeName(*f.mouthShape);
        }

        // The same clip snapped frame by frame from its neutral frame 0.
        options.tracker.snapMouth = false;
        const TrackResult raw = trackVideo(path, options);
        Tracker tracker;
        QString error;
        QVERIFY2(tracker.setNeutral(raw.neutralImage, &error), qPrintable(error));
        QVector<TrackedFrame> byFrame = raw.frames;
        snapClipMouth(&byFrame, tracker, MouthRange {});
        std::set<MouthShape> usedByFrame;
        for (const TrackedFrame &f : std::as_const(byFrame))
            usedByFrame.insert(*f.mouthShape);

        const auto sound = readAudio(path, 16000, &error);
        QVERIFY2(sound, qPrintable(error));
        const SoundAgreement clipAgreement = mouthSoundAgreement(track.frames, *sound, 16000, 1.0 / track.fps);
        const SoundAgreement frameAgreement = mouthSoundAgreement(byFrame, *sound, 16000, 1.0 / track.fps);
        const SoundAgreement tracked = mouthSoundAgreement(raw.frames, *sound, 16000, 1.0 / track.fps);
        qInfo("%s: %s: %d shapes (frame by frame %d), gain %.2f; sound r = %.3f (frame by frame %.3f, tracked %.3f)",
            qPrintable(clip), qPrintable(shapes), int(used.size()), int(usedByFrame.size()), track.mouthRange->gain,
            clipAgreement.correlation, frameAgreement.correlation, tracked.correlation);
        // Over the four clips: 3-5 shapes (frame by frame 2-4), `m` and `a` among them (the
        // silences at rest took away the shapes that were only lips apart in a pause: lbax4n
        // speaks with m, h and a).
        QVERIFY2(used.size() >= 3, qPrintable(QString::number(used.size())));
        QVERIFY(used.size() >= usedByFrame.size());
        QVERIFY(used.count(MouthShape::M) && used.count(MouthShape::A));
        // The shapes follow the sound better than frame by frame (r 0.38-0.78 against
        // 0.04-0.20), and keep what the tracked opening says of it: at least 0.8 of its
        // correlation (1.6-2.4 times it on the four: the silences at rest are where the sound
        // is quiet, which the tracked lips apart in a pause are not).
        QVERIFY2(clipAgreement.correlation > frameAgreement.correlation,
            qPrintable(QString::number(clipAgreement.correlation)));
        QVERIFY2(clipAgreement.correlation >= 0.8 * tracked.correlation,
            qPrintable(QString::number(clipAgreement.correlation)));
    }
};

TOONFACE_TEST_MAIN(TestMouthRange)
#include "tst_mouthrange.moc"
