#include "detect/regions.h"
#include "testmain.h"

#include <QPainter>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <thread>
#include <vector>

using namespace toonface;

class TestRegions : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void intensityAndHue_data();
    void intensityAndHue();
    void hueOfEveryColourOnManyThreads();
    void firstLevel();
    void regionGrowing();
    void refinement();
};

void TestRegions::intensityAndHue_data()
{
    QTest::addColumn<QColor>("colour");
    QTest::addColumn<double>("intensity");
    QTest::addColumn<double>("hue"); // normalised, [-127, 128]
    QTest::newRow("red") << QColor(255, 0, 0) << 85.0 << 0.0;
    QTest::newRow("green") << QColor(0, 255, 0) << 85.0 << 120.0 * 255 / 360;
    QTest::newRow("blue") << QColor(0, 0, 255) << 85.0 << -120.0 * 255 / 360;
    QTest::newRow("yellow") << QColor(255, 255, 0) << 170.0 << 60.0 * 255 / 360;
    QTest::newRow("magenta") << QColor(255, 0, 255) << 170.0 << -60.0 * 255 / 360;
    QTest::newRow("grey has no hue") << QColor(128, 128, 128) << 128.0 << 128.0;
}

void TestRegions::intensityAndHue()
{
    QFETCH(QColor, colour);
    QFETCH(double, intensity);
    QFETCH(double, hue);
    QImage img(3, 2, QImage::Format_RGB32);
    img.fill(colour);
    QVERIFY(std::abs(intensityPlane(img).at(2, 1) - intensity) < 1e-4);
    QVERIFY2(std::abs(huePlane(img).at(1, 1) - hue) < 1e-3, qPrintable(QString::number(huePlane(img).at(1, 1))));
}

// The hue of a photo's every colour, worked out on four threads at once (detections share the
// hue's table, filled as colours are met): each pixel is the Gonzalez & Woods HSI angle, from
// its arc cosine, the same on every thread.
void TestRegions::hueOfEveryColourOnManyThreads()
{
    QImage img(512, 256, QImage::Format_RGB32);
    quint32 seed = 12345;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            seed = seed * 1664525u + 1013904223u;
            img.setPixel(x, y, qRgb(int(seed >> 24), int((seed >> 16) & 0xff), int((seed >> 8) & 0xff)));
        }
    std::vector<Plane> planes(4);
    {
        std::vector<std::thread> threads;
        for (size_t i = 0; i < planes.size(); ++i)
            threads.emplace_back([&, i] { planes[i] = huePlane(img); });
        for (auto &t : threads)
            t.join();
    }
    int checked = 0;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const QRgb c = img.pixel(x, y);
            const double r = qRed(c), g = qGreen(c), b = qBlue(c);
            const double sum = r + g + b;
            const double saturation = sum > 0 ? 1 - 3 * std::min({r, g, b}) / sum : 0;
            double expected = 128;
            const double root = 2 * std::sqrt((r - g) * (r - g) + (r - b) * (g - b));
            if (saturation >= kMinSaturation && root > 0) {
                double theta = std::acos(std::clamp(((r - g) + (r - b)) / root, -1.0, 1.0)) * 180 / M_PI;
                if (b > g)
                    theta = -theta;
                expected = std::clamp(theta * 255 / 360, -127.0, 128.0);
                ++checked;
            }
            for (const Plane &p : planes)
                QVERIFY2(std::abs(p.at(x, y) - expected) < 1e-3,
                    qPrintable(
                        QStringLiteral("(%1, %2, %3): %4, not %5").arg(r).arg(g).arg(b).arg(p.at(x, y)).arg(expected)));
        }
    QVERIFY(checked > img.width() * img.height() / 2);
}

// t1 = m1 - s1 inside the rectangle only (sample standard deviation, eq. 3.2).
void TestRegions::firstLevel()
{
    Plane p {QSize(6, 4), std::vector<float>(24, 250.0f)};
    // The rectangle (1,1)-(4,2) holds 10, 20, ..., 80.
    const float inside[8] = {10, 20, 30, 40, 50, 60, 70, 80};
    for (int i = 0; i < 8; ++i)
        p.at(1 + i % 4, 1 + i / 4) = inside[i];
    const FirstLevel f = firstLevelThreshold(p, QRect(1, 1, 4, 2));
    const double m1 = 45.0;
    double ss = 0;
    for (float v : inside)
        ss += (v - m1) * (v - m1);
    const double s1 = std::sqrt(ss / 7.0);
    QVERIFY(std::abs(f.m1 - m1) < 1e-9);
    QVERIFY(std::abs(f.s1 - s1) < 1e-9);
    QVERIFY(std::abs(f.t1 - (m1 - s1)) < 1e-9);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 6; ++x)
            QCOMPARE(f.b1.at(x, y), std::uint8_t(p.at(x, y) > m1 - s1 ? 1 : 0));
    QCOMPARE(f.b1.at(1, 1), std::uint8_t(0)); // 10 <= t1: dark
    QCOMPARE(f.b1.at(0, 0), std::uint8_t(1));
}

