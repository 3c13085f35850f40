#include "benchmark.h"
#include "speechdata.h"

#include "speech/aligner.h"
#include "speech/audio.h"
#include "speech/lipsync.h"
#include "speech/pinyin.h"
#include "speech/script.h"

#include <QFile>
#include <QJsonArray>
#include <QMap>

#include <algorithm>
#include <cmath>

using namespace toonface;
using namespace toonface::speechbench;

namespace {

QJsonArray rounded(const std::vector<double> &v)
{
    QJsonArray a;
    for (const double x : v)
        a.append(std::isnan(x) ? QJsonValue(QJsonValue::Null) : QJsonValue(std::round(x)));
    return a;
}

// The shared data's Mandarin files, each against its reference onsets.
QJsonArray realFileFigures(const QString &dir, Errors *developed, Errors *heldOut)
{
    QJsonArray files;
    for (const RealFile &file : realFiles(dir)) {
        if (!QFile::exists(dir + QStringLiteral("/speech/") + file.name))
            continue;
        const LipsyncOutcome r = lipsyncRealFile(dir, file);
        Errors e;
        QJsonArray onsets;
        std::vector<double> signedErrors;
        for (int k = 0; r.ok() && k < r.result.syllables.size(); ++k) {
            const LipsyncSyllable &s = r.result.syllables[k];
            onsets.append(std::round(s.start * 1000));
            if (size_t(k) >= file.truth.size())
                continue;
            const double truth = file.truth[size_t(k)];
            signedErrors.push_back(std::isnan(truth) ? truth : (s.start - truth) * 1000);
            if (!std::isnan(truth))
                e.add(s.start, truth, s.confidence);
        }
        (file.heldOut ? heldOut : developed)->add(e);
        QJsonObject o = file.truth.empty() ? QJsonObject {} : e.json();
        o.insert(QStringLiteral("file"), file.name);
        o.insert(QStringLiteral("heldOut"), file.heldOut);
        o.insert(QStringLiteral("shortestSyllableMs"), std::round(shortestMs(r.result.syllables)));
        o.insert(QStringLiteral("lowestConfidence"), std::round(lowestConfidence(r.result.syllables) * 100) / 100);
        o.insert(QStringLiteral("truth"), file.note);
        o.insert(QStringLiteral("onsetsMs"), onsets);
        if (!file.truth.empty())
            o.insert(QStringLiteral("signedErrorsMs"), rounded(signedErrors));
        o.insert(QStringLiteral("status"), r.ok() ? QStringLiteral("ok") : r.error);
        files.append(o);
    }
    return files;
}

// One held-out syllable far off, with what it may share with the others: its initial and
// tone, the silence before it (the sentence's start or an inserted pause), its neighbours.
struct Miss
{
    double signedMs;
    QJsonObject what;
};

// The syllables a pause comes before: the recording's first, the one after the pause the
// recording inserts (`pausedBefore`), those after a break the script marks. After a pause the
// mouth is seen to start; an onset late there is a mouth late after every pause.
bool afterAPause(const Script &s, int k, int pausedBefore)
{
    return k == 0 || k == pausedBefore || s.syllables[k - 1].phraseBreakAfter;
}

// The onsets after a pause, all and by initial (a stop's closure is silent as the pause is;
// a fricative's noise is heard): where the mouth starts late, which initials it is.
struct AfterPause
{
    Errors all;
    QMap<QString, Errors> byInitial;
    void add(const QString &pinyin, double aligned, double truth, double confidence)
    {
        all.add(aligned, truth, confidence);
        const std::optional<PinyinParts> parts = splitPinyinSyllable(pinyin);
        const QString initial = parts && !parts->initial.isEmpty() ? parts->initial : QStringLiteral("(none)");
        byInitial[initial].add(aligned, truth, confidence);
    }
    QJsonObject json() const
    {
        QJsonObject o = all.json();
        QJsonObject by;
        for (auto it = byInitial.begin(); it != byInitial.end(); ++it) {
            QJsonObject e;
            e.insert(QStringLiteral("onsets"), int(it->ms.size()));
            e.insert(QStringLiteral("signedMedianMs"), std::round(Errors::quantileOf(it->signedMs, 0.5) * 10) / 10);
            e.insert(QStringLiteral("maxMs"), std::round(it->quantile(1.0) * 10) / 10);
            by.insert(it.key(), e);
        }
        o.insert(QStringLiteral("byInitial"), by);
        return o;
    }
};

// Adds an alignment of synthetic speech to `e` (and the syllables after a pause also to
// `afterPause`, when given); the shortest syllable to `shortest`; the syllables more than
// 50 ms off to `misses` (when given).
void scoreSynthetic(const Script &s, const Audio &rec, const std::vector<double> &truth, Errors *e, double *shortest,
    const AlignOptions &options = {}, std::vector<Miss> *misses = nullptr, const QString &voice = {},
    AfterPause *afterPause = nullptr, int pausedBefore = -1)
{
    const LipsyncResult r = lipsyncResult(s, alignScript(rec, s, options), rec.duration());
    for (int k = 0; k < r.syllables.size() && size_t(k) < truth.size(); ++k) {
        e->add(r.syllables[k].start, truth[size_t(k)], r.syllables[k].confidence);
        if (afterPause && afterAPause(s, k, pausedBefore))
            afterPause->add(s.syllables[k].pinyin, r.syllables[k].start, truth[size_t(k)], r.syllables[k].confidence);
        *shortest = std::min(*shortest, (r.syllables[k].end - r.syllables[k].start) * 1000);
        const double error = (r.syllables[k].start - truth[size_t(k)]) * 1000;
        if (!misses || std::abs(error) <= 50)
            continue;
        QString context;
        for (int j = std::max(0, k - 2); j <= std::min(int(s.syllables.size()) - 1, k + 2); ++j)
            context += j == k ? QLatin1Char('[') + s.syllables[j].text + QLatin1Char(']') : s.syllables[j].text;
        QJsonObject o;
        o.insert(QStringLiteral("voice"), voice);
        o.insert(QStringLiteral("syllable"), k);
        o.insert(QStringLiteral("afterAPause"), afterAPause(s, k, pausedBefore));
        o.insert(QStringLiteral("text"), context);
        o.insert(QStringLiteral("pinyin"), s.syllables[k].pinyin + QString::number(s.syllables[k].tone));
        o.insert(QStringLiteral("errorMs"), std::round(error));
        o.insert(QStringLiteral("lengthMs"), std::round((r.syllables[k].end - r.syllables[k].start) * 1000));
        o.insert(QStringLiteral("truthLengthMs"),
            size_t(k) + 1 < truth.size() ? std::round((truth[size_t(k) + 1] - truth[size_t(k)]) * 1000) : 0.0);
        o.insert(QStringLiteral("confidence"), std::round(r.syllables[k].confidence * 100) / 100);
        misses->push_back({error, o});
    }
}

// The held-out voices sentence by sentence in a clean recording (noise 45 dB under the
// speech): there a fricative's noise is heard, though not in the mid band the pauses are found
// by. The syllables after a pause apart.
QJsonObject heldOutClean()
{
    Errors pooled;
    AfterPause afterPause;
    quint32 seed = 3000;
    double shortest = 1e9;
    for (const Voice &v : kHeldOutVoices) {
        for (const QString &text : heldOutSentences()) {
            const Script s = mandarin(text);
            std::vector<double> truth;
            int pausedBefore = -1;
            const Audio rec = syntheticRecording(s, v, seed++, &truth, 45, &pausedBefore);
            scoreSynthetic(s, rec, truth, &pooled, &shortest, {}, nullptr, {}, &afterPause, pausedBefore);
        }
    }
    QJsonObject out = pooled.json();
    out.insert(QStringLiteral("afterAPause"), afterPause.json());
    out.insert(QStringLiteral("shortestSyllableMs"), std::round(shortest));
    return out;
}

// The held-out voices, sentence by sentence, and one of them reading them all for a minute.
QJsonObject heldOutSynthetic()
{
    Errors pooled, unadapted;
    AfterPause afterPause;
    AlignOptions noAdaptation;
    noAdaptation.adaptToSpeaker = false;
    QJsonArray perVoice;
    quint32 seed = 1000;
    double shortestAll = 1e9;
    const QStringList texts = heldOutSentences();
    std::vector<Miss> misses;
    for (const Voice &v : kHeldOutVoices) {
        Errors e;
        double shortest = 1e9;
        for (const QString &text : texts) {
            const Script s = mandarin(text);
            std::vector<double> truth;
            int pausedBefore = -1;
            const Audio rec = syntheticRecording(s, v, seed++, &truth, 20, &pausedBefore);
            scoreSynthetic(
                s, rec, truth, &e, &shortest, {}, &misses, QString::fromLatin1(v.voice), &afterPause, pausedBefore);
            double ignored = 0;
            scoreSynthetic(s, rec, truth, &unadapted, &ignored, noAdaptation);
        }
        pooled.add(e);
        shortestAll = std::min(shortestAll, shortest);
        QJsonObject o = e.json();
        o.insert(QStringLiteral("voice"), QString::fromLatin1(v.voice));
        o.insert(QStringLiteral("rate"), v.rate);
        o.insert(QStringLiteral("pitch"), v.pitch);
        o.insert(QStringLiteral("shortestSyllableMs"), std::round(shortest));
        perVoice.append(o);
    }
    QJsonObject out = pooled.json();
    out.insert(QStringLiteral("shortestSyllableMs"), std::round(shortestAll));
    out.insert(QStringLiteral("voices"), perVoice);
    out.insert(QStringLiteral("withoutAdaptation"), unadapted.json());
    out.insert(QStringLiteral("afterAPause"), afterPause.json());
    std::sort(misses.begin(), misses.end(),
        [](const Miss &a, const Miss &b) { return std::abs(a.signedMs) > std::abs(b.signedMs); });
    QJsonArray worst;
    for (const Miss &m : misses)
        worst.append(m.what);
    out.insert(QStringLiteral("offBy50Ms"), worst);
    // One speaker for about a minute: the sentences over and over in one recording.
    {
        QString text;
        for (int k = 0; k < 3; ++k)
            text += texts.join(QString());
        const Script s = mandarin(text);
        std::vector<double> truth;
        const Audio rec = syntheticRecording(s, kHeldOutVoices[0], 7, &truth);
        Errors e;
        double shortest = 1e9;
        scoreSynthetic(s, rec, truth, &e, &shortest);
        Errors plain;
        double ignored = 0;
        scoreSynthetic(s, rec, truth, &plain, &ignored, noAdaptation);
        QJsonObject o = e.json();
        o.insert(QStringLiteral("withoutAdaptation"), plain.json());
        o.insert(QStringLiteral("audioSeconds"), std::round(rec.duration()));
        o.insert(QStringLiteral("voice"), QString::fromLatin1(kHeldOutVoices[0].voice));
        o.insert(QStringLiteral("shortestSyllableMs"), std::round(shortest));
        out.insert(QStringLiteral("oneSpeakerMinute"), o);
    }
    return out;
}

QJsonObject alignReal()
{
    QJsonObject out;
    out.insert(QStringLiteral("heldOutSynthetic"), heldOutSynthetic());
    out.insert(QStringLiteral("heldOutClean"), heldOutClean());
    const QString dir = bench::sharedDataDir();
    if (dir.isEmpty()) {
        out.insert(QStringLiteral("skipped"), QStringLiteral("no shared data"));
        return out;
    }
    Errors developed, heldOut;
    QJsonArray files = realFileFigures(dir, &developed, &heldOut);
    // GRID (English): word onsets, units of 1/25000 s.
    {
        const AudioResult a = loadAudio(dir + QStringLiteral("/video/id2_vcd_swwp2s.mpg"));
        const GridWordTier tier = gridWordTier(dir);
        if (!tier.words.isEmpty() && a.ok()) {
            const AlignResult r = alignScript(a.audio, parseScript(tier.words.join(QLatin1Char(' '))).script);
            Errors e;
            for (int k = 0; r.ok() && k < r.syllables.size(); ++k)
                e.add(r.syllables[k].start, tier.onsets[size_t(k)], r.syllables[k].confidence);
            QJsonObject o = e.json();
            o.insert(QStringLiteral("file"),
                QStringLiteral("id2_vcd_swwp2s.mpg (English words, not in the Mandarin figures)"));
            files.append(o);
        }
    }
    Errors all = developed;
    all.add(heldOut);
    out.insert(QStringLiteral("real"), all.json());
    out.insert(QStringLiteral("realDevelopedOn"), developed.json());
    out.insert(QStringLiteral("realHeldOut"), heldOut.json());
    out.insert(QStringLiteral("files"), files);
    // A minute of the shared recordings joined, through toonface-cli as a whole process.
    out.insert(QStringLiteral("minuteWholeProcess"), lipsyncLongReal({3}));
    out.insert(QStringLiteral("what"),
        QStringLiteral(
            "Mandarin onsets against references: real files (developed on / held out) and espeak-ng "
            "voices and tempi no constant was chosen on (20 dB noise, an unmarked pause; heldOutClean: 45 dB); "
            "afterAPause: the first syllable, the one after the unmarked pause, those after a marked "
            "break (byInitial: their signed median and max by initial); signed = "
            "aligned - reference (positive: mouth late); offBy80MsFlagged: of the onsets > 80 ms off, "
            "how many had confidence < 0.5"));
    return out;
}

} // namespace

TOONFACE_BENCHMARK("speech.alignReal", alignReal);
