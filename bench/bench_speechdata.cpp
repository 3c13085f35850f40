#include "speechdata.h"

#include "io/textgrid.h"
#include "speech/tts.h"

#include <QFile>
#include <QRandomGenerator>
#include <QTemporaryDir>

#include <algorithm>
#include <cmath>

namespace toonface::speechbench {

using Interval = TextGridInterval;

QJsonObject Errors::json() const
{
    QJsonObject o;
    auto r1 = [](double v) { return std::round(v * 10) / 10; };
    o.insert(QStringLiteral("onsets"), int(ms.size()));
    o.insert(QStringLiteral("medianMs"), r1(quantile(0.5)));
    o.insert(QStringLiteral("p90Ms"), r1(quantile(0.9)));
    o.insert(QStringLiteral("maxMs"), r1(quantile(1.0)));
    o.insert(QStringLiteral("within20Ms"), std::round(within(20) * 1000) / 1000);
    o.insert(QStringLiteral("within50Ms"), std::round(within(50) * 1000) / 1000);
    o.insert(QStringLiteral("signedMedianMs"), r1(quantileOf(signedMs, 0.5)));
    // How many of the onsets more than 80 ms off the aligner flagged as doubtful.
    int off = 0, offFlagged = 0, flaggedAll = 0;
    for (size_t k = 0; k < ms.size(); ++k) {
        flaggedAll += flagged[k] ? 1 : 0;
        if (ms[k] > 80) {
            ++off;
            offFlagged += flagged[k] ? 1 : 0;
        }
    }
    o.insert(QStringLiteral("offBy80Ms"), off);
    o.insert(QStringLiteral("offBy80MsFlagged"), offFlagged);
    o.insert(QStringLiteral("flagged"), flaggedAll);
    // The shares the editor's tint is judged by: of the onsets > 80 ms off, how many it marks;
    // of all, how many (a tint on every other syllable says nothing).
    o.insert(QStringLiteral("offBy80MsFlaggedShare"), off ? std::round(1000.0 * offFlagged / off) / 1000 : 1.0);
    o.insert(
        QStringLiteral("flaggedShare"), ms.empty() ? 0.0 : std::round(1000.0 * flaggedAll / double(ms.size())) / 1000);
    return o;
}

const QStringList &sentences()
{
    static const QStringList s = {
        QStringLiteral("今天天气很好，我们去公园散步吧。"),
        QStringLiteral("我爱北京天安门，天安门上太阳升。"),
        QStringLiteral("这个问题很难回答，请你再说一遍。"),
        QStringLiteral("小明每天早上六点起床，然后去学校上课。"),
        QStringLiteral("春眠不觉晓，处处闻啼鸟。夜来风雨声，花落知多少。"),
        QStringLiteral("银行的工作人员说，明天下午三点以后可以来取钱。"),
    };
    return s;
}

const Voice kVoices[4] = {{"cmn-latn-pinyin+f2", 140, 70}, {"cmn-latn-pinyin+m3", 230, 35},
    {"cmn-latn-pinyin+f4", 180, 85}, {"cmn-latn-pinyin+klatt", 120, 45}};

// Speakers no constant of the aligner was chosen on: espeak-ng variants, rates and pitches
// unlike kVoices (which speech.alignSynthetic reports) and the reference's default voice.
const Voice kHeldOutVoices[6]
    = {{"cmn-latn-pinyin+m1", 170, 40}, {"cmn-latn-pinyin+f5", 210, 75}, {"cmn-latn-pinyin+m7", 110, 30},
        {"cmn-latn-pinyin+klatt3", 260, 60}, {"cmn-latn-pinyin+croak", 150, 50}, {"cmn-latn-pinyin+f1", 125, 90}};

// The shared sentences and some whose tones change in context (一, 不, 3rd before 3rd).
QStringList heldOutSentences()
{
    return sentences()
        + QStringList {QStringLiteral("我们一起去买一本书，好不好？"), QStringLiteral("你不要一天到晚想这个问题。"),
            QStringLiteral("老李很少给小马打电话。"), QStringLiteral("一个人不是一座孤岛。")};
}

Audio syntheticRecording(
    const Script &script, const Voice &v, quint32 seed, std::vector<double> *truth, double snrDb, int *pausedBefore)
{
    TtsOptions o;
    o.voice = QString::fromLatin1(v.voice);
    o.rate = v.rate;
    o.pitch = v.pitch;
    const TtsResult r = synthesize(script, o);
    Audio spoken = resampled(r.audio, kSpeechSampleRate);
    QRandomGenerator rng(seed);
    const double lead = 0.3 + 0.6 * rng.generateDouble(), trail = 0.2 + 0.5 * rng.generateDouble();
    const int pauseAfter = 1 + int(rng.bounded(std::max(1, int(script.syllables.size()) - 2)));
    const double pause = 0.25 + 0.3 * rng.generateDouble();
    if (pausedBefore)
        *pausedBefore = pauseAfter;
    const double cut = r.units[pauseAfter].start;
    Audio out;
    out.samples.fill(0.0f, qsizetype(lead * kSpeechSampleRate));
    const qsizetype cutAt = qsizetype(cut * kSpeechSampleRate);
    out.samples += spoken.samples.mid(0, cutAt);
    out.samples += QVector<float>(qsizetype(pause * kSpeechSampleRate), 0.0f);
    out.samples += spoken.samples.mid(cutAt);
    out.samples += QVector<float>(qsizetype(trail * kSpeechSampleRate), 0.0f);
    double power = 0;
    for (float s : spoken.samples)
        power += double(s) * s;
    power /= std::max<qsizetype>(spoken.samples.size(), 1);
    const double sigma = std::sqrt(power / std::pow(10.0, snrDb / 10));
    for (float &s : out.samples) {
        // Box-Muller
        const double u1 = std::max(rng.generateDouble(), 1e-12), u2 = rng.generateDouble();
        s += float(sigma * std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * u2));
    }
    truth->clear();
    for (int k = 0; k < r.units.size(); ++k)
        truth->push_back(lead + r.units[k].start + (k >= pauseAfter ? pause : 0.0));
    return out;
}

