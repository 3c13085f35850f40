#include "anim/easing.h"
#include "anim/timeline.h"
#include "anim/timelineevaluator.h"
#include "face/averageface.h"
#include "face/emotion.h"
#include "face/fapu.h"
#include "face/mouthshape.h"
#include "face/pose.h"
#include "testmain.h"

#include <QLineF>
#include <QTest>

#include <algorithm>
#include <cmath>

using namespace toonface;

namespace {

using Mouth = std::array<QPointF, 4>;

constexpr double kTol = 1e-9; // pixels, for values that are exact by construction

FaceModel testFace()
{
    return averageFace(QRectF(100, 150, 200, 240), QSize(400, 500));
}

double distance(const Mouth &a, const Mouth &b)
{
    double d = 0;
    for (int k = 0; k < 4; ++k)
        d = std::max(d, QLineF(a[k], b[k]).length());
    return d;
}

Mouth mix(const Mouth &a, const Mouth &b, double s)
{
    Mouth m;
    for (int k = 0; k < 4; ++k)
        m[k] = a[k] * (1 - s) + b[k] * s;
    return m;
}

// Largest difference between two poses over every quantity.
double distance(const Pose &a, const Pose &b)
{
    double d = 0;
    for (int i = 0; i < kPointCount; ++i)
        d = std::max(d, QLineF(a.offset[i], b.offset[i]).length());
    d = std::max({d, std::abs(a.leftEyeOpen - b.leftEyeOpen), std::abs(a.rightEyeOpen - b.rightEyeOpen),
        std::abs(a.head.rotationDeg - b.head.rotationDeg), QLineF(a.head.translation, b.head.translation).length(),
        std::abs(a.head.scale - b.head.scale)});
    return d;
}

QPointF offsetOf(const Pose &p, const char *id)
{
    return p.offset[pt::idx(id)];
}

MouthKey key(double time, MouthShape shape, std::optional<double> duration = std::nullopt, double weight = 1.0)
{
    return {time, shape, weight, duration};
}

} // namespace

class TestTimelineEvaluator : public QObject
{
    Q_OBJECT

    const FaceModel m_face = testFace();
    const MouthShapeSet m_shapes;

    Mouth shape(MouthShape s, const Mouth *previous = nullptr) const
    {
        return m_shapes.displacements(s, m_face, previous);
    }

private Q_SLOTS:
    void easeIsSmoothstep()
    {
        QCOMPARE(ease(0.0), 0.0);
        QCOMPARE(ease(0.5), 0.5);
        QCOMPARE(ease(1.0), 1.0);
        QCOMPARE(ease(-1.0), 0.0);
        QCOMPARE(ease(2.0), 1.0);
        QCOMPARE(easeSlope(0.0), 0.0);
        QCOMPARE(easeSlope(1.0), 0.0);
        QCOMPARE(easeSlope(0.5), 1.5);
        // The SMIL spline "1/3 0 2/3 1": a cubic Bezier with y controls 0, 0, 1, 1 at x = u.
        for (double u = 0; u <= 1.0; u += 0.05) {
            const double bezier = 3 * (1 - u) * u * u + u * u * u;
            QVERIFY(std::abs(ease(u) - bezier) < 1e-12);
        }
    }

    void emptyTimelineIsNeutral()
    {
        const TimelineEvaluator e(Timeline(), m_face, m_shapes);
        QCOMPARE(e.evaluate(0.0), Pose());
        QCOMPARE(e.evaluate(3.0), Pose());
        QCOMPARE(e.duration(), 0.0);
        QCOMPARE(e.keyTimes(), QVector<double> {0.0});

        // A face photographed with its lips apart rests with them shut, speech or not.
        FaceModel open = m_face;
        for (const char *id : {"8.2", "2.3", "2.1"})
            open.setPoint(pt::idx(id), open.point(id) + QPointF(0, 0.5 * m_face.fapu().mns0));
        const TimelineEvaluator silent(Timeline(), open, m_shapes);
        QCOMPARE(silent.evaluate(1.0), mouthPose(open, m_shapes, MouthShape::M));
        const auto shut = posedPoints(open, silent.evaluate(1.0));
        QVERIFY(std::abs(shut[pt::idx("2.3")].y() - shut[pt::idx("2.2")].y()) < 1e-9);
    }

    void atKeyFramesTheShapeIsExact()
    {
        Timeline t;
        t.addMouthKey(key(1.0, MouthShape::A));
        t.addMouthKey(key(1.2, MouthShape::U));
        t.addMouthKey(key(1.4, MouthShape::E));
        t.addMouthKey(key(1.6, MouthShape::N, 0.2));
        t.addMouthKey(key(1.8, MouthShape::O, 0.2));
        const TimelineEvaluator e(t, m_face, m_shapes);
        const Mouth eShape = shape(MouthShape::E);
        const Mouth expected[]
            = {shape(MouthShape::A), shape(MouthShape::U), eShape, shape(MouthShape::N, &eShape), shape(MouthShape::O)};
        for (int i = 0; i < 5; ++i) {
            const double time = 1.0 + 0.2 * i;
            QVERIFY2(distance(e.mouthAt(time), expected[i]) < kTol, qPrintable(QString::number(time)));
            const Pose p = e.evaluate(time);
            for (int k = 0; k < 4; ++k)
                QVERIFY(QLineF(offsetOf(p, kMouthControlIds[k]), expected[i][k]).length() < kTol);
        }
        // `n` keeps the corners of the shape before it (`e` spreads them).
        QCOMPARE(e.mouthAt(1.6)[Left], eShape[Left]);
        QVERIFY(!eShape[Left].isNull());
    }

