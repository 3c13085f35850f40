#pragma once

#include <QVector>

#include <array>
#include <cstddef>
#include <vector>

namespace toonface {

// What says that an aligned syllable's onset may be far off: signs the aligner gathers for each
// syllable, and the confidence made of them.
//
// The confidence is a logistic model of "this onset is more than 80 ms off" over these signs,
// fitted across speakers (the espeak-ng voices and tempi of the speech benchmarks and the
// shared real recordings, leaving one speaker out at a time: `toonface-bench
// speech.alignConfidence` refits it and prints what it catches on speakers it was not fitted
// on). A syllable below kDoubtfulConfidence is doubtful (the editor tints it).
enum class Doubt {
    Unclear, // 1 - the onset's acoustic evidence or landmark strength (0..1)
    WarpGap, // seconds between the segmentation's onset and the warp's estimate
    PriorShift, // seconds the segmentation moved the onset from the warped prior
    Match, // mean feature distance of the syllable's warped frames to the reference's
    MatchExcess, // Match minus the mean of the neighbours' (a local mismatch)
    LengthMisfit, // |ln(length / expected length at the speaker's pace)|
    AtMinimum, // 1 when the syllable was held near its least length, else 0
    NearPause, // 1 - seconds from the onset to the nearest pause (capped at 1 s)
    PassMove, // seconds the speaker-adapted pass moved the onset (0 when not adapted)
    RefineMove, // seconds the boundary refinement moved the onset
    NeighbourGap, // the larger WarpGap of the syllables either side
    HeardMisfit, // |ln(heard)|: speech the warp gave the syllable against its expected length
};
inline constexpr int kDoubtCount = 12;
using Doubts = std::array<double, kDoubtCount>;

inline double &at(Doubts &d, Doubt which)
{
    return d[std::size_t(which)];
}

// The editor tints syllables below this confidence as doubtful.
inline constexpr double kDoubtfulConfidence = 0.5;

// A recording's syllables' doubts, each measured against the recording's own: the signs that
// differ from speaker to speaker even where the onsets are right (how far a real voice's warp
// against the synthetic reference strays, how much its syllables' lengths vary) less their
// median over the recording. `raw` holds one entry per syllable.
std::vector<Doubts> relativeDoubts(const std::vector<Doubts> &raw);

// 0..1 from relative doubts; below kDoubtfulConfidence when the model expects the onset more
// than 80 ms off.
double syllableConfidence(const Doubts &relative);

// The model's weights (its last entry the intercept), for the benchmark that refits them.
const std::array<double, kDoubtCount + 1> &confidenceWeights();

// The same with given weights.
double syllableConfidence(const Doubts &relative, const std::array<double, kDoubtCount + 1> &weights);

} // namespace toonface
