#include "detect/landmarkmap.h"
#include "syntheticlandmarks.h"
#include "testmain.h"

#include <QFile>
#include <QLineF>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace toonface;
using toonface::testing::syntheticLandmarks;

Q_DECLARE_METATYPE(QTransform)

namespace {

// The correspondence table of shared/data/README.md, restated here as the specification.
struct Row
{
    const char *id;
    std::vector<int> ibug;
};
const std::vector<Row> kTable = {
    {"3.12", {36}},
    {"3.7", {45}},
    {"3.8", {39}},
    {"3.11", {42}},
    {"3.2", {37, 38}},
    {"3.1", {43, 44}},
    {"3.4", {40, 41}},
    {"3.3", {46, 47}},
    {"3.6", {36, 37, 38, 39, 40, 41}},
    {"3.5", {42, 43, 44, 45, 46, 47}},
    {"4.6", {17}},
    {"4.5", {26}},
    {"4.2", {21}},
    {"4.1", {22}},
    {"9.4", {31}},
    {"9.5", {35}},
    {"9.15", {33}},
    {"2.1", {8}},
    {"8.4", {48}},
    {"8.3", {54}},
    {"8.9", {50}},
    {"8.10", {52}},
    {"8.1", {51}},
    {"8.2", {57}},
    {"2.2", {62}},
    {"2.3", {66}},
};

} // namespace

class TestLandmarkMap : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void correspondences_data();
    void correspondences();
    void derivedOrder_data();
    void derivedOrder();
    void estimatedHairGoesOnBeyondTheEdge();
    void nmeOfExactMappingIsZero();
    void nmeScalesWithError();
    void earFromProfile();
    void pointsKeptInPhoto();
    void ptsFiles();
};

static void addPlacements()
{
    QTest::addColumn<QTransform>("placement");
    QTest::newRow("upright 300px") << QTransform().translate(150, 200).scale(300, 300);
    QTest::newRow("small 40px") << QTransform().translate(500, 400).scale(40, 40);
    QTest::newRow("tilted 15deg") << QTransform().translate(300, 250).rotate(15).scale(250, 250);
    QTest::newRow("tilted -25deg") << QTransform().translate(300, 300).rotate(-25).scale(250, 250);
    QTest::newRow("narrow face") << QTransform().translate(300, 200).scale(200, 300);
}

void TestLandmarkMap::correspondences_data()
{
    addPlacements();
}

void TestLandmarkMap::correspondences()
{
    QFETCH(QTransform, placement);
    const auto ibug = syntheticLandmarks(placement);
    const FaceModel face = faceFromLandmarks68(ibug, QSize(1200, 1200));
    for (const Row &r : kTable) {
        QPointF expected;
        for (int i : r.ibug)
            expected += ibug[i];
        expected /= double(r.ibug.size());
        const QPointF got = face.point(r.id);
        QVERIFY2(QLineF(got, expected).length() < 1e-9, r.id);
    }
}

void TestLandmarkMap::derivedOrder_data()
{
    addPlacements();
}