    void betweenKeyFramesTheMouthEases()
    {
        Timeline t;
        t.addMouthCues({{1.0, 1.5, MouthShape::A}, {1.5, 2.0, MouthShape::O}});
        const double c = t.smoothing().coarticulation;
        const TimelineEvaluator e(t, m_face, m_shapes);
        const Mouth a = shape(MouthShape::A), o = shape(MouthShape::O);
        // Held until the mouth anticipates the next shape...
        QVERIFY(distance(e.mouthAt(1.2), a) < kTol);
        QVERIFY(distance(e.mouthAt(1.5 - c), a) < kTol);
        // ...then eased: half way at the window's middle, 7/27 at its first third.
        QVERIFY(distance(e.mouthAt(1.5 - c / 2), mix(a, o, 0.5)) < kTol);
        QVERIFY(distance(e.mouthAt(1.5 - 2 * c / 3), mix(a, o, 7.0 / 27.0)) < kTol);
        QVERIFY(distance(e.mouthAt(1.5), o) < kTol);

        // Monotonic: every coordinate moves one way from a to o.
        Mouth previous = e.mouthAt(1.5 - c);
        for (double time = 1.5 - c; time <= 1.5; time += c / 50) {
            const Mouth now = e.mouthAt(time);
            for (int k = 0; k < 4; ++k) {
                const QPointF step = now[k] - previous[k];
                const QPointF way = o[k] - a[k];
                QVERIFY(step.x() * way.x() >= -1e-12 && step.y() * way.y() >= -1e-12);
            }
            previous = now;
        }

        // Zero slope at the key frames: the mouth arrives and leaves softly. The slope next to a
        // key is a tiny fraction of the slope in the middle of the move.
        const double h = 1e-4;
        const double full = distance(a, o);
        const double peak = distance(e.mouthAt(1.5 - c / 2 + h), e.mouthAt(1.5 - c / 2)) / h;
        QVERIFY(std::abs(peak - 1.5 * full / c) < 0.01 * peak);
        QVERIFY(distance(e.mouthAt(1.5), e.mouthAt(1.5 - h)) / h < 0.01 * peak);
        QVERIFY(distance(e.mouthAt(1.5 - c + h), e.mouthAt(1.5 - c)) / h < 0.01 * peak);
    }

    void shortIntervalsEaseOverTheWholeInterval()
    {
        Timeline t;
        t.addMouthCues({{1.0, 1.08, MouthShape::A}, {1.08, 1.3, MouthShape::I}});
        const TimelineEvaluator e(t, m_face, m_shapes);
        const Mouth a = shape(MouthShape::A), i = shape(MouthShape::I);
        QVERIFY(distance(e.mouthAt(1.04), mix(a, i, 0.5)) < kTol);
        QVERIFY(distance(e.mouthAt(1.0), a) < kTol);
    }

    void weightScalesTheShape()
    {
        Timeline t;
        t.addMouthKey(key(1.0, MouthShape::A, 0.5, 0.5));
        const TimelineEvaluator e(t, m_face, m_shapes);
        QVERIFY(distance(e.mouthAt(1.2), mix(Mouth {}, shape(MouthShape::A), 0.5)) < kTol);
    }

    void minimumHoldBlendsShortKeys()
    {
        Timeline t;
        t.addMouthCues({{1.0, 1.2, MouthShape::A}, {1.2, 1.22, MouthShape::I}, {1.22, 1.5, MouthShape::O}});
        const Mouth i = shape(MouthShape::I), o = shape(MouthShape::O);
        // minHold 0.06: the 20 ms `i` merges with `o`, weighted 20 ms : 60 ms.
        const TimelineEvaluator held(t, m_face, m_shapes);
        const Mouth blend = mix(i, o, 0.06 / 0.08);
        QVERIFY(distance(held.mouthAt(1.2), blend) < kTol);
        QVERIFY(distance(held.mouthAt(1.3), blend) < kTol);
        double closestToI = 1e9;
        for (double time = 1.0; time < 1.6; time += 0.001)
            closestToI = std::min(closestToI, distance(held.mouthAt(time), i));
        QVERIFY2(closestToI > 0.5, qPrintable(QString::number(closestToI)));

        // With no minimum hold the 20 ms key would be shown, snapping in and out.
        MouthSmoothing snap = t.smoothing();
        snap.minHold = 0;
        t.setSmoothing(snap);
        const TimelineEvaluator snapped(t, m_face, m_shapes);
        QVERIFY(distance(snapped.mouthAt(1.2), i) < kTol);
        QVERIFY(distance(snapped.mouthAt(1.22), o) < kTol);
    }

