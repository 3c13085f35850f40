#pragma once

#include "speech/audio.h"
#include "speech/progress.h"
#include "speech/script.h"

#include <QString>
#include <QVector>

namespace toonface {

struct TtsOptions
{
    int rate = 175; // words per minute (espeak-ng accepts 80..450)
    int pitch = 50; // 0..100
    int pitchRange = 50; // 0..100: how much the pitch moves
    // An espeak-ng voice, optionally with a variant ("cmn-latn-pinyin+f2"); empty picks
    // cmn-latn-pinyin for Mandarin (fed pinyin with tone numbers: the plain cmn voice misreads
    // characters) and en for English.
    QString voice;
};

// One phoneme of the synthesized speech: espeak-ng's mnemonic and when it starts (seconds).
struct TtsPhoneme
{
    QString name;
    double start = 0;
};

// When one script syllable (or English word) is spoken in the synthesized audio.
struct TtsUnit
{
    double start = 0; // seconds: the library's word event
    double end = 0; // seconds: the pause or the next unit that follows its last phoneme
    QVector<TtsPhoneme> phonemes;
};

struct TtsResult
{
    QString error; // empty on success
    Audio audio; // mono, at espeak-ng's own rate (22050 Hz); empty when the samples went to a sink
    double duration = 0; // seconds spoken
    QVector<TtsUnit> units; // one per script syllable, in order
    bool ok() const { return error.isEmpty(); }
};

// Speaks `script` with espeak-ng (synchronous mode) and returns the samples with the exact
// start and end of every syllable, from the library's word and phoneme events.
// Thread-safe: calls are serialised (espeak-ng keeps global state). Cancel is polled per chunk.
TtsResult synthesize(const Script &script, const TtsOptions &options = {}, const SpeechProgressFn &progress = {},
    const std::atomic_bool *cancel = nullptr);

// The same, handing the samples to `sink` as they are made (at result.audio.sampleRate)
// instead of keeping them: result.audio.samples stays empty. A long script's rendering need
// never be held whole.
TtsResult synthesize(const Script &script, const TtsOptions &options, const AudioSink &sink,
    const SpeechProgressFn &progress = {}, const std::atomic_bool *cancel = nullptr);

// espeak-ng's sample rate (starting the library if needed); 0 when it cannot start.
int ttsSampleRate();
// Why espeak-ng cannot start.
QString ttsUnavailable();

// The text handed to espeak-ng for `script` (pinyin with tone numbers, or English words, with
// commas at phrase breaks, and after every ~300-500 bytes without one: espeak-ng loses the
// word events after a clause it has to cut); `offsets`, when given, receives each
// syllable's offset in it.
QString ttsInputText(const Script &script, QVector<int> *offsets = nullptr);

// The voice `options` name for `language`.
QString ttsVoice(const TtsOptions &options, Language language);

} // namespace toonface
