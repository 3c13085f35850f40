#pragma once

#include "face/facemodel.h"

#include <QImage>
#include <QLineF>

#include <vector>

namespace toonface {

// What refineFromPhoto() did, for confidence figures and debug images.
struct HairSearchReport
{
    double hairFraction = 0; // share of the hair points placed from the photo (0: all by rule)
    double earFraction = 0; // share of the ears placed from the photo
    std::vector<QLineF> rays; // the search rays, from where each search started to where it ended
    QImage regionMask; // when debugging: the hair/skin/background classes as colours, photo-sized
};

// Refines the estimated points of a face mapped from landmarks (faceFromLandmarks68) with
// the photo: the hair outline and the ears. Points the photo does not settle keep their
// geometric estimate. Measured points (eyes, brows, nose, mouth, jaw) are not moved.
//
// requires: face was placed on `image` (same pixel frame); image is not null.
void refineFromPhoto(
    FaceModel *face, const QImage &image, HairSearchReport *report = nullptr, bool withDebugImages = false);

} // namespace toonface
