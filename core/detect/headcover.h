#pragma once

#include "detect/headparse.h"

#include <QColor>

namespace toonface {

// What lies over the forehead and beside the face in a parse of the head (headparse.h): the
// evidence a hat, a cap, a scarf or a wrap leaves that hair does not. Hair takes the brows'
// colour family and the hues hair grows in, its edge over the forehead curves or breaks into
// strands; a covering is often a colour no hair has, unlike the brows, with a straight edge low
// on the forehead, and a scarf wraps the sides of the face in the same colour.
struct HeadCover
{
    bool seen = false; // enough of the person, not skin, right over the forehead to measure
    double l = 0, a = 0, b = 0; // its median CIE L*a*b*
    QColor colour; // ... in sRGB
    double chroma = 0;
    double hueOff = 0; // degrees its hue lies outside the hues hair grows in (0 inside them, or too grey to tell)
    double toSkin = 0, toBrows = 0; // L*a*b* distances from the cheeks' and the brows' colours
    double lighter = 0; // its L* over the brows' (positive: lighter)
    double edgeSpread = -1; // the forehead's top edge about its best straight line, in eye distances (80th percentile)
    double edgeHeight = 0; // the forehead's top edge above the brows' top, in eye distances (median)
    double sides = 0; // share of bands beside the cheeks of its colour (a scarf or a hood wraps them)
};

HeadCover measureCover(const HeadParse &parse);

// Whether the covering is headwear, not hair: a colour no hair grows in (its hue outside hair's,
// by kColourScore degrees times chroma / 100; not in colours darker than kCoverDarkest in HSV value,
// whose hue a cast decides: black hair goes navy under a cool light), or white far lighter than the
// brows (hair that white goes with white brows). kCoverColourScore is the threshold
// `toonface-bench likeness.attributes` fits on all the labelled faces (held-out folds: right on
// 0.89); the white rule's two are set below the white coverings' (L* 87 to 98, over the brows by
// 62 to 73) rather than fitted: the fit takes any covering lighter than L* 58 for white, which
// on other faces would take blond and grey hair (L* up to 60 and more) for caps. (One haired
// crop whose room shows over its head, at L* 87 and 60 over its brows, is taken for a cap.)
bool isHeadwear(const HeadCover &cover);
inline constexpr double kCoverColourScore = 10.9;
inline constexpr double kCoverDarkest = 0.2;
inline constexpr double kCoverWhiteL = 80.0;
inline constexpr double kCoverWhiteOverBrows = 50.0;
// Headwear wraps the head (a headscarf, a hood) when its colour covers at least this share of the
// bands beside the cheeks (half: hair or the room beside the face fill the rest of them otherwise).
inline constexpr double kWrapSides = 0.5;

} // namespace toonface
