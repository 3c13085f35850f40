#pragma once

#include "face/facemodel.h"
#include "face/pose.h"

#include <QImage>
#include <QPointF>
#include <QVector>

#include <array>

namespace toonface {

// What a tracking method measured on one frame: the 72 points in the frame's pixels (the
// mouth, eyelids, eyeballs and brows measured; the others carried along with the head), the
// points stable under expressions that the head's motion is fitted on, and a confidence 0..1.
struct FaceMeasurement
{
    bool found = false;
    double confidence = 0;
    std::array<QPointF, kPointCount> points {};
    QVector<int> stable; // indices of points that only the head moves (eye corners, nose)
};

// The head's motion from the neutral face to a frame: the similarity (rotation, scale,
// translation) that best carries the neutral's stable points onto the frame's.
struct HeadMotion
{
    double a = 1, b = 0; // scale * (cos, sin) of the rotation
    QPointF t;
    QPointF map(QPointF p) const { return {a * p.x() - b * p.y() + t.x(), b * p.x() + a * p.y() + t.y()}; }
    QPointF unmap(QPointF p) const;
    double scale() const { return std::hypot(a, b); }
    double rotationDeg() const;
};
HeadMotion fitHeadMotion(const std::array<QPointF, kPointCount> &neutral, const std::array<QPointF, kPointCount> &now,
    const QVector<int> &stable);

// The motion of one frame relative to the neutral face, in ES0 units of the neutral face.
struct FaceMotion
{
    // Every point's displacement in the neutral face's frame (the head's motion taken out).
    std::array<QPointF, kPointCount> displacementEs0 {};
    double rotationDeg = 0; // positive: clockwise on screen
    QPointF translationEs0; // of the eyes' midpoint
    double scale = 1.0;
    double leftEyeOpen = 1.0; // lid aperture / the neutral's (image-left eye)
    double rightEyeOpen = 1.0;
    double mouthOpenEs0 = 0; // gap between the inner lips 2.2-2.3
    QPointF gazeEs0; // the eyeballs' mean offset from their eyes' centres, relative to the neutral's
};
// requires: neutral.found, its eyeball centres apart. The brows' displacements are fitted by
// fitBrowMotion.
FaceMotion measureMotion(const FaceMeasurement &neutral, const FaceMeasurement &now);

// A brow moves as a whole: it rises or falls, tilts (its inner end against its outer: sad,
// angry), and is drawn in or out. Replaces each brow's four point displacements by their
// least-squares straight line along the brow (in the position from its inner end, on the
// neutral face), which keeps those motions exactly and leaves out the point-to-point wobble of
// tracked landmarks that would bend the drawn brow into shapes no brow makes.
void fitBrowMotion(const std::array<QPointF, kPointCount> &neutral, std::array<QPointF, kPointCount> *displacement);

// The pupil in an eye outlined by `outline` (frame pixels) of a grey image: the centroid of its
// darkest quarter of pixels (iris and pupil), or the outline's centre when the eye is too small
// to tell.
QPointF locatePupil(const QImage &gray, const QVector<QPointF> &outline);

} // namespace toonface