// Derived points checked in the synthetic face's own upright unit box (the inverse of the
// placement), where "left", "above" and "outside" are plain coordinate comparisons.
void TestLandmarkMap::derivedOrder()
{
    QFETCH(QTransform, placement);
    const auto ibug = syntheticLandmarks(placement);
    const FaceModel face = faceFromLandmarks68(ibug, QSize(2000, 2000));
    QVERIFY(face.isValid());
    const QTransform back = placement.inverted();
    auto P = [&](const char *id) { return back.map(face.point(id)); };
    auto X = [&](const char *id) { return P(id).x(); };
    auto Y = [&](const char *id) { return P(id).y(); };
    for (int i = 0; i < kPointCount; ++i) {
        const QPointF q = face.point(i);
        QVERIFY2(std::isfinite(q.x()) && std::isfinite(q.y()), qPrintable(pointId(i)));
    }

    // Brows: ordered along the brow, all above the eyes.
    const char *brows[] = {"4.6", "4.4a", "4.4", "4.2", "4.1", "4.3", "4.3a", "4.5"};
    for (int i = 0; i + 1 < 8; ++i)
        QVERIFY2(X(brows[i]) < X(brows[i + 1]), brows[i]);
    for (const char *b : brows)
        QVERIFY2(Y(b) < Y("3.2") && Y(b) < Y("3.1"), b);

    // Nose: bridge points between the inner eye corners at eyeball height; sides top-down.
    const double eyeMidY = (Y("3.6") + Y("3.5")) / 2;
    QVERIFY(X("3.8") < X("9.6") && X("9.6") < X("9.7") && X("9.7") < X("3.11"));
    QCOMPARE_LE(std::abs(Y("9.6") - eyeMidY), 1e-9);
    QCOMPARE_LE(std::abs(Y("9.7") - eyeMidY), 1e-9);
    QVERIFY(Y("9.6") < Y("9.14") && Y("9.14") < Y("9.2") && Y("9.2") < Y("9.4"));
    QVERIFY(Y("9.7") < Y("9.13") && Y("9.13") < Y("9.1") && Y("9.1") < Y("9.5"));
    QVERIFY(X("9.2") < X("9.4") && X("9.14") < X("9.13") && X("9.5") < X("9.1"));

    // Contour: cheeks at eye level outside the eyes; jaw at mouth level outside the mouth;
    // lower jaw between the jaw and the chin.
    QCOMPARE_LE(std::abs(Y("5.2") - eyeMidY), 0.01);
    QCOMPARE_LE(std::abs(Y("5.1") - eyeMidY), 0.01);
    QVERIFY(X("5.2") < X("3.12") && X("5.1") > X("3.7"));
    QCOMPARE_LE(std::abs(Y("2.14") - (Y("8.4") + Y("8.3")) / 2), 0.01);
    QVERIFY(X("2.14") < X("8.4") && X("2.13") > X("8.3"));
    QVERIFY(X("2.14") < X("2.12") && X("2.12") < X("2.1") && Y("2.14") < Y("2.12") && Y("2.12") < Y("2.1"));
    QVERIFY(X("2.1") < X("2.11") && X("2.11") < X("2.13") && Y("2.13") < Y("2.11") && Y("2.11") < Y("2.1"));

    // Forehead above the brows; temples between the cheeks and the midline.
    const double browTop = std::min(Y("4.4"), Y("4.3"));
    QVERIFY(Y("11.1") < browTop && Y("11.2") < browTop && Y("11.3") < browTop);
    QVERIFY(Y("11.1") < Y("11.2") && Y("11.1") < Y("11.3"));
    QVERIFY(X("5.2") < X("11.2") && X("11.2") < X("11.1") && X("11.1") < X("11.3") && X("11.3") < X("5.1"));

    // Ears outside the cheeks, top above the lobe.
    QVERIFY(X("10.4") < X("5.2") && X("10.3") > X("5.1"));
    QVERIFY(X("10.4") < X("10.10") && X("10.3") > X("10.9"));
    QVERIFY(Y("10.2") < Y("10.4") && Y("10.4") < Y("10.6") && Y("10.10") < Y("10.6"));
    QVERIFY(Y("10.1") < Y("10.3") && Y("10.3") < Y("10.5") && Y("10.9") < Y("10.5"));

    // Hair: rising from the image-left end to h.10 above the forehead, falling to h.19;
    // the arc's ends lie outside the cheeks.
    for (int i = 0; i < 9; ++i) {
        QVERIFY2(P(pointId(i).toLatin1().constData()).y() > P(pointId(i + 1).toLatin1().constData()).y(),
            qPrintable(pointId(i)));
        QVERIFY2(P(pointId(18 - i).toLatin1().constData()).y() > P(pointId(17 - i).toLatin1().constData()).y(),
            qPrintable(pointId(18 - i)));
    }
    QVERIFY(Y("h.10") < Y("11.1"));
    QVERIFY(X("h.1") < X("5.2") && X("h.19") > X("5.1"));
    QCOMPARE_LE(std::abs(X("h.10") - (X("5.2") + X("5.1")) / 2), 0.01);
}

void TestLandmarkMap::estimatedHairGoesOnBeyondTheEdge()
{
    // A face whose brows are 20 px from the top: the hair estimate reaches above the image, where
    // the head goes on (kept on the edge, it would be drawn flat-topped); it is the estimate of
    // the same face in a photo that shows the whole head. Ears are kept in the photo.
    const auto ibug = syntheticLandmarks(QTransform().translate(100, -40).scale(300, 300));
    const QSize size(500, 400);
    const FaceModel face = faceFromLandmarks68(ibug, size);
    const FaceModel whole = faceFromLandmarks68(ibug, QSize());
    for (int i = 0; i < kPointCount; ++i) {
        const PointGroup g = pointTable()[i].group;
        const QPointF q = face.point(i);
        if (g == PointGroup::Ears)
            QVERIFY2(q.x() >= 0 && q.y() >= 0 && q.x() <= size.width() - 1 && q.y() <= size.height() - 1,
                qPrintable(pointId(i)));
        else if (g == PointGroup::Hair || pointId(i).startsWith(QLatin1String("11.")))
            QCOMPARE(q, whole.point(i));
    }
    QVERIFY(face.point("h.10").y() < -10);
    // Measured points are not clamped: the chin stays where the landmarks put it.
    QCOMPARE(face.point("2.1"), ibug[8]);
}

void TestLandmarkMap::nmeOfExactMappingIsZero()
{
    const auto ibug = syntheticLandmarks(QTransform().translate(100, 100).rotate(10).scale(200, 200));
    QCOMPARE_LE(normalizedMeanError(faceFromLandmarks68(ibug, QSize(800, 800)), ibug), 1e-12);
}