    void minimumHoldMergesRunsOfFlickers()
    {
        // Shapes alternating every 30 ms: with minHold 60 ms no pure shape is ever shown.
        Timeline t;
        QVector<MouthCue> cues;
        for (int k = 0; k < 8; ++k)
            cues.append({1.0 + 0.03 * k, 1.03 + 0.03 * k, k % 2 ? MouthShape::I : MouthShape::A});
        t.addMouthCues(cues);
        const TimelineEvaluator e(t, m_face, m_shapes);
        const Mouth a = shape(MouthShape::A), i = shape(MouthShape::I);
        const double span = distance(a, i);
        for (double time = 1.0; time < 1.24; time += 0.002) {
            const Mouth m = e.mouthAt(time);
            QVERIFY2(distance(m, a) > 0.25 * span && distance(m, i) > 0.25 * span, qPrintable(QString::number(time)));
        }
        // The runs [a i] at 1.00, 1.06 and 1.12 all blend to the same mix: the mouth stays still
        // instead of flickering (until it moves on to the last run, [a i] then silence).
        for (double time = 1.0; time <= 1.12; time += 0.002)
            QVERIFY2(distance(e.mouthAt(time), mix(a, i, 0.5)) < kTol, qPrintable(QString::number(time)));
    }

    void silenceReturnsToM()
    {
        const Mouth a = shape(MouthShape::A), o = shape(MouthShape::O);
        {
            // A pause of 0.8 s after the sound shuts the mouth.
            Timeline t;
            t.addMouthCues({{1.0, 1.2, MouthShape::A}, {2.0, 2.3, MouthShape::O}});
            const TimelineEvaluator e(t, m_face, m_shapes);
            QVERIFY(distance(e.mouthAt(0.5), Mouth {}) < kTol); // before speech
            QVERIFY(distance(e.mouthAt(1.15), a) < kTol);
            QVERIFY(distance(e.mouthAt(1.6), Mouth {}) < kTol);
            QVERIFY(distance(e.mouthAt(2.0), o) < kTol);
            QVERIFY(distance(e.mouthAt(2.5), Mouth {}) < kTol); // after speech
            // Closing eases over `coarticulation` from the end of the sound.
            QVERIFY(distance(e.mouthAt(1.25), mix(a, Mouth {}, 0.5)) < kTol);
        }
        {
            // A pause shorter than silenceHold keeps the shape.
            Timeline t;
            t.addMouthCues({{1.0, 1.2, MouthShape::A}, {1.45, 1.7, MouthShape::O}});
            const TimelineEvaluator e(t, m_face, m_shapes);
            QVERIFY(distance(e.mouthAt(1.3), a) < kTol);
            QVERIFY(distance(e.mouthAt(1.4), mix(a, o, 0.5)) < kTol);
        }
        {
            // Keys with no duration: a gap of more than 300 ms with no key shuts the mouth
            // (after a minimum hold); a shorter one does not.
            Timeline t;
            t.addMouthKey(key(1.0, MouthShape::A));
            t.addMouthKey(key(2.0, MouthShape::O));
            t.addMouthKey(key(2.25, MouthShape::A));
            const TimelineEvaluator e(t, m_face, m_shapes);
            QVERIFY(distance(e.mouthAt(1.0), a) < kTol);
            QVERIFY(distance(e.mouthAt(1.0 + t.smoothing().minHold), a) < kTol);
            QVERIFY(distance(e.mouthAt(1.5), Mouth {}) < kTol);
            QVERIFY(distance(e.mouthAt(2.1), o) < kTol);
            QVERIFY(distance(e.mouthAt(2.25), a) < kTol);
            QVERIFY(distance(e.mouthAt(3.0), Mouth {}) < kTol);
        }
        {
            // `n` after a silence has neutral corners.
            Timeline t;
            t.addMouthCues({{1.0, 1.2, MouthShape::E}, {2.0, 2.3, MouthShape::N}});
            const TimelineEvaluator e(t, m_face, m_shapes);
            QCOMPARE(e.mouthAt(2.0)[Left], QPointF());
            QCOMPARE(e.mouthAt(2.0)[Right], QPointF());
        }
    }

