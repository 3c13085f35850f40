#include "io/textgrid.h"
#include "shareddata.h"
#include "speech/aligner.h"
#include "speech/audio.h"
#include "speech/onsetsignals.h"
#include "speech/script.h"
#include "speech/tts.h"
#include "spokenrecordings.h"
#include "testmain.h"

#include <QFile>
#include <QProcess>
#include <QRandomGenerator>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>

using namespace toonface;
using namespace toonface::testing;

namespace {

// The AISHELL-3 sentence's characters and their onsets (seconds × scale + offset) from its
// TextGrid words tier.
QString ssbWords(const QString &dir, double scale, double offset, std::vector<double> *truth)
{
    QString text;
    truth->clear();
    for (const TextGridInterval &w :
        readTextGridTier(dir + QStringLiteral("SSB00050015.TextGrid"), QStringLiteral("words"))) {
        if (w.text.isEmpty() || w.text.startsWith(QLatin1Char('[')))
            continue;
        text += w.text;
        truth->push_back(w.start * scale + offset);
    }
    return text;
}

using Interval = TextGridInterval;

} // namespace

class TestAligner : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void syntheticSpeech_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("voice");
        QTest::addColumn<int>("rate");
        QTest::addColumn<int>("pitch");
        QTest::addColumn<double>("snr");
        // Voices, rates and pitches other than the reference's (cmn-latn-pinyin, matched rate).
        QTest::newRow("female slow") << QStringLiteral("今天天气很好，我们去公园散步吧。") << "cmn-latn-pinyin+f2"
                                     << 130 << 75 << 30.0;
        QTest::newRow("male fast") << QStringLiteral("这个问题很难回答，请你再说一遍。") << "cmn-latn-pinyin+m3" << 220
                                   << 35 << 25.0;
        QTest::newRow("klatt noisy") << QStringLiteral("小明每天早上六点起床，然后去学校上课。")
                                     << "cmn-latn-pinyin+klatt" << 150 << 50 << 15.0;
    }
    void syntheticSpeech()
    {
        QFETCH(QString, text);
        QFETCH(QString, voice);
        QFETCH(int, rate);
        QFETCH(int, pitch);
        QFETCH(double, snr);
        const Script script = mandarin(text);
        TtsOptions o;
        o.voice = voice;
        o.rate = rate;
        o.pitch = pitch;
        std::vector<double> truth;
        const Audio rec = recording(script, o, snr, quint32(rate + pitch), &truth);
        const AlignResult r = alignScript(rec, script);
        QVERIFY2(r.ok(), qPrintable(r.error));
        checkWellFormed(r, int(script.syllables.size()), rec.duration());
        const auto [median, p90] = onsetErrors(r, truth);
        // Tolerances: the bench's synthetic set has a median of about 17 ms; one file may be
        // worse, a broken aligner is far worse (hundreds of ms).
        QVERIFY2(median <= 45, qPrintable(QStringLiteral("median onset error %1 ms").arg(median)));
        QVERIFY2(p90 <= 200, qPrintable(QStringLiteral("90th percentile %1 ms").arg(p90)));
        // Speech found where it is: not in the leading or trailing silence.
        QVERIFY(r.speechStart > truth.front() - 0.1);
        QVERIFY(r.speechEnd < rec.duration() - 0.2);
    }

    // The initial after a nasal coda. A nasal or liquid initial continues the coda's murmur
    // (an-men, ming-mei, shang-liu, chun-mian, hen-nan, qing-ni), and the fall into the coda is
    // no onset: placed there, they came out 100-140 ms early. A voiceless one (shang-tai,
    // yang-sheng, hang-de, ming-tian, xiang-zhe) follows a fall into the coda as deep in the
    // voiced loudness as its own closure or frication: taken for its onset, it came out
    // 80-120 ms early.
    void initialAfterANasalCoda_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("voice");
        QTest::addColumn<int>("rate");
        QTest::addColumn<int>("pitch");
        QTest::addColumn<double>("snr");
        QTest::addColumn<bool>("voiceless"); // the initials checked: voiceless, or m n l r
        QTest::addColumn<double>("tolerance"); // ms
        QTest::newRow("tian an men") << QStringLiteral("我爱北京天安门，天安门上太阳升。") << "cmn-latn-pinyin+f4"
                                     << 180 << 85 << 30.0 << false << 80.0;
        QTest::newRow("ming mei") << QStringLiteral("小明每天早上六点起床。") << "cmn-latn-pinyin+f2" << 140 << 70
                                  << 30.0 << false << 80.0;
        QTest::newRow("chun mian") << QStringLiteral("春眠不觉晓，这个问题很难回答，请你再说一遍。")
                                   << "cmn-latn-pinyin+f4" << 160 << 60 << 30.0 << false << 80.0;
        QTest::newRow("qing ni croak") << QStringLiteral("这个问题很难回答，请你再说一遍。") << "cmn-latn-pinyin+croak"
                                       << 150 << 50 << 20.0 << false << 60.0;
        QTest::newRow("ming mei croak") << QStringLiteral("小明每天早上六点起床，然后去学校上课。")
                                        << "cmn-latn-pinyin+croak" << 150 << 50 << 20.0 << false << 60.0;
        QTest::newRow("shang tai") << QStringLiteral("我爱北京天安门，天安门上太阳升。") << "cmn-latn-pinyin+f5" << 210
                                   << 75 << 20.0 << true << 60.0;
        QTest::newRow("hang de") << QStringLiteral("银行的工作人员说，明天下午三点以后可以来取钱。")
                                 << "cmn-latn-pinyin+f5" << 210 << 75 << 20.0 << true << 60.0;
        QTest::newRow("xiang zhe") << QStringLiteral("你不要一天到晚想这个问题。") << "cmn-latn-pinyin+croak" << 150
                                   << 50 << 20.0 << true << 60.0;
    }
    void initialAfterANasalCoda()
    {
        QFETCH(QString, text);
        QFETCH(QString, voice);
        QFETCH(int, rate);
        QFETCH(int, pitch);
        QFETCH(double, snr);
        QFETCH(bool, voiceless);
        QFETCH(double, tolerance);
        const Script script = mandarin(text);
        TtsOptions o;
        o.voice = voice;
        o.rate = rate;
        o.pitch = pitch;
        std::vector<double> truth;
        const Audio rec = recording(script, o, snr, quint32(voiceless ? rate + pitch : rate), &truth);
        const AlignResult r = alignScript(rec, script);
        QVERIFY2(r.ok(), qPrintable(r.error));
        int checked = 0;
        QString errors;
        double worst = 0;
        for (int k = 1; k < script.syllables.size(); ++k) {
            const QString &before = script.syllables[k - 1].pinyin;
            const bool nasalCoda = before.endsWith(QLatin1Char('n')) || before.endsWith(QLatin1String("ng"));
            const OnsetKind kind = onsetKind(script.syllables[k]);
            const bool sonorant = QStringLiteral("mnlr").contains(script.syllables[k].pinyin.at(0));
            if (!nasalCoda || (voiceless ? kind != OnsetKind::Voiceless : !sonorant))
                continue;
            ++checked;
            const double error = (r.syllables[k].start - truth[size_t(k)]) * 1000;
            errors += QStringLiteral("%1 after %2: %3 ms; ").arg(script.syllables[k].pinyin, before).arg(error);
            worst = std::max(worst, std::abs(error));
        }
        QVERIFY2(worst <= tolerance, qPrintable(errors));
        QVERIFY(checked >= 2);
    }

    void syllableAfterAnUnmarkedPause_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<quint32>("seed");
        QTest::newRow("0") << QStringLiteral("今天天气很好，我们去公园散步吧。") << 1u;
        QTest::newRow("1") << QStringLiteral("这个问题很难回答，请你再说一遍。") << 2u;
        QTest::newRow("2") << QStringLiteral("小明每天早上六点起床，然后去学校上课。") << 3u;
        QTest::newRow("3") << QStringLiteral("我爱北京天安门，天安门上太阳升。") << 4u;
    }
    void syllableAfterAnUnmarkedPause()
    {
        // The klatt voice's syllables with a long nucleus tempted the segmentation to start the
        // syllable after a pause before it, in the nucleus of the one before.
        QFETCH(QString, text);
        QFETCH(quint32, seed);
        const Script script = mandarin(text);
        TtsOptions o;
        o.voice = QStringLiteral("cmn-latn-pinyin+klatt");
        o.rate = 120;
        o.pitch = 45;
        std::vector<double> truth;
        int paused = 0;
        const Audio rec = recording(script, o, 20, seed, &truth, &paused);
        const AlignResult r = alignScript(rec, script);
        QVERIFY2(r.ok(), qPrintable(r.error));
        const double error = (r.syllables[paused].start - truth[size_t(paused)]) * 1000;
        // Before the 0.3 s pause would be about -300 ms.
        QVERIFY2(error > -150, qPrintable(QStringLiteral("%1 ms").arg(error)));
    }

    void longSpeechUsesTheCoarseToFinePath()
    {
        // 40 s: more DTW cells than one full matrix allows.
        QString text;
        for (int i = 0; i < 6; ++i)
            text += QStringLiteral(
                "春眠不觉晓，处处闻啼鸟。夜来风雨声，花落知多少。银行的工作人员说，明天下午三点以后可以来取钱。");
        const Script script = mandarin(text);
        TtsOptions o;
        o.voice = QStringLiteral("cmn-latn-pinyin+f4");
        o.rate = 150;
        std::vector<double> truth;
        const Audio rec = recording(script, o, 30, 5, &truth);
        QVERIFY(rec.duration() > 35);
        const AlignResult r = alignScript(rec, script);
        QVERIFY2(r.ok(), qPrintable(r.error));
        checkWellFormed(r, int(script.syllables.size()), rec.duration());
        const auto [median, p90] = onsetErrors(r, truth);
        QVERIFY2(median <= 45 && p90 <= 200, qPrintable(QStringLiteral("%1 / %2 ms").arg(median).arg(p90)));
    }

    void piecesAtOtherLevelsAndPaces_data()
    {
        QTest::addColumn<QVector<double>>("gainsDb");
        QTest::addColumn<QVector<int>>("rates");
        QTest::newRow("quiet middle") << QVector<double> {0, -20, 0} << QVector<int> {150, 150, 150};
        QTest::newRow("loud end, slow start") << QVector<double> {-18, -18, 0} << QVector<int> {110, 170, 150};
        QTest::newRow("falling, fast middle") << QVector<double> {0, -10, -20} << QVector<int> {140, 210, 130};
    }
    void piecesAtOtherLevelsAndPaces()
    {
        // A recording joined from pieces (or a speaker turning away from the microphone): each
        // phrase at its own level and pace. Measured against the whole recording, the quiet
        // phrase's speech was taken for pauses and its syllables squeezed or misplaced.
        QFETCH(QVector<double>, gainsDb);
        QFETCH(QVector<int>, rates);
        const QStringList said = {QStringLiteral("银行的工作人员说明天下午三点以后可以来取钱"),
            QStringLiteral("小明每天早上六点起床然后去学校上课"), QStringLiteral("今天天气很好我们去公园散步吧")};
        QVector<QPair<Script, int>> parts;
        for (int p = 0; p < said.size(); ++p)
            parts.append({mandarin(said[p]), rates[p]});
        std::vector<double> truth;
        const Audio rec
            = pieces(parts, QStringLiteral("cmn-latn-pinyin+f2"), 0.5, 0.6, 40, 35, 11, &truth, 200, gainsDb);
        const Script script = mandarin(said.join(QString()));
        const AlignResult r = alignScript(rec, script);
        QVERIFY2(r.ok(), qPrintable(r.error));
        checkWellFormed(r, int(script.syllables.size()), rec.duration());
        checkNotSqueezed(r);
        const auto [median, p90] = onsetErrors(r, truth);
        QVERIFY2(median <= 30 && p90 <= 80, qPrintable(QStringLiteral("%1 / %2 ms").arg(median).arg(p90)));
    }

    void realMandarin_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("truthFile"); // TextGrid; empty: no timing truth
        QTest::addColumn<QString>("tier");
        QTest::addColumn<QString>("script"); // empty: the TextGrid's words are the script
        QTest::addColumn<int>("firstTruth"); // the syllable the TextGrid's first onset belongs to
        // AISHELL-3 sentence, character onsets from a forced aligner's words tier.
        QTest::newRow("SSB00050015") << "SSB00050015_16k.wav"
                                     << "SSB00050015.TextGrid"
                                     << "words" << QString() << 0;
        // Beijing disyllables: hand-cut C1 V1 C2 V2 of a word inside a carrier phrase; neither is
        // given. The waveform shows six syllables (two, the word, two): a neutral script of six
        // syllables stands for them, and C1 and C2 start syllables 3 and 4.
        QTest::newRow("beijing_f3_50_a") << "beijing_f3_50_a.wav"
                                         << "beijing_f3_50_a.TextGrid"
                                         << "syll"
                                         << "da1 da1 da1 da1 da1 da1" << 2;
        QTest::newRow("beijing_m5_17_c") << "beijing_m5_17_c.wav"
                                         << "beijing_m5_17_c.TextGrid"
                                         << "syll"
                                         << "da1 da1 da1 da1 da1 da1" << 2;
        // 48 kHz, transcript only: checked against its waveform plot (bench speech.plots).
        QTest::newRow("NST_ID001") << "NST_ID001.wav" << QString() << QString() << QStringLiteral("你好你好") << 0;
    }
    void realMandarin()
    {
        QFETCH(QString, file);
        QFETCH(QString, truthFile);
        QFETCH(QString, tier);
        QFETCH(QString, script);
        QFETCH(int, firstTruth);
        const QString dir = testing::sharedDataDir() + QStringLiteral("/speech/");
        if (!QFile::exists(dir + file))
            QSKIP(qPrintable(QStringLiteral("shared data (speech/%1) not present").arg(file)));
        QString text = script;
        std::vector<double> truth;
        for (const Interval &w : readTextGridTier(dir + truthFile, tier)) {
            if (w.text.isEmpty() || w.text.startsWith(QLatin1Char('[')))
                continue;
            if (tier == QLatin1String("words")) {
                text += w.text;
                truth.push_back(w.start);
            } else if (w.text.startsWith(QLatin1Char('C'))) {
                truth.push_back(w.start);
            }
        }
        const AudioResult audio = loadAudio(dir + file);
        QVERIFY2(audio.ok(), qPrintable(audio.error));
        const Script parsed = mandarin(text);
        const AlignResult r = alignScript(audio.audio, parsed);
        QVERIFY2(r.ok(), qPrintable(r.error));
        checkWellFormed(r, int(parsed.syllables.size()), audio.audio.duration());
        if (truthFile.isEmpty()) {
            // No timing truth: every syllable inside the speech found, none squeezed to nothing
            // (a syllable of natural speech lasts 80 ms and more).
            for (const AlignedSyllable &s : r.syllables) {
                QVERIFY(s.start >= r.speechStart - 1e-9 && s.end <= r.speechEnd + 1e-9);
                QVERIFY2(s.end - s.start >= 0.08, qPrintable(QStringLiteral("%1 s").arg(s.end - s.start)));
            }
            return;
        }
        QVERIFY(!truth.empty());
        AlignResult compared = r;
        compared.syllables = r.syllables.mid(firstTruth, qsizetype(truth.size()));
        QCOMPARE(compared.syllables.size(), qsizetype(truth.size()));
        const auto [median, p90] = onsetErrors(compared, truth);
        // The targets of the speech issue for real Mandarin (with two onsets per file, p90 is
        // the larger error).
        QVERIFY2(median <= 30 || truth.size() < 3, qPrintable(QStringLiteral("median %1 ms").arg(median)));
        QVERIFY2(p90 <= 80, qPrintable(QStringLiteral("p90 %1 ms").arg(p90)));
    }

    void realMandarinOtherVoicesAndPaces_data()
    {
        QTest::addColumn<QStringList>("effect");
        QTest::addColumn<double>("scale");
        QTest::addColumn<double>("offset");
        // The same recording made into other speakers: slower, faster, higher, lower, noisier,
        // with more silence around it (sox effects; truth moved accordingly).
        QTest::newRow("tempo 0.85") << QStringList {QStringLiteral("tempo"), QStringLiteral("0.85")} << 1 / 0.85 << 0.0;
        QTest::newRow("tempo 1.15") << QStringList {QStringLiteral("tempo"), QStringLiteral("1.15")} << 1 / 1.15 << 0.0;
        QTest::newRow("pitch +300") << QStringList {QStringLiteral("pitch"), QStringLiteral("300")} << 1.0 << 0.0;
        QTest::newRow("pitch -300") << QStringList {QStringLiteral("pitch"), QStringLiteral("-300")} << 1.0 << 0.0;
        QTest::newRow("padded") << QStringList {QStringLiteral("pad"), QStringLiteral("1.3"), QStringLiteral("0.8")}
                                << 1.0 << 1.3;
    }
    void realMandarinOtherVoicesAndPaces()
    {
        QFETCH(QStringList, effect);
        QFETCH(double, scale);
        QFETCH(double, offset);
        const QString dir = testing::sharedDataDir() + QStringLiteral("/speech/");
        if (!QFile::exists(dir + QStringLiteral("SSB00050015_16k.wav")))
            QSKIP("shared data (speech/SSB00050015_16k.wav) not present");
        const QString sox = QStandardPaths::findExecutable(QStringLiteral("sox"));
        if (sox.isEmpty())
            QSKIP("sox is not installed");
        QTemporaryDir tmp;
        const QString out = tmp.filePath(QStringLiteral("variant.wav"));
        QVERIFY(QProcess::execute(sox, QStringList {dir + QStringLiteral("SSB00050015_16k.wav"), out} + effect) == 0);
        std::vector<double> truth;
        const QString text = ssbWords(dir, scale, offset, &truth);
        const AudioResult audio = loadAudio(out);
        QVERIFY(audio.ok());
        const AlignResult r = alignScript(audio.audio, mandarin(text));
        QVERIFY2(r.ok(), qPrintable(r.error));
        const auto [median, p90] = onsetErrors(r, truth);
        // Looser than the targets for the original: these are harder (and espeak-ng renders
        // the reference a little differently depending on what it spoke before). The SSB
        // reference (a neural forced aligner) marks onsets about 20 ms before the acoustic
        // landmarks the aligner's second pass settles on (hand-cut boundaries: within 10 ms).
        QVERIFY2(median <= 40 && p90 <= 100, qPrintable(QStringLiteral("%1 / %2 ms").arg(median).arg(p90)));
    }

    // (After the real recordings: espeak-ng renders a reference a little differently depending
    // on what it spoke before, and beijing_m5_17_c's second onset is sensitive to that.)
    // Noise before the first word, louder than the quiet of the pauses later (and a hum under
    // everything): not silence by the whole band's energy. The warp took it for speech and drew
    // the first syllables into it (squeezed, and 100-800 ms early); now the mid band's pauses
    // count as silence for the warp, and the search window counts speech, not pauses.
    void noiseBeforeTheSpeech_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("voice");
        QTest::addColumn<int>("rate");
        QTest::addColumn<double>("leadSnr");
        QTest::newRow("f2") << QStringLiteral("你更喜欢老鹰还是鹦鹉") << "cmn-latn-pinyin+f2" << 150 << 15.0;
        QTest::newRow("m3") << QStringLiteral("这个问题很难回答，请你再说一遍。") << "cmn-latn-pinyin+m3" << 200
                            << 12.0;
        QTest::newRow("f4") << QStringLiteral("银行的工作人员说，明天下午三点以后可以来取钱。") << "cmn-latn-pinyin+f4"
                            << 170 << 15.0;
    }
    void noiseBeforeTheSpeech()
    {
        QFETCH(QString, text);
        QFETCH(QString, voice);
        QFETCH(int, rate);
        QFETCH(double, leadSnr);
        const Script script = mandarin(text);
        std::vector<double> truth;
        const Audio rec = pieces({{script, rate}}, voice, 0.9, 0, 30, 40, quint32(rate), &truth, leadSnr);
        const AlignResult r = alignScript(rec, script);
        QVERIFY2(r.ok(), qPrintable(r.error));
        checkWellFormed(r, int(script.syllables.size()), rec.duration());
        for (int k = 0; k < 2; ++k) {
            const double error = (r.syllables[k].start - truth[size_t(k)]) * 1000;
            QVERIFY2(std::abs(error) <= 60, qPrintable(QStringLiteral("syllable %1: %2 ms").arg(k).arg(error)));
        }
        const auto [median, p90] = onsetErrors(r, truth);
        QVERIFY2(median <= 45 && p90 <= 120, qPrintable(QStringLiteral("%1 / %2 ms").arg(median).arg(p90)));
        checkNotSqueezed(r);
    }

    // A real speaker (AISHELL-3) with the noise of a room before the first word: 0.9 s of hiss
    // and hum `leadSnr` dB under the speech, louder than the recording's own pauses.
    void realSpeakerAfterANoisyLead_data()
    {
        QTest::addColumn<double>("leadSnr");
        QTest::addColumn<double>("humShare");
        QTest::newRow("hiss 20 dB") << 20.0 << 0.0;
        QTest::newRow("hiss 15 dB") << 15.0 << 0.0;
        QTest::newRow("hum and hiss 15 dB") << 15.0 << 0.7;
        QTest::newRow("hum and hiss 10 dB") << 10.0 << 0.7;
    }
    void realSpeakerAfterANoisyLead()
    {
        QFETCH(double, leadSnr);
        QFETCH(double, humShare);
        const QString dir = testing::sharedDataDir() + QStringLiteral("/speech/");
        if (!QFile::exists(dir + QStringLiteral("SSB00050015_16k.wav")))
            QSKIP("shared data (speech/SSB00050015_16k.wav) not present");
        AudioResult audio = loadAudio(dir + QStringLiteral("SSB00050015_16k.wav"));
        QVERIFY(audio.ok());
        const Audio speech = resampled(audio.audio, kSpeechSampleRate);
        double power = 0;
        qsizetype loud = 0;
        for (float v : speech.samples)
            if (std::abs(v) > 0.02f) {
                power += double(v) * v;
                ++loud;
            }
        power /= double(std::max<qsizetype>(loud, 1));
        const double lead = 0.9;
        const double noise = std::sqrt(power / std::pow(10.0, leadSnr / 10));
        QRandomGenerator rng(11);
        Audio rec;
        rec.sampleRate = kSpeechSampleRate;
        for (int i = 0; i < int(lead * kSpeechSampleRate); ++i) {
            const double t = double(i) / kSpeechSampleRate;
            const double u1 = std::max(rng.generateDouble(), 1e-12), u2 = rng.generateDouble();
            const double hiss = std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * u2);
            const double hum
                = std::sqrt(2.0) * (std::sin(2 * M_PI * 50 * t) + 0.5 * std::sin(2 * M_PI * 150 * t)) / 1.118;
            // Faded in and out over 50 ms, as a room's noise is not switched.
            const double fade = std::min({1.0, t / 0.05, (lead - t) / 0.05});
            rec.samples.append(float(noise * fade * (humShare * hum + (1 - humShare) * hiss)));
        }
        rec.samples += speech.samples;
        std::vector<double> truth;
        const QString text = ssbWords(dir, 1.0, lead, &truth);
        const AlignResult r = alignScript(rec, mandarin(text));
        QVERIFY2(r.ok(), qPrintable(r.error));
        const auto [median, p90] = onsetErrors(r, truth);
        QVERIFY2(median <= 35 && p90 <= 100, qPrintable(QStringLiteral("%1 / %2 ms").arg(median).arg(p90)));
        checkNotSqueezed(r);
    }

    // Syllables the recording does not say (a script whose second half is another sentence
    // with as many syllables) come out less confident than those it does.
    void confidenceFlagsDoubtfulSyllables()
    {
        const QString said = QStringLiteral("今天天气很好，我们去公园散步吧。");
        const QString written = QStringLiteral("今天天气很好，春眠不觉晓花落吧。");
        std::vector<double> truth;
        const Audio rec
            = pieces({{mandarin(said), 160}}, QStringLiteral("cmn-latn-pinyin+f2"), 0.5, 0, 40, 30, 5, &truth);
        const Script script = mandarin(written);
        QCOMPARE(script.syllables.size(), mandarin(said).syllables.size());
        const AlignResult r = alignScript(rec, script);
        QVERIFY2(r.ok(), qPrintable(r.error));
        double right = 0, wrong = 0;
        for (int k = 0; k < 6; ++k)
            right += r.syllables[k].confidence / 6;
        for (int k = 6; k < 13; ++k)
            wrong += r.syllables[k].confidence / 7;
        QVERIFY2(wrong < right - 0.1, qPrintable(QStringLiteral("said %1, not said %2").arg(right).arg(wrong)));
    }

    // The editor's tint: syllables the aligner cannot have placed right (the script's second
    // half is words the recording does not say, so their onsets are wherever the warp ran) come
    // out below kDoubtfulConfidence, the ones it says mostly above it.
    void confidenceFlagsMisalignedSyllables()
    {
        const QString said = QStringLiteral("今天天气很好，我们去公园散步吧。");
        const QString written = QStringLiteral("今天天气很好，春眠不觉晓花落吧。");
        std::vector<double> truth;
        const Audio rec
            = pieces({{mandarin(said), 160}}, QStringLiteral("cmn-latn-pinyin+f2"), 0.5, 0, 40, 30, 5, &truth);
        const AlignResult r = alignScript(rec, mandarin(written));
        QVERIFY2(r.ok(), qPrintable(r.error));
        int flaggedSaid = 0, flaggedWrong = 0;
        QString figures;
        for (int k = 0; k < r.syllables.size(); ++k) {
            const bool flagged = r.syllables[k].confidence < kDoubtfulConfidence;
            (k < 6 ? flaggedSaid : flaggedWrong) += flagged ? 1 : 0;
            figures += QStringLiteral("%1 %2 ms %3; ")
                           .arg(k)
                           .arg(std::round((r.syllables[k].start - truth[size_t(k)]) * 1000))
                           .arg(r.syllables[k].confidence, 0, 'f', 2);
        }
        QVERIFY2(flaggedSaid <= 1, qPrintable(figures));
        QVERIFY2(flaggedWrong >= 3, qPrintable(figures));
    }

    // The editor's tint means something: over four voices and tempi reading ten sentences each
    // (noise 20 dB under the speech, a pause the script does not mark), most syllables more
    // than 80 ms off are flagged doubtful (15 of 19 with the model shipped), few syllables in all
    // (8 %). Recordings made unlike the benchmark's the model was fitted on (speechdata.h).
    void confidenceFlagsSyllablesFarOff()
    {
        const QStringList texts = {QStringLiteral("今天天气很好，我们去公园散步吧。"),
            QStringLiteral("我爱北京天安门，天安门上太阳升。"), QStringLiteral("这个问题很难回答，请你再说一遍。"),
            QStringLiteral("小明每天早上六点起床，然后去学校上课。"),
            QStringLiteral("春眠不觉晓，处处闻啼鸟。夜来风雨声，花落知多少。"),
            QStringLiteral("银行的工作人员说，明天下午三点以后可以来取钱。"),
            QStringLiteral("我们一起去买一本书，好不好？"), QStringLiteral("你不要一天到晚想这个问题。"),
            QStringLiteral("老李很少给小马打电话。"), QStringLiteral("一个人不是一座孤岛。")};
        const QVector<TtsOptions> voices = {{170, 40, 50, QStringLiteral("cmn-latn-pinyin+m1")},
            {210, 75, 50, QStringLiteral("cmn-latn-pinyin+f5")}, {120, 45, 50, QStringLiteral("cmn-latn-pinyin+klatt")},
            {150, 50, 50, QStringLiteral("cmn-latn-pinyin+croak")}};
        int all = 0, flagged = 0, off = 0, offFlagged = 0;
        quint32 seed = 40;
        for (const TtsOptions &voice : voices)
            for (const QString &text : texts) {
                const Script script = mandarin(text);
                std::vector<double> truth;
                const AlignResult r = alignScript(recording(script, voice, 20, seed++, &truth), script);
                QVERIFY2(r.ok(), qPrintable(r.error));
                for (int k = 0; k < r.syllables.size(); ++k) {
                    const bool doubtful = r.syllables[k].confidence < kDoubtfulConfidence;
                    const bool far = std::abs(r.syllables[k].start - truth[size_t(k)]) > 0.08;
                    ++all;
                    flagged += doubtful ? 1 : 0;
                    off += far ? 1 : 0;
                    offFlagged += far && doubtful ? 1 : 0;
                }
            }
        const QString figures = QStringLiteral("%1 of %2 syllables > 80 ms off flagged, %3 of %4 in all")
                                    .arg(offFlagged)
                                    .arg(off)
                                    .arg(flagged)
                                    .arg(all);
        QVERIFY2(off >= 3, qPrintable(figures));
        // 70 %: looking for the pause before a voiceless initial over the initial's length
        // (hiddeninitials.cpp) put three flagged syllables back within 80 ms (h +148, h +112,
        // t +91 ms): 15 of 19 flagged became 12 of 17; the five unflagged are the same ones.
        QVERIFY2(offFlagged >= 0.7 * off && flagged <= 0.1 * all, qPrintable(figures));
    }

    // A syllable whose initial is a long noise (h, an aspirated stop) after a pause the script
    // does not mark, in a slow voice and a noisy recording: the noise of the initial sinks into
    // the pause's, and the onset must not be put at the vowel, an initial's length late.
    void noisyInitialHiddenInAPause()
    {
        const Script first = mandarin(QStringLiteral("这个问题")), second = mandarin(QStringLiteral("很难回答"));
        std::vector<double> truth;
        const Audio rec
            = pieces({{first, 110}, {second, 110}}, QStringLiteral("cmn-latn-pinyin+m7"), 0.5, 0.35, 60, 20, 9, &truth);
        const AlignResult r = alignScript(rec, mandarin(QStringLiteral("这个问题很难回答")));
        QVERIFY2(r.ok(), qPrintable(r.error));
        const double error = (r.syllables[4].start - truth[4]) * 1000;
        QVERIFY2(std::abs(error) <= 80, qPrintable(QStringLiteral("很 off by %1 ms").arg(error)));
    }

    // The first syllable of a recording and the one after a pause the script does not mark,
    // each with a voiceless initial: its noise lies above the mid band the pauses are found by
    // (and under the noise of a noisy recording), so the pause seemed to run up to the vowel
    // and the onset landed there, 40-105 ms late (a mouth late after every pause). Voices the
    // held-out figures are not measured on, in a noisy (20 dB) and a clean (45 dB) recording.
    void voicelessInitialAfterAPause_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("voice");
        QTest::addColumn<int>("rate");
        QTest::addColumn<double>("snrDb");
        const QString question = QStringLiteral("这个问题很难回答，请你再说一遍。");
        QTest::newRow("zh f2 noisy") << question << QStringLiteral("cmn-latn-pinyin+f2") << 140 << 20.0;
        QTest::newRow("zh klatt noisy") << question << QStringLiteral("cmn-latn-pinyin+klatt") << 120 << 20.0;
        QTest::newRow("q, t f4 noisy") << QStringLiteral("请你再说一遍，这个问题很难回答。")
                                       << QStringLiteral("cmn-latn-pinyin+f4") << 180 << 20.0;
        QTest::newRow("ch m3 noisy") << QStringLiteral("春眠不觉晓，处处闻啼鸟。")
                                     << QStringLiteral("cmn-latn-pinyin+m3") << 230 << 20.0;
        QTest::newRow("ch f2 clean") << QStringLiteral("春眠不觉晓，处处闻啼鸟。")
                                     << QStringLiteral("cmn-latn-pinyin+f2") << 140 << 45.0;
        const QString morning = QStringLiteral("小明每天早上六点起床，然后去学校上课。");
        QTest::newRow("x, h f4 clean") << morning << QStringLiteral("cmn-latn-pinyin+f4") << 180 << 45.0;
        QTest::newRow("x, h klatt clean") << morning << QStringLiteral("cmn-latn-pinyin+klatt") << 120 << 45.0;
    }
    void voicelessInitialAfterAPause()
    {
        QFETCH(QString, text);
        QFETCH(QString, voice);
        QFETCH(int, rate);
        QFETCH(double, snrDb);
        const Script script = mandarin(text);
        std::vector<double> truth;
        int paused = 0;
        const Audio rec = recording(script, {rate, 50, 50, voice}, snrDb, 3, &truth, &paused);
        const AlignResult r = alignScript(rec, script);
        QVERIFY2(r.ok(), qPrintable(r.error));
        for (const int k : {0, paused}) {
            const double error = (r.syllables[k].start - truth[size_t(k)]) * 1000;
            QVERIFY2(std::abs(error) <= 35,
                qPrintable(
                    QStringLiteral("%1 (syllable %2) off by %3 ms").arg(script.syllables[k].text).arg(k).arg(error)));
        }
    }

    // A pause the script does not mark with a loud breath in it (noise 10 dB under the
    // speech, 0.2 s, between two quiet stretches), the phrase before it spoken as a phrase's
    // end: the breath belongs to the pause. Counted as speech, it split the pause and drew the
    // syllables either side into it: runs of three to five slid by 0.1-0.7 s.
    void breathInAnUnmarkedPause_data()
    {
        QTest::addColumn<QString>("before");
        QTest::addColumn<QString>("after");
        QTest::addColumn<QString>("voice");
        QTest::addColumn<int>("rate");
        QTest::addColumn<double>("gap");
        QTest::newRow("klatt3 fast") << QStringLiteral("我爱") << QStringLiteral("北京天安门，天安门上太阳升。")
                                     << QStringLiteral("cmn-latn-pinyin+klatt3") << 260 << 0.61;
        QTest::newRow("m7 slow") << QStringLiteral("我们一起去") << QStringLiteral("买一本书，好不好？")
                                 << QStringLiteral("cmn-latn-pinyin+m7") << 110 << 0.41;
    }
    void breathInAnUnmarkedPause()
    {
        QFETCH(QString, before);
        QFETCH(QString, after);
        QFETCH(QString, voice);
        QFETCH(int, rate);
        QFETCH(double, gap);
        const Script first = mandarin(before), second = mandarin(after);
        std::vector<double> truth;
        Audio rec = pieces({{first, rate}, {second, rate}}, voice, 0.5, gap, 60, 20, 11, &truth);
        // The breath: in the middle of the gap before the second piece's first onset.
        const int k = int(first.syllables.size());
        double power = 0;
        qsizetype loud = 0;
        for (const float s : rec.samples)
            if (std::abs(s) > 0.01f) {
                power += double(s) * s;
                ++loud;
            }
        power /= double(std::max<qsizetype>(loud, 1));
        const qsizetype length = qsizetype(0.2 * kSpeechSampleRate);
        const qsizetype from = qsizetype((truth[size_t(k)] - 0.5 * gap - 0.1) * kSpeechSampleRate);
        const double amplitude = std::sqrt(3 * power / 10.0);
        QRandomGenerator rng(12);
        for (qsizetype i = 0; i < length; ++i)
            rec.samples[from + i]
                += float(amplitude * std::sin(M_PI * double(i) / double(length)) * (2 * rng.generateDouble() - 1));
        const Script script = mandarin(before + after);
        const AlignResult r = alignScript(rec, script);
        QVERIFY2(r.ok(), qPrintable(r.error));
        for (int q = 0; q < r.syllables.size(); ++q) {
            const double error = (r.syllables[q].start - truth[size_t(q)]) * 1000;
            QVERIFY2(std::abs(error) <= 150,
                qPrintable(
                    QStringLiteral("%1 (syllable %2) off by %3 ms").arg(script.syllables[q].text).arg(q).arg(error)));
        }
    }

    void silenceCannotBeAligned()
    {
        Audio quiet;
        for (int i = 0; i < 3 * kSpeechSampleRate; ++i)
            quiet.samples.append(float(1e-4 * std::sin(i * 0.37)));
        const AlignResult r = alignScript(quiet, mandarin(QStringLiteral("你好")));
        QCOMPARE(r.status, AlignStatus::CannotAlign);
        QVERIFY2(r.error.contains(QStringLiteral("no speech")), qPrintable(r.error));
    }

    void scriptFarTooLongForTheAudio()
    {
        const Script shortScript = mandarin(QStringLiteral("你好"));
        const Audio spoken = resampled(synthesize(shortScript).audio, kSpeechSampleRate);
        QString text;
        for (int i = 0; i < 10; ++i)
            text += QStringLiteral("今天天气很好我们去公园散步吧");
        const AlignResult r = alignScript(spoken, mandarin(text));
        QCOMPARE(r.status, AlignStatus::CannotAlign);
        QVERIFY2(r.error.contains(QStringLiteral("far too long")), qPrintable(r.error));
    }

    void emptyInputs()
    {
        QCOMPARE(alignScript(Audio {}, mandarin(QStringLiteral("你好"))).status, AlignStatus::BadInput);
        Audio some;
        some.samples.fill(0.1f, 16000);
        QCOMPARE(alignScript(some, Script {}).status, AlignStatus::BadInput);
    }

    void progressAndCancel()
    {
        const Script script = mandarin(QStringLiteral("今天天气很好"));
        const Audio spoken = resampled(synthesize(script).audio, kSpeechSampleRate);
        double last = -1;
        bool monotone = true;
        const AlignResult ok = alignScript(spoken, script, {}, [&](double f, const QString &) {
            monotone = monotone && f >= last;
            last = f;
        });
        QVERIFY(ok.ok());
        QVERIFY(monotone);
        QCOMPARE(last, 1.0);
        std::atomic_bool cancel {true};
        QCOMPARE(alignScript(spoken, script, {}, {}, &cancel).status, AlignStatus::Cancelled);
    }

    void referencePhonemesAreMappedInsideTheirSyllable()
    {
        const Script script = mandarin(QStringLiteral("喵喵"));
        TtsOptions o;
        o.voice = QStringLiteral("cmn-latn-pinyin+f3");
        const Audio spoken = resampled(synthesize(script, o).audio, kSpeechSampleRate);
        const AlignResult r = alignScript(spoken, script);
        QVERIFY(r.ok());
        for (const AlignedSyllable &s : r.syllables) {
            QVERIFY(!s.phonemes.isEmpty());
            for (const TtsPhoneme &p : s.phonemes)
                QVERIFY(p.start >= s.start - 1e-9 && p.start <= s.end + 1e-9);
        }
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestAligner)
#include "tst_aligner.moc"