Script mandarin(const QString &text)
{
    return parseScript(text, Language::Mandarin).script;
}

QVector<RealFile> realFiles(const QString &dir)
{
    QVector<RealFile> files;
    const QString speech = dir + QStringLiteral("/speech/");
    // AISHELL-3 sentence: character onsets from the words tier.
    {
        RealFile f {QStringLiteral("SSB00050015_16k.wav"), {}, {}, QStringLiteral("TextGrid words tier")};
        for (const Interval &w :
            readTextGridTier(speech + QStringLiteral("SSB00050015.TextGrid"), QStringLiteral("words"))) {
            if (w.text.startsWith(QLatin1Char('[')) || w.text.isEmpty())
                continue;
            f.script += w.text;
            f.truth.push_back(w.start);
        }
        files.append(f);
    }
    // Beijing disyllables: a hand-cut two-syllable word (C1 V1 C2 V2) inside a carrier
    // phrase. Neither the word nor the phrase is given: the waveform plot shows six syllables
    // (two, the word, two), so a neutral script of six "da1" stands for them; the truth is the
    // start of C1 and of C2 (syllables 3 and 4), the others have none (NaN).
    for (const char *name : {"beijing_f3_50_a", "beijing_m5_17_c"}) {
        RealFile f {QString::fromLatin1(name) + QStringLiteral(".wav"), QStringLiteral("da1 da1 da1 da1 da1 da1"), {},
            QStringLiteral("words not given: 6 syllables counted on the plot, neutral script 'da1' x6; truth = "
                           "starts of C1 and C2 for syllables 3 and 4")};
        f.truth.assign(6, std::nan(""));
        int k = 2;
        for (const Interval &w : readTextGridTier(
                 speech + QString::fromLatin1(name) + QStringLiteral(".TextGrid"), QStringLiteral("syll"))) {
            if (w.text.startsWith(QLatin1Char('C')) && k < 4)
                f.truth[size_t(k++)] = w.start;
        }
        files.append(f);
    }
    // Penn forced aligner's word tier: word onsets are the onsets of each word's first
    // syllable; the other syllables have none (NaN). Held out: measured, never tuned on.
    {
        RealFile f {QStringLiteral("p2fa_test1.wav"), {}, {},
            QStringLiteral("HELD OUT: TextGrid word tier (Penn forced aligner), word onsets scored")};
        for (const Interval &w :
            readTextGridTier(speech + QStringLiteral("p2fa_test1.TextGrid"), QStringLiteral("word"))) {
            if (w.text.isEmpty() || w.text == QLatin1String("sp") || w.text == QLatin1String("sil"))
                continue;
            f.script += w.text;
            f.truth.push_back(w.start);
            f.heldOut = true;
            for (size_t k = 1; k < w.text.toStdU32String().size(); ++k)
                f.truth.push_back(std::nan(""));
        }
        files.append(f);
    }
    for (const char *name : {"NST_ID001", "BAC009S0002W0122", "BAC009S0002W0123"}) {
        QFile t(speech + QString::fromLatin1(name) + QStringLiteral(".txt"));
        RealFile f {QString::fromLatin1(name) + QStringLiteral(".wav"), {}, {},
            QStringLiteral("transcript only: checked on a plot")};
        if (t.open(QIODevice::ReadOnly))
            f.script = QString::fromUtf8(t.readAll()).trimmed();
        files.append(f);
    }
    return files;
}

double shortestMs(const QVector<LipsyncSyllable> &syllables)
{
    double shortest = syllables.isEmpty() ? 0.0 : 1e9;
    for (const LipsyncSyllable &s : syllables)
        shortest = std::min(shortest, (s.end - s.start) * 1000.0);
    return shortest;
}

double lowestConfidence(const QVector<LipsyncSyllable> &syllables)
{
    double lowest = syllables.isEmpty() ? 0.0 : 1.0;
    for (const LipsyncSyllable &s : syllables)
        lowest = std::min(lowest, s.confidence);
    return lowest;
}

// Aligns `file` exactly as `toonface-cli lipsync` does (lipsyncFiles on the audio file and a
// script file).
LipsyncOutcome lipsyncRealFile(const QString &dir, const RealFile &file)
{
    QTemporaryDir tmp;
    const QString scriptPath = tmp.filePath(QStringLiteral("script.txt"));
    QFile s(scriptPath);
    if (!s.open(QIODevice::WriteOnly))
        return {};
    s.write(file.script.toUtf8());
    s.close();
    return lipsyncFiles(dir + QStringLiteral("/speech/") + file.name, scriptPath);
}

GridWordTier gridWordTier(const QString &dataDir)
{
    QStringList words;
    std::vector<double> onsets;
    QFile f(dataDir + QStringLiteral("/video/swwp2s.align"));
    if (!f.open(QIODevice::ReadOnly))
        return {};
    for (const QString &line : QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
        const QStringList cols = line.trimmed().split(QLatin1Char(' '), Qt::SkipEmptyParts);
        if (cols.size() == 3 && cols[2] != QLatin1String("sil")) {
            words.append(cols[2]);
            onsets.push_back(cols[0].toDouble() / 25000.0);
        }
    }
    return {words, onsets};
}

} // namespace toonface::speechbench
