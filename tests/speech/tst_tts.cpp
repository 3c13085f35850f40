#include "speech/script.h"
#include "speech/tts.h"
#include "speech/ttsvoicefile.h"
#include "testmain.h"

#include <QFile>
#include <QTemporaryDir>

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
        // The reference says the tones as spoken: 你 rises before 好.
        QCOMPARE(ttsInputText(script(QStringLiteral("你好，绿色")), &offsets), QStringLiteral("ni2 hao3, lv4 se4."));
        QCOMPARE(offsets, (QVector<int> {0, 4, 10, 14}));
        QCOMPARE(ttsInputText(script(QStringLiteral("Hello there, world"))), QStringLiteral("Hello there, world."));
    }

    void longRunsWithoutPunctuationAreCutIntoClauses()
    {
        // 160 syllables without a mark: espeak-ng would cut the clause itself at 800 bytes and
        // then report no word events for a dozen syllables, which got next to no time.
        QString text;
        for (int k = 0; k < 10; ++k)
            text += QStringLiteral("银行的工作人员说明天下午三点");
        const Script s = script(text);
        QCOMPARE(s.syllables.size(), 140);
        const QString input = ttsInputText(s);
        int longest = 0, run = 0;
        for (const QChar c : input) {
            run = c == QLatin1Char(',') ? 0 : run + 1;
            longest = std::max(longest, run);
        }
        QVERIFY2(longest <= 520, qPrintable(input));
        QVERIFY(input.count(QLatin1Char(',')) >= 1);
        const TtsResult r = synthesize(s);
        QVERIFY2(r.ok(), qPrintable(r.error));
        QCOMPARE(r.units.size(), s.syllables.size());
        for (int k = 0; k < r.units.size(); ++k)
            QVERIFY2(r.units[k].end - r.units[k].start > 0.06,
                qPrintable(QStringLiteral("syllable %1: %2 s").arg(k).arg(r.units[k].end - r.units[k].start)));
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

    // espeak-ng's pitch flutter runs on inside the library from one rendering to the next:
    // the same request after the same history sounded (and lasted) differently each time.
    // Every voice is loaded without it.
    void renderingDoesNotDriftFromOneToTheNext_data()
    {
        QTest::addColumn<QString>("voice");
        QTest::newRow("default") << QString();
        QTest::newRow("variant m3") << QStringLiteral("cmn-latn-pinyin+m3");
    }
    void renderingDoesNotDriftFromOneToTheNext()
    {
        QFETCH(QString, voice);
        TtsOptions o;
        o.voice = voice;
        const Script a = script(QStringLiteral("ni3 hao3 shi4 jie4"));
        const Script b = script(QStringLiteral("wo3 geng4 xi3 huan1 ying1 wu3 he2 lao3 ying1"));
        QVERIFY(synthesize(b, o).ok());
        const TtsResult first = synthesize(a, o);
        const TtsResult repeated = synthesize(a, o);
        QVERIFY(synthesize(b, o).ok());
        const TtsResult afterOther = synthesize(a, o);
        QVERIFY(first.ok() && repeated.ok() && afterOther.ok());
        for (const TtsResult *again : {&repeated, &afterOther}) {
            QCOMPARE(again->audio.samples.size(), first.audio.samples.size());
            QVERIFY(again->audio.samples == first.audio.samples);
            for (int k = 0; k < first.units.size(); ++k)
                QCOMPARE(again->units[k].start, first.units[k].start);
        }
    }

    // The voice file: the base voice's lines, the variant's attributes (not its name or
    // language), flutter off; nothing for a voice or variant that does not exist.
    void steadyVoiceFileContents()
    {
        QTemporaryDir data, out;
        QVERIFY(data.isValid() && out.isValid());
        QDir(data.path()).mkpath(QStringLiteral("lang/sit"));
        QDir(data.path()).mkpath(QStringLiteral("voices/!v"));
        auto write = [&](const QString &rel, const QByteArray &text) {
            QFile f(data.filePath(rel));
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(text);
        };
        write(QStringLiteral("lang/sit/cmn-Latn-pinyin"), "name Chinese\nlanguage cmn-latn-pinyin\npitch 80 118\n");
        write(QStringLiteral("voices/!v/f9"), "language variant\nname female9\npitch 142 220\nbreath 0 2\n");
        const QString plain = steadyVoiceFile(QStringLiteral("cmn-latn-pinyin"), data.path(), out.path());
        QVERIFY(!plain.isEmpty());
        QFile p(plain);
        QVERIFY(p.open(QIODevice::ReadOnly));
        QCOMPARE(p.readAll(), QByteArray("name Chinese\nlanguage cmn-latn-pinyin\npitch 80 118\nflutter 0\n"));
        const QString variant = steadyVoiceFile(QStringLiteral("cmn-latn-pinyin+f9"), data.path(), out.path());
        QVERIFY(!variant.isEmpty() && variant != plain);
        QFile v(variant);
        QVERIFY(v.open(QIODevice::ReadOnly));
        const QByteArray text = v.readAll();
        QVERIFY(text.startsWith("name Chinese\nlanguage cmn-latn-pinyin\n"));
        QVERIFY(text.contains("pitch 142 220\nbreath 0 2\n"));
        QVERIFY(!text.contains("female9") && !text.contains("language variant"));
        QVERIFY(text.endsWith("flutter 0\n"));
        // espeak-ng reads at most 59 characters of the path.
        QVERIFY(variant.size() - out.path().size() <= 10);
        QVERIFY(steadyVoiceFile(QStringLiteral("no-such-voice"), data.path(), out.path()).isEmpty());
        QVERIFY(steadyVoiceFile(QStringLiteral("cmn-latn-pinyin+nothing"), data.path(), out.path()).isEmpty());
        QVERIFY(steadyVoiceFile(QStringLiteral("cmn-latn-pinyin+../x"), data.path(), out.path()).isEmpty());
    }

    // Streaming to a sink gives the same samples and times as keeping them.
    void sinkGetsTheSameSamples()
    {
        const Script a = script(QStringLiteral("ni3 hao3 shi4 jie4"));
        const TtsResult kept = synthesize(a);
        QVector<float> streamed;
        int calls = 0;
        const TtsResult sunk = synthesize(a, {}, [&](const float *s, qsizetype n) {
            streamed.append(QVector<float>(s, s + n));
            ++calls;
        });
        QVERIFY(kept.ok() && sunk.ok());
        QVERIFY(sunk.audio.samples.isEmpty());
        QCOMPARE(sunk.audio.sampleRate, kept.audio.sampleRate);
        QVERIFY(calls > 1);
        QVERIFY(streamed == kept.audio.samples);
        QCOMPARE(sunk.duration, kept.duration);
        QCOMPARE(kept.duration, kept.audio.duration());
        QCOMPARE(sunk.units.size(), kept.units.size());
        for (int k = 0; k < kept.units.size(); ++k) {
            QCOMPARE(sunk.units[k].start, kept.units[k].start);
            QCOMPARE(sunk.units[k].end, kept.units[k].end);
        }
    }

    void cancel()
    {
        std::atomic_bool flag {true};
        const TtsResult r = synthesize(script(QStringLiteral("今天天气很好我们去公园散步")), {}, {}, &flag);
        QVERIFY(!r.ok());
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestTts)
#include "tst_tts.moc"
