#pragma once

// The cartoon cues of an expression beyond the points' motion: frown lines between lowered brows
// and flared nostrils, worry lines over raised inner brow ends, forehead lines over raised brows,
// cheek lines and blush beside a smiling mouth. Internal to core/render (SvgFace draws them).
//
// Each cue's strength comes from how far the posed points have moved from the neutral ones, so it
// follows an emotion's intensity (and its fades on the timeline) wherever the pose comes from. A
// cue is always present with the same element structure, so an SMIL export animates it like the
// mouth: at strength 0 it has no area (a crease is a lens of zero width, a blush a circle of zero
// radius) and draws nothing.

#include "render/svgparts.h"

namespace toonface::svgparts {

// How strongly the pose shows each cue, 0..1, from the posed points `P`, the neutral ones `N` (the
// photo's) and those of the face at rest `R` (restingFacePose): a point's move counts from the
// nearer of its two resting places, and not at all between them, so neither the photo's own
// expression nor the rest that takes it out draws a cue; an emotion's move past both does.
struct CueStrengths
{
    double frown = 0; // inner brow ends lowered (angry)
    double worry = 0; // inner brow ends raised above the outer ones (sad)
    double forehead = 0; // whole brows raised (surprise)
    double smile = 0; // mouth corners raised (smile)
};
CueStrengths cueStrengths(const Pt &P, const Pt &N, const Pt &R, double es0);

// A tapered line from a to b bowed by `bow` toward `side` at its middle (path data): a lens
// `halfWidth` thick in the middle; with halfWidth 0 it has no area.
QByteArray lens(QPointF a, QPointF b, QPointF side, double bow, double halfWidth);

// Dynamic parts, drawn over the jaw and under the mouth: "blush-left/right" (style key "blush"),
// "crease-cheek-left/right", "crease-frown-left/right", "crease-nostril-left/right" (flared
// nostrils), "crease-worry-left/right",
// "crease-forehead-1/2" (style key "creases").
void makeExpressionCues(const Pt &P, const Pt &N, const Pt &R, double es0, std::vector<Part> *out);

} // namespace toonface::svgparts
