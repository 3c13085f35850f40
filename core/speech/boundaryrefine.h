#pragma once

#include "speech/features.h"
#include "speech/onsetsignals.h"

#include <vector>

namespace toonface {

// The aligner's second pass: once the warp and the segmentation have put each syllable onset
// in the right place to within a few frames, each one is moved, within a small window that
// keeps every syllable its least length, to the acoustic landmark its kind of onset makes:
// where the previous syllable's voiced loudness falls fastest into a voiceless initial's
// closure or frication, where the mid band steps down into a nasal or liquid (or, after a
// nasal coda, where the spectrum changes fastest), where the loudness valley before a vowel
// or glide bottoms out, and where the sound rises out of a pause. The segmentation's knee
// (where a fall starts, on loudness smoothed over ±20 ms) lies before the landmark; the
// landmark is the boundary phoneticians mark. Positions are refined between frames.
struct BoundaryInput
{
    std::vector<double> starts; // seconds, one per syllable, increasing
    std::vector<OnsetKind> kinds; // how each syllable begins
    std::vector<bool> afterNasal; // the previous syllable ends in a nasal coda
    std::vector<double> minSeconds; // each syllable's least length
    double speechEnd = 0; // seconds: the end of the last syllable's speech
};

struct RefinedBoundary
{
    double start = 0; // seconds
    double strength = 0; // 0..1: how clear the landmark is (0: none found, the onset kept)
};

// Window half-width searched around each onset.
inline constexpr double kRefineWindow = 0.03; // seconds

std::vector<RefinedBoundary> refineBoundaries(
    const SpeechFeatures &f, const OnsetSignals &sig, const BoundaryInput &in);

} // namespace toonface
