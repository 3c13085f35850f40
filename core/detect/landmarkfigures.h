#pragma once

// The figures of a landmark detection, for the detection steps view and --debug-dir. Private to
// core/detect.

#include "detect/facescan.h"
#include "detect/hairsearch.h"
#include "detect/headregions.h"
#include "detect/landmarkmap.h"
#include "face/facemodel.h"

#include <QImage>
#include <QMap>
#include <QString>

#include <array>
#include <vector>

namespace toonface {

// Into *out: "detect-landmarks" (the faces' boxes, the chosen one green, and the 68 landmarks on
// the photo), "detect-points-crop" (the 72 points on the head enlarged to about 800 px, labelled
// when there is a QGuiApplication; the geometric hair and ear estimates before the photo search
// in orange), and the hair search's and the regions' own images when they made them.
void addLandmarkDebugImages(QMap<QString, QImage> *out, const QImage &image, const std::vector<FaceBox> &faces,
    int chosen, const std::array<QPointF, kIbugPointCount> &ibug, const FaceModel &geometric, const FaceModel &face,
    const HairSearchReport &hair, const HeadRegionReport &regions);

} // namespace toonface
