#include "speech/aligner.h"
#include "speech/audio.h"
#include "speech/script.h"
#include "speech/tts.h"

#include <QRandomGenerator>
#include <QTest>

#include <algorithm>
#include <cmath>

using namespace toonface;

namespace {

// A clause spoken in another voice, with `lead` s of silence before and 0.4 s after, faint
// white noise over all of it (`snrDb` under the speech), and, when `pause` > 0, `pause`
// seconds inserted before syllable `at` that the script does not mark: silence, or a breath
// (noise 30 dB under the speech, band-limited by a one-pole low-pass) when `breath`.
// `pauseStart` gets where the inserted stretch begins.
Audio clause(const TtsResult &spoken, int at, double pause, bool breath, double *pauseStart)
{
    const QVector<float> speech = resampled(spoken.audio, kSpeechSampleRate).samples;
    double power = 0;
    qsizetype loud = 0;
    for (float s : speech)
        if (std::abs(s) > 1e-4f) {
            power += double(s) * s;
            ++loud;
        }
    power /= double(std::max<qsizetype>(loud, 1));
    const double lead = 0.5;
    const qsizetype cut = qsizetype(spoken.units[at].start * kSpeechSampleRate);
    *pauseStart = lead + double(cut) / kSpeechSampleRate;
    Audio out;
    out.samples.fill(0.0f, qsizetype(lead * kSpeechSampleRate));
    out.samples += speech.mid(0, cut);
    QVector<float> gap(qsizetype(pause * kSpeechSampleRate), 0.0f);
    if (breath) {
        QRandomGenerator rng(7);
        const double sigma = std::sqrt(power / std::pow(10.0, 30.0 / 10)) * 2.0;
        double low = 0;
        for (qsizetype i = 0; i < gap.size(); ++i) {
            const double u1 = std::max(rng.generateDouble(), 1e-12), u2 = rng.generateDouble();
            low += 0.3 * (sigma * std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * u2) - low);
            // Rising and falling over the breath.
            gap[i] = float(low * std::sin(M_PI * double(i) / double(gap.size())));
        }
    }
    out.samples += gap;
    out.samples += speech.mid(cut);
    out.samples += QVector<float>(qsizetype(0.4 * kSpeechSampleRate), 0.0f);
    const double sigma = std::sqrt(power / std::pow(10.0, 40.0 / 10));
    QRandomGenerator rng(3);
    for (float &s : out.samples) {
        const double u1 = std::max(rng.generateDouble(), 1e-12), u2 = rng.generateDouble();
        s += float(sigma * std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * u2));
    }
    return out;
}

} // namespace

class TestAlignerPauses : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void unmarkedPauseInsideAClause_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("voice");
        QTest::addColumn<int>("rate");
        QTest::addColumn<double>("pause");
        QTest::addColumn<bool>("breath");
        // Clauses with no punctuation inside; the pause goes before the middle syllable.
        const QStringList texts = {QStringLiteral("我们明天早上一起去公园散步然后回家吃饭"),
            QStringLiteral("这个问题其实很难回答请你再仔细想一想"),
            QStringLiteral("银行的工作人员说明天下午三点以后可以来取钱")};
        const QStringList voices = {QStringLiteral("cmn-latn-pinyin+f2"), QStringLiteral("cmn-latn-pinyin+m3"),
            QStringLiteral("cmn-latn-pinyin+klatt")};
        const int rates[] = {150, 190, 130};
        for (int t = 0; t < texts.size(); ++t)
            for (const double pause : {0.3, 0.6, 1.2})
                for (const bool breath : {false, true})
                    QTest::addRow("%d %s %.1fs %s", t, qPrintable(voices[t]), pause, breath ? "breath" : "silence")
                        << texts[t] << voices[t] << rates[t] << pause << breath;
    }
    void unmarkedPauseInsideAClause()
    {
        // A speaker pauses (a breath, a hesitation) where the script has no punctuation: the
        // reference runs on without a pause there. Every onset should be where it is without
        // the pause (moved by the pause after it), and neither syllable next to the pause
        // should reach into it.
        QFETCH(QString, text);
        QFETCH(QString, voice);
        QFETCH(int, rate);
        QFETCH(double, pause);
        QFETCH(bool, breath);
        const Script script = parseScript(text, Language::Mandarin).script;
        TtsOptions o;
        o.voice = voice;
        o.rate = rate;
        const TtsResult spoken = synthesize(script, o);
        QVERIFY2(spoken.ok(), qPrintable(spoken.error));
        const int n = int(script.syllables.size());
        const int at = n / 2;
        double pauseStart = 0, unused = 0;
        const AlignResult plain = alignScript(clause(spoken, at, 0.0, false, &unused), script);
        const AlignResult paused = alignScript(clause(spoken, at, pause, breath, &pauseStart), script);
        QVERIFY2(plain.ok() && paused.ok(), qPrintable(plain.error + paused.error));
        QCOMPARE(paused.syllables.size(), n);
        double worst = 0;
        int worstAt = 0;
        for (int k = 0; k < n; ++k) {
            const double expected = plain.syllables[k].start + (k >= at ? pause : 0.0);
            const double error = std::abs(paused.syllables[k].start - expected);
            if (error > worst) {
                worst = error;
                worstAt = k;
            }
        }
        QVERIFY2(worst <= 0.03,
            qPrintable(QStringLiteral("syllable %1 (%2, pause before %3) is %4 ms from its place without the pause")
                           .arg(worstAt)
                           .arg(script.syllables[worstAt].pinyin)
                           .arg(at)
                           .arg(worst * 1000, 0, 'f', 0)));
        // The syllable before the pause ends where its sound ends, the one after starts where
        // its sound starts.
        QVERIFY2(paused.syllables[at - 1].end <= pauseStart + 0.03,
            qPrintable(QStringLiteral("%1 runs %2 ms into the pause")
                           .arg(script.syllables[at - 1].pinyin)
                           .arg((paused.syllables[at - 1].end - pauseStart) * 1000, 0, 'f', 0)));
        QVERIFY2(paused.syllables[at].start >= pauseStart + pause - 0.03,
            qPrintable(QStringLiteral("%1 starts %2 ms inside the pause")
                           .arg(script.syllables[at].pinyin)
                           .arg((pauseStart + pause - paused.syllables[at].start) * 1000, 0, 'f', 0)));
    }
};

QTEST_GUILESS_MAIN(TestAlignerPauses)
#include "tst_alignerpauses.moc"
