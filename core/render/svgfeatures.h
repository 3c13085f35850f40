#pragma once

// The layers of what a person wears or grows (Style::appearance): glasses, moustache, beard and
// hat, each one SVG element named by its id. Internal to core/render (SvgFace draws them).

#include "render/style.h"
#include "render/svgparts.h"

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

// The face outline over the skull of a bald head: the jaw sides, the cheeks and the hair
// outline's crown (within a skull's height; the sides a rounded arch, whatever the outline did
// there), with the jaw's tangents at both ends (so the jaw joins it smoothly).
QByteArray baldFaceOutline(const Pt &P, double es0, QPointF startTangent, QPointF endTangent);

} // namespace toonface::svgparts
