#include "detect/classic.h"
#include "detect/detector.h"
#include "detect/landmarkmap.h"
#include "shareddata.h"

#include "testphotos.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QPainter>
#include <QRandomGenerator>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <functional>
#include <numbers>

using namespace toonface;

namespace {

// A drawn frontal face on a plain blue background: eyeball centres at (cx -+ 45, 230),
// so d = 90.
struct DrawnFace
{
    QImage image;
    QPointF eyeL {195, 230}, eyeR {285, 230};
    double irisR = 7;
    QRectF browL {172, 196, 46, 8}, browR {262, 196, 46, 8};
    QRectF mouth {205, 338, 70, 14};
    QPointF nostrilL {229, 300}, nostrilR {251, 300};
    QRectF head {130, 110, 220, 300}; // the skin ellipse
    QRectF hair {118, 80, 244, 200}; // the hair ellipse, behind the skin
};

// lightIrises: grey-blue irises with a small pupil, outlined by lash lines that thicken toward
// the outer corners (mascara), as in many photos: the dark points of an eye hold no iris disc.
DrawnFace drawFace(bool lightIrises = false)
{
    DrawnFace f;
    f.image = QImage(480, 480, QImage::Format_RGB32);
    f.image.fill(QColor(150, 180, 230));
    QPainter p(&f.image);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(60, 35, 20));
    p.drawEllipse(f.hair);
    const QColor skin(225, 180, 150);
    p.setBrush(skin);
    p.drawEllipse(QRectF(116, 215, 24, 50)); // ears
    p.drawEllipse(QRectF(340, 215, 24, 50));
    p.drawEllipse(f.head);
    p.setBrush(QColor(245, 245, 240));
    p.setPen(QPen(QColor(60, 40, 30), 2)); // the lash line
    p.drawEllipse(f.eyeL, 19, 8); // eye whites
    p.drawEllipse(f.eyeR, 19, 8);
    p.setPen(Qt::NoPen);
    p.setBrush(lightIrises ? QColor(150, 170, 185) : QColor(30, 20, 15));
    p.drawEllipse(f.eyeL, f.irisR, f.irisR);
    p.drawEllipse(f.eyeR, f.irisR, f.irisR);
    if (lightIrises) {
        p.setBrush(QColor(30, 20, 15));
        p.drawEllipse(f.eyeL, 2.0, 2.0);
        p.drawEllipse(f.eyeR, 2.0, 2.0);
        // The thick outer lash corners: wedges along the upper lids' outer ends.
        for (int side : {-1, 1}) {
            const QPointF e = side < 0 ? f.eyeL : f.eyeR;
            const QPointF tip = e + QPointF(side * 22, -1);
            const QPointF polygon[3] = {tip, e + QPointF(side * 8, -8.5), e + QPointF(side * 12, -4)};
            p.drawPolygon(polygon, 3);
            p.drawEllipse(e + QPointF(side * 16, -4), 4.5, 4.5);
        }
    }
    p.setBrush(QColor(70, 45, 30));
    p.drawRect(f.browL);
    p.drawRect(f.browR);
    p.setBrush(QColor(90, 50, 45));
    p.drawEllipse(f.nostrilL, 5, 3);
    p.drawEllipse(f.nostrilR, 5, 3);
    p.setBrush(QColor(150, 50, 60));
    p.drawEllipse(f.mouth);
    p.end();
    return f;
}

} // namespace

namespace {

using testing::sharedFacesDir;

} // namespace

Q_DECLARE_METATYPE(std::vector<QRect>)

class TestClassic : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void score_data();
    void score();
    void eyePair_data();
    void eyePair();
    void eyeball_data();
    void eyeball();
    void sobel();
    void featureEdgeParts_data();
    void featureEdgeParts();
    void featureEdgeMirror();
    void edgeThresholdsFromSeed();
    void verticalCut_data();
    void verticalCut();
    void cheeks_data();
    void cheeks();
    void ringShaped_data();
    void ringShaped();
    void darkness_data();
    void darkness();
    void pairInFace_data();
    void pairInFace();
    void mouthRow_data();
    void mouthRow();
    void drawnFace();
    void lightIrises();
    void graceHopper();
    void realPortraits_data();
    void realPortraits();
    void greyAndTiny();
    void throughDetector();
    void noFaceAroundPair();
    void sharedDataNme_data();
    void sharedDataNme();
    void sharedDataNmeWithFaceBox_data();
    void sharedDataNmeWithFaceBox();
};

void TestClassic::score_data()
{
    QTest::addColumn<double>("a1");
    QTest::addColumn<double>("a2");
    QTest::newRow("equal, full") << 1.0 << 1.0;
    QTest::newRow("equal, small") << 0.2 << 0.2;
    QTest::newRow("unequal") << 1.0 << 0.5;
    QTest::newRow("swapped") << 0.5 << 1.0;
}

void TestClassic::score()
{
    QFETCH(double, a1);
    QFETCH(double, a2);
    const double big = std::max(a1, a2), small = std::min(a1, a2);
    const double s = big / small;
    QVERIFY(std::abs(eyePairScore(a1, a2) - (big * small - s * s) / 2) < 1e-12);
}

