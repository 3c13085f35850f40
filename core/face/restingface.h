#pragma once

// The face at rest: what of a photo's brows and mouth is the moment's expression rather than the
// person, and the room the brows have to move in. Emotions (emotion.h) start from it, so that a
// photo's own frown, raised brows or smile do not show through every preset.

#include "face/pose.h"

namespace toonface {

class FaceModel;

// Where people's brows rest, in eye distances (ES0) above the eye corner below each end and
// square to the eye line: the middle half (25th to 75th percentile) of the 160 faces of the
// shared labelled set (faces-attributes, points by the landmark method, both sides averaged).
// A brow inside these bands is the person's own and stays; a brow outside them (a frown pulls
// the inner end down and in, surprise or worry lift it) is brought to the nearest edge.
struct BrowRestBands
{
    double heightLow = 0.205, heightHigh = 0.281; // mean of the inner and outer end's heights
    double slantLow = 0.053, slantHigh = 0.142; // inner end's height minus the outer end's
    double innerGapLow = 0.311; // distance between the inner ends, along the eye line
};
inline constexpr BrowRestBands kBrowRest {};

// The mouth corners at rest lie on the line where the lips meet, or a little below it: in the same
// set, the 10th percentile of the faces not smiling is 0.04 ES0 below it. Higher corners are the
// photo's smile, lower ones a grimace.
inline constexpr double kRestingCornerDrop = 0.04;

// The mouth's width at rest, corner to corner along the eye line in ES0: the 75th percentile of the
// 81 faces not smiling in the same set (median 0.853; the 80 smiling ones' median is 1.012). A
// wider mouth is the photo's smile stretching it, and its corners come in to that width.
inline constexpr double kRestingMouthWidthHigh = 0.919;

// The offsets, at full weight, that bring the brows of `face` into kBrowRest (the middle points
// 4.4a, 4.4 and their mirrors follow the ends by their place along the brow) and the mouth
// corners 8.4, 8.3 onto their resting height and within kRestingMouthWidthHigh. Zero for a face
// already at rest.
Pose restingFacePose(const FaceModel &face);

// How far the brows may rise: never above the hairline (11.1), where a hat's brim is drawn, less
// the brim's depth and half a brow (kBrowBelowHairline ES0), nor above their own place in the
// photo where that is higher. Brows of `pose` that would rise past it come down together, as a
// whole, by what the farthest point overshoots: their shapes (a sad brow's slant) stay.
inline constexpr double kBrowBelowHairline = 0.15;
void keepBrowsUnderHairline(const FaceModel &face, Pose *pose);

// The brows' and mouth's shape in a posed face, for tests and checks: per side, in ES0 above the
// eye corners and square to the eye line (image-left side first); the mouth corners' mean height
// above the middle of the lips' meeting line (2.2, 2.3), and the inner ends' gap.
struct ExpressionShape
{
    double innerHeight[2] {}, outerHeight[2] {};
    double slant(int side) const { return innerHeight[side] - outerHeight[side]; }
    double innerGap = 0;
    double cornerLift = 0;
    double mouthOpen = 0; // 2.3 below 2.2, in ES0
    double lipHeight = 0; // the lips' outer height, 8.2 below 8.1, in ES0
};
ExpressionShape expressionShape(const FaceModel &face, const Pose &pose);

} // namespace toonface
