#include "testmain.h"

#include "export/smilreduce.h"

#include <QTest>

#include <cmath>
#include <random>

using namespace toonface;
using namespace toonface::smil;

namespace {

// A channel of `size` numbers written to 0.1 px, one pixel a unit.
Channel channelOf(int size)
{
    Channel c;
    c.kind = size == 1 ? ChannelKind::Number : ChannelKind::Points;
    c.size = size;
    c.decimals = 1;
    c.weight = 1;
    return c;
}

// The ease 3u^2 - 2u^3 as the key refinement writes it.
Timing ease()
{
    return Timing {0.0, 1.0};
}

// Keys as lip sync makes them for the mouth: each cue an ease of 60-140 ms to a random shape,
// then a hold of 0-200 ms, some cues cut by the next before their ease ends (two eases in a
// row), and now and then a small move; values in tenths of a pixel.
ChannelKeys mouthLikeKeys(const Channel &c, int cues, quint32 seed)
{
    std::mt19937 rng(seed);
    auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    ChannelKeys k;
    k.channel = 0;
    qint64 t = 0;
    k.times.append(t);
    QVector<qint64> value(c.size, 0);
    k.values.append(value);
    for (int i = 0; i < cues; ++i) {
        const bool small = i % 7 == 3;
        for (int j = 0; j < c.size; ++j)
            value[j] += qint64(std::llround(uniform(-1, 1) * (small ? 4 : 150)));
        t += qint64(uniform(600, 1400)); // grid steps of 0.1 ms
        k.times.append(t);
        k.values.append(value);
        k.timings.append(ease());
        if (uniform(0, 1) < 0.7) {
            t += qint64(uniform(1, 2000));
            k.times.append(t);
            k.values.append(value);
            k.timings.append(std::nullopt);
        }
    }
    return k;
}

// The largest difference, in pixels, between two keyings of a channel at `samples` times per
// interval of `a` and at each of its keys.
double largestDifference(const Channel &c, const ChannelKeys &a, const ChannelKeys &b, int samples)
{
    QVector<double> va(c.size), vb(c.size);
    double worst = 0;
    for (qsizetype m = 0; m + 1 < a.times.size(); ++m) {
        for (int s = 0; s <= samples; ++s) {
            const double n = double(a.times[m]) + double(a.times[m + 1] - a.times[m]) * s / samples;
            keyedValue(c, a, n, va.data());
            keyedValue(c, b, n, vb.data());
            for (int j = 0; j < c.size; ++j)
                worst = std::max(worst, c.weight * std::abs(va[j] - vb[j]));
        }
    }
    return worst;
}

} // namespace

