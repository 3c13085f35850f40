#pragma once

#include "speech/progress.h"

#include <utility>
#include <vector>

namespace toonface {

// Dynamic time warping between two feature sequences, multi-resolution (FastDTW-style: a
// full DTW on averaged frames, refined level by level inside a corridor around the coarser
// path), so that ten minutes of speech cost about as much as a few seconds at full DTW.
//
// Steps are symmetric (diagonal counts the local cost twice). A frame that is silence in one
// sequence may be held against any frame of the other for `silenceCost` instead of its
// distance: pauses one speaker makes and the other does not are absorbed without bending the
// path elsewhere. A frame in a long pause (`pause`: a pause, not a stop's closure) is held so
// cheaply only where the other sequence may pause: at its own pauses and at its `pauseAt`
// frames (the last frame of each syllable of a reference rendered without pauses there),
// for `pauseCost`; anywhere else it costs `silenceCost` whatever it faces. A pause the speaker
// makes between two syllables where the script marks none is absorbed there, at the
// boundary, rather than at a closure of the other sequence (silent too) or by a pause the
// other makes a few syllables away.
struct DtwSequence
{
    const float *vectors = nullptr; // frames × dim
    const float *silence = nullptr; // frames, 0..1 (may be null)
    int frames = 0;
    const float *pause = nullptr; // frames, 0..1 (may be null): part of a long pause
    const float *pauseAt = nullptr; // frames, 0..1 (may be null): where a pause of the other may be held
};

struct DtwOptions
{
    int dim = 0;
    float silenceCost = 1.0f;
    float pauseCost = 0.25f; // per frame held at a `pauseAt` frame (times silenceCost)
    long maxFullCells = 4'000'000; // the coarsest level is a full DTW of at most this many cells
    int radius = 6; // corridor half-width, in frames of the finer level
    // The half-width of the first refinement, of the coarsest level's path (when larger than
    // radius): the coarsest level averages most and errs most (a pause put a syllable off);
    // once the next level has put its path right, the finer ones need only `radius`.
    int coarseRadius = 0;
    // When > 0: the path keeps within `band` frames (of the full resolution) of the line on
    // which both sequences have spoken the same share of their speech (frames with silence
    // < 0.5). A full DTW at the coarsest level a long recording allows averages a third of a
    // second into a frame and loses its way; within the band the coarsest level stays fine.
    int band = 0;
    // When set: a path (full-resolution frames, from (0, 0) to the last frames) the warp is
    // known to lie near, e.g. an earlier warp of the same recording against a like
    // reference. The coarsest level then searches only within `guideRadius` frames (of the
    // full resolution) of it rather than the whole band: the same path whenever the band's
    // best lies that near, at a fraction of the cost.
    const std::vector<std::pair<int, int>> *guide = nullptr;
    int guideRadius = 250;
    // Without a guide: where the coarsest level's corridor is wider than four times the
    // guide's, the same search one level coarser (a quarter of the cells) makes the guide.
    bool pilot = false;
};

// The warping path from (0, 0) to (a.frames-1, b.frames-1), as (i in a, j in b) pairs;
// empty when cancelled or a sequence is empty. `meanCost` (optional) receives the mean local
// cost along the path.
std::vector<std::pair<int, int>> dtwPath(
    const DtwSequence &a, const DtwSequence &b, const DtwOptions &options, const std::atomic_bool *cancel = nullptr);

} // namespace toonface