void TestClassic::eyePair_data()
{
    QTest::addColumn<std::vector<QRect>>("distractors");
    QTest::addColumn<bool>("mayPair"); // whether the distractors may form candidate pairs
    QTest::newRow("alone") << std::vector<QRect> {} << false;
    // A pair tilted by about 14 degrees, a pair of very unequal blobs, a long bar: never pairs.
    QTest::newRow("tilted pair") << std::vector<QRect> {QRect(40, 300, 16, 12), QRect(120, 320, 16, 12)} << false;
    QTest::newRow("unequal pair") << std::vector<QRect> {QRect(40, 300, 30, 24), QRect(120, 300, 8, 6)} << false;
    QTest::newRow("bar") << std::vector<QRect> {QRect(140, 400, 200, 10)} << false;
    // Nostrils and brows pair, but score below the eyes (nostrils) or give way to them in the
    // pipeline (brows, see drawnFace).
    QTest::newRow("nostrils") << std::vector<QRect> {QRect(230, 280, 8, 5), QRect(250, 280, 8, 5)} << true;
    QTest::newRow("brows") << std::vector<QRect> {QRect(170, 190, 46, 9), QRect(264, 190, 46, 9)} << true;
}

// Dark eye blobs at (180..209, 224..235) and (270..299, 224..235) among distractors: the best
// candidate below the brow line is the eye pair.
void TestClassic::eyePair()
{
    QFETCH(std::vector<QRect>, distractors);
    QFETCH(bool, mayPair);
    QImage img(480, 480, QImage::Format_Grayscale8);
    img.fill(220);
    QPainter p(&img);
    p.fillRect(QRect(180, 224, 30, 12), Qt::black);
    p.fillRect(QRect(270, 224, 30, 12), Qt::black);
    for (const QRect &r : distractors)
        p.fillRect(r, Qt::black);
    p.end();
    Mask m {img.size(), std::vector<std::uint8_t>(size_t(480) * 480)};
    for (int y = 0; y < 480; ++y)
        for (int x = 0; x < 480; ++x)
            m.at(x, y) = qGray(img.pixel(x, y)) > 100;
    const auto dark = growRegions(m, 0);
    const auto pairs = eyePairCandidates(dark, img.size());
    int best = -1;
    for (int i = 0; i < int(pairs.size()) && best < 0; ++i)
        if (dark[pairs[i].left].box.top() > 200)
            best = i;
    QVERIFY(best >= 0);
    QCOMPARE(dark[pairs[best].left].box, QRect(180, 224, 30, 12));
    QCOMPARE(dark[pairs[best].right].box, QRect(270, 224, 30, 12));
    for (const auto &c : pairs) {
        const QPointF delta = dark[c.right].centroid - dark[c.left].centroid;
        QVERIFY(delta.x() > 0);
        QVERIFY(std::abs(delta.y()) <= std::tan(10.0 * std::numbers::pi / 180.0) * delta.x() + 1e-9);
        if (!mayPair) {
            QCOMPARE(dark[c.left].box.top(), 224);
            QCOMPARE(dark[c.right].box.top(), 224);
        }
    }
    for (size_t i = 1; i < pairs.size(); ++i)
        QVERIFY(pairs[i - 1].score >= pairs[i].score);
}

void TestClassic::eyeball_data()
{
    QTest::addColumn<QPointF>("centre");
    QTest::addColumn<double>("radius");
    QTest::newRow("centred") << QPointF(50, 30) << 8.0;
    QTest::newRow("looking left") << QPointF(40, 30) << 8.0;
    QTest::newRow("large") << QPointF(55, 31) << 11.0;
}

// A dark almond (the lash line and corners) with a round iris: the eyeball is the iris.
void TestClassic::eyeball()
{
    QFETCH(QPointF, centre);
    QFETCH(double, radius);
    QImage img(100, 60, QImage::Format_Grayscale8);
    img.fill(255);
    QPainter p(&img);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(QPen(Qt::black, 2));
    p.setBrush(Qt::white);
    p.drawEllipse(QPointF(50, 30), 32, 9);
    p.setPen(Qt::NoPen);
    p.setBrush(Qt::black);
    p.drawEllipse(centre, radius, radius);
    p.end();
    Mask m {img.size(), std::vector<std::uint8_t>(size_t(100) * 60)};
    for (int y = 0; y < 60; ++y)
        for (int x = 0; x < 100; ++x)
            m.at(x, y) = qGray(img.pixel(x, y)) < 128;
    const Eyeball e = detectEyeball(m, QRect(15, 15, 72, 32));
    QVERIFY2(QLineF(e.centre, centre).length() <= 1.5,
        qPrintable(QStringLiteral("%1,%2").arg(e.centre.x()).arg(e.centre.y())));
    QVERIFY2(std::abs(e.radius - radius) <= 1.5, qPrintable(QString::number(e.radius)));
}

// Eq. (3.13) on a vertical step from 10 to 110: 4 x 100 on both sides of the step, 0 elsewhere.
void TestClassic::sobel()
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

void TestClassic::featureEdgeParts_data()
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

void TestClassic::featureEdgeParts()
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
void TestClassic::featureEdgeMirror()
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
void TestClassic::edgeThresholdsFromSeed()
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

