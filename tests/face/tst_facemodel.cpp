#include "face/averageface.h"
#include "face/emotion.h"
#include "face/facemodel.h"
#include "face/fapu.h"
#include "face/headturn.h"
#include "face/mouthshape.h"
#include "face/pointtable.h"
#include "face/pose.h"
#include "testmain.h"

#include <QLineF>
#include <QSet>
#include <QTest>
#include <QTransform>

#include <cmath>

using namespace toonface;

namespace {

FaceModel testFace()
{
    return averageFace(QRectF(100, 150, 200, 240), QSize(400, 500));
}

QPointF p(const std::array<QPointF, kPointCount> &pts, const char *id)
{
    return pts[pt::idx(id)];
}

bool near(QPointF a, QPointF b, double tol = 1e-9)
{
    return QLineF(a, b).length() <= tol;
}

} // namespace

class TestFaceModel : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void pointIdsLookUpTheirIndex()
    {
        // Every id finds its own row, by QString and by Latin-1 view alike; other names none.
        for (int i = 0; i < kPointCount; ++i) {
            const char *id = pointTable()[i].id;
            QCOMPARE(pointIndex(QLatin1StringView(id)), i);
            QCOMPARE(pointIndex(QString::fromLatin1(id)), i);
            QCOMPARE(pt::idx(id), i);
            QCOMPARE(pointId(i), QString::fromLatin1(id));
        }
        for (const char *bad :
            {"", "8", "8.", "8.99", "x.1", "8.9 ", "H.1", "08.9", "8.09", "h.01", ".9", "123.1", "8.-1"})
            QCOMPARE(pointIndex(QLatin1StringView(bad)), -1);
        // A view that is part of a longer string reads only its own characters.
        QCOMPARE(pointIndex(QLatin1StringView("8.9x", 3)), pointIndex(QStringLiteral("8.9")));
    }

    // The head's turn and tilt from its points: none for the front-facing average face; a face
    // rotated in the picture gives that roll; the nose tip moved aside along the eye line by
    // depth · tan(yaw) gives that yaw; beyond kDrawnWellDeg the cartoon is said to look twisted.
    void headTurnFromThePoints()
    {
        const FaceModel front = averageFace(QRectF(100, 150, 200, 240), QSize(400, 500));
        const HeadTurn none = headTurn(front);
        QVERIFY(std::abs(none.yawDeg) < 1.0);
        QVERIFY(std::abs(none.rollDeg) < 1.0);
        QVERIFY(!turnedTooFar(none));

        for (double degrees : {-25.0, 10.0, 20.0}) {
            FaceModel tilted = front;
            QTransform rotation;
            rotation.translate(200, 250).rotate(degrees).translate(-200, -250);
            for (int i = 0; i < kPointCount; ++i)
                tilted.setPoint(i, rotation.map(front.point(i)));
            const HeadTurn turn = headTurn(tilted);
            QVERIFY2(std::abs(turn.rollDeg - degrees) < 0.5 + std::abs(none.rollDeg),
                qPrintable(QString::number(turn.rollDeg)));
            QCOMPARE(turnedTooFar(turn), std::abs(degrees) > kDrawnWellDeg);
        }
        for (double yaw : {-30.0, 8.0, 25.0}) {
            FaceModel turned = front;
            const double es0 = QLineF(front.point("3.6"), front.point("3.5")).length();
            const QPointF eyeMid = (front.point("3.6") + front.point("3.5")) / 2.0;
            const QPointF nose(eyeMid.x() + kNoseDepthEs0 * std::tan(yaw * M_PI / 180) * es0, front.point("9.15").y());
            turned.setPoint(pt::idx("9.15"), nose);
            const HeadTurn turn = headTurn(turned);
            QVERIFY2(std::abs(turn.yawDeg - yaw) < 1.0, qPrintable(QString::number(turn.yawDeg)));
            QCOMPARE(turnedTooFar(turn), std::abs(yaw) > kDrawnWellDeg);
        }
    }

    void pointTableMatchesContract()
    {
        const auto &t = pointTable();
        QCOMPARE(int(t.size()), 72);
        QSet<QString> ids;
        int counts[7] = {};
        for (const auto &info : t) {
            ids.insert(QString::fromLatin1(info.id));
            counts[int(info.group)]++;
        }
        QCOMPARE(ids.size(), 72);
        QCOMPARE(counts[int(PointGroup::Hair)], 19);
        QCOMPARE(counts[int(PointGroup::Contour)], 10);
        QCOMPARE(counts[int(PointGroup::Ears)], 8);
        QCOMPARE(counts[int(PointGroup::Eyebrows)], 8);
        QCOMPARE(counts[int(PointGroup::Eyes)], 10);
        QCOMPARE(counts[int(PointGroup::Nose)], 9);
        QCOMPARE(counts[int(PointGroup::Mouth)], 8);
        QCOMPARE(pointId(0), QStringLiteral("h.1"));
        QCOMPARE(pointIndex(QStringLiteral("h.10")), 9);
        QCOMPARE(pointIndex(QStringLiteral("2.3")), 71);
        QCOMPARE(pointIndex(QStringLiteral("nope")), -1);
        for (const char *c : {"8.9", "8.2", "8.4", "8.3", "3.6", "3.5", "4.6", "4.1"})
            QVERIFY2(t[pt::idx(c)].control, c);
        for (const char *d : {"8.10", "8.1", "2.2", "2.3", "2.1", "h.1", "9.15"})
            QVERIFY2(!t[pt::idx(d)].control, d);
        PointGroup g;
        QVERIFY(groupFromName(QStringLiteral("eyebrows"), &g));
        QCOMPARE(g, PointGroup::Eyebrows);
        QVERIFY(!groupFromName(QStringLiteral("beard"), &g));
    }

    void fapuOnKnownFace()
    {
        FaceModel f(QSize(100, 100));
        auto set = [&](const char *id, double x, double y) { f.setPoint(pt::idx(id), {x, y}); };
        set("3.6", 30, 40);
        set("3.5", 70, 40);
        set("9.15", 50, 60);
        set("2.2", 50, 72);
        set("2.3", 50, 72);
        set("8.1", 50, 68);
        set("8.2", 50, 77);
        set("8.4", 38, 72);
        set("8.3", 62, 72);
        set("3.2", 30, 37);
        set("3.4", 30, 43);
        set("3.1", 70, 36);
        set("3.3", 70, 44);
        set("2.1", 51, 90);
        const Fapu fapu = f.fapu();
        QCOMPARE(fapu.es0, 40.0);
        QCOMPARE(fapu.ens0, 20.0);
        QCOMPARE(fapu.mns0, 12.0);
        QCOMPARE(fapu.mw0, 24.0);
        QCOMPARE(fapu.leftEyeH, 6.0);
        QCOMPARE(fapu.rightEyeH, 8.0);
        QCOMPARE(fapu.upperLipH, 4.0);
        QCOMPARE(fapu.lowerLipH, 5.0);
        QCOMPARE(fapu.jawH, 13.0);
        QCOMPARE(fapu.pixel(), 0.4);
        QCOMPARE(fapu.eyeMid, QPointF(50, 40));
    }

    void neutralPoseReproducesNeutralFace()
    {
        const FaceModel f = testFace();
        QVERIFY(f.isValid());
        QCOMPARE(posedPoints(f, Pose {}), f.points());
    }

    void derivedPointsFollowMouthControls()
    {
        const FaceModel f = testFace();
        const Fapu fapu = f.fapu();
        Pose pose;
        pose.offset[pt::idx("8.9")] = {-2, -4};
        pose.offset[pt::idx("8.2")] = {1, 10};
        pose.offset[pt::idx("8.4")] = {-6, 0};
        pose.offset[pt::idx("8.3")] = {8, 0};
        const auto q = posedPoints(f, pose);
        const double axis = (p(q, "8.4").x() + p(q, "8.3").x()) / 2;
        const double axis0 = (f.point("8.4").x() + f.point("8.3").x()) / 2;
        // 8.10 mirrors 8.9's motion about the (moving) mouth axis.
        QCOMPARE(p(q, "8.10").x() - axis,
            (f.point("8.10").x() - axis0) - ((p(q, "8.9").x() - axis) - (f.point("8.9").x() - axis0)));
        QCOMPARE(p(q, "8.10").y(), f.point("8.10").y() - 4);
        // 8.1 keeps its neutral offset from 8.9.
        QVERIFY(near(p(q, "8.1") - p(q, "8.9"), f.point("8.1") - f.point("8.9")));
        // inner lips: 2.2 = 8.1 + (0, UpperLipH), 2.3 = 8.2 - (0, LowerLipH) on the average face.
        QVERIFY(near(p(q, "2.2"), p(q, "8.1") + QPointF(0, fapu.upperLipH), 1e-6));
        QVERIFY(near(p(q, "2.3"), p(q, "8.2") - QPointF(0, fapu.lowerLipH), 1e-6));
        // jaw: 2.1 = 8.2 + (0, JawH); lower jaw points take half the chin's displacement.
        QVERIFY(near(p(q, "2.1") - p(q, "8.2"), f.point("2.1") - f.point("8.2")));
        QVERIFY(near(p(q, "2.12") - f.point("2.12"), QPointF(0.5, 5)));
        QVERIFY(near(p(q, "2.11") - f.point("2.11"), QPointF(0.5, 5)));
        // non-control points ignore offsets
        Pose stray;
        stray.offset[pt::idx("9.15")] = {50, 50};
        QCOMPARE(p(posedPoints(f, stray), "9.15"), f.point("9.15"));
    }

    void closedLipsTouch()
    {
        const FaceModel f = testFace();
        Pose pose;
        pose.offset[pt::idx("8.2")] = {0, -20}; // lower lip pushed far up
        const auto q = posedPoints(f, pose);
        QVERIFY(p(q, "2.2").y() <= p(q, "2.3").y() + 1e-9);
        QCOMPARE(p(q, "2.2").y(), p(q, "2.3").y());
    }

    void blinkClosesLidsAndClampsEyeball()
    {
        const FaceModel f = testFace();
        Pose pose;
        pose.leftEyeOpen = 0;
        pose.rightEyeOpen = 0.5;
        pose.offset[pt::idx("3.6")] = {-500, 0};
        const auto q = posedPoints(f, pose);
        const double cornerY = (f.point("3.12").y() + f.point("3.8").y()) / 2;
        QCOMPARE(p(q, "3.2").y(), cornerY);
        QCOMPARE(p(q, "3.4").y(), cornerY);
        const double rightLine = (f.point("3.11").y() + f.point("3.7").y()) / 2;
        QCOMPARE(p(q, "3.1").y(), rightLine + (f.point("3.1").y() - rightLine) * 0.5);
        QCOMPARE(p(q, "3.6").x(), f.point("3.12").x());
    }

    void mouthShapeDefaults_data()
    {
        QTest::addColumn<QString>("shape");
        for (MouthShape s : kAllMouthShapes)
            QTest::newRow(qPrintable(mouthShapeName(s))) << mouthShapeName(s);
    }

    // A face photographed with its lips apart rests with them shut, and every shape starts from
    // there: `m` shuts them, `a` opens by the table's amount from shut lips.
    void lipsApartRestShut()
    {
        const FaceModel closed = testFace();
        QCOMPARE(restingMouth(closed), (std::array<QPointF, 4> {}));
        FaceModel open = closed;
        const Fapu u = closed.fapu();
        const double gap = 0.6 * u.mns0;
        for (const char *id : {"8.2", "2.3", "2.1"})
            open.setPoint(pt::idx(id), open.point(id) + QPointF(0, gap));
        const double openGap = open.point("2.3").y() - open.point("2.2").y();
        const std::array<QPointF, 4> rest = restingMouth(open);
        QVERIFY(std::abs(rest[0].y() - 0.25 * openGap) < 1e-9); // the upper lip lowers a quarter
        QVERIFY(std::abs(rest[1].y() + 0.75 * openGap) < 1e-9); // the lower lip and jaw rise the rest
        MouthShapeSet set;
        const auto shut = posedPoints(open, mouthPose(open, set, MouthShape::M));
        QVERIFY(std::abs(shut[pt::idx("2.3")].y() - shut[pt::idx("2.2")].y()) < 1e-9);
        QVERIFY(std::abs(shut[pt::idx("2.1")].y() - (open.point("2.1").y() - 0.75 * openGap)) < 1e-9);
        const auto wide = posedPoints(open, mouthPose(open, set, MouthShape::A));
        const double opening = wide[pt::idx("8.2")].y() - shut[pt::idx("8.2")].y();
        QVERIFY(std::abs(opening - 0.8 * open.fapu().mns0) < 1e-9);
        // A hair's breadth apart counts as touching.
        FaceModel nearly = closed;
        nearly.setPoint(pt::idx("2.3"), nearly.point("2.3") + QPointF(0, 0.05 * u.mns0));
        QCOMPARE(restingMouth(nearly), (std::array<QPointF, 4> {}));
    }

    void mouthShapeDefaults()
    {
        QFETCH(QString, shape);
        const auto s = mouthShapeFromName(shape);
        QVERIFY(s);
        const FaceModel f = testFace();
        const Fapu u = f.fapu();
        const double px = u.pixel();
        MouthShapeSet set;
        const std::array<QPointF, 4> prev = {QPointF(0, 0), QPointF(0, 0), QPointF(-7, 2), QPointF(7, 2)};
        const auto d = set.displacements(*s, f, &prev);
        using A = std::array<QPointF, 4>;
        A expect;
        switch (*s) {
        case MouthShape::M: expect = {}; break;
        case MouthShape::F: expect = A {QPointF(), QPointF(0, -0.5 * u.lowerLipH), QPointF(), QPointF()}; break;
        case MouthShape::H:
        case MouthShape::U:
            expect = A {QPointF(0, -0.3 * u.mns0), QPointF(0, 0.3 * u.mns0), QPointF(0, -px), QPointF(0, -px)};
            break;
        case MouthShape::A:
            expect = A {
                QPointF(0, -0.3 * u.mns0), QPointF(0, 0.8 * u.mns0), QPointF(u.mw0 / 8, 0), QPointF(-u.mw0 / 8, 0)};
            break;
        case MouthShape::I:
            expect = A {QPointF(), QPointF(0, u.mns0 / 6), QPointF(-u.mw0 / 12, -3 * px), QPointF(u.mw0 / 12, -3 * px)};
            break;
        case MouthShape::E:
            expect = A {QPointF(), QPointF(0, u.mns0 / 2), QPointF(-u.mw0 / 12, -3 * px), QPointF(u.mw0 / 12, -3 * px)};
            break;
        case MouthShape::O: {
            const double mid = (f.point("8.9").y() - 0.3 * u.mns0 + f.point("8.2").y() + 0.5 * u.mns0) / 2;
            expect = A {QPointF(0, -0.3 * u.mns0), QPointF(0, 0.5 * u.mns0),
                QPointF(0.2 * u.mw0, mid - f.point("8.4").y()), QPointF(-0.2 * u.mw0, mid - f.point("8.3").y())};
            break;
        }
        case MouthShape::N: expect = A {QPointF(0, -0.25 * u.mns0), QPointF(0, 0.5 * u.mns0), prev[2], prev[3]}; break;
        }
        for (int k = 0; k < 4; ++k)
            QVERIFY2(near(d[k], expect[k], 1e-9), kMouthControlIds[k]);
        QVERIFY(set.isDefault(*s));
    }

    void mouthShapesAreEditable()
    {
        const FaceModel f = testFace();
        MouthShapeSet set;
        MouthShapePreset wide = set.preset(MouthShape::A);
        wide.offsets[Down].dy.mns = 1.2;
        set.setPreset(MouthShape::A, wide);
        QVERIFY(!set.isDefault(MouthShape::A));
        const Pose pose = mouthPose(f, set, MouthShape::A);
        QCOMPARE(pose.offset[pt::idx("8.2")].y(), 1.2 * f.fapu().mns0);
        QVERIFY(!(set == MouthShapeSet()));
    }

    void emotionIntensityScales()
    {
        const FaceModel f = testFace();
        for (Emotion e : kAllEmotions) {
            const Pose full = emotionPose(f, e, 1.0);
            const Pose half = emotionPose(f, e, 0.5);
            const Pose none = emotionPose(f, e, 0.0);
            QCOMPARE(none, Pose {});
            for (int i = 0; i < kPointCount; ++i) {
                QVERIFY(near(half.offset[i], full.offset[i] * emotionWeight(0.5), 1e-9));
                // mirrored: left and right counterparts move with opposite x, same y
                const char *mirror = mirrorPointId(pointTable()[i].id);
                const int j = pt::idx(mirror);
                if (j != i && pointTable()[i].group != PointGroup::Mouth) {
                    QCOMPARE(full.offset[i].y(), full.offset[j].y());
                    QCOMPARE(full.offset[i].x(), -full.offset[j].x());
                }
            }
            QVERIFY(emotionFromName(emotionName(e)) == e);
        }
        // Expressions read as they should: smile lifts the mouth corners, sad lowers them,
        // surprise raises the brows and opens the mouth, angry pulls the inner brows down.
        const double es0 = f.fapu().es0;
        QVERIFY(emotionPose(f, Emotion::Smile, 1).offset[pt::idx("8.4")].y() < -0.05 * es0);
        QVERIFY(emotionPose(f, Emotion::Sad, 1).offset[pt::idx("8.3")].y() > 0.05 * es0);
        QVERIFY(emotionPose(f, Emotion::Surprise, 1).offset[pt::idx("4.4")].y() < -0.1 * es0);
        QVERIFY(emotionPose(f, Emotion::Surprise, 1).offset[pt::idx("8.2")].y() > 0.1 * es0);
        QVERIFY(emotionPose(f, Emotion::Angry, 1).offset[pt::idx("4.1")].y() > 0.05 * es0);
        QVERIFY(!emotionFromName(QStringLiteral("bored")));
    }

    void posesComposeAndInterpolate()
    {
        Pose a;
        a.offset[3] = {2, 4};
        a.leftEyeOpen = 0.5;
        a.head.rotationDeg = 10;
        Pose b;
        b.offset[3] = {4, -4};
        b.leftEyeOpen = 0.5;
        b.head.translation = {6, 0};
        const Pose sum = a + b;
        QCOMPARE(sum.offset[3], QPointF(6, 0));
        QCOMPARE(sum.leftEyeOpen, 0.25);
        QCOMPARE(sum.head.rotationDeg, 10.0);
        QCOMPARE(sum.head.translation, QPointF(6, 0));
        const Pose mid = Pose::lerp(a, b, 0.25);
        QCOMPARE(mid.offset[3], QPointF(2.5, 2));
        QCOMPARE(mid.head.rotationDeg, 7.5);
        QCOMPARE(Pose::lerp(a, b, 0), a);
        QCOMPARE(Pose::lerp(a, b, 1), b);
    }

    void mergeDetectionKeepsHandPlacedPoints()
    {
        FaceModel mine = testFace();
        mine.setPoint(pt::idx("8.4"), {1, 2}, true);
        const FaceModel detected = averageFace(QRectF(110, 160, 200, 240), QSize(400, 500));
        FaceModel kept = mine;
        kept.mergeDetection(detected, true);
        QCOMPARE(kept.point("8.4"), QPointF(1, 2));
        QVERIFY(kept.isHandPlaced(pt::idx("8.4")));
        QCOMPARE(kept.point("8.3"), detected.point("8.3"));
        FaceModel replaced = mine;
        replaced.mergeDetection(detected, false);
        QCOMPARE(replaced.points(), detected.points());
        QCOMPARE(replaced.handPlacedCount(), 0);
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestFaceModel)
#include "tst_facemodel.moc"
