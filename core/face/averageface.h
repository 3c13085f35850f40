#pragma once

#include "face/facemodel.h"

#include <QPointF>
#include <QRectF>

#include <array>

namespace toonface {

// A frontal average face laid out in a unit box: x from the left cheek (0) to the right
// cheek (1), y from the brows' upper edge (about 0.2) to the chin (about 1), the way face
// detectors frame a face. Points above (hair, forehead) and outside (ears) fall outside [0, 1].
const std::array<QPointF, kPointCount> &averageFaceUnitPoints();

// The average face placed in `faceBox` of an image of `imageSize`. Used where no photo
// gives the points: a fresh drawing, the start of manual placement, and test fixtures.
FaceModel averageFace(const QRectF &faceBox, QSize imageSize);

} // namespace toonface
