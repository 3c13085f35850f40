#pragma once

#include "speech/aligner.h"
#include "speech/features.h"
#include "speech/script.h"
#include "speech/tts.h"

#include <vector>

namespace toonface {

// Speaker adaptation of the aligner's reference: once a recording is aligned, its own frames
// say what each class of sound (kinds of initials, finals by their vowel, pauses) sounds like
// in this voice. The reference rendering's frames of each class are moved by the difference
// between the recording's mean and the reference's mean of that class (a per-class shift of
// the feature space), and the recording is warped again against the adapted reference.
//
// A class with few frames moves by a shrunk share of that difference (n / (n + kPriorFrames)):
// a short recording barely changes its reference, a long one adapts it fully.

// The sound classes: 0 silence, then initials by manner, then finals by their vowel.
inline constexpr int kSoundClasses = 14;
inline constexpr double kPriorFrames = 30.0;
// The aligner adapts only recordings of at least this many syllables (about 15 s of speech).
inline constexpr int kAdaptMinSyllables = 60;

// The class of each frame of a rendering or recording whose syllables lie at `starts` /
// `ends` (seconds; the initial ends at `initialEnds`, equal to the start when there is none),
// from the features' silence (quiet frames are class 0).
std::vector<int> soundClasses(const SpeechFeatures &f, const Script &script, const std::vector<double> &starts,
    const std::vector<double> &initialEnds, const std::vector<double> &ends);

// Moves the vectors of `reference` (classes `refClasses`) toward those of `recording`
// (classes `recClasses`), class by class; returns how many classes moved.
int adaptReference(const SpeechFeatures &recording, const std::vector<int> &recClasses, SpeechFeatures *reference,
    const std::vector<int> &refClasses);

} // namespace toonface
