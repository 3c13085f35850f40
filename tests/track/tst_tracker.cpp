#include "face/averageface.h"
#include "talkingface.h"
#include "testmain.h"
#include "track/facemeasure.h"
#include "track/oneeuro.h"
#include "track/retarget.h"
#include "track/tracker.h"

#include <QFileInfo>
#include <QLineF>
#include <QPainter>
#include <QRandomGenerator>
#include <QTest>

#include <cmath>
#include <functional>

using namespace toonface;

Q_DECLARE_METATYPE(toonface::DetectionMethod)

namespace {

// A portrait without glasses, so that painted lids read as shut eyes.
const QString kPortrait = QStringLiteral("/usr/lib/python3/dist-packages/skimage/data/astronaut.png");
constexpr double kFps = 25.0;

// The schedule of the drawn face: mouth opening and eye opening per frame.
struct Schedule
{
    QVector<double> mouth;
    QVector<double> eyes;
};

Schedule schedule()
{
    Schedule s;
    for (int i = 0; i < 60; ++i) {
        double m = 0, e = 1;
        if (i >= 12 && i <= 17)
            m = 1.0;
        if (i >= 35 && i <= 39)
            m = 0.6;
        if (i == 25 || i == 26 || i == 48 || i == 49)
            e = 0;
        if (i == 24 || i == 27 || i == 47 || i == 50)
            e = 0.5;
        s.mouth.append(m);
        s.eyes.append(e);
    }
    return s;
}

// Adds sensor-like noise (uniform, +-amplitude grey levels), the same for the same seed.
QImage noisy(const QImage &image, int amplitude, quint32 seed)
{
    QImage out = image;
    QRandomGenerator rng(seed);
    for (int y = 0; y < out.height(); ++y) {
        QRgb *row = reinterpret_cast<QRgb *>(out.scanLine(y));
        for (int x = 0; x < out.width(); ++x) {
            const int n = int(rng.bounded(2 * amplitude + 1)) - amplitude;
            row[x] = qRgb(std::clamp(qRed(row[x]) + n, 0, 255), std::clamp(qGreen(row[x]) + n, 0, 255),
                std::clamp(qBlue(row[x]) + n, 0, 255));
        }
    }
    return out;
}

// The first frame from which `values` stay at or above `level` for two frames, or -1.
int firstRise(const QVector<double> &values, double level, int from = 0)
{
    for (int i = from; i + 1 < values.size(); ++i) {
        if (values[i] >= level && values[i + 1] >= level)
            return i;
    }
    return -1;
}

} // namespace