// Two blobs, one touching diagonally (8-connected), one ring enclosing a light hole.
void TestRegions::regionGrowing()
{
    QImage img(40, 30, QImage::Format_Grayscale8);
    img.fill(255);
    QPainter p(&img);
    p.fillRect(QRect(2, 2, 5, 4), Qt::black); // region A (area 20)
    p.fillRect(QRect(7, 6, 3, 3), Qt::black); // touches A only at a corner
    p.fillRect(QRect(20, 10, 10, 10), Qt::black); // ring
    p.fillRect(QRect(23, 13, 4, 4), Qt::white); // its hole
    p.end();
    const Plane plane = intensityPlane(img);
    const FirstLevel f = firstLevelThreshold(plane, QRect(0, 0, 40, 30));
    std::vector<int> labels;
    const auto dark = growRegions(f.b1, 0, &labels);
    QCOMPARE(int(dark.size()), 2);
    QCOMPARE(dark[0].area, 20 + 9);
    QCOMPARE(dark[0].box, QRect(2, 2, 8, 7));
    QCOMPARE(dark[1].area, 100 - 16);
    QCOMPARE(dark[1].box, QRect(20, 10, 10, 10));
    QVERIFY(std::abs(dark[1].centroid.x() - 24.5) < 1e-9);
    QCOMPARE(labels[size_t(12) * 40 + 21], dark[1].label);
    QCOMPARE(labels[0], 0);
    const auto light = growRegions(f.b1, 1);
    QCOMPARE(int(light.size()), 2); // the surround and the hole
    QVERIFY(light[0].touchesBorder);
    QCOMPARE(light[1].area, 16);
    QVERIFY(!light[1].touchesBorder);
}

// A blue background, a skin disc with dark eyes, a dark hair cap joined to the border:
// F_final is the disc with its eyes, the hair is the cap.
void TestRegions::refinement()
{
    QImage img(200, 200, QImage::Format_RGB32);
    img.fill(QColor(90, 140, 220));
    QPainter p(&img);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(40, 25, 20));
    p.drawRect(QRect(40, 0, 120, 60)); // hair, touching the top border
    p.setBrush(QColor(225, 180, 150));
    p.drawEllipse(QRect(50, 40, 100, 130));
    p.setBrush(QColor(30, 30, 30));
    p.drawEllipse(QRect(70, 90, 14, 10));
    p.drawEllipse(QRect(116, 90, 14, 10));
    p.end();
    const QRect rect(70, 70, 60, 60);
    const FirstLevel f = firstLevelThreshold(intensityPlane(img), rect);
    const SecondLevel s = secondLevelThreshold(huePlane(img), f.b1, rect);
    QCOMPARE(s.b2.at(100, 140), std::uint8_t(0)); // skin
    QCOMPARE(s.b2.at(5, 190), std::uint8_t(1)); // background
    QCOMPARE(s.b2.at(77, 95), std::uint8_t(1)); // a dark eye is not skin in B2
    const RefinedRegions r = refineRegions(f.b1, s.b2);
    QCOMPARE(r.face.at(77, 95), std::uint8_t(1)); // the eye hole is filled
    QCOMPARE(r.face.at(100, 150), std::uint8_t(1));
    QCOMPARE(r.face.at(5, 190), std::uint8_t(0));
    QCOMPARE(r.face.at(100, 10), std::uint8_t(0));
    QCOMPARE(r.hair.at(100, 10), std::uint8_t(1));
    QCOMPARE(r.hair.at(45, 5), std::uint8_t(1));
    QCOMPARE(r.hair.at(5, 190), std::uint8_t(0));
    QCOMPARE(r.hair.at(100, 150), std::uint8_t(0));
}

TOONFACE_TEST_GUILESS_MAIN(TestRegions)
#include "tst_regions.moc"
