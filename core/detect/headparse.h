#pragma once

#include "face/facemodel.h"

#include <QColor>
#include <QImage>
#include <QPoint>
#include <QPointF>
#include <QSize>
#include <QTransform>

#include <cstdint>
#include <vector>

namespace toonface {

// A parse of the head around a detected face: which pixels near it belong to the person and,
// of those, which are skin. The person is cut from the background as a whole (GrabCut, seeded
// from the landmarks: the face inside its contour is the person for sure, an ellipse over the
// crown and a column under the chin probably, the far corners above the mouth not); the skin is
// the person's own, modelled on the cheeks in CIE L*a*b* (so a dark or a pale skin, a colour
// cast or a dim photo do not change what is skin). Every length is a multiple of the eyes'
// distance d: the parse is made in a frame where the eyes are level and kParseEyeDistance
// pixels apart, so its cost does not grow with the photo.
struct HeadParse
{
    enum Label : std::uint8_t {
        Outside, // beyond the photo's edge
        Background,
        Skin, // the person, coloured as the cheeks
        Other, // the person, not skin: hair, headwear, brows, eyes, lips, clothes
    };

    bool valid = false;
    QSize size; // of the work frame
    QTransform toWork; // photo to work frame
    std::vector<std::uint8_t> labels; // row-major, one Label per work pixel

    // Up the forehead's middle columns from the brows: the head's top (where the person ends) in
    // eye distances above the brows' top, and how far up toward it the skin reaches (0..1; a bald
    // head's skin reaches its top; a scalp's shine is its skin, hair as dark as the skin is not:
    // the scalp is no darker than the forehead over kScalpDarker). crownCut: the photo's edge
    // stops most columns' skin; topCut: it stops most columns' head (hair or a hat may go on).
    bool crownCut = true, topCut = false;
    double headHeight = 0, scalpReach = 0;
    // Evidence of a bald head in a crop that cuts the crown off (measured, not decided on: see
    // the bench's bald report): the share of skin over the forehead's middle from the brows up
    // to the photo's top edge or the head's (crownSkin), and beside the temples, from the brows
    // up kTempleBand d (templeSkin); 0 where the photo shows none of it.
    double crownSkin = 0, templeSkin = 0;

    // How far the hair falls beside the face: the lowest row (on the lower side) where a band
    // beside the cheeks still holds hair of the crown's colour, in eye distances below the chin's
    // point (negative: above it). hairSeen: the crown showed hair to take the colour from;
    // fallCut: the photo ends while the hair still falls.
    bool hairSeen = false, fallCut = false;
    bool templeHairSeen = false; // the crown showed none, the temples did (a tight crop): its colour came from there
    double hairFall = 0;
    // A tight crop's temple sample far lighter than the cheeks (templeLighter, in L*, at least
    // kRoomLighter) is the room beside a short-haired head, not hair: what falls in its colour
    // beside the face is the wall, so the fall is left at the eyes' line (roomFall) and the
    // outline does not follow it. measuredFall is the fall as its colour was followed.
    bool roomFall = false;
    double templeLighter = 0, measuredFall = 0;
    QPointF fallEnds[2]; // in the photo: where each side's fall ends, at the hair's outer edge (left, right)

    // What the parse measured in: the work frame's pixels (RGB), the cheeks' median colour, the
    // brows' points and their top row, the hair's colour (sampled over the forehead, or
    // beside the temples; invalid unless hairSeen or templeHairSeen), and up each forehead column the skin's last pixel
    // below the photo's edge.
    QImage work;
    QColor cheeks, hair;
    // The pixels (photo colours, 0xffRRGGBB) the hair's colour was taken from: the person's
    // pixels other than skin over the forehead or beside the temples (haircolour.h reads them).
    std::vector<QRgb> hairSample;
    std::vector<QPointF> brows;
    double browTop = 0;
    std::vector<QPoint> foreheadTop;
    QPointF sideCheeks[2][2]; // the cheeks' lines beside the face (left, right), each from eye level to the jaw

    Label at(int x, int y) const { return Label(labels[size_t(y) * size.width() + x]); }
};

inline constexpr double kParseEyeDistance = 24.0;
// L* by which a tight crop's temple sample outshines the skin when it is the room, or a shine, not
// hair: its fall is not followed (HeadParse::roomFall) and its colour not drawn (photocolours.cpp).
// Chosen for the colour by leave-one-out over the 79 crops of faces-attributes whose hair colour
// is labelled, for drawing light hair (blond, grey) light and dark hair dark: held out 0.835
// right, against 0.759 drawing every sample. For the hair's length the same rule holds out 0.73
// right over the 44 crops whose temples gave the colour (the fall's two thresholds fitted per
// fold; 0.66 without it), where fitting it afresh as a third threshold holds out 0.68 (too many
// thresholds for 44 faces). `toonface-bench likeness.attributes` prints both.
inline constexpr double kRoomLighter = 17.0;

// Nothing (valid false) for an invalid face or a null photo.
HeadParse parseHead(const QImage &photo, const FaceModel &face);

// The hair outline's lower ends follow the hair down beside the face where the parse sees it
// fall lower than the outline ends (long hair the outline's search stopped short of; where the
// photo's edge cuts the fall, down to that edge); points the user placed stay. True when a point
// moved.
bool followHairFall(FaceModel *face, const HeadParse &parse);

} // namespace toonface
