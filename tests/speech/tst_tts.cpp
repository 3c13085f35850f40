#include "speech/script.h"
#include "speech/tts.h"

#include <QTest>

#include <cmath>

using namespace toonface;

namespace {

Script script(const QString &text, Language language = Language::Auto)
{
    const ScriptParse p = parseScript(text, language);
    return p.script;
}

double rms(const Audio &a, double from, double to)
{
    const qsizetype i0 = std::clamp<qsizetype>(qsizetype(from * a.sampleRate), 0, a.samples.size());
    const qsizetype i1 = std::clamp<qsizetype>(qsizetype(to * a.sampleRate), 0, a.samples.size());
    double acc = 0;
    for (qsizetype i = i0; i < i1; ++i)
        acc += double(a.samples[i]) * a.samples[i];
    return i1 > i0 ? std::sqrt(acc / double(i1 - i0)) : 0.0;
}

// Fundamental frequency of [from, to) by the autocorrelation peak between 60 and 500 Hz.
double f0(const Audio &a, double from, double to)
{
    const qsizetype i0 = qsizetype(from * a.sampleRate), i1 = qsizetype(to * a.sampleRate);
    double best = -1;
    int bestLag = 0;
    for (int lag = a.sampleRate / 500; lag <= a.sampleRate / 60; ++lag) {
        double acc = 0;
        for (qsizetype i = i0; i + lag < i1; ++i)
            acc += double(a.samples[i]) * a.samples[i + lag];
        if (acc > best) {
            best = acc;
            bestLag = lag;
        }
    }
    return bestLag ? double(a.sampleRate) / bestLag : 0.0;
}

} // namespace

class TestTts : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void inputText()
    {
        QVector<int> offsets;
        QCOMPARE(ttsInputText(script(QStringLiteral("你好，绿色")), &offsets), QStringLiteral("ni3 hao3, lv4 se4."));
        QCOMPARE(offsets, (QVector<int> {0, 4, 10, 14}));
        QCOMPARE(ttsInputText(script(QStringLiteral("Hello there, world"))), QStringLiteral("Hello there, world."));
    }

    void mandarinSyllableTimes()
    {
        const TtsResult r = synthesize(script(QStringLiteral("你好，世界")));
        QVERIFY2(r.ok(), qPrintable(r.error));
        QCOMPARE(r.units.size(), 4);
        QVERIFY(r.audio.sampleRate > 8000);
        for (int k = 0; k < 4; ++k) {
            const TtsUnit &u = r.units[k];
            QVERIFY(u.end > u.start + 0.05);
            QVERIFY(u.end <= r.audio.duration() + 1e-9);
            if (k > 0)
                QVERIFY(u.start >= r.units[k - 1].end - 1e-9);
            QVERIFY(!u.phonemes.isEmpty());
            QVERIFY(std::abs(u.phonemes.first().start - u.start) < 0.05);
            // Sound inside each syllable.
            QVERIFY(rms(r.audio, u.start, u.end) > 0.01);
        }
        // The comma is a pause: a quiet gap between 好 and 世.
        QVERIFY(r.units[2].start - r.units[1].end > 0.05);
        QVERIFY(rms(r.audio, r.units[1].end + 0.01, r.units[2].start - 0.01)
            < 0.3 * rms(r.audio, r.units[1].start, r.units[1].end));
    }

    void rateChangesDuration()
    {
        const Script s = script(QStringLiteral("今天天气很好我们去公园散步"));
        TtsOptions slow, fast;
        slow.rate = 120;
        fast.rate = 300;
        const TtsResult a = synthesize(s, slow), b = synthesize(s, fast);
        QVERIFY(a.ok() && b.ok());
        QVERIFY(b.audio.duration() < 0.7 * a.audio.duration());
        QCOMPARE(a.units.size(), s.syllables.size());
        QCOMPARE(b.units.size(), s.syllables.size());
    }

    void pitchChangesVoice()
    {
        const Script s = script(QStringLiteral("ma1"));
        TtsOptions low, high;
        low.pitch = 10;
        high.pitch = 90;
        const TtsResult a = synthesize(s, low), b = synthesize(s, high);
        QVERIFY(a.ok() && b.ok());
        const auto mid = [](const TtsUnit &u) {
            return std::pair {u.start + 0.4 * (u.end - u.start), u.start + 0.8 * (u.end - u.start)};
        };
        const auto [a0, a1] = mid(a.units[0]);
        const auto [b0, b1] = mid(b.units[0]);
        QVERIFY2(f0(b.audio, b0, b1) > 1.2 * f0(a.audio, a0, a1),
            qPrintable(QStringLiteral("%1 vs %2 Hz").arg(f0(b.audio, b0, b1)).arg(f0(a.audio, a0, a1))));
    }

    void englishWords()
    {
        const Script s = script(QStringLiteral("Set white with p two soon."));
        QCOMPARE(s.language, Language::English);
        const TtsResult r = synthesize(s);
        QVERIFY2(r.ok(), qPrintable(r.error));
        QCOMPARE(r.units.size(), 6);
        for (int k = 1; k < r.units.size(); ++k)
            QVERIFY(r.units[k].start > r.units[k - 1].start);
        QVERIFY(!r.units[0].phonemes.isEmpty());
    }

    void voiceVariantAndBadVoice()
    {
        TtsOptions female;
        female.voice = QStringLiteral("cmn-latn-pinyin+f2");
        QVERIFY(synthesize(script(QStringLiteral("ni3 hao3")), female).ok());
        TtsOptions bad;
        bad.voice = QStringLiteral("no-such-voice");
        const TtsResult r = synthesize(script(QStringLiteral("ni3 hao3")), bad);
        QVERIFY(!r.ok());
        QVERIFY(r.error.contains(QStringLiteral("no-such-voice")));
    }

    void cancel()
    {
        std::atomic_bool flag {true};
        const TtsResult r = synthesize(script(QStringLiteral("今天天气很好我们去公园散步")), {}, {}, &flag);
        QVERIFY(!r.ok());
    }
};

QTEST_GUILESS_MAIN(TestTts)
#include "tst_tts.moc"
