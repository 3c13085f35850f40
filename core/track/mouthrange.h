#pragma once

#include "track/tracker.h"

#include <QVector>

#include <array>

namespace toonface {

// How the speaker of a whole clip moves the lips, so that the tracked mouth can be snapped to
// the nine shapes of face-model.md over the clip rather than frame by frame.
//
// A filmed mouth and the shape table differ in two ways. The table's neutral is the lips shut,
// while the neutral frame (the clip's first by default) may catch them apart: every closure
// then reads as the lower lip rising, i.e. `f`. And a speaker on video articulates within a
// small range: over the GRID clips of shared/data the outer lips (8.9 to 8.2) part from shut
// by 0.15-0.22 ES0 in 95 % of the frames, while the table's `a` parts them by 1.1 MNS0
// (0.37-0.46 ES0 on those faces), so only the shapes nearest to shut (m, h, e, f) were in reach. So a clip's
// mouth is measured as a range:
// - `closedEs0`: where the four mouth controls (8.9, 8.2, 8.4, 8.3; ES0 of the neutral face,
//   the head's motion taken out) lie with the lips shut: the median over the clip's most closed
//   frames (the kClosedShare of them whose outer lips part the least). The table's `m`.
// - `gain`: the factor that carries the clip's wide openings (`wideOpeningEs0`, the 95th
//   percentile of the outer lips' parting from closed) onto the table's widest opening, `a`'s:
//   the speaker's range mapped onto the character's. One factor for all four controls keeps
//   each motion's direction, so a rounded mouth stays rounded and a spread one spread.
struct MouthRange
{
    std::array<QPointF, 4> closedEs0 {};
    double gain = 1.0;
    double wideOpeningEs0 = 0;
    int framesMeasured = 0; // the frames the face was found on
};

// The share of a clip's frames taken as its closed mouth. Speech shuts the lips for its pauses
// and its p, b, m and f: in the GRID clips 25-40 % of the frames (silence around the sentence
// included), in continuous speech about a tenth. The median of the tenth that part the least
// stays on shut lips in either.
inline constexpr double kClosedShare = 0.1;
// The clip's wide opening, as a percentile of its frames' parting from closed: the few frames
// of its most open vowels.
inline constexpr double kWideOpeningPercentile = 0.95;
// A clip's mouth is enlarged at most this much: a mouth that parts by less than a quarter of
// `a` (a whisper, a still face) is not blown up into shouting, and the tracker's jitter on a
// still face (a few thousandths of ES0) stays far below the step to the nearest open shape.
// The GRID speakers need 1.8-3.2 (their wide openings against `a`'s).
inline constexpr double kMaxMouthGain = 4.0;

// Measures `frames` (tracked without snapping: their mouth controls' displacements are the
// measured ones). `widestOpeningEs0` is the table's widest parting of the outer lips, the
// y of 8.2 minus that of 8.9 in the widest shape (`a` by default), in ES0 of the neutral face.
// Lost frames are left out; with none found the range is the identity (closed at the neutral,
// gain 1).
MouthRange measureMouthRange(const QVector<TrackedFrame> &frames, double widestOpeningEs0);

// The table's widest parting of the outer lips (8.2's y minus 8.9's) over the shapes the
// tracker snaps to, in ES0 of its neutral face. requires: tracker.hasNeutral()
double widestMouthOpeningEs0(const Tracker &tracker);

// Snaps the mouth of every frame of a clip tracked without snapping to the nearest of the
// tracker's shapes (as Tracker::nearestMouthShape()), after carrying it into the table's terms:
// its displacement from `range.closedEs0`, times `range.gain`. Each frame's mouthShape is set
// and its mouth controls' displacements become the shape's (relative to `m`, as a snapping
// tracker sets them); lost frames hold the shape before them (`m` before any). Frames marked
// in `silent` (track/clipsilence.h; empty: none) are `m`, the mouth at rest, however the lips
// stand: a speaker's lips apart in a pause read as an open vowel. The frames' points and
// mouthOpenEs0 stay as measured.
void snapClipMouth(
    QVector<TrackedFrame> *frames, const Tracker &tracker, const MouthRange &range, const QVector<bool> &silent = {});

} // namespace toonface
