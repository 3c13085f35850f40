#pragma once

#include "face/facemodel.h"

#include <QPointF>
#include <QSize>
#include <QString>

#include <array>
#include <functional>
#include <vector>

namespace toonface {

inline constexpr int kIbugPointCount = 68;

// Maps the 68 landmarks of the iBUG/300-W scheme (0-based, as dlib's shape_predictor gives
// them; index 0 is the jaw's image-left end) onto the 72 points of face-model.md.
//
// Eyes, brow ends, nostrils, nose tip, mouth and chin follow the correspondence table of the
// scoring protocol (shared/data/README.md); every other point is derived by a rule stated in
// landmarkmap.cpp. The rules work in the face's own frame (x along the eye line, y down
// perpendicular to it), so a tilted head gives a tilted model. Hair, forehead and ears are
// not in the 68 points: they are a geometric estimate from the face's proportions, which
// refineFromPhoto() (hairsearch.h) improves when the photo allows.
//
// requires: the 68 points are finite and the two eyes are apart.
// ensures: all 72 points are finite; when imageSize is valid, the estimated ears are clamped
// into the image; the hair and forehead go on beyond an edge that cuts the head off (a head
// kept inside would be drawn with a flat top); the measured points are left as given.
FaceModel faceFromLandmarks68(const std::array<QPointF, kIbugPointCount> &ibug, QSize imageSize);

// The head's layout that the estimated points are built on, from a face's measured points
// (eyes, brows, nose, mouth, cheeks, chin). Lengths in image pixels; positions in the face
// frame: origin at EyeMid (between the eyeball centres), x along the eye line toward the
// image-right eye, y perpendicular, down the face.
struct HeadGeometry
{
    QPointF origin;
    QPointF ex {1, 0};
    QPointF ey {0, 1};
    double eyeDistance = 0; // ES0
    double browY = 0; // mean height of the eight brow points
    double noseBaseY = 0; // the nose tip 9.15's height
    double hairlineY = 0; // rule of thirds: as far above the brows as the nose base is below
    double midX = 0; // the face's midline (11.1.x)
    QPointF hairCentre; // centre of the hair ellipse (between the cheeks, at eye level)
    double hairAx = 0; // its semi-axes
    double hairAy = 0;

    QPointF toLocal(QPointF image) const;
    QPointF toImage(QPointF local) const;
    // The geometric hair point h.(i+1), i = 0..18, in the face frame.
    QPointF hairPoint(int i) const;
};

// requires: the eyes, brows, nose tip, cheeks 5.2/5.1 and chin 2.1 of `face` are placed.
HeadGeometry headGeometry(const FaceModel &face);

// The estimated forehead and hair of `face` from its measured points (headGeometry()): 11.1 on
// the hairline on the face's midline, the temples 11.2/11.3 beside it, the hair outline
// h.1..h.19 on the hair ellipse, beyond the photo's edge where it cuts the head off.
// faceFromLandmarks68() places them so; a face found otherwise (the classic method) gets them
// the same way before the photo search refines them (refineFromPhoto(), hairsearch.h).
// requires: as headGeometry(). Returns the geometry they were placed on.
HeadGeometry estimateForeheadAndHair(FaceModel *face);

// The ear beside a cheek from a profile of the skin's width beyond the cheek contour, one
// width per row ys[i] (equal steps `step`, top to bottom): the longest run of rows whose width
// lies in [minWidth, maxWidth] is the ear when its length is within [minLength, maxLength]. Its
// four points (10.2 10.4 10.6 10.10 on the left, 10.1 10.3 10.5 10.9 on the right) go to
// at(y, out), the point `out` beyond the contour on row y: the top a third of its width out, the
// widest row at its width, the bottom half out, the lobe's attachment on the contour. Returns
// false (the face unchanged) when no run qualifies.
struct EarProfileLimits
{
    double minWidth, maxWidth, minLength, maxLength;
};
bool placeEarFromProfile(FaceModel *face, bool left, const std::vector<double> &ys, const std::vector<double> &widths,
    double step, const EarProfileLimits &limits, const std::function<QPointF(double, double)> &at);

// Moves the points `which` selects (by index) that lie outside a photo of `size` onto its border.
void keepInPhoto(FaceModel *face, QSize size, const std::function<bool(int)> &which);

// The reverse of the table for the compared points: the iBUG reference position of a
// Toonface point used in NME scoring, or false when the point is not scored.
// `ibug` are the ground-truth landmarks; *pos receives the point to compare with.
bool scoredReference(int pointIndex, const std::array<QPointF, kIbugPointCount> &ibug, QPointF *pos);

// Reads a 300-W annotation (.pts: "version: 1", "n_points: 68", "{", 68 lines "x y" in 1-based
// pixels, "}") into 0-based iBUG points. False with *error naming the file and the problem.
bool readIbugPts(const QString &path, std::array<QPointF, kIbugPointCount> *pts, QString *error = nullptr);

// The 300-W normalised mean error of `face` against ground-truth landmarks: the mean distance
// over the scored points divided by the distance between iBUG 36 and 45.
double normalizedMeanError(const FaceModel &face, const std::array<QPointF, kIbugPointCount> &ibug);

} // namespace toonface