void TestClassic::verticalCut_data()
{
    QTest::addColumn<int>("axis");
    QTest::addColumn<QRect>("region");
    QTest::newRow("centred") << 100 << QRect(70, 20, 61, 30);
    QTest::newRow("axis left of centre") << 95 << QRect(70, 20, 61, 30);
    QTest::newRow("axis right of centre") << 108 << QRect(70, 20, 61, 30);
}

// Random texture mirrored about x = axis: the cut finds the axis exactly.
void TestClassic::verticalCut()
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

void TestClassic::cheeks_data()
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
void TestClassic::cheeks()
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

namespace {

// How far p lies off the ellipse's outline, in units of its semi-axes (0 on it).
double offEllipse(QPointF p, const QRectF &e)
{
    const QPointF c = e.center();
    return std::abs(std::hypot((p.x() - c.x()) / (e.width() / 2), (p.y() - c.y()) / (e.height() / 2)) - 1.0);
}

// x of the skin ellipse's edge at height y (left side).
double ellipseLeftX(const QRectF &e, double y)
{
    const double t = (y - e.center().y()) / (e.height() / 2);
    return e.center().x() - e.width() / 2 * std::sqrt(std::max(0.0, 1 - t * t));
}

} // namespace

// Every group of the drawn face within a stated tolerance: inner features within d/10,
// the contour and ears within d/5, the hair above the ears within 6% of the hair ellipse.
namespace {

// A mask of one drawn shape (value 0 = dark, as in B1) on 1, and the dark regions' labels.
struct DrawnMask
{
    Mask mask;
    std::vector<int> labels;
    std::vector<Region> dark;
};

DrawnMask drawnMask(QSize size, const std::function<void(QPainter &)> &draw)
{
    QImage img(size, QImage::Format_Grayscale8);
    img.fill(255);
    QPainter p(&img);
    draw(p);
    p.end();
    DrawnMask out;
    out.mask = {size, std::vector<std::uint8_t>(size_t(size.width()) * size.height())};
    for (int y = 0; y < size.height(); ++y)
        for (int x = 0; x < size.width(); ++x)
            out.mask.at(x, y) = qGray(img.pixel(x, y)) > 128;
    out.dark = growRegions(out.mask, 0, &out.labels);
    return out;
}

} // namespace

void TestClassic::ringShaped_data()
{
    QTest::addColumn<int>("shape");
    QTest::addColumn<bool>("ring");
    QTest::newRow("filled disc") << 0 << false;
    QTest::newRow("thin loop (spectacle rim)") << 1 << true;
    QTest::newRow("disc with a small highlight") << 2 << false;
    QTest::newRow("open arc") << 3 << false;
}

void TestClassic::ringShaped()
{
    QFETCH(int, shape);
    QFETCH(bool, ring);
    const DrawnMask m = drawnMask(QSize(100, 100), [&](QPainter &p) {
        p.setPen(Qt::NoPen);
        p.setBrush(Qt::black);
        if (shape == 0 || shape == 2)
            p.drawEllipse(QPointF(50, 50), 20, 14);
        if (shape == 2) {
            p.setBrush(Qt::white);
            p.drawEllipse(QPointF(46, 46), 3, 3);
        }
        if (shape == 1) {
            p.setPen(QPen(Qt::black, 3));
            p.setBrush(Qt::NoBrush);
            p.drawEllipse(QPointF(50, 50), 30, 20);
        }
        if (shape == 3) {
            p.setPen(QPen(Qt::black, 3));
            p.drawArc(QRectF(20, 30, 60, 40), 0, 180 * 16);
        }
    });
    QCOMPARE(m.dark.size(), size_t(1));
    QCOMPARE(isRingShaped(m.dark.front(), m.labels, QSize(100, 100)), ring);
}

void TestClassic::darkness_data()
{
    QTest::addColumn<int>("surround");
    QTest::addColumn<double>("expected");
    QTest::newRow("dark blob on skin") << 200 << 160.0;
    QTest::newRow("dark blob on dark cloth") << 45 << 5.0;
}

// A blob at level 40 in a field of `surround`: the contrast is the difference of the levels.
void TestClassic::darkness()
{
    QFETCH(int, surround);
    QFETCH(double, expected);
    Plane I {QSize(80, 80), std::vector<float>(80 * 80, float(surround))};
    Mask m {I.size, std::vector<std::uint8_t>(80 * 80, 1)};
    for (int y = 30; y < 42; ++y)
        for (int x = 25; x < 55; ++x) {
            I.at(x, y) = 40;
            m.at(x, y) = 0;
        }
    std::vector<int> labels;
    const auto dark = growRegions(m, 0, &labels);
    QCOMPARE(dark.size(), size_t(1));
    QVERIFY(std::abs(darknessContrast(I, dark.front(), labels) - expected) < 1e-3);
}