void TestLandmarkMap::nmeScalesWithError()
{
    // Shifting every scored point by 5% of the outer-eye-corner distance gives NME 0.05.
    const auto ibug = syntheticLandmarks(QTransform().translate(100, 100).scale(200, 200));
    FaceModel face = faceFromLandmarks68(ibug, QSize(800, 800));
    const double iod = QLineF(ibug[36], ibug[45]).length();
    for (int i = 0; i < kPointCount; ++i)
        face.setPoint(i, face.point(i) + QPointF(0, 0.05 * iod));
    QCOMPARE_LE(std::abs(normalizedMeanError(face, ibug) - 0.05), 1e-9);
    QPointF ref;
    QVERIFY(scoredReference(pt::idx("3.6"), ibug, &ref));
    QVERIFY(!scoredReference(pt::idx("h.10"), ibug, &ref));
}

TOONFACE_TEST_GUILESS_MAIN(TestLandmarkMap)
// The ear is the longest run of plausible widths; its points land on the run's top, widest
// row and bottom; a run too short, or widths out of range, place nothing.
void TestLandmarkMap::earFromProfile()
{
    std::vector<double> ys, widths;
    for (int i = 0; i < 20; ++i) {
        ys.push_back(100 + 2.0 * i);
        // Rows 3-4: a short plausible run; rows 8-15: the ear, widest (9) at row 11.
        widths.push_back(i == 3 || i == 4 ? 5.0 : i >= 8 && i <= 15 ? 9.0 - std::abs(i - 11) * 0.5 : 0.0);
    }
    const EarProfileLimits limits {4.0, 12.0, 10.0, 30.0};
    auto at = [](double y, double out) { return QPointF(50 - out, y); }; // contour at x = 50, ear to the left
    FaceModel face;
    QVERIFY(placeEarFromProfile(&face, true, ys, widths, 2.0, limits, at));
    QCOMPARE(face.point("10.2"), QPointF(50 - 0.3 * widths[8], ys[8]));
    QCOMPARE(face.point("10.4"), QPointF(41, ys[11]));
    QCOMPARE(face.point("10.6"), QPointF(50 - 0.5 * widths[15], ys[15]));
    QCOMPARE(face.point("10.10"), QPointF(50, ys[15] - 0.12 * (ys[15] - ys[8])));
    QCOMPARE(face.point("10.1"), QPointF()); // the other side untouched

    FaceModel none;
    QVERIFY(!placeEarFromProfile(&none, false, ys, widths, 2.0, {4.0, 12.0, 20.0, 30.0}, at)); // 16 px < 20
    QVERIFY(!placeEarFromProfile(&none, false, ys, widths, 2.0, {10.0, 12.0, 1.0, 30.0}, at)); // all too narrow
    QCOMPARE(none.point("10.4"), QPointF());
}

void TestLandmarkMap::pointsKeptInPhoto()
{
    FaceModel face;
    face.setPoint(0, QPointF(-5, 40));
    face.setPoint(1, QPointF(120, 130));
    face.setPoint(2, QPointF(300, -1));
    keepInPhoto(&face, QSize(100, 200), [](int i) { return i != 2; });
    QCOMPARE(face.point(0), QPointF(0, 40));
    QCOMPARE(face.point(1), QPointF(99, 130));
    QCOMPARE(face.point(2), QPointF(300, -1)); // not selected
}

// 300-W .pts files: 1-based pixels become 0-based; a malformed file is an error naming it.
void TestLandmarkMap::ptsFiles()
{
    QTemporaryDir dir;
    auto write = [&](const QString &name, const QByteArray &body) {
        QFile f(dir.filePath(name));
        if (f.open(QIODevice::WriteOnly))
            f.write(body);
        return f.fileName();
    };
    QByteArray good = "version: 1\nn_points: 68\n{\n";
    for (int i = 0; i < kIbugPointCount; ++i)
        good += QByteArray::number(10 + i) + ' ' + QByteArray::number(20.5 + 2 * i) + '\n';
    good += "}\n";
    std::array<QPointF, kIbugPointCount> pts {};
    QString error;
    QVERIFY2(readIbugPts(write(QStringLiteral("good.pts"), good), &pts, &error), qPrintable(error));
    QCOMPARE(pts[0], QPointF(9, 19.5));
    QCOMPARE(pts[67], QPointF(76, 153.5));

    const QString shortFile = write(QStringLiteral("short.pts"), "version: 1\n{\n1 2\n3 4\n}\n");
    QVERIFY(!readIbugPts(shortFile, &pts, &error));
    QVERIFY(error.startsWith(shortFile));
    QVERIFY(error.contains(QStringLiteral("4 numbers")));
    QByteArray word = good;
    word.replace("10 20.5", "ten 20.5");
    QVERIFY(!readIbugPts(write(QStringLiteral("word.pts"), word), &pts, &error));
    QVERIFY(error.contains(QStringLiteral("point 1")));
    QVERIFY(!readIbugPts(dir.filePath(QStringLiteral("missing.pts")), &pts, &error));
    QVERIFY(error.contains(QStringLiteral("missing.pts")));
}

#include "tst_landmarkmap.moc"
