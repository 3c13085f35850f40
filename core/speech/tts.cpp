#include "speech/tts.h"

#include "i18n/coretext.h"
#include "speech/pinyin.h"
#include "speech/tonesandhi.h"
#include "speech/ttsvoicefile.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QHash>
#include <QMutex>
#include <QMutexLocker>
#include <QRandomGenerator>

#include <espeak-ng/espeak_ng.h>
#include <espeak-ng/speak_lib.h>

#include <cstring>

namespace toonface {

namespace {

QMutex &espeakMutex()
{
    static QMutex m;
    return m;
}

// What the synthesis callback fills; only touched under espeakMutex().
struct Collector
{
    std::vector<short> samples; // when there is no sink
    const AudioSink *sink = nullptr;
    std::vector<float> converted; // the sink's block
    qint64 count = 0; // samples made
    struct Word
    {
        int textPosition; // 1-based character position in the input
        double start;
    };
    std::vector<Word> words;
    struct Phoneme
    {
        QString name;
        double start;
    };
    std::vector<Phoneme> phonemes; // in order; pauses included
    std::vector<int> phonemeWord; // index into words (-1 before the first word)
    const std::atomic_bool *cancel = nullptr;
    const SpeechProgressFn *progress = nullptr;
    double expectedSeconds = 1;
    int rate = 22050;
};

Collector *g_collector = nullptr;

int synthCallback(short *wav, int count, espeak_EVENT *events)
{
    Collector *c = g_collector;
    if (!c)
        return 1;
    if (wav && count > 0) {
        c->count += count;
        if (c->sink) {
            c->converted.resize(size_t(count));
            for (int i = 0; i < count; ++i)
                c->converted[size_t(i)] = wav[i] / 32768.0f;
            (*c->sink)(c->converted.data(), count);
        } else {
            c->samples.insert(c->samples.end(), wav, wav + count);
        }
    }
    for (espeak_EVENT *e = events; e && e->type != espeakEVENT_LIST_TERMINATED; ++e) {
        if (e->type == espeakEVENT_WORD) {
            c->words.push_back({e->text_position, e->audio_position / 1000.0});
        } else if (e->type == espeakEVENT_PHONEME) {
            char name[9] = {};
            std::memcpy(name, e->id.string, 8);
            c->phonemes.push_back({QString::fromUtf8(name), e->audio_position / 1000.0});
            c->phonemeWord.push_back(int(c->words.size()) - 1);
        }
    }
    if (c->progress && *c->progress)
        (*c->progress)(std::min(0.99, double(c->count) / c->rate / c->expectedSeconds), QStringLiteral("speaking"));
    return isCancelled(c->cancel) ? 1 : 0;
}

// Starts espeak-ng once; its sample rate, or 0. Called with espeakMutex() held.
int startEspeak()
{
    static int sampleRate = 0;
    if (sampleRate <= 0) {
        sampleRate = espeak_Initialize(
            AUDIO_OUTPUT_SYNCHRONOUS, 0, nullptr, espeakINITIALIZE_PHONEME_EVENTS | espeakINITIALIZE_DONT_EXIT);
        if (sampleRate <= 0)
            return sampleRate = 0;
        espeak_SetSynthCallback(synthCallback);
    }
    return sampleRate;
}

// A directory for the voice files of this process, removed at exit. espeak-ng lowercases the
// path of a voice file it is given and reads at most 59 characters of it: the path must be
// short and lowercase.
struct VoiceDir
{
    QString path;
    VoiceDir()
    {
        for (const QString &base : {QDir::tempPath(), QStringLiteral("/tmp")}) {
            const QString candidate = base
                + QStringLiteral("/tfv-%1-%2")
                      .arg(QCoreApplication::applicationPid())
                      .arg(QRandomGenerator::global()->generate(), 8, 16, QLatin1Char('0'));
            if (candidate == candidate.toLower() && candidate.size() < 48 && QDir().mkpath(candidate)) {
                path = candidate;
                return;
            }
        }
    }
    ~VoiceDir()
    {
        if (!path.isEmpty())
            QDir(path).removeRecursively();
    }
};

// Selects `voice` without its pitch flutter (see steadyVoiceFile), or as espeak-ng names it
// when no file for it can be made. Called with espeakMutex() held.
bool selectVoice(const QString &voice)
{
    static const VoiceDir dir;
    static QHash<QString, QString> files;
    auto found = files.constFind(voice);
    if (found == files.constEnd()) {
        const char *data = nullptr;
        espeak_Info(&data);
        const QString path
            = !dir.path.isEmpty() && data ? steadyVoiceFile(voice, QFile::decodeName(data), dir.path) : QString();
        found = files.insert(voice, path);
    }
    if (!found->isEmpty() && espeak_ng_SetVoiceByFile(QFile::encodeName(*found).constData()) == ENS_OK)
        return true;
    return espeak_SetVoiceByName(voice.toUtf8().constData()) == EE_OK;
}

bool isPause(const QString &phoneme)
{
    return phoneme.startsWith(QLatin1Char('_'));
}

} // namespace

int ttsSampleRate()
{
    QMutexLocker lock(&espeakMutex());
    return startEspeak();
}

QString ttsUnavailable()
{
    return ScriptText::tr("espeak-ng cannot start: its data is missing (install espeak-ng-data)");
}

QString ttsVoice(const TtsOptions &options, Language language)
{
    if (!options.voice.isEmpty())
        return options.voice;
    return language == Language::English ? QStringLiteral("en") : QStringLiteral("cmn-latn-pinyin");
}

QString ttsInputText(const Script &script, QVector<int> *offsets)
{
    QString text;
    if (offsets)
        offsets->clear();
    // espeak-ng cuts a clause longer than its buffer (800 bytes) at a word of its choice and
    // then reports no word events for a dozen words after the cut: their syllables would
    // get no times. A long run without punctuation is broken into clauses well under that,
    // where the script leaves a space between words if it can.
    constexpr int kClauseSoft = 300, kClauseHard = 500; // bytes (the text is ASCII but for English accents)
    int clauseStart = 0;
    // The tones as a speaker says them (一, 不, 3rd before 3rd), not as the dictionary lists them.
    const QVector<int> tones = spokenTones(script);
    for (qsizetype k = 0; k < script.syllables.size(); ++k) {
        const ScriptSyllable &s = script.syllables[k];
        if (!text.isEmpty())
            text += QLatin1Char(' ');
        if (offsets)
            offsets->append(int(text.size()));
        text += script.language == Language::English ? s.text : toneNumberSpelling({s.pinyin, tones[k]});
        const bool wordEnds
            = k + 1 < script.syllables.size() && script.syllables[k + 1].position > s.position + s.length;
        const int clause = int(text.size()) - clauseStart;
        if (s.phraseBreakAfter
            || (k + 1 < script.syllables.size() && (clause >= kClauseHard || (clause >= kClauseSoft && wordEnds)))) {
            text += QLatin1Char(',');
            clauseStart = int(text.size());
        }
    }
    text += QLatin1Char('.');
    return text;
}

TtsResult synthesize(
    const Script &script, const TtsOptions &options, const SpeechProgressFn &progress, const std::atomic_bool *cancel)
{
    return synthesize(script, options, AudioSink {}, progress, cancel);
}

TtsResult synthesize(const Script &script, const TtsOptions &options, const AudioSink &sink,
    const SpeechProgressFn &progress, const std::atomic_bool *cancel)
{
    TtsResult result;
    if (script.syllables.isEmpty()) {
        result.error = ScriptText::tr("nothing to speak");
        return result;
    }
    QMutexLocker lock(&espeakMutex());
    const int sampleRate = startEspeak();
    if (sampleRate <= 0) {
        result.error = ttsUnavailable();
        return result;
    }
    const QString voice = ttsVoice(options, script.language);
    if (!selectVoice(voice)) {
        result.error = ScriptText::tr("espeak-ng has no voice '%1'").arg(voice);
        return result;
    }
    espeak_SetParameter(espeakRATE, std::clamp(options.rate, 80, 450), 0);
    espeak_SetParameter(espeakPITCH, std::clamp(options.pitch, 0, 100), 0);
    espeak_SetParameter(espeakRANGE, std::clamp(options.pitchRange, 0, 100), 0);
    espeak_SetParameter(espeakPUNCTUATION, espeakPUNCT_NONE, 0);

    QVector<int> offsets;
    const QString text = ttsInputText(script, &offsets);
    const QByteArray utf8 = text.toUtf8();
    Collector collector;
    collector.cancel = cancel;
    if (sink)
        collector.sink = &sink;
    collector.progress = &progress;
    collector.rate = sampleRate;
    collector.expectedSeconds = std::max(0.5, script.syllables.size() * 60.0 / std::max(options.rate, 80) * 1.3);
    g_collector = &collector;
    const espeak_ERROR rc = espeak_Synth(
        utf8.constData(), size_t(utf8.size()) + 1, 0, POS_CHARACTER, 0, espeakCHARS_UTF8, nullptr, nullptr);
    espeak_Synchronize();
    g_collector = nullptr;
    if (isCancelled(cancel)) {
        result.error = ScriptText::tr("cancelled");
        return result;
    }
    if (rc != EE_OK || collector.count == 0) {
        result.error = ScriptText::tr("espeak-ng could not speak the script");
        return result;
    }

    result.audio.sampleRate = sampleRate;
    result.audio.samples.resize(qsizetype(collector.samples.size()));
    for (size_t i = 0; i < collector.samples.size(); ++i)
        result.audio.samples[qsizetype(i)] = collector.samples[i] / 32768.0f;
    collector.samples = {};
    const double total = double(collector.count) / sampleRate;
    result.duration = total;

    // Word events → syllables by their position in the input (character positions count
    // code points from 1; the input is ASCII but for English words with accents, so map
    // through UTF-16 offsets of the code points).
    QVector<int> cpToUtf16;
    for (int i = 0; i < text.size(); ++i) {
        if (!text.at(i).isLowSurrogate())
            cpToUtf16.append(i);
    }
    const int n = int(script.syllables.size());
    QVector<int> wordUnit(qsizetype(collector.words.size()), -1);
    result.units.resize(n);
    QVector<bool> seen(n, false);
    for (size_t w = 0; w < collector.words.size(); ++w) {
        const int cp = collector.words[w].textPosition - 1;
        const int at = cp >= 0 && cp < cpToUtf16.size() ? cpToUtf16[cp] : -1;
        int unit = -1;
        for (int k = n - 1; k >= 0; --k) {
            if (at >= offsets[k]) {
                unit = k;
                break;
            }
        }
        if (unit < 0)
            continue;
        wordUnit[qsizetype(w)] = unit;
        if (!seen[unit]) {
            result.units[unit].start = collector.words[w].start;
            seen[unit] = true;
        }
    }
    // A syllable espeak-ng gave no event of its own (rare) starts where its neighbours allow.
    for (int k = 0; k < n; ++k) {
        if (seen[k])
            continue;
        int next = k + 1;
        while (next < n && !seen[next])
            ++next;
        const double before = k > 0 ? result.units[k - 1].start : 0.0;
        const double after = next < n ? result.units[next].start : total;
        result.units[k].start = before + (after - before) * (k > 0 ? 0.5 : 0.0);
        seen[k] = true;
    }
    // Phonemes to their syllable; a syllable ends at the first pause after its last phoneme.
    QVector<double> lastSound(n, -1), pauseAfter(n, -1);
    for (size_t p = 0; p < collector.phonemes.size(); ++p) {
        const int w = collector.phonemeWord[p];
        const int unit = w >= 0 ? wordUnit[w] : -1;
        if (unit < 0)
            continue;
        const auto &ph = collector.phonemes[p];
        if (isPause(ph.name)) {
            if (lastSound[unit] >= 0 && pauseAfter[unit] < 0)
                pauseAfter[unit] = ph.start;
            continue;
        }
        result.units[unit].phonemes.append({ph.name, ph.start});
        lastSound[unit] = ph.start;
        pauseAfter[unit] = -1;
    }
    for (int k = 0; k < n; ++k) {
        const double next = k + 1 < n ? result.units[k + 1].start : total;
        double end = pauseAfter[k] >= 0 ? pauseAfter[k] : next;
        end = std::min(end, next);
        result.units[k].end = std::max(end, result.units[k].start);
    }
    if (progress)
        progress(1.0, QStringLiteral("speaking"));
    return result;
}

} // namespace toonface
