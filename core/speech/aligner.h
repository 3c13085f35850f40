#pragma once

#include "speech/alignconfidence.h"
#include "speech/audio.h"
#include "speech/features.h"
#include "speech/paceprobe.h"
#include "speech/progress.h"
#include "speech/script.h"
#include "speech/tts.h"

#include <QString>
#include <QVector>

namespace toonface {

struct AlignOptions
{
    // The espeak-ng rendering the recording is warped against. rate 0 matches the speaker's
    // rate automatically (a first rendering measures it).
    TtsOptions reference {0, 50, 50, {}};
    // The second pass that moves each onset to the acoustic landmark nearby (boundaryrefine.h).
    bool refineBoundaries = true;
    // Re-alignment against the reference adapted to the recording's voice (speakeradapt.h),
    // for scripts of kAdaptMinSyllables or more.
    bool adaptToSpeaker = true;
};

enum class AlignStatus { Ok, CannotAlign, BadInput, Cancelled };

struct AlignedSyllable
{
    double start = 0; // seconds in the audio
    double end = 0; // seconds; <= the next syllable's start
    double confidence = 0; // 0..1: below kDoubtfulConfidence the onset may well be > 80 ms off
    Doubts doubts {}; // what the confidence was made of (alignconfidence.h)
    QVector<TtsPhoneme> phonemes; // the reference's phonemes, their starts mapped into the audio
    // The recording's speech the warp gave the syllable over the length the reference and the
    // speaker's pace expect: about 1; near 0 for a syllable the speaker did not say.
    double heard = 1;
};

// Below this share of its expected length a syllable counts as not spoken (AlignResult::unspoken).
inline constexpr double kUnspokenShare = 0.3;

struct AlignResult
{
    AlignStatus status = AlignStatus::BadInput;
    QString error; // why, when status != Ok
    QVector<AlignedSyllable> syllables; // one per script syllable when Ok
    // Syllables of the script the recording seems not to hold (a dropped word): their
    // confidence is 0 and their times where the warp ran through them.
    QVector<int> unspoken;
    double speechStart = 0; // first and last moment of speech found in the audio
    double speechEnd = 0;
    bool ok() const { return status == AlignStatus::Ok; }
};

// Finds when each syllable of `script` is spoken in `audio` (any rate; mono).
//
// Method: MFCC, energy and voicing features of the recording are warped by multi-resolution
// dynamic time warping onto those of an espeak-ng rendering of the same script whose syllable
// times are known exactly from the library's events; pauses either side makes alone are
// absorbed as silence, a pause of the speaker where the script marks none at a syllable
// boundary (never at a stop's closure inside a syllable). Each onset is then moved to the
// acoustic boundary nearby (the end of a pause, or the energy valley or voicing change between
// two syllable nuclei) that best fits its initial.
// Fails with CannotAlign when the audio holds no speech, or far too little speech for the
// script (or far too much). Thread-safe (the espeak-ng rendering is serialised).
AlignResult alignScript(const Audio &audio, const Script &script, const AlignOptions &options = {},
    const SpeechProgressFn &progress = {}, const std::atomic_bool *cancel = nullptr);

// The same on a recording given by its features (computeSpeechFeatures, or a
// SpeechFeatureStream fed while decoding): its audio need not be held.
AlignResult alignScript(const SpeechFeatures &recording, const Script &script, const AlignOptions &options = {},
    const SpeechProgressFn &progress = {}, const std::atomic_bool *cancel = nullptr);

// The same with the pace probe of `script` and `options.reference` made beforehand (started
// before the recording is decoded, it is rendered meanwhile on another core).
AlignResult alignScript(const SpeechFeatures &recording, PaceProbe &probe, const Script &script,
    const AlignOptions &options = {}, const SpeechProgressFn &progress = {}, const std::atomic_bool *cancel = nullptr);

// The same against a given reference rendering of the script (`reference.units` one per
// syllable); alignScript renders it itself.
AlignResult alignToReference(const Audio &audio, const Script &script, const TtsResult &reference,
    const SpeechProgressFn &progress = {}, const std::atomic_bool *cancel = nullptr);

} // namespace toonface