    void emotionCombinesWithSpeech()
    {
        Timeline t;
        t.addMouthCues({{1.0, 1.3, MouthShape::A}, {2.0, 2.3, MouthShape::U}});
        t.addEmotionClip({0.0, 4.0, Emotion::Smile, 1.0, 0.5, 0.5});
        const TimelineEvaluator e(t, m_face, m_shapes);
        const Pose smile = emotionPose(m_face, Emotion::Smile, 1.0);
        const Mouth a = shape(MouthShape::A);

        const Pose speaking = e.evaluate(1.1);
        const Pose silent = e.evaluate(1.7);
        // The smile is added to the speech shape...
        for (int k = 0; k < 4; ++k) {
            const char *id = kMouthControlIds[k];
            QVERIFY(QLineF(offsetOf(speaking, id), a[k] + offsetOf(smile, id)).length() < kTol);
            QVERIFY(QLineF(offsetOf(silent, id), offsetOf(smile, id)).length() < kTol);
        }
        // ...so the smiling mouth still opens,
        QVERIFY(offsetOf(speaking, "8.2").y() - offsetOf(silent, "8.2").y() > 0.5 * a[Down].y());
        // with its corners raised above a neutral face's speaking corners.
        Timeline neutral;
        neutral.addMouthCues({{1.0, 1.3, MouthShape::A}});
        const auto plain = posedPoints(m_face, TimelineEvaluator(neutral, m_face, m_shapes).evaluate(1.1));
        const auto smiling = posedPoints(m_face, speaking);
        QVERIFY(smiling[pt::idx("8.4")].y() < plain[pt::idx("8.4")].y() - 1.0);
        QVERIFY(smiling[pt::idx("8.3")].y() < plain[pt::idx("8.3")].y() - 1.0);
        QCOMPARE(offsetOf(speaking, "4.4"), offsetOf(smile, "4.4")); // brows follow the emotion alone
        QCOMPARE(speaking.leftEyeOpen, smile.leftEyeOpen);
    }

    // A photo taken with the lips apart: the animation shuts them at rest, and a sad clip over
    // the rest draws them as it draws a photo taken with the lips together (sad once shut them a
    // second time, lifting the lower lip's outline into a sliver).
    void sadOverRestShutsTheLipsOnce()
    {
        const double es0 = m_face.fapu().es0;
        FaceModel apart = m_face;
        for (const char *id : {"8.2", "2.3", "2.1"})
            apart.setPoint(pt::idx(id), apart.point(id) + QPointF(0, 0.12 * es0), apart.isHandPlaced(pt::idx(id)));
        Timeline t;
        t.addEmotionClip({0.0, 4.0, Emotion::Sad, 1.0, 0.0, 0.0});
        auto sadAtRest = [&](const FaceModel &face) {
            return posedPoints(face, TimelineEvaluator(t, face, m_shapes).evaluate(2.0));
        };
        const auto together = sadAtRest(m_face), p = sadAtRest(apart);
        auto lip = [](const auto &points, const char *outer, const char *inner) {
            return points[pt::idx(outer)].y() - points[pt::idx(inner)].y();
        };
        QVERIFY(p[pt::idx("2.3")].y() - p[pt::idx("2.2")].y() < 0.02 * es0);
        QVERIFY2(std::abs(lip(p, "8.2", "2.3") - lip(together, "8.2", "2.3")) < 0.01 * es0,
            qPrintable(QStringLiteral("lower lip %1, with the lips photographed together %2")
                           .arg(lip(p, "8.2", "2.3"))
                           .arg(lip(together, "8.2", "2.3"))));
        // The still drawing of sad is that frame.
        const auto still = posedPoints(apart, stillEmotionPose(apart, Emotion::Sad, 1.0));
        for (int i = 0; i < kPointCount; ++i)
            QVERIFY(QLineF(still[i], p[i]).length() < 1e-6);
    }

    void emotionFadesInAndOut_data()
    {
        QTest::addColumn<double>("time");
        QTest::addColumn<double>("envelope");
        // Clip [1, 5], intensity 0.8, fade in 1 s, fade out 0.5 s.
        QTest::newRow("before") << 0.5 << 0.0;
        QTest::newRow("start") << 1.0 << 0.0;
        QTest::newRow("mid fade in") << 1.5 << 0.4;
        QTest::newRow("third of fade in") << 1.0 + 1.0 / 3 << 0.8 * 7 / 27;
        QTest::newRow("held") << 3.0 << 0.8;
        QTest::newRow("mid fade out") << 4.75 << 0.4;
        QTest::newRow("end") << 5.0 << 0.0;
        QTest::newRow("after") << 6.0 << 0.0;
    }

    void emotionFadesInAndOut()
    {
        QFETCH(double, time);
        QFETCH(double, envelope);
        Timeline t;
        t.addEmotionClip({1.0, 5.0, Emotion::Surprise, 0.8, 1.0, 0.5});
        const TimelineEvaluator e(t, m_face, m_shapes);
        // Held at the weight the clip's intensity draws (emotionPose's), faded along the ease.
        const double weight = envelope / 0.8 * emotionWeight(0.8);
        QVERIFY(std::abs(e.emotionEnvelopeAt(0, time) - weight) < 1e-12);
        const Pose full = emotionPose(m_face, Emotion::Surprise, 1.0);
        QVERIFY(distance(e.evaluate(time), Pose::lerp(Pose(), full, weight)) < 1e-9);
        if (time == 3.0)
            QVERIFY(distance(e.evaluate(time), emotionPose(m_face, Emotion::Surprise, 0.8)) < 1e-9);
    }

