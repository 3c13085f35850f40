#include "benchmark.h"

#include "speech/aligner.h"
#include "speech/audio.h"
#include "speech/script.h"
#include "speech/tts.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QRandomGenerator>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>

using namespace toonface;

namespace {

struct Interval
{
    double start, end;
    QString text;
};

// The intervals of the tier named `tier` of a Praat TextGrid (long or short text format).
QVector<Interval> readTextGrid(const QString &path, const QString &tier)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    QString text = QString::fromUtf8(f.readAll());
    text.remove(QRegularExpression(QStringLiteral("\\[\\d+\\]")));
    QStringList tokens;
    const QRegularExpression tok(QStringLiteral("\"((?:[^\"]|\"\")*)\"|(-?\\d+(?:\\.\\d+)?(?:[eE][-+]?\\d+)?)"));
    for (auto it = tok.globalMatch(text); it.hasNext();) {
        const auto m = it.next();
        tokens.append(m.capturedStart(1) >= 0 ? QStringLiteral("\"") + m.captured(1) : m.captured(2));
    }
    QVector<Interval> out;
    for (int i = 0; i + 4 < tokens.size(); ++i) {
        if (tokens[i] != QLatin1String("\"IntervalTier"))
            continue;
        const QString name = tokens[i + 1].mid(1);
        const int count = tokens[i + 4].toInt();
        if (name != tier)
            continue;
        for (int k = 0; k < count && i + 5 + 3 * k + 2 < tokens.size(); ++k) {
            const int at = i + 5 + 3 * k;
            out.append({tokens[at].toDouble(), tokens[at + 1].toDouble(), tokens[at + 2].mid(1)});
        }
        break;
    }
    return out;
}

struct Errors
{
    std::vector<double> ms;
    void add(double a, double b) { ms.push_back(std::abs(a - b) * 1000.0); }
    double quantile(double q) const
    {
        if (ms.empty())
            return 0;
        std::vector<double> v = ms;
        std::sort(v.begin(), v.end());
        return v[std::min(v.size() - 1, size_t(q * double(v.size() - 1) + 0.5))];
    }
    QJsonObject json() const
    {
        QJsonObject o;
        o.insert(QStringLiteral("onsets"), int(ms.size()));
        o.insert(QStringLiteral("medianMs"), std::round(quantile(0.5) * 10) / 10);
        o.insert(QStringLiteral("p90Ms"), std::round(quantile(0.9) * 10) / 10);
        o.insert(QStringLiteral("maxMs"), std::round(quantile(1.0) * 10) / 10);
        return o;
    }
};

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

struct Voice
{
    const char *voice;
    int rate, pitch;
};
const Voice kVoices[] = {{"cmn-latn-pinyin+f2", 140, 70}, {"cmn-latn-pinyin+m3", 230, 35},
    {"cmn-latn-pinyin+f4", 180, 85}, {"cmn-latn-pinyin+klatt", 120, 45}};

// A synthetic recording: the script spoken in `v`, with leading and trailing silence, a pause
// the script does not mark, and white noise at 20 dB SNR; `truth` gets its syllable onsets.
Audio syntheticRecording(const Script &script, const Voice &v, quint32 seed, std::vector<double> *truth)
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
    const double sigma = std::sqrt(power / 100.0); // 20 dB
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

} // namespace

TOONFACE_BENCHMARK("speech.alignSynthetic", [] {
    Errors all;
    QJsonArray perVoice;
    quint32 seed = 1;
    for (const Voice &v : kVoices) {
        Errors e;
        for (const QString &text : sentences()) {
            const Script s = mandarin(text);
            std::vector<double> truth;
            const Audio rec = syntheticRecording(s, v, seed++, &truth);
            const AlignResult r = alignScript(rec, s);
            if (!r.ok())
                continue;
            for (int k = 0; k < r.syllables.size(); ++k) {
                e.add(r.syllables[k].start, truth[size_t(k)]);
                all.add(r.syllables[k].start, truth[size_t(k)]);
            }
        }
        QJsonObject o = e.json();
        o.insert(QStringLiteral("voice"), QString::fromLatin1(v.voice));
        o.insert(QStringLiteral("rate"), v.rate);
        o.insert(QStringLiteral("pitch"), v.pitch);
        perVoice.append(o);
    }
    QJsonObject out = all.json();
    out.insert(QStringLiteral("what"),
        QStringLiteral("espeak-ng voices other than the reference's, 20 dB white noise, "
                       "leading/trailing silence and one unmarked pause"));
    out.insert(QStringLiteral("voices"), perVoice);
    return out;
});