void TestClassic::pairInFace_data()
{
    // A face ellipse 220 x 300 centred at (240, 260), eyes at y 230, 90 apart (as drawFace).
    QTest::addColumn<QPointF>("left");
    QTest::addColumn<QPointF>("right");
    QTest::addColumn<bool>("inFace");
    QTest::newRow("eyes") << QPointF(195, 230) << QPointF(285, 230) << true;
    QTest::newRow("eyes, tilted 8 degrees") << QPointF(195, 236) << QPointF(284, 224) << true;
    QTest::newRow("brows") << QPointF(195, 200) << QPointF(285, 200) << true;
    QTest::newRow("mouth corners (only the chin below)") << QPointF(205, 345) << QPointF(275, 345) << false;
    QTest::newRow("nostrils (far inside the face)") << QPointF(229, 300) << QPointF(251, 300) << false;
    QTest::newRow("fringe strands") << QPointF(225, 150) << QPointF(255, 150) << false;
    QTest::newRow("wider than the face") << QPointF(110, 230) << QPointF(370, 230) << false;
    QTest::newRow("outside the face") << QPointF(20, 60) << QPointF(100, 60) << false;
}

void TestClassic::pairInFace()
{
    QFETCH(QPointF, left);
    QFETCH(QPointF, right);
    QFETCH(bool, inFace);
    const DrawnMask face = drawnMask(QSize(480, 480), [](QPainter &p) {
        p.setPen(Qt::NoPen);
        p.setBrush(Qt::black);
        p.drawEllipse(QRectF(130, 110, 220, 300));
    });
    Mask F = face.mask;
    for (auto &v : F.values)
        v = !v; // the ellipse is the face (1)
    PairReach reach;
    QCOMPARE(eyePairInFace(F, left, right, &reach), inFace);
    if (qstrcmp(QTest::currentDataTag(), "eyes") == 0) {
        // 180 px to the chin = 2 d; the ellipse's half width at y 230 is ~107 px = 1.19 d.
        QVERIFY(std::abs(reach.below - 2.0) < 0.05);
        QVERIFY(std::abs(reach.side - 1.19) < 0.05);
    }
}

void TestClassic::mouthRow_data()
{
    QTest::addColumn<int>("mouthY"); // 0: no mouth
    QTest::addColumn<bool>("mouth");
    QTest::newRow("mouth 1.1 d below") << 329 << true;
    QTest::newRow("mouth 0.75 d below") << 298 << true;
    QTest::newRow("no mouth") << 0 << false;
    QTest::newRow("mouth 2 d below (out of the band)") << 410 << false;
}

// Skin at 180 with soft noise-free shading; a lip line at level 90, 60 px wide, 6 px high.
void TestClassic::mouthRow()
{
    QFETCH(int, mouthY);
    QFETCH(bool, mouth);
    Plane I {QSize(480, 480), std::vector<float>(480 * 480)};
    for (int y = 0; y < 480; ++y)
        for (int x = 0; x < 480; ++x)
            I.at(x, y) = 180.0f - 0.05f * std::abs(y - 260);
    if (mouthY > 0)
        for (int y = mouthY - 3; y < mouthY + 3; ++y)
            for (int x = 210; x < 270; ++x)
                I.at(x, y) = 90;
    double row = -1;
    const double c = mouthRowContrast(I, QPointF(195, 230), QPointF(285, 230), &row);
    QCOMPARE(c >= 0.15, mouth);
    if (mouth) // the darkest row is one of the lip line's, given below the pair's centre
        QVERIFY(row >= mouthY - 3 - 230 && row <= mouthY + 2 - 230);
}