    void shortClipsShrinkTheirFades()
    {
        Timeline t;
        t.addEmotionClip({0.0, 0.4, Emotion::Sad, 1.0, 0.3, 0.5}); // fades shrink to 0.15 and 0.25
        t.addEmotionClip({1.0, 2.0, Emotion::Angry, 0.5, 0.0, 0.0});
        const TimelineEvaluator e(t, m_face, m_shapes);
        QVERIFY(std::abs(e.emotionEnvelopeAt(0, 0.075) - 0.5) < 1e-12);
        QVERIFY(std::abs(e.emotionEnvelopeAt(0, 0.15) - 1.0) < 1e-12);
        QVERIFY(std::abs(e.emotionEnvelopeAt(0, 0.275) - 0.5) < 1e-12);
        QCOMPARE(e.emotionEnvelopeAt(1, 1.0), emotionWeight(0.5)); // no fade: a step
        QCOMPARE(e.emotionEnvelopeAt(1, 1.999), emotionWeight(0.5));
    }

    void overlappingEmotionsAdd()
    {
        Timeline t;
        t.addEmotionClip({0.0, 10.0, Emotion::Smile, 0.5, 0.0, 0.0});
        t.addEmotionClip({2.0, 3.0, Emotion::Surprise, 1.0, 0.0, 0.0});
        const TimelineEvaluator e(t, m_face, m_shapes);
        const Pose both = emotionPose(m_face, Emotion::Smile, 0.5) + emotionPose(m_face, Emotion::Surprise, 1.0);
        QVERIFY(distance(e.evaluate(2.5), both) < 1e-9);
        QVERIFY(distance(e.evaluate(5.0), emotionPose(m_face, Emotion::Smile, 0.5)) < 1e-9);
    }

    void blinkClosesFasterThanItOpens()
    {
        Timeline t;
        t.addBlink({1.0, 0.2});
        const TimelineEvaluator e(t, m_face, m_shapes);
        QCOMPARE(e.blinkOpenAt(0.99), 1.0);
        QCOMPARE(e.blinkOpenAt(1.0), 1.0);
        QCOMPARE(e.blinkOpenAt(1.2), 1.0);
        // Time from fully open to shut, and from shut to fully open.
        double lastOpen = 1.0, firstShut = -1, lastShut = -1, firstOpen = -1;
        for (double time = 1.0; time <= 1.2 + 1e-9; time += 0.0005) {
            const double open = e.blinkOpenAt(time);
            if (open > 0.999 && firstShut < 0)
                lastOpen = time;
            if (open < 0.001) {
                if (firstShut < 0)
                    firstShut = time;
                lastShut = time;
            }
            if (open > 0.999 && lastShut > 0 && firstOpen < 0)
                firstOpen = time;
        }
        const double closing = firstShut - lastOpen;
        const double opening = firstOpen - lastShut;
        QVERIFY2(closing > 0 && opening > 0, qPrintable(QStringLiteral("%1 %2").arg(closing).arg(opening)));
        QVERIFY2(closing < 0.6 * opening, qPrintable(QStringLiteral("%1 %2").arg(closing).arg(opening)));
        QVERIFY(lastShut - firstShut > 0.02); // shut for a moment

        // In the pose the lids close: the upper lid reaches the corner line.
        const Pose shut = e.evaluate(1.0 + 0.2 * (kBlinkPhases.closing + kBlinkPhases.shut / 2));
        QCOMPARE(shut.leftEyeOpen, 0.0);
        QCOMPARE(shut.rightEyeOpen, 0.0);
        const auto pts = posedPoints(m_face, shut);
        QVERIFY(std::abs(pts[pt::idx("3.2")].y() - pts[pt::idx("3.4")].y()) < 1e-9);
        // Lids scaled by an emotion still blink shut.
        t.addEmotionClip({0.0, 2.0, Emotion::Surprise, 1.0, 0.0, 0.0});
        const TimelineEvaluator surprised(t, m_face, m_shapes);
        QCOMPARE(surprised.evaluate(0.5).leftEyeOpen, emotionPose(m_face, Emotion::Surprise, 1).leftEyeOpen);
        QCOMPARE(surprised.evaluate(1.0 + 0.2 * (kBlinkPhases.closing + kBlinkPhases.shut / 2)).leftEyeOpen, 0.0);
    }

    void overlappingBlinksTakeTheSmallerOpening()
    {
        Timeline t;
        t.addBlink({1.0, 0.4});
        t.addBlink({1.05, 0.1});
        const TimelineEvaluator e(t, m_face, m_shapes);
        for (double time = 0.9; time < 1.5; time += 0.01) {
            Timeline one, two;
            one.addBlink({1.0, 0.4});
            two.addBlink({1.05, 0.1});
            const double expected = std::min(TimelineEvaluator(one, m_face, m_shapes).blinkOpenAt(time),
                TimelineEvaluator(two, m_face, m_shapes).blinkOpenAt(time));
            QCOMPARE(e.blinkOpenAt(time), expected);
        }
    }

