#pragma once

// The pieces of the landmark detection (detector.cpp) that video tracking reuses frame after
// frame without running the whole detection: the shared model, the grey image the model wants,
// the face detector's boxes, and fits of the 68 points from a box or from the face of the frame
// before.

#include "detect/detectionruntime.h"
#include "detect/landmarkmap.h"

#include <QImage>
#include <QPointF>
#include <QRectF>
#include <QString>

#include <array>
#include <memory>
#include <vector>

namespace toonface {

class LandmarkPredictor;
using Landmarks68 = std::array<QPointF, kIbugPointCount>;

// The landmark model: sharedLandmarkModel() of detect/detectionruntime.h.

// Grey levels as the landmark model and the face detector were trained on: (R + G + B) / 3.
QImage landmarkGray(const QImage &image);

// A face the HOG face detector found: its box in the image's pixels and its margin over the
// detector's threshold (0 at the threshold).
struct FaceCandidate
{
    QRectF box;
    double score = 0;
};

// The faces in `gray` (landmarkGray()) as detectFace() finds them: passes from large faces
// (a third of the shorter side) to small ones, stopping at the first pass that finds one.
// Thread-safe (a detector per thread).
std::vector<FaceCandidate> findFaceCandidates(const QImage &gray);

// Whether the detector sees a face in `region` of `gray` whose box is about `faceSize` pixels:
// the region is scaled so that such a face fills the detector's window and scanned over a few
// pyramid levels (faces 0.8x - 1.6x that size). Returns the best box (image pixels), or a
// candidate with an empty box. A few milliseconds for a face region of any size.
FaceCandidate verifyFace(const QImage &gray, const QRectF &region, double faceSize);

// The 68 points from a detector box, as detection fits them (a first fit, then a fit in the
// upright box the first one implies).
Landmarks68 fitLandmarksInBox(const LandmarkPredictor &model, const QImage &gray, const QRectF &box);

// The 68 points of a face that was at `previous` a moment before (the frame before in a
// video): the model starts from the upright box that `previous` implies, so one fit suffices.
Landmarks68 fitLandmarksFrom(const LandmarkPredictor &model, const QImage &gray, const Landmarks68 &previous);

// The detector box `points` imply (the model's mean shape fitted to them), its roll in degrees
// and how far, on average, the points lie from that fitted mean shape, in units of the box's
// side: about 0.03-0.06 for faces, more for shapes no face has.
struct ImpliedBox
{
    QRectF box; // upright, of the implied size, about the implied centre
    double rollDeg = 0;
    double residual = 0;
};
ImpliedBox impliedBox(const LandmarkPredictor &model, const Landmarks68 &points);

} // namespace toonface
