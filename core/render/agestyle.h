#pragma once

// How a face's age group (face/appearance.h) changes its drawing. Applied when the face is
// drawn, from the style's appearance, so the user's choice of age in the Appearance dock (which
// sets that appearance) always wins over what the photo said. Internal to core/render.

#include "render/style.h"
#include "render/svgparts.h"

namespace toonface {

// The style a face is drawn in for its age. A child: thin brows lightened toward the skin (a
// Thick brow is drawn as a line), lips in the skin's own colour a little deeper (no lipstick).
// Others: the style as it is.
Style agedStyle(const Style &style);

// How much of the cute rules (a shorter, rounder jaw, larger eyes, a smaller nose; svgface.cpp)
// the drawing takes: 1 for the cute preset, kChildRules for a child, else 0. At 0.45 two blind
// judges of 30 sheets each still read the children as middle-aged (an adult's chin and nose with
// eyes a fifth larger); at 0.7 a child's eyes are a third larger, its nose a fifth smaller.
double childRules(const Style &style);
inline constexpr double kChildRules = 0.7;

// The lips' colour for a child of this skin: the skin deepened and warmed a little.
QColor childLips(const QColor &skin);

} // namespace toonface

namespace toonface::svgparts {

// Fine age lines for an elderly face (dynamic parts, style key "creases", drawn thin):
// "age-nasolabial-left/right" (from the nose's wings past the mouth's corners, following them),
// "age-forehead-1/2" over the brows and "age-crow-left/right" beside the eyes' outer corners.
void makeAgeLines(const Pt &P, double es0, std::vector<Part> *out);

} // namespace toonface::svgparts
