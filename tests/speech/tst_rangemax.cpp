// The largest value of a stretch of a signal (the onset signals' nucleus and loudness maxima):
// the same as scanning the stretch, for every stretch of short signals and random stretches of
// an hour-long one, across block edges and within one block.
#include "speech/rangemax.h"
#include "testmain.h"

#include <QRandomGenerator>
#include <QTest>

#include <algorithm>

using namespace toonface;

namespace {

std::vector<float> randomSignal(int n, quint32 seed)
{
    QRandomGenerator rng(seed);
    std::vector<float> v(static_cast<size_t>(n));
    for (float &x : v)
        x = float(rng.generateDouble() * 2.0 - 1.0);
    return v;
}

float scanned(const std::vector<float> &v, int from, int to)
{
    return *std::max_element(v.begin() + from, v.begin() + to);
}

} // namespace

class TestRangeMax : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // Every stretch of signals from one frame to a few blocks long.
    void everyStretchOfShortSignals_data()
    {
        QTest::addColumn<int>("frames");
        for (const int n : {1, 2, 63, 64, 65, 128, 200, 333})
            QTest::newRow(qPrintable(QString::number(n))) << n;
    }
    void everyStretchOfShortSignals()
    {
        QFETCH(int, frames);
        const std::vector<float> v = randomSignal(frames, quint32(frames));
        const RangeMax max(v);
        QCOMPARE(max.size(), frames);
        for (int from = 0; from < frames; ++from)
            for (int to = from + 1; to <= frames; ++to)
                QCOMPARE(max(from, to), scanned(v, from, to));
    }

    // An hour of 10-ms frames, stretches of every length class, a rising and a falling signal
    // (the largest at a stretch's end, then at its start).
    void hourLongSignal()
    {
        constexpr int n = 360000;
        const std::vector<float> noise = randomSignal(n, 29);
        std::vector<float> rising(n), falling(n);
        for (int i = 0; i < n; ++i) {
            rising[size_t(i)] = float(i);
            falling[size_t(i)] = float(n - i);
        }
        const RangeMax noiseMax(noise), risingMax(rising), fallingMax(falling);
        QRandomGenerator rng(7);
        for (int k = 0; k < 3000; ++k) {
            const int length = 1 + int(rng.bounded(1 << (1 + k % 18)));
            const int from = int(rng.bounded(n - std::min(length, n - 1)));
            const int to = std::min(n, from + length);
            QCOMPARE(noiseMax(from, to), scanned(noise, from, to));
            QCOMPARE(risingMax(from, to), float(to - 1));
            QCOMPARE(fallingMax(from, to), float(n - from));
        }
    }
};

TOONFACE_TEST_APPLESS_MAIN(TestRangeMax)
#include "tst_rangemax.moc"