void TestClassic::drawnFace()
{
    const DrawnFace f = drawFace();
    const ClassicResult r = detectClassic(f.image, true);
    QVERIFY2(r.ok, qPrintable(r.error));
    const QString dir = qEnvironmentVariable("TOONFACE_CLASSIC_DEBUG");
    if (!dir.isEmpty()) {
        f.image.save(dir + QStringLiteral("/input.png"));
        for (auto it = r.debugImages.begin(); it != r.debugImages.end(); ++it)
            it.value().save(dir + QLatin1Char('/') + it.key() + QStringLiteral(".png"));
    }
    const double d = 90;
    QVERIFY(std::abs(r.d - d) < 2);
    auto near = [&](const char *id, QPointF expected, double tol) {
        const QPointF got = r.face.point(id);
        const double err = QLineF(got, expected).length();
        if (err > tol)
            qWarning("%s at (%.1f, %.1f), expected (%.1f, %.1f) within %.1f", id, got.x(), got.y(), expected.x(),
                expected.y(), tol);
        return err <= tol;
    };
    const double inner = d / 10, outer = d / 5;
    // Eyes
    QVERIFY(near("3.6", f.eyeL, 2));
    QVERIFY(near("3.5", f.eyeR, 2));
    QVERIFY(near("3.2", f.eyeL - QPointF(0, f.irisR), 2.5));
    QVERIFY(near("3.4", f.eyeL + QPointF(0, f.irisR), 2.5));
    QVERIFY(near("3.1", f.eyeR - QPointF(0, f.irisR), 2.5));
    QVERIFY(near("3.12", f.eyeL - QPointF(20, 0), inner));
    QVERIFY(near("3.8", f.eyeL + QPointF(20, 0), inner));
    QVERIFY(near("3.11", f.eyeR - QPointF(20, 0), inner));
    QVERIFY(near("3.7", f.eyeR + QPointF(20, 0), inner));
    // Brows
    const double browY = f.browL.center().y();
    QVERIFY(near("4.6", QPointF(f.browL.left(), browY), inner));
    QVERIFY(near("4.2", QPointF(f.browL.right(), browY), inner));
    QVERIFY(near("4.5", QPointF(f.browR.right(), browY), inner));
    QVERIFY(near("4.1", QPointF(f.browR.left(), browY), inner));
    for (const char *id : {"4.4a", "4.4", "4.3", "4.3a"})
        QVERIFY(near(id, QPointF(r.face.point(id).x(), browY), inner));
    QVERIFY(r.face.point("4.6").x() < r.face.point("4.4a").x() && r.face.point("4.4a").x() < r.face.point("4.4").x()
        && r.face.point("4.4").x() < r.face.point("4.2").x());
    // Nose: the tip on the midline at the nostrils' bottom, the wings at the nostrils' sides.
    QVERIFY(near("9.15", QPointF(240, f.nostrilL.y() + 3), inner));
    QVERIFY(near("9.2", QPointF(f.nostrilL.x() - 5, r.face.point("9.2").y()), inner));
    QVERIFY(near("9.1", QPointF(f.nostrilR.x() + 5, r.face.point("9.1").y()), inner));
    QVERIFY(std::abs(r.noseCut - 240) <= 1.5);
    // Mouth
    const QPointF mc = f.mouth.center();
    QVERIFY(near("8.4", QPointF(f.mouth.left(), mc.y()), inner));
    QVERIFY(near("8.3", QPointF(f.mouth.right(), mc.y()), inner));
    QVERIFY(near("8.1", QPointF(240, f.mouth.top()), inner));
    QVERIFY(near("8.2", QPointF(240, f.mouth.bottom()), inner));
    QVERIFY(near("2.2", mc, inner));
    QVERIFY(std::abs(r.mouthCut - 240) <= 1.5);
    // Contour
    QVERIFY(near("2.1", QPointF(240, f.head.bottom()), inner));
    QVERIFY(near("11.1", QPointF(240, f.head.top()), inner));
    QVERIFY(near("2.14", QPointF(ellipseLeftX(f.head, r.face.point("2.14").y()), r.face.point("2.14").y()), inner));
    QVERIFY(near("5.2", QPointF(ellipseLeftX(f.head, 230), 230), inner));
    QVERIFY(near("5.1", QPointF(480 - ellipseLeftX(f.head, 230), 230), inner));
    QVERIFY(offEllipse(r.face.point("2.12"), f.head) < 0.05);
    QVERIFY(offEllipse(r.face.point("2.11"), f.head) < 0.05);
    // Ears (drawn 116..140 and 340..364 wide, 215..265 high)
    QVERIFY(near("10.4", QPointF(116, r.face.point("10.4").y()), outer));
    QVERIFY(near("10.3", QPointF(364, r.face.point("10.3").y()), outer));
    QVERIFY(near("10.2", QPointF(r.face.point("10.2").x(), 215), outer));
    QVERIFY(near("10.1", QPointF(r.face.point("10.1").x(), 215), outer));
    // Hair: h.10 on the crown; the arc over the head on the hair ellipse.
    QVERIFY(near("h.10", QPointF(240, f.hair.top()), inner));
    for (int i = 3; i <= 15; ++i) {
        const QPointF h = r.face.point(pt::idx("h.1") + i);
        QVERIFY2(offEllipse(h, f.hair) < 0.06, qPrintable(QStringLiteral("h.%1").arg(i + 1)));
    }
    QVERIFY(r.face.isValid());
}

// Light irises: the eye regions are the lash lines, whose thickest part (the outer corner)
// would hold the largest dark circle; the eyeball centre must still be the eye's middle.
void TestClassic::lightIrises()
{
    const DrawnFace f = drawFace(true);
    const ClassicResult r = detectClassic(f.image, true);
    const QString dir = qEnvironmentVariable("TOONFACE_CLASSIC_DEBUG");
    if (!dir.isEmpty())
        for (auto it = r.debugImages.begin(); it != r.debugImages.end(); ++it)
            it.value().save(dir + QStringLiteral("/light-") + it.key() + QStringLiteral(".png"));
    QVERIFY2(r.ok, qPrintable(r.error));
    qInfo("eyeballs (%.1f, %.1f) r %.1f and (%.1f, %.1f) r %.1f", r.eyeballs[0].centre.x(), r.eyeballs[0].centre.y(),
        r.eyeballs[0].radius, r.eyeballs[1].centre.x(), r.eyeballs[1].centre.y(), r.eyeballs[1].radius);
    // Within a third of the iris' width of the drawn centres, horizontally and vertically.
    QVERIFY(QLineF(r.face.point("3.6"), f.eyeL).length() <= 2 * f.irisR / 3 + 1);
    QVERIFY(QLineF(r.face.point("3.5"), f.eyeR).length() <= 2 * f.irisR / 3 + 1);
    QVERIFY(std::abs(r.d - 90) < 6);
}