    void gazeAndHeadEaseBetweenKeys()
    {
        Timeline t;
        t.addGazeKey({1.0, {0.0, 0.0}});
        t.addGazeKey({2.0, {0.1, -0.05}});
        t.addHeadKey({0.0, 0.0, {}, 1.0});
        t.addHeadKey({2.0, 10.0, {0.2, 0.0}, 1.1});
        const TimelineEvaluator e(t, m_face, m_shapes);
        const double es0 = m_face.fapu().es0;
        const Pose mid = e.evaluate(1.5);
        QVERIFY(QLineF(offsetOf(mid, "3.6"), QPointF(0.05, -0.025) * es0).length() < kTol);
        QVERIFY(QLineF(offsetOf(mid, "3.5"), QPointF(0.05, -0.025) * es0).length() < kTol);
        QCOMPARE(offsetOf(e.evaluate(0.5), "3.6"), QPointF()); // first value before the first key
        QVERIFY(QLineF(offsetOf(e.evaluate(9.0), "3.5"), QPointF(0.1, -0.05) * es0).length() < kTol);
        const Pose half = e.evaluate(1.0);
        QVERIFY(std::abs(half.head.rotationDeg - 5.0) < 1e-12);
        QVERIFY(QLineF(half.head.translation, QPointF(0.1 * es0, 0)).length() < kTol);
        QVERIFY(std::abs(half.head.scale - 1.05) < 1e-12);
        QVERIFY(std::abs(e.evaluate(0.5).head.rotationDeg - 10.0 * ease(0.25)) < 1e-12);
    }

    void poseTrackEasesControlPointsInEs0Units()
    {
        const FaceModel face = testFace();
        const double es0 = face.fapu().es0;
        QVERIFY(es0 > 0);
        Timeline t;
        t.addPoseKey({1.0, {{QStringLiteral("8.2"), {0.0, 0.2}}, {QStringLiteral("4.4"), {0.0, -0.05}}}});
        t.addPoseKey({2.0, {{QStringLiteral("8.2"), {0.1, 0.4}}}}); // 4.4 absent: back to 0
        const MouthShapeSet shapes;
        const TimelineEvaluator e(t, face, shapes);
        const Pose rest = TimelineEvaluator(Timeline(), face, shapes).evaluate(0.0);
        const int chin = pt::idx("8.2");
        const int brow = pt::idx("4.4");
        QCOMPARE(e.poseTrackPoints(), (QVector<int> {std::min(chin, brow), std::max(chin, brow)}));

        auto added = [&](double time, int index) { return e.evaluate(time).offset[index] - rest.offset[index]; };
        // Before the first key its value holds, after the last the last one.
        QVERIFY(QLineF(added(0.0, chin), QPointF(0, 0.2 * es0)).length() < kTol);
        QVERIFY(QLineF(added(1.0, brow), QPointF(0, -0.05 * es0)).length() < kTol);
        QVERIFY(QLineF(added(3.0, chin), QPointF(0.1 * es0, 0.4 * es0)).length() < kTol);
        QVERIFY(QLineF(added(3.0, brow), QPointF()).length() < kTol);
        // Between keys: ease().
        for (double u : {0.25, 0.5, 0.8}) {
            const QPointF expected = QPointF(0, 0.2 * es0) + QPointF(0.1 * es0, 0.2 * es0) * ease(u);
            QVERIFY(QLineF(added(1.0 + u, chin), expected).length() < kTol);
            QVERIFY(QLineF(added(1.0 + u, brow), QPointF(0, -0.05 * es0) * (1 - ease(u))).length() < kTol);
        }
        // Only the named points move; where the character speaks the speech owns the mouth
        // (jawKeyGivesWayToSpeech), and the brow's key still adds.
        const Pose p = e.evaluate(1.5);
        for (int i = 0; i < kPointCount; ++i) {
            if (i != chin && i != brow)
                QCOMPARE(p.offset[i], rest.offset[i]);
        }
        Timeline speech;
        speech.addMouthKey({1.5, MouthShape::A, 1.0, 0.5});
        speech.addMouthKey({2.5, MouthShape::M, 1.0, 0.5});
        Timeline speaking = t;
        speaking.setMouthKeys(speech.mouthKeys());
        const TimelineEvaluator both(speaking, face, shapes);
        const Pose spoken = TimelineEvaluator(speech, face, shapes).evaluate(1.5);
        QVERIFY(QLineF(both.evaluate(1.5).offset[chin], spoken.offset[chin]).length() < kTol);
        QVERIFY(QLineF(both.evaluate(1.5).offset[brow], spoken.offset[brow] + added(1.5, brow)).length() < kTol);

        // The same track on a face twice the size moves twice as far (retargeting by ES0).
        const FaceModel big = averageFace(QRectF(200, 300, 400, 480), QSize(800, 1000));
        const TimelineEvaluator onBig(t, big, shapes);
        const Pose bigRest = TimelineEvaluator(Timeline(), big, shapes).evaluate(0.0);
        const QPointF bigAdded = onBig.evaluate(1.5).offset[chin] - bigRest.offset[chin];
        QVERIFY(QLineF(bigAdded, added(1.5, chin) * (big.fapu().es0 / es0)).length() < 1e-6);

        // The derived points follow: the inner lower lip and the chin move with 8.2.
        const auto posed = posedPoints(face, e.evaluate(3.0));
        const auto neutral = posedPoints(face, rest);
        QVERIFY(posed[pt::idx("2.1")].y() - neutral[pt::idx("2.1")].y() > 0.39 * es0);
    }

