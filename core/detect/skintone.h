#pragma once

#include <QColor>

namespace toonface {

// Whether a pixel is the skin of a given colour, as it shows under the same light: its
// chromaticity (r, g over r + g + b) within kSkinChroma of the skin's, lit more or less (a scalp
// shines, a jaw is in shadow: luma within kSkinShade times the skin's).
inline constexpr double kSkinChroma = 0.035;
inline constexpr double kSkinShade[2] = {0.55, 1.6};
bool skinLike(QRgb c, const QColor &skin);

// Skin under a shine: brighter than the skin, its chromaticity on the way from the skin's toward
// neutral light's (a shine adds the light's own colour), at most kShineToNeutral of the way there
// (white and grey hair lie at its end), and within kSkinChroma of that way.
inline constexpr double kShineToNeutral = 0.75;
bool shineOnSkin(QRgb c, const QColor &skin);

double lumaOf(QRgb c); // Rec. 601 luma

} // namespace toonface
