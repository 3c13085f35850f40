#pragma once

// The steps of the classic pipeline (classic.h) that detectClassic() runs and no caller outside
// it needs: the feature regions of Algorithm 4.6 and the placement of the 72 points (section
// 4.3). Private to core/detect.

#include "detect/classic.h"
#include "detect/regions.h"
#include "face/facemodel.h"

#include <QPoint>
#include <QRect>
#include <QSize>

#include <vector>

namespace toonface {

// The pixels of the edge components that reach into `seedRect`, kept inside `clip`.
struct FeatureRegion
{
    QRect box;
    std::vector<QPoint> pixels;
};

FeatureRegion growFeature(const Mask &edges, QRect seedRect, QRect clip);

// The feature regions found in the 2d x 2d square: the image-left eye and brow, the nose, the mouth.
struct ClassicFeatures
{
    FeatureRegion eye, brow, nose, mouth;
};

// Section 4.3.1: the points of the brows, eyes, nose and mouth from their feature regions, the
// eyeballs (res.eyeballs, res.d, res.eyeMid) and the central cuts (res.noseCut, res.mouthCut);
// the right side mirrors the left about the eyeballs' perpendicular bisector. The other points
// are left for placeOutline(). In the pixels of the working image of `size`.
FaceModel placeFeaturePoints(const ClassicFeatures &features, const ClassicResult &res, QSize size);

// Section 4.3.2: the cheek boundaries (res->cheekLeft, res->cheekRight), the contour by
// searching out of F_final, the ears beside it and the hair outline on H_final, around the points
// of placeFeaturePoints().
void placeOutline(FaceModel *face, const RefinedRegions &refined, QSize size, ClassicResult *res);

} // namespace toonface