TOONFACE_BENCHMARK("speech.alignReal", [] {
    QJsonObject out;
    const QString dir = bench::sharedDataDir();
    if (dir.isEmpty()) {
        out.insert(QStringLiteral("skipped"), QStringLiteral("no shared data"));
        return out;
    }
    Errors all;
    QJsonArray files;
    // AISHELL-3 sentence: character onsets from the words tier.
    {
        const QVector<Interval> words
            = readTextGrid(dir + QStringLiteral("/speech/SSB00050015.TextGrid"), QStringLiteral("words"));
        QString text;
        std::vector<double> truth;
        for (const Interval &w : words) {
            if (w.text.startsWith(QLatin1Char('[')) || w.text.isEmpty())
                continue;
            text += w.text;
            truth.push_back(w.start);
        }
        const AudioResult a = loadAudio(dir + QStringLiteral("/speech/SSB00050015_16k.wav"));
        const ScriptParse s = parseScript(text);
        if (a.ok() && s.ok()) {
            const AlignResult r = alignScript(a.audio, s.script);
            Errors e;
            QJsonArray onsets;
            if (r.ok()) {
                for (int k = 0; k < r.syllables.size() && size_t(k) < truth.size(); ++k) {
                    e.add(r.syllables[k].start, truth[size_t(k)]);
                    all.add(r.syllables[k].start, truth[size_t(k)]);
                    onsets.append(std::round((r.syllables[k].start - truth[size_t(k)]) * 1000));
                }
            }
            QJsonObject o = e.json();
            o.insert(QStringLiteral("file"), QStringLiteral("SSB00050015_16k.wav"));
            o.insert(QStringLiteral("signedErrorsMs"), onsets);
            o.insert(QStringLiteral("status"), r.ok() ? QStringLiteral("ok") : r.error);
            files.append(o);
        }
    }
    // GRID (English): word onsets, units of 1/25000 s.
    {
        QFile f(dir + QStringLiteral("/video/swwp2s.align"));
        const AudioResult a = loadAudio(dir + QStringLiteral("/video/id2_vcd_swwp2s.mpg"));
        if (f.open(QIODevice::ReadOnly) && a.ok()) {
            QStringList words;
            std::vector<double> truth;
            for (const QString &line : QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
                const QStringList cols = line.trimmed().split(QLatin1Char(' '), Qt::SkipEmptyParts);
                if (cols.size() == 3 && cols[2] != QLatin1String("sil")) {
                    words.append(cols[2]);
                    truth.push_back(cols[0].toDouble() / 25000.0);
                }
            }
            const AlignResult r = alignScript(a.audio, parseScript(words.join(QLatin1Char(' '))).script);
            Errors e;
            for (int k = 0; r.ok() && k < r.syllables.size(); ++k)
                e.add(r.syllables[k].start, truth[size_t(k)]);
            QJsonObject o = e.json();
            o.insert(QStringLiteral("file"),
                QStringLiteral("id2_vcd_swwp2s.mpg (English words, not in the Mandarin figures)"));
            files.append(o);
        }
    }
    out = all.json();
    out.insert(QStringLiteral("files"), files);
    return out;
});

namespace {

// About `seconds` of synthetic Mandarin speech (a voice other than the reference's) with its
// script; the sentences repeat.
std::pair<Audio, Script> longRecording(double seconds)
{
    TtsOptions o;
    o.voice = QStringLiteral("cmn-latn-pinyin+f2");
    o.rate = 160;
    QString round = sentences().join(QString());
    const double perRound = synthesize(mandarin(round), o).audio.duration();
    QString text;
    for (int k = 0; k < std::max(1, int(std::ceil(seconds / perRound))); ++k)
        text += round;
    if (seconds < perRound) // a prefix of the sentences
        text = round.left(int(round.size() * seconds / perRound) + 1);
    const Script script = mandarin(text);
    return {resampled(synthesize(script, o).audio, kSpeechSampleRate), script};
}

const double kSpeedLengths[] = {10.0, 60.0, 600.0}; // seconds

} // namespace

TOONFACE_BENCHMARK("speech.alignSpeed", [] {
    QJsonObject out;
    for (const double seconds : kSpeedLengths) {
        const auto recording = longRecording(seconds);
        const Audio &audio = recording.first;
        const Script &script = recording.second;
        AlignResult r;
        const double ms = bench::medianMs([&] { r = alignScript(audio, script); }, seconds > 100 ? 1 : 3, 0);
        QJsonObject o;
        o.insert(QStringLiteral("audioSeconds"), std::round(audio.duration() * 10) / 10);
        o.insert(QStringLiteral("syllables"), int(script.syllables.size()));
        o.insert(QStringLiteral("alignMs"), std::round(ms));
        o.insert(QStringLiteral("timesRealTime"), std::round(audio.duration() * 1000.0 / ms));
        o.insert(QStringLiteral("ok"), r.ok());
        out.insert(QStringLiteral("%1s").arg(int(seconds)), o);
    }
    out.insert(QStringLiteral("what"), QStringLiteral("alignScript on one core, reference rendering included"));
    return out;
});