    // An Edit Pose jaw key is one key on the pose track, held before and after it. Where a
    // recording plays the speech's mouth wins (the jaw key held the mouth open through all the
    // speech) but around the key's own time, where the jaw opens as dragged; where it is silent
    // the key shapes the mouth; the hand-overs ease, and the export knows their times.
    void jawKeyGivesWayToSpeech()
    {
        const FaceModel face = testFace();
        const double es0 = face.fapu().es0;
        const MouthShapeSet shapes;
        Timeline speech;
        speech.setAudioClips({AudioClip {QStringLiteral("/tmp/speech.wav"), 2.0, 2.0}});
        speech.addMouthKey({2.2, MouthShape::A, 1.0, 0.5});
        speech.addMouthKey({2.8, MouthShape::E, 1.0, 0.5});
        speech.addMouthKey({3.5, MouthShape::M, 1.0, 0.5});
        speech.addGazeKey({6.0, {0.0, 0.0}}); // the animation goes on after the speech
        Timeline posed = speech;
        // The jaw dragged open at 3.0, in the middle of the speech (and a brow with it).
        posed.addPoseKey({3.0, {{QStringLiteral("8.2"), {0.0, 0.4}}, {QStringLiteral("4.4"), {0.0, -0.05}}}});
        const TimelineEvaluator onlySpeech(speech, face, shapes);
        const TimelineEvaluator e(posed, face, shapes);
        const int lip = pt::idx("8.2");
        const int brow = pt::idx("4.4");
        const auto jaw
            = [&](double time) { return e.evaluate(time).offset[lip] - onlySpeech.evaluate(time).offset[lip]; };
        const QPointF open(0, 0.4 * es0);

        // At the key, as dragged; silent before and after the recording, the key's open jaw.
        for (double time : {3.0, 0.0, 1.0, 1.8, 4.2, 6.0})
            QVERIFY2(QLineF(jaw(time), open).length() < kTol, qPrintable(QString::number(time)));
        // The rest of the speech: the speech's mouth exactly, whatever shape it says.
        for (double time : {2.0, 2.2, 2.5, 3.3, 3.5, 4.0})
            QVERIFY2(QLineF(jaw(time), QPointF()).length() < kTol, qPrintable(QString::number(time)));
        // The hand-overs ease.
        const double edge = 2.0 - TimelineEvaluator::kSpeechFade / 2;
        QVERIFY(std::abs(jaw(edge).y() - open.y() * (1 - ease(0.5))) < kTol);
        const double reach = 3.0 + TimelineEvaluator::kPoseKeyReach / 2;
        QVERIFY(std::abs(jaw(reach).y() - open.y() * ease(0.5)) < kTol);
        // The brows are not the mouth's: their key adds in speech too.
        QVERIFY(QLineF(e.evaluate(2.5).offset[brow] - onlySpeech.evaluate(2.5).offset[brow], QPointF(0, -0.05 * es0))
                    .length()
            < kTol);
        // The export samples where the mouth changes hands.
        const QVector<double> times = e.keyTimes(Track::Pose);
        for (double time : {2.0 - TimelineEvaluator::kSpeechFade, 2.0, 4.0, 4.0 + TimelineEvaluator::kSpeechFade,
                 3.0 - TimelineEvaluator::kPoseKeyReach, 3.0 + TimelineEvaluator::kPoseKeyReach})
            QVERIFY2(std::any_of(times.cbegin(), times.cend(), [time](double k) { return std::abs(k - time) < 1e-9; }),
                qPrintable(QString::number(time)));
    }

    void poseTrackExportKeys()
    {
        const FaceModel face = testFace();
        Timeline t;
        t.addPoseKey({0.5, {{QStringLiteral("8.2"), {0.0, 0.2}}}});
        t.addPoseKey({1.0, {{QStringLiteral("8.2"), {0.0, 0.2}}}}); // holds
        t.addPoseKey({1.5, {{QStringLiteral("8.2"), {0.0, 0.0}}}});
        t.addGazeKey({3.0, {0.1, 0.0}});
        const TimelineEvaluator e(t, face, MouthShapeSet());
        const auto keys = e.exportKeys(Track::Pose);
        QCOMPARE(keys.times, (QVector<double> {0.0, 0.5, 1.0, 1.5, 3.0}));
        using S = TimelineEvaluator::Segment;
        QCOMPARE(keys.segments, (QVector<S> {S::Hold, S::Hold, S::Ease, S::Hold}));
        for (qsizetype i = 0; i < keys.segments.size(); ++i) {
            const double t0 = keys.times[i], t1 = keys.times[i + 1];
            const Pose p0 = e.evaluate(t0), p1 = e.evaluate(t1);
            for (double u : {0.2, 0.5, 0.9}) {
                const Pose inside = e.evaluate(t0 + (t1 - t0) * u);
                const double s = keys.segments[i] == S::Ease ? ease(u) : 0.0;
                QVERIFY(std::abs(inside.offset[pt::idx("8.2")].y()
                            - (p0.offset[pt::idx("8.2")].y() * (1 - s) + p1.offset[pt::idx("8.2")].y() * s))
                    < kTol);
            }
        }
        QVERIFY(e.keyTimes(kAllTracks).contains(1.5));
        QVERIFY(!e.keyTimes(Track::Mouth).contains(1.5));
    }