// The thesis' assumptions (plain background, frontal light) hold only roughly here; the
// test reports what the pipeline finds and checks the groups are ordered like a face.
void TestClassic::graceHopper()
{
    const QString path = QStringLiteral("/usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg");
    QImage img(path);
    if (img.isNull())
        QSKIP("grace_hopper.jpg is not installed (package python-matplotlib-data)");
    const ClassicResult r = detectClassic(img, true);
    const QString dir = qEnvironmentVariable("TOONFACE_CLASSIC_DEBUG");
    if (!dir.isEmpty())
        for (auto it = r.debugImages.begin(); it != r.debugImages.end(); ++it)
            it.value().save(dir + QStringLiteral("/hopper-") + it.key() + QStringLiteral(".png"));
    QVERIFY2(r.ok, qPrintable(r.error));
    qInfo("grace_hopper: %d eye-pair candidates, eyeballs (%.0f, %.0f) r %.1f and (%.0f, %.0f) r %.1f, d = %.1f, "
          "nose tip (%.0f, %.0f), mouth %.0f..%.0f at y %.0f, chin y %.0f, %.1f ms",
        r.candidateCount, r.eyeballs[0].centre.x(), r.eyeballs[0].centre.y(), r.eyeballs[0].radius,
        r.eyeballs[1].centre.x(), r.eyeballs[1].centre.y(), r.eyeballs[1].radius, r.d, r.face.point("9.15").x(),
        r.face.point("9.15").y(), r.face.point("8.4").x(), r.face.point("8.3").x(), r.face.point("8.4").y(),
        r.face.point("2.1").y(), r.timingMs.value(QStringLiteral("total")));
    const FaceModel &f = r.face;
    QVERIFY(f.isValid());
    QVERIFY(f.point("4.4").y() < f.point("3.6").y());
    QVERIFY(f.point("3.6").y() < f.point("9.15").y());
    QVERIFY(f.point("9.15").y() < f.point("8.2").y());
    QVERIFY(f.point("8.2").y() < f.point("2.1").y());
}

// Public-domain portraits that meet the thesis' assumptions (a large frontal face, a plain or
// simple background, frontal light): every group is found and placed like a face. Where the
// landmark model is installed, its result is the reference for where the eyes are.
void TestClassic::realPortraits_data()
{
    QTest::addColumn<QString>("path");
    QTest::addColumn<QString>("package");
    QTest::newRow("grace_hopper") << QStringLiteral("/usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg")
                                  << QStringLiteral("python-matplotlib-data");
    QTest::newRow("astronaut") << QStringLiteral("/usr/lib/python3/dist-packages/skimage/data/astronaut.png")
                               << QStringLiteral("python3-skimage");
}

void TestClassic::realPortraits()
{
    QFETCH(QString, path);
    QFETCH(QString, package);
    const QImage img(path);
    if (img.isNull())
        QSKIP(qPrintable(QStringLiteral("%1 is not installed (package %2)").arg(path, package)));
    const ClassicResult r = detectClassic(img);
    QVERIFY2(r.ok, qPrintable(r.error));
    QVERIFY(r.eyePairInFace); // found by the face check, not the thesis' fallback
    const FaceModel &f = r.face;
    QVERIFY(f.isValid());
    auto mean = [&](std::initializer_list<const char *> ids) {
        QPointF sum;
        for (const char *id : ids)
            sum += f.point(id);
        return sum / double(ids.size());
    };
    const QPointF brows = mean({"4.6", "4.4a", "4.4", "4.2", "4.5", "4.3a", "4.3", "4.1"});
    const QPointF eyes = mean({"3.6", "3.5"});
    const QPointF nose = mean({"9.2", "9.1", "9.15"});
    const QPointF mouth = mean({"8.4", "8.3", "8.1", "8.2"});
    const QPointF chin = f.point("2.1");
    qInfo("%s: d %.1f, k %.1f, rect (%d, %d), brows y %.0f, eyes y %.0f, nose y %.0f, mouth y %.0f, chin y %.0f",
        qPrintable(QFileInfo(path).fileName()), r.d, r.eyeLevelK, r.centralRect.x(), r.centralRect.y(), brows.y(),
        eyes.y(), nose.y(), mouth.y(), chin.y());
    // Top to bottom; image-left before image-right; all on the face's midline within d/2.
    QVERIFY(brows.y() < eyes.y());
    QVERIFY(eyes.y() < nose.y());
    QVERIFY(nose.y() < mouth.y());
    QVERIFY(mouth.y() < chin.y());
    QVERIFY(f.point("3.6").x() < f.point("3.5").x());
    QVERIFY(f.point("4.6").x() < f.point("4.5").x());
    QVERIFY(f.point("8.4").x() < f.point("8.3").x());
    QVERIFY(f.point("9.2").x() < f.point("9.1").x());
    for (const QPointF &p : {brows, nose, mouth, chin})
        QVERIFY(std::abs(p.x() - eyes.x()) < r.d / 2);
    // Proportions of a face: the mouth about d below the eyes (the thesis' Div_NM).
    QVERIFY(mouth.y() - eyes.y() > 0.6 * r.d && mouth.y() - eyes.y() < 1.6 * r.d);

    if (!preloadLandmarkModel())
        return;
    const DetectionResult ref = detectFace(img, {});
    QCOMPARE(ref.status, DetectStatus::Ok);
    const double refD = QLineF(ref.face.point("3.6"), ref.face.point("3.5")).length();
    for (const char *id : {"3.6", "3.5", "9.15", "2.2"})
        QVERIFY2(ref.faceBox.contains(f.point(id).toPoint()), id);
    // Eyeball centres within a fifth of the eye distance of the landmark method's.
    QVERIFY(QLineF(f.point("3.6"), ref.face.point("3.6")).length() < 0.2 * refD);
    QVERIFY(QLineF(f.point("3.5"), ref.face.point("3.5")).length() < 0.2 * refD);
}

