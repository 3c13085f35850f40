#pragma once

#include "speech/aligner.h"
#include "speech/features.h"
#include "speech/onsetsignals.h"
#include "speech/script.h"
#include "speech/tts.h"

namespace toonface {

// The aligner's correction for initials it cannot hear. A fricative, affricate or aspirated
// initial after a pause is 20 dB or more quieter than its vowel: in a noisy recording (noise
// within 30 dB of the speech) its noise is lost in the pause's, the pause seems to run up to
// the vowel, and the onset lands on the vowel's rise, late by the whole initial (an h of 150 ms
// in a slow voice). Where the sound right after such an onset is already voiced, the initial
// lies hidden in the pause: the onset moves back by the initial's length in the reference at
// the speaker's pace, never before the pause begins. Where the initial's noise is heard, the
// pause ends at it and the sound after the onset is voiceless; in a cleaner recording the
// pause is silence: nothing moves.
// `pace` is the recording's speech over the reference's; `reference` is the script's rendering
// the recording `a` (its signals `sig`) was aligned against, one unit per syllable of `r`.
void moveOnsetsOfHiddenInitials(const SpeechFeatures &a, const OnsetSignals &sig, const Script &script,
    const TtsResult &reference, double pace, AlignResult *r);

} // namespace toonface
