#pragma once

// The neck and shoulders under the head (style component "body": the clothing's colours; the neck
// takes the face's). Internal to core/render: SvgFace draws them in <g id="body"> behind the head
// group, outside the head's motion, so the shoulders stay put when the head turns or nods; the
// neck's top reaches up behind the jaw, so it stays attached to it.

#include "render/svgparts.h"

namespace toonface::svgparts {

// "shoulders" (style key "body") and then "neck" (style key "face"), from the neutral points.
std::vector<Part> makeBody(const Pt &P, double es0);

// How far below the chin the drawing reaches (ES0): the neck and the top of the shoulders. A
// photo with less room than this under the chin shows no body (sampleColours, detect/photocolours.h).
inline constexpr double kBodyRoomBelowChin = 0.6;

} // namespace toonface::svgparts
