#include "testmain.h"

#include "export/smilhidden.h"
#include "export/smilreduce.h"

#include <QTest>

#include <random>

using namespace toonface;
using namespace toonface::smil;

namespace {

Channel numberChannel(int part, const char *attribute, double base)
{
    Channel c;
    c.kind = ChannelKind::Number;
    c.part = part;
    c.attribute = QString::fromLatin1(attribute);
    c.base = {base};
    c.size = 1;
    c.decimals = 1;
    return c;
}

// Keys of one number at `times` (grid steps) with `values` (tenths of a pixel), eased.
ChannelKeys keysOf(int channel, const QVector<qint64> &times, const QVector<qint64> &values)
{
    ChannelKeys k;
    k.channel = channel;
    k.times = times;
    k.values = values;
    for (qsizetype i = 1; i < times.size(); ++i)
        k.timings.append(values[i] == values[i - 1] ? std::nullopt : std::optional<Timing>(Timing {0.0, 1.0}));
    return k;
}

// A position that moves every 500 steps, at random.
ChannelKeys wandering(int channel, qint64 length, quint32 seed)
{
    std::mt19937 rng(seed);
    QVector<qint64> times, values;
    for (qint64 t = 0; t <= length; t += 500) {
        times.append(t);
        values.append(qint64(rng() % 400) - 200);
    }
    return keysOf(channel, times, values);
}

bool inside(qint64 n, const QVector<std::pair<qint64, qint64>> &spans)
{
    return std::any_of(spans.cbegin(), spans.cend(), [&](const auto &s) { return s.first < n && n < s.second; });
}

} // namespace

// A circle of radius 0 draws nothing: the keys of its position there go (smilhidden.h).
class TestSmilHidden : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void zeroSpansOfARadius()
    {
        const Channel r = numberChannel(0, "r", 0);
        const ChannelKeys k = keysOf(1, {0, 1000, 2000, 5000, 6000, 9000, 10000}, {0, 0, 100, 100, 0, 0, 0});
        const QVector<std::pair<qint64, qint64>> want {{0, 1000}, {6000, 10000}};
        QCOMPARE(zeroSpans(r, k), want);
        // A radius drawn larger than its offsets take away is never 0.
        QVERIFY(zeroSpans(numberChannel(0, "r", 20), k).isEmpty());
        // A negative radius draws nothing either (SVG: an error, nothing rendered).
        QCOMPARE(zeroSpans(numberChannel(0, "r", -5), keysOf(1, {0, 10000}, {0, 0})).size(), 1);
    }

    void positionKeysGoWhereTheCircleIsHidden_data()
    {
        QTest::addColumn<quint32>("seed");
        for (quint32 seed : {1u, 2u, 3u})
            QTest::newRow(qPrintable(QString::number(seed))) << seed;
    }

    void positionKeysGoWhereTheCircleIsHidden()
    {
        QFETCH(quint32, seed);
        const QVector<Channel> channels {numberChannel(0, "cx", 100), numberChannel(0, "r", 0),
            numberChannel(1, "cx", 50), numberChannel(1, "r", 5)};
        const ChannelKeys radius = keysOf(1, {0, 1000, 2000, 5000, 6000, 9000, 10000}, {0, 0, 100, 100, 0, 0, 0});
        const QVector<std::pair<qint64, qint64>> hidden = zeroSpans(channels[1], radius);
        QVector<ChannelKeys> keys {
            wandering(0, 10000, seed), radius, wandering(2, 10000, seed + 10), keysOf(3, {0, 10000}, {0, 0})};
        const QVector<ChannelKeys> before = keys;
        dropHiddenKeys(channels, keys);

        // The radius, and the part whose radius never reaches 0, keep every key.
        for (int c : {1, 2, 3}) {
            QCOMPARE(keys[c].times, before[c].times);
            QCOMPARE(keys[c].values, before[c].values);
        }
        // The position keeps fewer keys, each as it was, with a timing per interval.
        const ChannelKeys &got = keys[0];
        QVERIFY(got.times.size() < before[0].times.size());
        QCOMPARE(got.timings.size(), got.times.size() - 1);
        QCOMPARE(got.values.size(), got.times.size());
        for (qsizetype i = 0; i < got.times.size(); ++i) {
            const qsizetype at = before[0].times.indexOf(got.times[i]);
            QVERIFY(at >= 0);
            QCOMPARE(got.values[i], before[0].values[at]);
        }
        // At most the first and the last key inside each hidden span stay.
        for (const auto &span : hidden) {
            const qint64 from = span.first, to = span.second;
            const auto within
                = std::count_if(got.times.cbegin(), got.times.cend(), [&](qint64 n) { return from < n && n < to; });
            QVERIFY2(within <= 2, qPrintable(QStringLiteral("%1 keys in %2-%3").arg(within).arg(from).arg(to)));
        }
        // Wherever the circle shows, the position is exactly what it was.
        for (qint64 n = 0; n <= 10000; n += 25) {
            if (inside(n, hidden))
                continue;
            double want = 0, have = 0;
            keyedValue(channels[0], before[0], double(n), &want);
            keyedValue(channels[0], got, double(n), &have);
            QVERIFY2(
                std::abs(want - have) < 1e-9, qPrintable(QStringLiteral("at %1: %2 != %3").arg(n).arg(have).arg(want)));
        }
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestSmilHidden)
#include "tst_smilhidden.moc"