    void shakeAndNodMoveTheHead()
    {
        Timeline t;
        t.addShake(1.0, 2.0, 8.0, 5.0);
        t.addNod(3.0, 4.0, 0.06, 4.0);
        const TimelineEvaluator e(t, m_face, m_shapes);
        const double fps = t.frameRate();
        int signChanges = 0;
        double previous = 0;
        for (int f = int(1.0 * fps); f <= int(2.0 * fps); ++f) {
            const double r = e.evaluate(f / fps).head.rotationDeg;
            if (std::abs(r) > 1e-9) {
                signChanges += previous != 0 && (r > 0) != (previous > 0);
                previous = r;
            }
        }
        QCOMPARE(signChanges, 4);
        QVERIFY(e.evaluate(1.1).head.rotationDeg > 7.9);
        QCOMPARE(e.evaluate(2.5).head, HeadPose());
        const double es0 = m_face.fapu().es0;
        QVERIFY(std::abs(e.evaluate(3.125).head.translation.y() - 0.06 * es0) < 1e-9);
        QVERIFY(e.evaluate(3.375).head.translation.y() < 0);
    }

    void exportKeyTimesDescribeThePose()
    {
        Timeline t;
        t.addMouthCues({{0.5, 0.7, MouthShape::A}, {0.7, 0.8, MouthShape::I}, {0.8, 1.1, MouthShape::U},
            {2.0, 2.4, MouthShape::O}, {2.4, 2.6, MouthShape::N}});
        t.addEmotionClip({1.5, 3.0, Emotion::Smile, 0.8, 0.3, 0.2});
        t.addBlink({1.2, 0.2});
        t.addBlink({2.7, 0.15});
        t.addGazeKey({0.0, {}});
        t.addGazeKey({1.3, {0.05, 0}});
        t.addShake(3.0, 3.5);
        t.setAudioClips({AudioClip {QStringLiteral("x.wav"), 0.0, 4.0}});
        const TimelineEvaluator e(t, m_face, m_shapes);
        const auto keys = e.exportKeys();
        QCOMPARE(keys.times.first(), 0.0);
        QCOMPARE(keys.times.last(), 4.0);
        QCOMPARE(keys.segments.size(), keys.times.size() - 1);
        for (qsizetype i = 1; i < keys.times.size(); ++i)
            QVERIFY(keys.times[i] > keys.times[i - 1]);
        for (const MouthKey &k : t.mouthKeys())
            QVERIFY(keys.times.contains(k.time));

        int counts[3] = {};
        for (qsizetype i = 0; i < keys.segments.size(); ++i) {
            const double t0 = keys.times[i], t1 = keys.times[i + 1];
            const Pose p0 = e.evaluate(t0), p1 = e.evaluate(t1);
            const auto kind = keys.segments[i];
            ++counts[int(kind)];
            for (double u : {0.2, 1.0 / 3.0, 0.5, 0.9}) {
                const Pose inside = e.evaluate(t0 + (t1 - t0) * u);
                if (kind == TimelineEvaluator::Segment::Hold)
                    QVERIFY2(distance(inside, p0) < 1e-9, qPrintable(QString::number(t0)));
                else if (kind == TimelineEvaluator::Segment::Ease)
                    QVERIFY2(distance(inside, Pose::lerp(p0, p1, ease(u))) < 1e-9, qPrintable(QString::number(t0)));
            }
        }
        QVERIFY(counts[int(TimelineEvaluator::Segment::Hold)] > 0);
        QVERIFY(counts[int(TimelineEvaluator::Segment::Ease)] > 5);
        QVERIFY(counts[int(TimelineEvaluator::Segment::Mixed)] > 0); // the smile fades in while speaking

        // One track's key times: only the head moves the head.
        const auto head = e.exportKeys(Track::Head);
        // 0, the shake's start, its 3 extremes (5 a second for 0.5 s, rounded) and end, the duration.
        QCOMPARE(head.times.size(), 1 + 5 + 1);
        for (auto kind : head.segments)
            QVERIFY(kind != TimelineEvaluator::Segment::Mixed);
        QVERIFY(e.keyTimes(Track::Mouth).size() < keys.times.size());
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestTimelineEvaluator)
#include "tst_timelineevaluator.moc"
