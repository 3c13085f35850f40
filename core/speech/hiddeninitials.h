#pragma once

#include "speech/aligner.h"
#include "speech/features.h"
#include "speech/onsetsignals.h"
#include "speech/script.h"
#include "speech/tts.h"

namespace toonface {

// The aligner's correction for the initials it cannot hear after a pause. A voiceless
// initial (a fricative, an affricate, a stop) after a pause is far quieter than its vowel, and
// its noise lies mostly above the mid band the pauses are found by: the pause seems to run up
// to the vowel, or to the initial's loudest part, and the onset lands late by the rest (50-100
// ms for the first syllable of a sentence; an h of 150 ms in a slow voice). In a noisy
// recording (noise within 30 dB of the speech) the vowel's start is what is heard: the onset
// moves to the initial's length in the reference, at the speaker's pace, before the first
// voiced frame, never before the pause begins. In a cleaner recording the initial's noise
// stands above the quiet in the whole band: the onset moves back over the frames that do, at
// most the initial's length; a stop's or an affricate's (whose closure is as silent as the
// pause) to the initial's length before the first loud voiced frame, at most the reference's
// closure before the first sound heard. The onset is looked at when a pause ends within the
// initial's length before it (at least 30 ms).
// `pace` is the recording's speech over the reference's; `reference` is the script's rendering
// the recording `a` (its signals `sig`) was aligned against, one unit per syllable of `r`.
void moveOnsetsOfHiddenInitials(const SpeechFeatures &a, const OnsetSignals &sig, const Script &script,
    const TtsResult &reference, double pace, AlignResult *r);

} // namespace toonface
