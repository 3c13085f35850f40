#pragma once

#include <QString>

namespace toonface {

enum class GlassesShape { None, Round, Rectangular, Rimless };

// How old the person looks, as far as the drawing cares: a child is drawn with thin light brows,
// lips of the skin's own colour, a rounder jaw and larger eyes (render/agestyle.h); an elderly
// person with a few fine age lines; an adult as the style says.
enum class AgeGroup { Adult, Child, Elderly };

// What a photo shows of the person beyond the 72 points: things worn and kinds of hair that the
// drawing adds as layers of their own (SVG ids "glasses", "moustache", "beard" (a beard or a goatee), "hat" and
// "hat-wrap"), each only
// when found. Their colours are the components "glasses" (stroke: frame; fill: lens tint, usually
// transparent), "moustache", "beard" and "hat"; a component's `visible` switches its layer off.
// The lenses as measured on the photo, in ES0 about each eye's middle (between its corners):
// half width and half height, and how far the lens's centre lies outward (toward the temple) and
// down from there. Zero half sizes: not measured, drawn in the shape's usual proportions.
struct GlassesFit
{
    double halfWidth = 0, halfHeight = 0;
    double outward = 0, down = 0;

    bool isSet() const { return halfWidth > 0 && halfHeight > 0; }
    bool operator==(const GlassesFit &) const = default;
};

struct Appearance
{
    GlassesShape glasses = GlassesShape::None;
    bool moustache = false;
    bool beard = false; // on the chin and along the jaw; it opens with the jaw
    bool goatee = false; // on the chin only, under the lower lip (drawn as the "beard" layer when there is no beard)
    bool hat = false; // the top of the head is a hat, not hair
    bool bald = false; // the head shows the skull: the hair outline is drawn as skin
    GlassesFit lens; // the lenses' size and place, when measured
    // The hat wraps the head's sides and falls past the chin (a headscarf, a hood): drawn around
    // the face in the hat's colour, no hair showing.
    bool wrap = false;
    AgeGroup age = AgeGroup::Adult;

    bool operator==(const Appearance &) const = default;
};

QString glassesShapeName(GlassesShape v); // "none", "round", "rectangular", "rimless"
bool glassesShapeFromName(const QString &name, GlassesShape *v);
QString ageGroupName(AgeGroup v); // "adult", "child", "elderly"
bool ageGroupFromName(const QString &name, AgeGroup *v);

} // namespace toonface
