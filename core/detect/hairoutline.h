#pragma once

#include "detect/headparse.h"
#include "face/facemodel.h"

#include <QPointF>

#include <vector>

namespace toonface {

// The hair's silhouette as the parse of the head sees it, in the parse's work frame (eyes level,
// kParseEyeDistance apart): up the image-left side from where the hair ends, over the crown, down
// the image-right side to where it ends there. Empty when the parse cannot tell it (no parse, no
// hair's colour seen, a side of the head above the eyes beyond the photo's edge). Hair running up
// to the photo's top edge is followed up to it (topCut); so is a crop that cuts the crown off
// (HeadParse::crownCut), from the edge down, in the colour the temples gave (not when that was
// the room, HeadParse::roomFall), as wide as the photo shows it where it runs off the sides.
struct HairSilhouette
{
    std::vector<QPointF> left; // from the left end up to the crown, at the midline
    std::vector<QPointF> right; // from the crown, at the midline, down to the right end
    double top = 0; // the crown's row
    bool topCut = false; // the crown's row is the photo's top edge: the head may go on above it
    bool valid() const { return !left.empty() && !right.empty(); }
};

HairSilhouette hairSilhouette(const HeadParse &parse);

// The hair outline h.1 … h.19 from the parse: the silhouette sampled at equal steps along its
// length, h.10 at the crown, h.1 and h.19 where the hair ends on each side (beside the face for
// short hair, down at the shoulders for long hair; a wide, curly head of hair is as wide as it
// is). Where the parse is unsure (hairSilhouette() empty: a head whose crown shows that runs off
// the photo's sides; or a silhouette above the eyes wider than the search allows an outline, the
// background taken for hair), the outline from the search stays and only its lower ends follow the hair's fall
// (followHairFall). Points the user placed stay; where the crown runs beyond the photo's top edge, so do the search's
// points above it; where the parse's fall (HeadParse::fallEnds) ends lower than the silhouette, the lower ends follow
// it (followHairFall). True when a point moved.
bool outlineHairFromParse(FaceModel *face, const HeadParse &parse);

// The hairline from the parse: 11.1 where the forehead's skin ends up the midline (a fringe ends
// it low on the forehead, where it is drawn; never lower than a fifth of the eyes' distance over
// the brows), the temples 11.2 / 11.3 moved in proportion. Nothing when the parse did not see the
// crown or saw a bald head's skin reach its top. Points the user placed stay. True when a point
// moved.
bool placeHairlineFromParse(FaceModel *face, const HeadParse &parse);

} // namespace toonface
