#pragma once

#include "face/pointtable.h"

#include <QPointF>

#include <array>

namespace toonface {

class FaceModel;

// A caricature of a face, as a cartoonist draws one: what makes the face differ from the average
// face (face-model.md's template with people's eyes, aligned to it by a similarity transform fitted
// to the contour, brows, eyes, nose and mouth) is exaggerated by `factor` (0 = the points as they are, 0.35 = a
// mild likeness, 1 = twice the difference). Eye size and shape, brow arch, nose width, mouth
// width, lip fullness, face width and jaw shape all follow from the points. The hair outline
// follows the contour near it and the ears follow the cheeks, so they stay attached. How far the
// lips are parted is the photo's moment, not the person's, and is not exaggerated.
//
// Returns the displacement of every point (pixels); each is at most kMaxCaricatureShift * ES0
// * factor long, so a badly placed point cannot tear the drawing. Zero for an invalid face.
inline constexpr double kMaxCaricatureShift = 0.4;
// People's eyes as the landmarks find them (caricature.cpp): the median eye's width (ES0) and its
// opening (the lids' distance over the width).
inline constexpr double kPeoplesEyeWidth = 0.395;
inline constexpr double kPeoplesEyeOpening = 0.30;
std::array<QPointF, kPointCount> caricatureOffsets(const FaceModel &face, double factor);

} // namespace toonface