class TestTracker : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void oneEuroStillAndFast()
    {
        // A still signal with jitter is held nearly still; a step passes within two samples.
        // Jitter of a still face: the filtered signal varies less than half as much as the raw one.
        OneEuroFilter f({1.0, 10.0, 1.0});
        QRandomGenerator rng(7);
        double raw = 0, filtered = 0;
        for (int i = 0; i < 200; ++i) {
            const double x = 0.005 * (rng.generateDouble() - 0.5) * 2;
            const double y = f.filter(x, 1.0 / kFps);
            if (i > 10) {
                raw += x * x;
                filtered += y * y;
            }
        }
        QVERIFY2(std::sqrt(filtered / raw) < 0.5, qPrintable(QString::number(std::sqrt(filtered / raw))));
        // A mouth opening by 0.3 ES0 at once.
        double y = 0;
        for (int i = 0; i < 3; ++i)
            y = f.filter(0.3, 1.0 / kFps);
        QVERIFY2(y > 0.25, qPrintable(QString::number(y)));
        // Unfiltered start: the first sample passes unchanged.
        OneEuroFilter g;
        QCOMPARE(g.filter(1.5, 0.04), 1.5);
    }

    void blinksFromOpenings()
    {
        QVector<double> t, open;
        for (int i = 0; i < 100; ++i) {
            t.append(i / kFps);
            open.append(i == 30 || i == 31 || i == 70 ? 0.2 : i == 50 ? 0.7 : 1.0);
        }
        const QVector<BlinkEvent> blinks = detectBlinks(t, open, kFps);
        QCOMPARE(blinks.size(), 2);
        QVERIFY(std::abs(blinkMiddle(blinks[0]) - 30.5 / kFps) < 1e-9);
        QVERIFY(std::abs(blinkMiddle(blinks[1]) - 70 / kFps) < 1e-9);
        for (const BlinkEvent &b : blinks) {
            QVERIFY(b.duration >= Timeline::kBlinkDurationMin);
            QVERIFY(b.duration <= Timeline::kBlinkDurationMax);
        }
        // A run bridged across one open frame is one blink.
        open[32] = 0.2;
        open[31] = 0.9;
        QCOMPARE(detectBlinks(t, open, kFps).size(), 2);
        QVERIFY(detectBlinks({}, {}, kFps).isEmpty());
    }

    void drawnFaceEventsWithinAFrame_data()
    {
        QTest::addColumn<DetectionMethod>("method");
        QTest::newRow("landmarks") << DetectionMethod::Landmarks;
        // Thesis ch. 6: the eyes' aperture and the mouth's opening measured on the regions the
        // neutral frame reserved.
        QTest::newRow("classic") << DetectionMethod::Classic;
    }

    void drawnFaceEventsWithinAFrame()
    {
        QFETCH(DetectionMethod, method);
        if (!QFileInfo::exists(kPortrait))
            QSKIP("astronaut.png is not installed (package python3-skimage)");
        const testing::TalkingFace talking {QImage(kPortrait)};
        QVERIFY(talking.isValid());
        const Schedule s = schedule();
        // The classic method assumes a large frontal face in the middle of the picture (thesis
        // 3.3): the frames are cut to the face, as a webcam or a GRID clip frames it.
        QRect cut = talking.frame(0, 1).rect();
        if (method == DetectionMethod::Classic) {
            const QRectF face = talking.face().bounds();
            cut = QRectF(face.center() - QPointF(0.8, 0.75) * face.width(), QSizeF(1.6, 1.5) * face.width())
                      .toAlignedRect()
                      .intersected(cut);
        }
        QVector<QImage> frames;
        for (int i = 0; i < s.mouth.size(); ++i)
            frames.append(noisy(talking.frame(s.mouth[i], s.eyes[i]).copy(cut), 3, quint32(i)));

        for (bool smooth : {false, true}) {
            TrackerOptions options;
            options.method = method;
            options.smooth = smooth;
            Tracker tracker(options);
            QString error;
            QVERIFY2(tracker.setNeutral(frames[0], &error), qPrintable(error));
            QCOMPARE(tracker.methodName(), detectionMethodName(method));
            QVector<double> mouth, eyes, times;
            QVector<TrackedFrame> tracked;
            for (int i = 0; i < frames.size(); ++i) {
                const TrackedFrame f = tracker.track(frames[i], i / kFps, i);
                QVERIFY2(!f.lost, qPrintable(QStringLiteral("frame %1 lost").arg(i)));
                QVERIFY2(f.confidence > 0.5, qPrintable(QString::number(f.confidence)));
                mouth.append(f.motion.mouthOpenEs0);
                eyes.append((f.motion.leftEyeOpen + f.motion.rightEyeOpen) / 2);
                times.append(f.time);
                tracked.append(f);
            }
            // The mouth opens at frame 12 and at frame 35: the tracked opening crosses half of
            // its peak within a frame of each.
            // (The portrait's lips are apart: the opening rises from that.)
            const double base = mouth[0];
            const double peak = *std::max_element(mouth.cbegin(), mouth.cend());
            QVERIFY2(peak - base > 0.15, qPrintable(QString::number(peak - base)));
            const int first = firstRise(mouth, base + (peak - base) / 2);
            QVERIFY2(std::abs(first - 12) <= 1, qPrintable(QStringLiteral("mouth opens at %1").arg(first)));
            const int second = firstRise(mouth, base + 0.6 * (peak - base) / 2, 20);
            QVERIFY2(std::abs(second - 35) <= 1, qPrintable(QStringLiteral("mouth opens again at %1").arg(second)));
            // Back to its rest between.
            QVERIFY(mouth[28] < base + (peak - base) / 4);
            // Blinks at frames 25.5 and 48.5.
            const QVector<BlinkEvent> blinks = detectBlinks(times, eyes, kFps);
            QCOMPARE(blinks.size(), 2);
            QVERIFY2(std::abs(blinkMiddle(blinks[0]) * kFps - 25.5) <= 1.0,
                qPrintable(QString::number(blinkMiddle(blinks[0]) * kFps)));
            QVERIFY2(std::abs(blinkMiddle(blinks[1]) * kFps - 48.5) <= 1.0,
                qPrintable(QString::number(blinkMiddle(blinks[1]) * kFps)));

            // Still face (frames 0-10, noise only): still points when filtered.
            double jitter = 0;
            for (int i = 1; i <= 10; ++i) {
                for (const char *id : kMouthControlIds)
                    jitter
                        = std::max(jitter, QLineF(tracked[i].motion.displacementEs0[pt::idx(id)], QPointF()).length());
            }
            qInfo("smooth %d: mouth opening %.3f ES0, still-face jitter %.4f ES0", int(smooth), peak - base, jitter);
            if (smooth)
                QVERIFY2(jitter < 0.01, qPrintable(QString::number(jitter)));
        }
    }

    void lostFaceHoldsAndIsFoundAgain_data()
    {
        QTest::addColumn<DetectionMethod>("method");
        QTest::addColumn<double>("shift"); // where the face comes back, in face widths to the right
        QTest::newRow("landmarks") << DetectionMethod::Landmarks << 0.0;
        QTest::newRow("landmarks, back elsewhere") << DetectionMethod::Landmarks << 0.6;
        QTest::newRow("classic") << DetectionMethod::Classic << 0.0;
        QTest::newRow("classic, back elsewhere") << DetectionMethod::Classic << 0.6;
    }

    void lostFaceHoldsAndIsFoundAgain()
    {
        QFETCH(DetectionMethod, method);
        QFETCH(double, shift);
        if (!QFileInfo::exists(kPortrait))
            QSKIP("astronaut.png is not installed (package python3-skimage)");
        const testing::TalkingFace talking {QImage(kPortrait)};
        QVERIFY(talking.isValid());
        // The classic method's frames cut to the face, as in drawnFaceEventsWithinAFrame.
        QRect cut = talking.frame(0, 1).rect();
        const QRectF face = talking.face().bounds();
        if (method == DetectionMethod::Classic) {
            cut = QRectF(face.center() - QPointF(0.8, 0.75) * face.width(), QSizeF(1.6, 1.5) * face.width())
                      .toAlignedRect()
                      .intersected(cut);
        }
        // The frames are wider than the cut, so that the face can come back further right.
        const int dx = int(shift * face.width());
        const QSize size = cut.size() + QSize(int(0.6 * face.width()), 0);
        const QColor backdrop(90, 110, 140);
        auto placed = [&](double open, int x) {
            QImage image(size, QImage::Format_RGB32);
            image.fill(backdrop);
            QPainter(&image).drawImage(x, 0, talking.frame(open, 1).copy(cut));
            return image;
        };
        QImage empty(size, QImage::Format_RGB32);
        empty.fill(backdrop);
        // A wall with a texture of its own (not the face) is no face either.
        QImage wall = empty.copy();
        for (int y = 0; y < wall.height(); ++y)
            for (int x = 0; x < wall.width(); ++x)
                wall.setPixelColor(x, y, ((x / 9 + y / 13) % 3) ? QColor(80, 70, 60) : QColor(200, 190, 170));
        TrackerOptions options;
        options.method = method;
        Tracker tracker(options);
        QString error;
        QVERIFY2(tracker.setNeutral(placed(0, 0), &error), qPrintable(error));
        const int eye = pt::idx("3.5");
        const double d
            = QLineF(tracker.neutralDetection().face.point("3.5"), tracker.neutralDetection().face.point("3.6"))
                  .length();
        TrackedFrame before;
        for (int i = 0; i < 30; ++i) {
            const bool away = i >= 10 && i < 20;
            const QImage image = away ? (i < 15 ? empty : wall) : placed(i >= 8 && i < 25 ? 0.8 : 0.0, i < 10 ? 0 : dx);
            const TrackedFrame f = tracker.track(image, i / kFps, i);
            QVERIFY2(f.lost == away, qPrintable(QStringLiteral("frame %1").arg(i)));
            if (i == 9)
                before = f;
            if (away) {
                QCOMPARE(f.confidence, 0.0);
                QCOMPARE(f.points, before.points); // holds the last pose
                QCOMPARE(f.motion.mouthOpenEs0, before.motion.mouthOpenEs0);
            } else {
                QVERIFY(f.confidence > 0.5);
            }
            if (i >= 20) { // found again where it is now, the mouth still open
                const QPointF moved = f.points[eye] - before.points[eye];
                QVERIFY2(std::abs(moved.x() - dx) < 0.1 * d && std::abs(moved.y()) < 0.1 * d,
                    qPrintable(QStringLiteral("frame %1: the eye moved by (%2, %3), the face by %4")
                                   .arg(i)
                                   .arg(moved.x())
                                   .arg(moved.y())
                                   .arg(dx)));
            }
            if (i == 22)
                QVERIFY(f.motion.mouthOpenEs0 > 0.1);
        }
    }

    void snappedMouthsBecomeMouthKeys()
    {
        if (!QFileInfo::exists(kPortrait))
            QSKIP("astronaut.png is not installed (package python3-skimage)");
        const testing::TalkingFace talking {QImage(kPortrait)};
        QVERIFY(talking.isValid());
        TrackerOptions options;
        options.snapMouth = true;
        Tracker tracker(options);
        QString error;
        QVERIFY2(tracker.setNeutral(talking.frame(0, 1), &error), qPrintable(error));
        // The nine shapes' own displacements snap to themselves.
        const FaceModel &face = tracker.neutralDetection().face;
        const MouthShapeSet shapes;
        const auto shut = shapes.displacements(MouthShape::M, face);
        for (MouthShape s : {MouthShape::M, MouthShape::A, MouthShape::I, MouthShape::O, MouthShape::E}) {
            const auto d = shapes.displacements(s, face, &shut);
            std::array<QPointF, 4> es0;
            for (int k = 0; k < 4; ++k)
                es0[k] = (d[k] - shut[k]) / face.fapu().es0;
            QCOMPARE(tracker.nearestMouthShape(es0), s);
        }
        QVector<TrackedFrame> frames;
        for (int i = 0; i < 20; ++i)
            frames.append(tracker.track(talking.frame(i >= 8 && i < 14 ? 1.0 : 0.0, 1), i / kFps, i));
        QCOMPARE(frames[2].mouthShape, std::optional<MouthShape>(MouthShape::M));
        QVERIFY(frames[11].mouthShape && *frames[11].mouthShape != MouthShape::M);
        Timeline timeline;
        addTrackToTimeline(frames, kFps, &timeline);
        QVERIFY(timeline.mouthKeys().size() >= 3); // m, open, m
        QCOMPARE(timeline.mouthKeys().first().shape, MouthShape::M);
        QVERIFY(!timeline.poseKeys().first().offsetsEs0.contains(QStringLiteral("8.2")));
        QVERIFY(timeline.poseKeys().first().offsetsEs0.contains(QStringLiteral("4.4")));
    }

    void continuousMouthsBecomePoseKeys()
    {
        if (!QFileInfo::exists(kPortrait))
            QSKIP("astronaut.png is not installed (package python3-skimage)");
        const testing::TalkingFace talking {QImage(kPortrait)};
        QVERIFY(talking.isValid());
        Tracker tracker;
        QString error;
        QVERIFY2(tracker.setNeutral(talking.frame(0, 1), &error), qPrintable(error));
        QVector<TrackedFrame> frames;
        for (int i = 0; i < 16; ++i)
            frames.append(tracker.track(talking.frame(i >= 6 && i < 12 ? 1.0 : 0.0, 1), i / kFps, i));
        frames[3].lost = true; // a lost frame gives no keys
        Timeline timeline;
        addTrackToTimeline(frames, kFps, &timeline, {}, 0.5);
        QCOMPARE(timeline.poseKeys().size(), 15);
        QCOMPARE(timeline.headKeys().size(), 15);
        QCOMPARE(timeline.gazeKeys().size(), 15);
        QVERIFY(timeline.mouthKeys().isEmpty());
        QCOMPARE(timeline.poseKeys().first().time, 0.5);
        const PoseKey &open = timeline.poseKeys()[9]; // frame 10
        QCOMPARE(open.time, 0.5 + 10 / kFps);
        QCOMPARE(open.offsetsEs0.value(QStringLiteral("8.2")), frames[10].motion.displacementEs0[pt::idx("8.2")]);
        QVERIFY(open.offsetsEs0.value(QStringLiteral("8.2")).y() > 0.1); // the lower lip went down
    }

    // A tracked brow moves as a brow does: its rise, tilt and squeeze come through exactly; the
    // points' wobble against each other (which would bend the drawn brow) does not.
    void browsMoveAsAWhole()
    {
        FaceMeasurement neutral;
        neutral.found = true;
        const FaceModel face = averageFace(QRectF(100, 100, 200, 260), QSize(400, 480));
        for (int i = 0; i < kPointCount; ++i)
            neutral.points[i] = face.point(i);
        for (const char *id : {"3.12", "3.8", "3.11", "3.7", "9.15", "9.4", "9.5"})
            neutral.stable.append(pt::idx(id));
        const double es0 = QLineF(neutral.points[pt::idx("3.6")], neutral.points[pt::idx("3.5")]).length();
        // Each brow from its inner end to its outer end.
        const std::array<std::array<const char *, 4>, 2> brows {
            {{"4.2", "4.4", "4.4a", "4.6"}, {"4.1", "4.3", "4.3a", "4.5"}}};
        using Motion = std::function<QPointF(int brow, int k)>;
        auto measured = [&](const Motion &by) {
            FaceMeasurement now = neutral;
            for (int b = 0; b < 2; ++b) {
                for (int k = 0; k < 4; ++k)
                    now.points[pt::idx(brows[b][k])] += by(b, k) * es0;
            }
            return measureMotion(neutral, now);
        };

        // The left brow raised and drawn in at its inner end, the right one tilted like a sad
        // brow (inner end up): every point as tracked.
        const Motion expressive = [](int b, int k) {
            return b == 0 ? QPointF(0.02 * (1 - k / 3.0), -0.12) : QPointF(-0.03, -0.1 * (1 - k / 3.0));
        };
        const FaceMotion exact = measured(expressive);
        for (int b = 0; b < 2; ++b) {
            for (int k = 0; k < 4; ++k) {
                const QPointF got = exact.displacementEs0[pt::idx(brows[b][k])];
                QVERIFY2(QLineF(got, expressive(b, k)).length() < 0.01,
                    qPrintable(
                        QStringLiteral("%1: %2, %3").arg(QLatin1StringView(brows[b][k])).arg(got.x()).arg(got.y())));
            }
        }

        // Wobble: the middle points up, the ends down (the brow bent, no rise). Each brow stays
        // straight (its displacements grow evenly along it), its mean stays put, and little of
        // the bend is left.
        const FaceMotion wobble = measured([](int, int k) { return QPointF(0, k == 1 || k == 2 ? -0.05 : 0.05); });
        for (const auto &brow : brows) {
            std::array<QPointF, 4> d;
            QPointF mean;
            for (int k = 0; k < 4; ++k) {
                d[k] = wobble.displacementEs0[pt::idx(brow[k])];
                mean += d[k] / 4.0;
                QVERIFY2(std::abs(d[k].y()) < 0.03, brow[k]);
            }
            QVERIFY(std::abs(mean.y()) < 0.01);
            // On one line: the middle points between the ends in proportion to where they are.
            const QPointF inner = face.point(pt::idx(brow[0])), outer = face.point(pt::idx(brow[3]));
            for (int k = 1; k < 3; ++k) {
                const QPointF p = face.point(pt::idx(brow[k]));
                const double u
                    = QPointF::dotProduct(p - inner, outer - inner) / QPointF::dotProduct(outer - inner, outer - inner);
                QVERIFY(QLineF(d[k], d[0] + (d[3] - d[0]) * u).length() < 1e-9);
            }
        }
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestTracker)
#include "tst_tracker.moc"
