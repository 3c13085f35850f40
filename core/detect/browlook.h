#pragma once

#include "render/style.h"

#include <QColor>
#include <QImage>

namespace toonface {

class FaceModel;

// How thick and how dark the person's brows are, from the photo: across each brow's middle, the
// L* profile (the median of the columns over the brow's middle third, on the level face of
// levelface.h) dips below the skin around it; the dip's depth is the brows' contrast and its
// width at half depth their thickness. Both are relative (ES0, and L* against the same photo's
// skin), so a small crop and a large portrait, a dim and a bright photo, read alike.
struct BrowLook
{
    double thickness = 0; // ES0, the two brows' mean
    double contrast = 0; // L* units below the skin around them, the two brows' mean
    bool seen = false; // both brows dip clearly (at least kBrowSeenContrast)
};

// The least contrast (L*) at which a brow counts as seen: below it the profile is skin, a fringe
// or a shadow's gradient, and the style keeps its brows.
inline constexpr double kBrowSeenContrast = 6.0;

BrowLook measureBrows(const QImage &photo, const FaceModel &face);

// Draws `brows` (the "eyebrows" component) as the look says: its line weight in proportion to the
// measured thickness, the median person's brows at the base style's weight (kBrowWidth; a
// cartoon's brows are drawn thinner than a photo's, whose median is kMedianBrowThickness), within
// kBrowWidths; and its colour's L* the measured contrast below the drawn skin's (its hue and
// colourfulness kept), so light brows on pale skin stay light and dark ones dark. An unseen look leaves it as it is.
// kMedianBrowThickness is the median over the 161 detected faces of faces-attributes (every age,
// sex and skin tone; `toonface-bench likeness.attributes` prints the measures' percentiles by
// group): 10th to 90th percentile 0.083 to 0.188 ES0, drawn 2.8 to 6.3.
inline constexpr double kMedianBrowThickness = 0.135;
inline constexpr double kBrowWidth = 4.5; // ES0/100, Style::baseComponents()' eyebrows
inline constexpr double kBrowWidths[2] = {1.5, 8.0};
// Drawn brows lie at least this far (L*) below the drawn skin, however faint the photo's: a
// cartoon's brow that does not read against the skin is no brow (the 10th percentile of the
// measured contrast over faces-attributes is 11.4, its median 28.6).
inline constexpr double kMinBrowContrast = 20.0;
void applyBrowLook(const BrowLook &look, const QColor &skinDrawn, ComponentStyle *brows);

} // namespace toonface