// A grey photo has no hue, so no face region from eq. (3.9): the inner features are still
// found and the outline falls back to its rules. A tiny image is refused with a reason.
void TestClassic::greyAndTiny()
{
    const DrawnFace f = drawFace();
    const ClassicResult r = detectClassic(f.image.convertToFormat(QImage::Format_Grayscale8));
    QVERIFY2(r.ok, qPrintable(r.error));
    QVERIFY(r.face.isValid());
    QVERIFY(QLineF(r.face.point("3.6"), f.eyeL).length() <= 2);
    QVERIFY(QLineF(r.face.point("3.5"), f.eyeR).length() <= 2);
    QVERIFY(QLineF(r.face.point("8.4"), QPointF(f.mouth.left(), f.mouth.center().y())).length() <= 9);
    for (int i = 0; i < kPointCount; ++i)
        QVERIFY2(QRectF(0, 0, 480, 480).contains(r.face.point(i)), qPrintable(pointId(i)));

    for (const QSize size : {QSize(1, 1), QSize(15, 200)}) {
        QImage tiny(size, QImage::Format_RGB32);
        tiny.fill(Qt::gray);
        const ClassicResult t = detectClassic(tiny);
        QVERIFY(!t.ok);
        QVERIFY(t.error.contains(QLatin1String("too small")));
    }
}

// detectFace(method classic) gives the pipeline's points and writes the thesis' figures.
void TestClassic::throughDetector()
{
    const DrawnFace f = drawFace();
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    DetectOptions options;
    options.method = DetectionMethod::Classic;
    options.debugDir = dir.filePath(QStringLiteral("debug"));
    const DetectionResult r = detectFace(f.image, options);
    QCOMPARE(r.status, DetectStatus::Ok);
    QCOMPARE(r.method, QStringLiteral("classic"));
    QCOMPARE(r.faceCount, 1);
    QVERIFY(QLineF(r.face.point("3.6"), f.eyeL).length() < 2);
    QVERIFY(r.faceBox.contains(f.mouth.center().toPoint()));
    QVERIFY(r.timingMs.contains(QStringLiteral("total")));
    QCOMPARE(r.groupConfidence.size(), 7);
    for (const char *name : {"classic-b1", "classic-b2", "classic-b3", "classic-face-hair", "classic-eye-pairs",
             "classic-eyeballs", "classic-edges", "classic-feature-regions", "classic-points"}) {
        const QImage img(QDir(options.debugDir).filePath(QLatin1StringView(name) + QStringLiteral(".png")));
        QVERIFY2(img.size() == f.image.size(), name);
    }
}

// Two dark blobs on a plain wall pair as eyes by eq. (3.5), but nothing around them is a face:
// the pipeline keeps the thesis' choice and says it failed the face checks; the detector
// refuses it with those checks named, as the classic method and as auto's last resort.
void TestClassic::noFaceAroundPair()
{
    const QImage wall = testing::darkPairOnAWall();
    const ClassicResult c = detectClassic(wall);
    QVERIFY2(c.ok, qPrintable(c.error));
    QVERIFY(!c.eyePairInFace);
    QVERIFY(QLineF(c.eyeballs[0].centre, QPointF(190, 200)).length() < 3);
    QVERIFY2(c.faceCheck.contains(QLatin1String("(190, 200) and (290, 200)")), qPrintable(c.faceCheck));
    QVERIFY2(c.faceCheck.contains(QLatin1String("no mouth row")), qPrintable(c.faceCheck));

    for (DetectionMethod m : {DetectionMethod::Classic, DetectionMethod::Auto}) {
        DetectOptions options;
        options.method = m;
        const DetectionResult r = detectFace(wall, options);
        QCOMPARE(r.status, DetectStatus::NoFace);
        if (m == DetectionMethod::Classic)
            QCOMPARE(r.error, QStringLiteral("The classic method found no face: %1.").arg(c.faceCheck));
        QVERIFY(!r.face.isValid());
    }

    // The drawn face passes the checks and is a face through the detector.
    const ClassicResult drawn = detectClassic(drawFace().image);
    QVERIFY(drawn.eyePairInFace);
    QVERIFY(drawn.faceCheck.isEmpty());
}

