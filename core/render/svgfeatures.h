#pragma once

// The layers of what a person wears or grows (Style::appearance): glasses, moustache, beard and
// hat, each one SVG element named by its id. Internal to core/render (SvgFace draws them).

#include "render/style.h"
#include "render/svgparts.h"

#include <algorithm>

namespace toonface::svgparts {

// Static: the hat, over the hair and the top of the face, below the brows.
Part makeHat(const Pt &P, double es0, int depth);
// A headscarf's or a hood's cloth around the face (behind it): over the head a little outside
// the hair outline, down both sides past the cheeks and jaw to under the chin.
Part makeWrap(const Pt &P, QPointF centre, double es0, int depth);
// Dynamic: the beard follows the jaw (it opens with it) and the lower lip; drawn before the mouth.
Part makeBeard(const Pt &P, double es0);
// Dynamic: a goatee, the chin's part of a beard (under the lower lip, round the chin), with the
// beard's id and colours; it follows the lower lip and the chin as they move.
Part makeGoatee(const Pt &P, double es0);
// Dynamic: the moustache follows the upper lip and its corners; drawn after the mouth.
Part makeMoustache(const Pt &P, double es0);
// Dynamic layer (above the eyes), but fixed to the eye corners: rims, bridge and arms; the lenses
// of the measured size and place when `fit` is set.
Part makeGlasses(const Pt &P, GlassesShape shape, const GlassesFit &fit, double es0);

// Where makeGlasses() draws the lenses: their centres (image-left first) and half sizes.
struct LensPlace
{
    QPointF centre[2];
    double halfWidth = 0, halfHeight = 0;
    double top() const { return std::min(centre[0].y() - halfHeight, centre[1].y() - halfHeight); }
};
LensPlace glassesLenses(const Pt &P, GlassesShape shape, const GlassesFit &fit, double es0);

// An expression never lifts a brow under the hat's brim (makeHat, across the hairline 11.1):
// when a point of `posed` lies higher than kBrowBelowHairline ES0 under 11.1 (or than its place
// in `neutral`, where the drawing's own brow is higher), both brows come down together by the most
// any point overshoots, keeping their shapes. (The pose already keeps them under the photo's
// hairline, keepBrowsUnderHairline; this holds it for the drawing's, which the style's caricature
// moves.)
void keepBrowsUnderBrim(Points &posed, const Points &neutral, double es0);

// An expression never pushes a brow down across the glasses' rims: each brow point of `posed`
// stays kBrowAboveRim ES0 (half a thick brow and the rim's stroke) above the lenses' top, or
// where it is in `neutral` when the photo's own brow already lies lower.
inline constexpr double kBrowAboveRim = 0.05;
void keepBrowsAboveGlasses(Points &posed, const Points &neutral, const LensPlace &lenses, double es0);

// The face outline over the skull of a bald head: the jaw sides, the cheeks and the hair
// outline's crown (within a skull's height; the sides a rounded arch, whatever the outline did
// there), with the jaw's tangents at both ends (so the jaw joins it smoothly).
QByteArray baldFaceOutline(const Pt &P, double es0, QPointF startTangent, QPointF endTangent);

} // namespace toonface::svgparts
