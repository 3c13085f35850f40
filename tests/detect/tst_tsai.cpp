#include "detect/tsai.h"
#include "testmain.h"

#include <QTest>

#include <cmath>

using namespace toonface;

Q_DECLARE_METATYPE(std::vector<double>)

class TestTsai : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void twoLevels_data();
    void twoLevels();
    void knownHistogram_data();
    void knownHistogram();
    void degenerate();
};

void TestTsai::twoLevels_data()
{
    QTest::addColumn<int>("low");
    QTest::addColumn<int>("high");
    QTest::addColumn<int>("lowCount");
    QTest::addColumn<int>("highCount");
    QTest::newRow("half") << 40 << 200 << 500 << 500;
    QTest::newRow("few dark") << 10 << 240 << 37 << 963;
    QTest::newRow("mostly dark") << 90 << 130 << 800 << 200;
    QTest::newRow("adjacent") << 127 << 128 << 3 << 7;
}

// A two-level image is its own moment-preserving answer: the levels and the exact fraction.
void TestTsai::twoLevels()
{
    QFETCH(int, low);
    QFETCH(int, high);
    QFETCH(int, lowCount);
    QFETCH(int, highCount);
    std::vector<double> h(256, 0.0);
    h[low] = lowCount;
    h[high] = highCount;
    const TsaiThreshold t = tsaiThreshold(h);
    QVERIFY(t.valid);
    QVERIFY(std::abs(t.z0 - low) < 1e-6);
    QVERIFY(std::abs(t.z1 - high) < 1e-6);
    QVERIFY(std::abs(t.p0 - double(lowCount) / (lowCount + highCount)) < 1e-9);
    QCOMPARE(t.threshold, low);
}

void TestTsai::knownHistogram_data()
{
    QTest::addColumn<std::vector<double>>("histogram");
    QTest::newRow("three levels") << std::vector<double> {0, 0, 5, 0, 0, 0, 3, 0, 0, 2};
    QTest::newRow("ramp") << std::vector<double> {1, 2, 3, 4, 5, 6, 7, 8};
    QTest::newRow("bimodal") << std::vector<double> {9, 20, 9, 1, 0, 0, 2, 10, 30, 12, 3};
    QTest::newRow("skewed") << std::vector<double> {50, 10, 5, 2, 1, 1, 1};
    // Sparse edges: most pixels flat, the p0-tile falls inside the edge bin's lower part.
    QTest::newRow("sparse edges") << std::vector<double> {970, 0, 0, 0, 0, 25, 0, 5};
}

// Against the closed form written out here from the moments (Tsai 1985, eqs. for c0, c1,
// z0, z1, p0), with the threshold as the p0-tile (the occupied level nearest p0).
void TestTsai::knownHistogram()
{
    QFETCH(std::vector<double>, histogram);
    double n = 0, m1 = 0, m2 = 0, m3 = 0;
    for (double c : histogram)
        n += c;
    for (size_t j = 0; j < histogram.size(); ++j) {
        m1 += histogram[j] / n * j;
        m2 += histogram[j] / n * j * j;
        m3 += histogram[j] / n * j * j * j;
    }
    const double cd = m2 - m1 * m1;
    const double c0 = (m1 * m3 - m2 * m2) / cd;
    const double c1 = (m1 * m2 - m3) / cd;
    const double z0 = (-c1 - std::sqrt(c1 * c1 - 4 * c0)) / 2;
    const double z1 = (-c1 + std::sqrt(c1 * c1 - 4 * c0)) / 2;
    const double p0 = (z1 - m1) / (z1 - z0);
    // The moments are preserved: p0 z0^k + (1 - p0) z1^k = m_k for k = 1, 2, 3.
    QVERIFY(std::abs(p0 * z0 + (1 - p0) * z1 - m1) < 1e-9 * std::max(1.0, m1));
    QVERIFY(std::abs(p0 * z0 * z0 + (1 - p0) * z1 * z1 - m2) < 1e-9 * std::max(1.0, m2));
    QVERIFY(std::abs(p0 * z0 * z0 * z0 + (1 - p0) * z1 * z1 * z1 - m3) < 1e-8 * std::max(1.0, m3));
    int expected = -1;
    double cumulative = 0, gap = 2;
    for (size_t j = 0; j < histogram.size(); ++j) {
        cumulative += histogram[j] / n;
        if (histogram[j] > 0 && std::abs(cumulative - p0) < gap - 1e-12) {
            gap = std::abs(cumulative - p0);
            expected = int(j);
        }
    }

    const TsaiThreshold t = tsaiThreshold(histogram);
    QVERIFY(t.valid);
    QVERIFY(std::abs(t.m1 - m1) < 1e-9 * std::max(1.0, m1));
    QVERIFY(std::abs(t.z0 - z0) < 1e-9 * std::max(1.0, std::abs(z0)));
    QVERIFY(std::abs(t.z1 - z1) < 1e-9 * std::max(1.0, std::abs(z1)));
    QVERIFY(std::abs(t.p0 - p0) < 1e-9);
    QVERIFY(t.z0 < t.z1);
    QVERIFY(t.p0 > 0 && t.p0 < 1);
    QCOMPARE(t.threshold, expected);
}

void TestTsai::degenerate()
{
    QVERIFY(!tsaiThreshold(std::vector<double>(256, 0.0)).valid);
    QVERIFY(!tsaiThreshold({}).valid);
    std::vector<double> single(256, 0.0);
    single[77] = 1000;
    const TsaiThreshold t = tsaiThreshold(single);
    QVERIFY(!t.valid);
    QCOMPARE(t.threshold, 77);
}

TOONFACE_TEST_GUILESS_MAIN(TestTsai)
#include "tst_tsai.moc"
