// The classic pipeline's feature edges and cuts (core/detect/classicfeatures.cpp) and its cheek
// boundaries (core/detect/classicpoints.cpp).

#include "detect/classic.h"
#include "testmain.h"

#include <QLineF>
#include <QRandomGenerator>
#include <QTest>

#include <cmath>
#include <functional>

using namespace toonface;

class TestClassicFeatures : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void sobel();
    void featureEdgeParts_data();
    void featureEdgeParts();
    void featureEdgeMirror();
    void edgeThresholdsFromSeed();
    void verticalCut_data();
    void verticalCut();
    void cheeks_data();
    void cheeks();
};

// Eq. (3.13) on a vertical step from 10 to 110: 4 x 100 on both sides of the step, 0 elsewhere.
void TestClassicFeatures::sobel()
{
    Plane I {QSize(10, 6), std::vector<float>(60, 10.0f)};
    for (int y = 0; y < 6; ++y)
        for (int x = 5; x < 10; ++x)
            I.at(x, y) = 110.0f;
    const Plane s = sobelEdges(I);
    for (int y = 1; y < 5; ++y) {
        QCOMPARE(s.at(4, y), 400.0f);
        QCOMPARE(s.at(5, y), 400.0f);
        QCOMPARE(s.at(3, y), 0.0f);
        QCOMPARE(s.at(6, y), 0.0f);
    }
    QCOMPARE(s.at(4, 0), 0.0f); // the frame
}

// An intensity that changes down the rows only, by D(y) = |I(y + 1) - I(y - 1)| chosen per row:
// eq. (3.13) gives every pixel of row y the strength 4 D(y). Each part of the square holds rows
// of two strengths, 4 a (three rows in four) and 4 b (every fourth), so Tsai's two levels are
// exactly those with p0 the share of 4 a: the threshold is 4 a and the edges are the b rows.
namespace {

struct RowProfile
{
    QImage image; // 8-bit grey levels, the same in every column
    std::vector<int> strength; // 4 D(y) per row
};

RowProfile rowProfile(QSize size, const std::function<int(int)> &D)
{
    std::vector<int> level(size_t(size.height()), 128);
    for (int y = 1; y + 1 < size.height(); ++y) {
        const int step = D(y);
        level[size_t(y + 1)]
            = level[size_t(y - 1)] + step <= 235 ? level[size_t(y - 1)] + step : level[size_t(y - 1)] - step;
    }
    RowProfile out;
    out.image = QImage(size, QImage::Format_RGB32);
    out.strength.assign(size_t(size.height()), 0);
    for (int y = 0; y < size.height(); ++y) {
        auto *row = reinterpret_cast<QRgb *>(out.image.scanLine(y));
        for (int x = 0; x < size.width(); ++x)
            row[x] = qRgb(level[size_t(y)], level[size_t(y)], level[size_t(y)]);
        if (y > 0 && y + 1 < size.height())
            out.strength[size_t(y)] = 4 * std::abs(level[size_t(y + 1)] - level[size_t(y - 1)]);
    }
    return out;
}

} // namespace

void TestClassicFeatures::featureEdgeParts_data()
{
    QTest::addColumn<QPointF>("left");
    QTest::addColumn<QPointF>("right");
    QTest::addColumn<QList<double>>("divisions"); // Div_EE, Div_EN, Div_NM
    QTest::addColumn<QList<int>>("a"); // the common step of each part
    QTest::addColumn<QList<int>>("b"); // the step of every fourth row
    QTest::newRow("thesis lines") << QPointF(50, 60) << QPointF(110, 60) << QList<double> {45, 80, 120}
                                  << QList<int> {2, 3, 5, 7} << QList<int> {20, 12, 30, 25};
    QTest::newRow("fractional lines") << QPointF(60, 70.5) << QPointF(100, 70.5) << QList<double> {62.4, 83.8, 101.2}
                                      << QList<int> {6, 1, 4, 2} << QList<int> {9, 15, 40, 11};
}

void TestClassicFeatures::featureEdgeParts()
{
    QFETCH(QPointF, left);
    QFETCH(QPointF, right);
    QFETCH(QList<double>, divisions);
    QFETCH(QList<int>, a);
    QFETCH(QList<int>, b);
    const double d = QLineF(left, right).length();
    const QPointF mid = (left + right) / 2;
    const int top = int(std::ceil(mid.y() - d / 2));
    const double cuts[5] = {double(top), divisions[0], divisions[1], divisions[2], 1e9};
    auto partOf = [&](int y) {
        int part = 0;
        while (part < 3 && y >= int(std::ceil(cuts[part + 1])))
            ++part;
        return part;
    };
    auto firstRow = [&](int part) { return std::max(top, int(std::ceil(cuts[part]))); };
    const RowProfile profile = rowProfile(QSize(180, 180), [&](int y) {
        const int part = partOf(y);
        return (y - firstRow(part)) % 4 == 1 ? b[part] : a[part];
    });
    const FeatureEdges e
        = featureEdges(intensityPlane(profile.image), left, right, divisions[0], divisions[1], divisions[2]);
    QCOMPARE(e.square, QRectF(mid.x() - d, mid.y() - d / 2, 2 * d, 2 * d).toAlignedRect());
    for (int part = 0; part < 4; ++part)
        QCOMPARE(e.thresholds[size_t(part)], 4.0 * a[part]);
    for (int y = e.square.top(); y <= e.square.bottom(); ++y) {
        const bool strong = profile.strength[size_t(y)] == 4 * b[partOf(y)];
        for (int x : {e.square.left(), int(mid.x()), e.square.right()})
            QVERIFY2(e.edges.at(x, y) == strong, qPrintable(QStringLiteral("row %1").arg(y)));
    }
    QCOMPARE(e.edges.at(e.square.left() - 1, e.square.top() + 2), 0); // nothing outside the square
}

