#pragma once

#include "face/facemodel.h"

#include <QImage>

namespace toonface {

// Measures of what a face wears or grows, each against the person's own skin in the same photo
// (CIE L*a*b*, the cheeks under the eyes as the reference), so that a dark or a light skin, a
// colour cast or a dim photo do not change what they say. Measured on a face whose eyes are
// level (appearance.cpp turns a tilted one first). Each is a share or a ratio; the decisions'
// thresholds are in appearance.h.
struct AppearanceEvidence
{
    // Facial hair, per place (upper lip; chin; jaw's sides, the weaker of the two): the share of
    // pixels that are hair, i.e. darker than the cheeks by more than their own spread and
    // textured (fine detail above the cheeks'), the evidence shadows and a dark jaw line lack:
    // those are smooth.
    double lipHair = 0, chinHair = 0, jawHair = 0;
    // The same places' fine texture (mean |L* - its 3x3 mean|, the face scaled to kEvidenceEs0)
    // over the cheeks'.
    double lipDetail = 0, chinDetail = 0, jawDetail = 0;
    // The same places' median L* less the cheeks' (negative: darker), and how much less red
    // (a*) they are than the cheeks: hair is less red than the skin it grows from, where a
    // shadow on skin or a dark jaw line keeps the skin's redness (jaw: the side losing less).
    double lipDL = 0, chinDL = 0, jawDL = 0, lipRedLoss = 0, chinRedLoss = 0, jawRedLoss = 0;
    // The redness the chin and the jaw's sides (their mean; the jaw: the weaker side) lose
    // against the less red of the cheeks and the forehead between the brows. A beard, dark,
    // grey or fair, and however smooth it looks at kEvidenceEs0, is less red than all the skin
    // above it; a smile's or make-up's flushed cheeks make a bare chin only less red than the
    // cheeks, not than the forehead. (On faces-attributes the beards whose chin is too smooth
    // for chinDetail lose 3 to 6.5 here, no woman or child more than 1.5; ROC area 0.84 for a
    // beard.) Measured, not decided on: as a fourth alternative of the chin's rule it raised the
    // beard's held-out recall from 0.57 to 0.63 but cost its precision, 0.92 to 0.84 (10 x
    // 5-fold splits, bench likeness.attributes), so the rule leaves it out.
    double lowerRedLoss = 0;
    // How unlike the cheeks the upper lip is as a whole: the distance (CIE76 delta E*ab) from the
    // cheeks' median L*, a*, b* to the lip's. A moustache changes lightness, redness and
    // yellowness together (grey or fair hair too, by a*, b*, where it hardly darkens); a shadow
    // under the nose mostly darkens. On faces-attributes it ranks moustaches above the rest
    // better than the redness loss alone (ROC area 0.91 against 0.85, bench likeness.attributes).
    double lipColour = 0;
    // Glasses' bridge: over the nose's middle between the inner eye corners, the strongest thin
    // line (a dip or a ridge in L* across a few pixels) against the nose's own smooth run, in
    // L* units; and the same measured beside each eye's outer corner on vertical lines (a frame's
    // side rims; the weaker side).
    double bridgeLine = 0, sideRims = 0;
    // Rims under both eyes: a thin horizontal line below the lower lid (the weaker eye), L*.
    double lowerRims = 0;
    double cheekL = 0; // the cheeks' median L*
};

// The face is measured scaled to this eye separation (pixels), so that fine texture means the
// same on a small crop and on a large portrait.
inline constexpr double kEvidenceEs0 = 48.0;

AppearanceEvidence measureEvidence(const QImage &photo, const FaceModel &face);

} // namespace toonface