// The SMIL export drops the keys that the interpolation between their neighbours gives within
// a tolerance (smilreduce.h).
class TestSmilReduce : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // Keys all on one line at a steady pace (linear timings) collapse to the two ends.
    void keysOnALineCollapse()
    {
        const Channel c = channelOf(2);
        ChannelKeys k;
        for (int i = 0; i <= 10; ++i) {
            k.times.append(100 * i);
            k.values.append({10 * i, -5 * i});
            if (i)
                k.timings.append(Timing {});
        }
        const ChannelKeys original = k;
        reduceKeys(c, 0.3, &k);
        QCOMPARE(k.times, (QVector<qint64> {0, 1000}));
        QCOMPARE(k.values, (QVector<qint64> {0, 0, 100, -50}));
        QCOMPARE(k.timings.size(), qsizetype(1));
        QVERIFY(k.timings[0].has_value());
        QVERIFY(largestDifference(c, original, k, 16) <= 1e-9);
    }

    // A point moving along a line whose middle key lies off the line (no timing can take it
    // there): 0.2 px off, within the tolerance, the key goes; 0.5 px off it stays.
    void aKeyOffTheLineStays_data()
    {
        QTest::addColumn<int>("offTenths");
        QTest::addColumn<int>("keys");
        QTest::newRow("0.2 px off") << 2 << 2;
        QTest::newRow("0.5 px off") << 5 << 3;
    }

    void aKeyOffTheLineStays()
    {
        QFETCH(int, offTenths);
        QFETCH(int, keys);
        const Channel c = channelOf(2);
        ChannelKeys k;
        k.times = {0, 500, 1000};
        k.values = {0, 0, 50, offTenths, 100, 0};
        k.timings = {Timing {}, Timing {}};
        reduceKeys(c, 0.3, &k);
        QCOMPARE(k.times.size(), qsizetype(keys));
    }

    // Holds stay holds: a channel that holds, eases and holds again keeps its resting values
    // exact while it rests.
    void holdsStayExact()
    {
        const Channel c = channelOf(2);
        ChannelKeys k;
        k.times = {0, 2000, 3000, 6000};
        k.values = {0, 0, 0, 0, 400, -300, 400, -300};
        k.timings = {std::nullopt, ease(), std::nullopt};
        const ChannelKeys original = k;
        reduceKeys(c, 0.3, &k);
        QVector<double> v(2);
        for (double n : {0.0, 1000.0, 1999.0, 3000.0, 4500.0, 6000.0}) {
            keyedValue(c, k, n, v.data());
            QVector<double> want(2);
            keyedValue(c, original, n, want.data());
            QCOMPARE(v, want);
        }
    }

    // A mouth-like channel of 400 cues: fewer keys; at every original key time and at 64 times
    // in each of its intervals the reduced channel stays within the tolerance; the kept keys
    // are original keys with their values; every timing is a valid keySpline.
    void reducedChannelStaysWithinTheTolerance_data()
    {
        QTest::addColumn<int>("size");
        QTest::addColumn<double>("tolerance");
        QTest::addColumn<quint32>("seed");
        QTest::newRow("one number, 0.3 px") << 1 << 0.3 << 1u;
        QTest::newRow("a path of 14, 0.3 px") << 14 << 0.3 << 2u;
        QTest::newRow("a path of 14, 0.1 px") << 14 << 0.1 << 3u;
        QTest::newRow("a pair, 1 px") << 2 << 1.0 << 4u;
    }

    void reducedChannelStaysWithinTheTolerance()
    {
        QFETCH(int, size);
        QFETCH(double, tolerance);
        QFETCH(quint32, seed);
        const Channel c = channelOf(size);
        const ChannelKeys original = mouthLikeKeys(c, 400, seed);
        ChannelKeys k = original;
        reduceKeys(c, tolerance, &k);
        qInfo("%lld keys -> %lld", qlonglong(original.times.size()), qlonglong(k.times.size()));
        QVERIFY(k.times.size() < original.times.size());
        QCOMPARE(k.timings.size(), k.times.size() - 1);
        QCOMPARE(k.values.size(), k.times.size() * size);
        QCOMPARE(k.times.first(), original.times.first());
        QCOMPARE(k.times.last(), original.times.last());
        for (qsizetype i = 0; i < k.times.size(); ++i) {
            const qsizetype o = original.times.indexOf(k.times[i]);
            QVERIFY(o >= 0);
            QCOMPARE(k.values.mid(i * size, size), original.values.mid(o * size, size));
        }
        for (const std::optional<Timing> &t : k.timings) {
            if (!t)
                continue;
            for (double v : {t->x1, t->y1, t->x2, t->y2})
                QVERIFY(v >= 0 && v <= 1);
        }
        // Every original key time (s = 0 of each interval) and 63 times between.
        const double worst = largestDifference(c, original, k, 64);
        qInfo("largest difference %.3f px (tolerance %.2f)", worst, tolerance);
        QVERIFY2(worst <= tolerance, qPrintable(QString::number(worst)));
    }

    // Tolerance 0 leaves the keys alone.
    void zeroToleranceKeepsEveryKey()
    {
        const Channel c = channelOf(3);
        ChannelKeys k = mouthLikeKeys(c, 50, 7);
        const ChannelKeys original = k;
        reduceKeys(c, 0, &k);
        QCOMPARE(k.times, original.times);
        QCOMPARE(k.values, original.values);
    }

    // A timing with free x control points: x rises from 0 to 1 and the progress at x is the
    // curve's y where its x is x.
    void timingWithFreeControlPoints()
    {
        const Timing t {0.0, 1.0, 0.8, 0.1};
        QVERIFY(!t.thirds());
        for (double x : {0.0, 0.1, 0.37, 0.5, 0.9, 1.0}) {
            const double s = t.parameter(x);
            QVERIFY(std::abs(Timing::bezier(t.x1, t.x2, s) - x) < 1e-9);
            QCOMPARE(t.at(x), Timing::bezier(t.y1, t.y2, s));
        }
        // The thirds: x is the parameter.
        const Timing thirds {0.2, 0.9};
        QVERIFY(thirds.thirds());
        QVERIFY(std::abs(thirds.parameter(0.3) - 0.3) < 1e-9);
    }
};

TOONFACE_TEST_APPLESS_MAIN(TestSmilReduce)
#include "tst_smilreduce.moc"
