// The classic pipeline's eye-pair search (core/detect/classiceyes.cpp): eq. (3.5), the pairing
// rules, the face checks of a pair, the eyeball.

#include "detect/classic.h"
#include "testmain.h"

#include <QPainter>
#include <QTest>

#include <cmath>
#include <functional>
#include <numbers>

using namespace toonface;

Q_DECLARE_METATYPE(std::vector<QRect>)

class TestClassicEyes : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void score_data();
    void score();
    void eyePair_data();
    void eyePair();
    void eyeball_data();
    void eyeball();
    void ringShaped_data();
    void ringShaped();
    void darkness_data();
    void darkness();
    void pairInFace_data();
    void pairInFace();
    void mouthRow_data();
    void mouthRow();
};

void TestClassicEyes::score_data()
{
    QTest::addColumn<double>("a1");
    QTest::addColumn<double>("a2");
    QTest::newRow("equal, full") << 1.0 << 1.0;
    QTest::newRow("equal, small") << 0.2 << 0.2;
    QTest::newRow("unequal") << 1.0 << 0.5;
    QTest::newRow("swapped") << 0.5 << 1.0;
}

void TestClassicEyes::score()
{
    QFETCH(double, a1);
    QFETCH(double, a2);
    const double big = std::max(a1, a2), small = std::min(a1, a2);
    const double s = big / small;
    QVERIFY(std::abs(eyePairScore(a1, a2) - (big * small - s * s) / 2) < 1e-12);
}

void TestClassicEyes::eyePair_data()
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
void TestClassicEyes::eyePair()
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

void TestClassicEyes::eyeball_data()
{
    QTest::addColumn<QPointF>("centre");
    QTest::addColumn<double>("radius");
    QTest::newRow("centred") << QPointF(50, 30) << 8.0;
    QTest::newRow("looking left") << QPointF(40, 30) << 8.0;
    QTest::newRow("large") << QPointF(55, 31) << 11.0;
}

// A dark almond (the lash line and corners) with a round iris: the eyeball is the iris.
void TestClassicEyes::eyeball()
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

void TestClassicEyes::ringShaped_data()
{
    QTest::addColumn<int>("shape");
    QTest::addColumn<bool>("ring");
    QTest::newRow("filled disc") << 0 << false;
    QTest::newRow("thin loop (spectacle rim)") << 1 << true;
    QTest::newRow("disc with a small highlight") << 2 << false;
    QTest::newRow("open arc") << 3 << false;
}

void TestClassicEyes::ringShaped()
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

void TestClassicEyes::darkness_data()
{
    QTest::addColumn<int>("surround");
    QTest::addColumn<double>("expected");
    QTest::newRow("dark blob on skin") << 200 << 160.0;
    QTest::newRow("dark blob on dark cloth") << 45 << 5.0;
}

// A blob at level 40 in a field of `surround`: the contrast is the difference of the levels.
void TestClassicEyes::darkness()
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

void TestClassicEyes::pairInFace_data()
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

void TestClassicEyes::pairInFace()
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

void TestClassicEyes::mouthRow_data()
{
    QTest::addColumn<int>("mouthY"); // 0: no mouth
    QTest::addColumn<bool>("mouth");
    QTest::newRow("mouth 1.1 d below") << 329 << true;
    QTest::newRow("mouth 0.75 d below") << 298 << true;
    QTest::newRow("no mouth") << 0 << false;
    QTest::newRow("mouth 2 d below (out of the band)") << 410 << false;
}

// Skin at 180 with soft noise-free shading; a lip line at level 90, 60 px wide, 6 px high.
void TestClassicEyes::mouthRow()
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

TOONFACE_TEST_MAIN(TestClassicEyes)
#include "tst_classiceyes.moc"