// A feature on one side counts on both: a vertical step left of the midline only is an edge at
// its mirror too; the other columns hold none.
void TestClassicFeatures::featureEdgeMirror()
{
    Plane I {QSize(160, 160), std::vector<float>(160 * 160, 100.0f)};
    for (int y = 0; y < 160; ++y)
        for (int x = 0; x < 40; ++x)
            I.at(x, y) = 160.0f;
    // Only the columns 2 .. 39 are lighter, so the right side has no step of its own.
    for (int y = 0; y < 160; ++y)
        for (int x = 0; x < 2; ++x)
            I.at(x, y) = 100.0f;
    const FeatureEdges e = featureEdges(I, QPointF(50, 60), QPointF(110, 60), 45, 80, 120);
    const int y = 100;
    QCOMPARE(e.edges.at(39, y), 1);
    QCOMPARE(e.edges.at(40, y), 1);
    QCOMPARE(e.edges.at(120, y), 1); // the mirror of 40
    QCOMPARE(e.edges.at(121, y), 1); // the mirror of 39
    for (int x : {30, 60, 80, 100, 130})
        QCOMPARE(e.edges.at(x, y), 0);
}

// The landmark method's seed: the same square and parts, measured on a crop around the face
// (the classic method's pixels when the photo needs no scaling), into the seed.
void TestClassicFeatures::edgeThresholdsFromSeed()
{
    const RowProfile profile = rowProfile(QSize(300, 260), [](int y) { return y % 5 == 0 ? 9 + y % 7 : 1 + y % 3; });
    TrackingSeed seed;
    seed.eyeballs[0] = QPointF(130, 120);
    seed.eyeballs[1] = QPointF(190, 124);
    seed.eyeMid = (seed.eyeballs[0] + seed.eyeballs[1]) / 2;
    seed.d = QLineF(seed.eyeballs[0], seed.eyeballs[1]).length();
    seed.divEE = 105;
    seed.divEN = seed.eyeMid.y() + seed.d / 3;
    seed.divNM = seed.eyeMid.y() + seed.d;
    measureEdgeThresholds(profile.image, &seed);
    const FeatureEdges whole = featureEdges(
        intensityPlane(profile.image), seed.eyeballs[0], seed.eyeballs[1], seed.divEE, seed.divEN, seed.divNM);
    QVERIFY(seed.edgeThresholds == whole.thresholds);
    for (double t : seed.edgeThresholds)
        QCOMPARE_GT(t, 0.0);

    TrackingSeed none;
    measureEdgeThresholds(profile.image, &none); // no geometry: nothing measured
    QVERIFY(none.edgeThresholds == (std::array<double, 4> {}));
}

void TestClassicFeatures::verticalCut_data()
{
    QTest::addColumn<int>("axis");
    QTest::addColumn<QRect>("region");
    QTest::newRow("centred") << 100 << QRect(70, 20, 61, 30);
    QTest::newRow("axis left of centre") << 95 << QRect(70, 20, 61, 30);
    QTest::newRow("axis right of centre") << 108 << QRect(70, 20, 61, 30);
}

// Random texture mirrored about x = axis: the cut finds the axis exactly.
void TestClassicFeatures::verticalCut()
{
    QFETCH(int, axis);
    QFETCH(QRect, region);
    QRandomGenerator rng(7);
    Plane I {QSize(200, 80), std::vector<float>(200 * 80)};
    for (int y = 0; y < 80; ++y) {
        for (int x = axis; x < 200; ++x) {
            const float v = float(rng.bounded(256));
            I.at(x, y) = v;
            if (2 * axis - x >= 0)
                I.at(2 * axis - x, y) = v;
        }
    }
    QCOMPARE(centralVerticalCut(I, region), axis);
}

void TestClassicFeatures::cheeks_data()
{
    QTest::addColumn<int>("halfWidth"); // the face column's half width
    QTest::addColumn<int>("earWidth"); // 0: no ears
    QTest::addColumn<int>("shift"); // the face's midline off the given one (mirror symmetry still used)
    QTest::newRow("no ears") << 100 << 0 << 0;
    QTest::newRow("ears") << 100 << 20 << 0;
    QTest::newRow("narrow face, ears") << 70 << 15 << 0;
}

// A face rectangle 300 rows high with ear tabs 50 rows high at eye level: the cheeks are the
// face's sides, not the ears' outer edges.
void TestClassicFeatures::cheeks()
{
    QFETCH(int, halfWidth);
    QFETCH(int, earWidth);
    QFETCH(int, shift);
    Mask m {QSize(400, 400), std::vector<std::uint8_t>(size_t(400) * 400, 0)};
    const int cx = 200 + shift;
    for (int y = 50; y < 350; ++y)
        for (int x = cx - halfWidth; x < cx + halfWidth; ++x)
            m.at(x, y) = 1;
    for (int y = 120; y < 170; ++y)
        for (int k = 0; k < earWidth; ++k) {
            m.at(cx - halfWidth - 1 - k, y) = 1;
            m.at(cx + halfWidth + k, y) = 1;
        }
    double left = 0, right = 0;
    cheekOffset(m, QPointF(200, 130), 90, &left, &right);
    QVERIFY2(std::abs(left - (cx - halfWidth)) <= 2, qPrintable(QString::number(left)));
    QVERIFY2(std::abs(right - (cx + halfWidth)) <= 2, qPrintable(QString::number(right)));
}

TOONFACE_TEST_MAIN(TestClassicFeatures)
#include "tst_classicfeatures.moc"
