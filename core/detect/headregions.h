#pragma once

#include "detect/faceregions.h"
#include "face/facemodel.h"

#include <QImage>
#include <QLineF>
#include <QRectF>
#include <QString>

#include <vector>

namespace toonface {

// The thesis' face and hair regions (Algorithms 4.1, 4.3, 4.4) around a face whose inner
// points are known (from landmarks), and the hair and ear points found on them (4.3.2).
struct HeadRegionReport
{
    // The thresholds and colours measured (seed.valid when the regions could be computed;
    // its geometric part is not filled here, see seedGeometryFromPoints()).
    TrackingSeed seed;
    bool hairUsable = false; // the hair points were placed from the regions
    bool earUsable[2] = {false, false}; // each ear (image-left first) was placed from F's bulge
    double hairFraction = 0; // share of the outline's searches that ended on the head's edge
    bool longHair = false; // the outline goes down beside the face past the ears
    QString hairProblem; // why the hair region was not used, when it was not
    QRectF faceRegion; // the box of F_final's face component, image pixels
    QRectF hairRegion; // the box of the head's hair pixels (empty when none)
    std::vector<QLineF> rays; // the outline searches, for debugging
    QImage regionImage; // when asked: photo-sized overlay, face region skin-coloured, hair brown
};

// Computes F_final and H_final (regions.h) on a cut-out around the head of `face`, with the
// thresholds of Algorithms 4.1 and 4.3 measured in the face's own central rectangle (from the
// outer eye corners, the brows and the mouth: the known face takes the place of the
// eye-pair search), and places from them:
//  - the hair outline h.1..h.19, by outward searches over the head (face region, then hair
//    region) from eye level; hair that falls below the ears makes the outline go down beside
//    the face to where the hair ends; with no hair the points lie on the skull's edge;
//    dark pixels of a colour far from the hair's own (measured beside the temples) are not
//    hair (a hat);
//  - the ears, from the face region's bulges beside the cheek contour between brow and nose
//    base.
// Points whose region is unusable (a background of skin colour merging with the face, or a
// dark background merging with the hair) are not moved, and the report says so; the measured
// inner points and the forehead 11.x are never moved.
//
// requires: face was placed on `image` (same pixel frame); image is not null.
HeadRegionReport refineFromRegions(FaceModel *face, const QImage &image, bool withDebugImages = false);

} // namespace toonface