void TestClassic::sharedDataNme_data()
{
    QTest::addColumn<QString>("image");
    QTest::addColumn<QString>("pts");
    QTest::addColumn<double>("bound");
    // Measured bounds (NME 0.101 and 0.087 when set) for the photos that meet the thesis'
    // assumptions: a frontal face over the middle of the picture on a plain background.
    // lfpw 0003 (the face in the top third over a bare chest of the same hue, light eyes) and
    // einstein (grey, a small face off-centre in a busy scene) do not: measured only.
    const QMap<QString, double> bounds {
        {QStringLiteral("lfpw_trainset_image_0001"), 0.15}, {QStringLiteral("lfpw_trainset_image_0002"), 0.15}};
    const QDir dir(sharedFacesDir());
    int rows = 0;
    for (const QFileInfo &pts : dir.entryInfoList({QStringLiteral("*.pts")}, QDir::Files, QDir::Name)) {
        for (const char *ext : {".png", ".jpg"}) {
            const QString image = dir.filePath(pts.completeBaseName() + QLatin1String(ext));
            if (QFileInfo::exists(image)) {
                QTest::newRow(qPrintable(pts.completeBaseName()))
                    << image << pts.filePath() << bounds.value(pts.completeBaseName(), -1.0);
                ++rows;
                break;
            }
        }
    }
    if (rows == 0)
        QTest::newRow("no data") << QString() << QString() << -1.0;
}

// A photo with a bound must be found within it; the others must either place a valid face or
// say why not.
void TestClassic::sharedDataNme()
{
    QFETCH(QString, image);
    QFETCH(QString, pts);
    QFETCH(double, bound);
    if (image.isEmpty())
        QSKIP("no research photos (set TOONFACE_DATA_DIR to the shared data folder)");
    std::array<QPointF, kIbugPointCount> truth {};
    QVERIFY2(readIbugPts(pts, &truth), qPrintable(pts));
    const QImage photo(image);
    QVERIFY2(!photo.isNull(), qPrintable(image));
    const ClassicResult r = detectClassic(photo, true);
    const QString dir = qEnvironmentVariable("TOONFACE_CLASSIC_DEBUG");
    if (!dir.isEmpty())
        for (auto it = r.debugImages.begin(); it != r.debugImages.end(); ++it)
            it.value().save(dir + QLatin1Char('/') + QFileInfo(image).completeBaseName() + QLatin1Char('-') + it.key()
                + QStringLiteral(".png"));
    if (!r.ok) {
        QVERIFY(!r.error.isEmpty());
        qInfo("%s: classic found no face: %s", qPrintable(QFileInfo(image).fileName()), qPrintable(r.error));
        QVERIFY2(bound < 0, "a photo that meets the thesis' assumptions must be found");
        return;
    }
    QVERIFY(r.face.isValid());
    const double nme = normalizedMeanError(r.face, truth);
    QVERIFY(std::isfinite(nme));
    qInfo("%s: classic NME %.4f (bound %s), %.1f ms%s", qPrintable(QFileInfo(image).fileName()), nme,
        bound < 0 ? "none" : qPrintable(QString::number(bound)), r.timingMs.value(QStringLiteral("total")),
        r.eyePairInFace ? "" : qPrintable(QStringLiteral("; the detector refuses it: ") + r.faceCheck));
    // A pair that failed the face checks is not a face for the detector: the check must say why.
    QCOMPARE(r.faceCheck.isEmpty(), r.eyePairInFace);
    if (bound >= 0) {
        QVERIFY2(nme <= bound, qPrintable(QStringLiteral("NME %1 > %2").arg(nme).arg(bound)));
        QVERIFY(r.eyePairInFace);
    }
}

// The same, with the central rectangle taken from the landmark detector's face box.
void TestClassic::sharedDataNmeWithFaceBox_data()
{
    sharedDataNme_data();
}

void TestClassic::sharedDataNmeWithFaceBox()
{
    QFETCH(QString, image);
    QFETCH(QString, pts);
    QFETCH(double, bound);
    Q_UNUSED(bound); // measured only: the face box moves the central rectangle off the thesis' own
    if (image.isEmpty())
        QSKIP("no research photos (set TOONFACE_DATA_DIR to the shared data folder)");
    if (!preloadLandmarkModel())
        QSKIP("the landmark model (libdlib-data) is not installed; no face box to seed with");
    std::array<QPointF, kIbugPointCount> truth {};
    QVERIFY2(readIbugPts(pts, &truth), qPrintable(pts));
    const QImage photo(image);
    QVERIFY2(!photo.isNull(), qPrintable(image));
    const DetectionResult box = detectFace(photo, {});
    QCOMPARE(box.status, DetectStatus::Ok);
    const ClassicResult r = detectClassic(photo, true, box.faceBox);
    const QString dir = qEnvironmentVariable("TOONFACE_CLASSIC_DEBUG");
    if (!dir.isEmpty())
        for (auto it = r.debugImages.begin(); it != r.debugImages.end(); ++it)
            it.value().save(dir + QLatin1Char('/') + QFileInfo(image).completeBaseName() + QStringLiteral("-boxed-")
                + it.key() + QStringLiteral(".png"));
    if (!r.ok) {
        QVERIFY(!r.error.isEmpty());
        qInfo("%s: classic in the face box found no face: %s", qPrintable(QFileInfo(image).fileName()),
            qPrintable(r.error));
        return;
    }
    QVERIFY(r.face.isValid());
    const double nme = normalizedMeanError(r.face, truth);
    QVERIFY(std::isfinite(nme));
    qInfo("%s: classic in the face box NME %.4f (landmarks %.4f), %.1f ms", qPrintable(QFileInfo(image).fileName()),
        nme, normalizedMeanError(box.face, truth), r.timingMs.value(QStringLiteral("total")));
}

QTEST_MAIN(TestClassic)
#include "tst_classic.moc"
