#pragma once

#include "face/facemodel.h"

#include <QPointF>
#include <QPolygonF>
#include <QRectF>

#include <array>

namespace toonface {

// The regions of a detected face, in image pixels (thesis chapter 3: face, hair and ear
// regions, and the feature regions of 3.4.3). A box or outline that was not found is empty.
struct FaceRegions
{
    QRectF face; // the face contour's box (forehead to chin, cheek to cheek)
    QPolygonF faceOutline; // 11.2 11.1 11.3 5.1 2.13 2.11 2.1 2.12 2.14 5.2, clockwise on screen
    QRectF hair;
    QPolygonF hairOutline; // h.1 .. h.19
    QRectF ears[2]; // image-left first
    QRectF brows[2]; // image-left first
    QRectF eyes[2]; // image-left first
    QRectF nose;
    QRectF mouth;

    bool operator==(const FaceRegions &) const = default;
};

// Colour statistics of a set of pixels: the mean of each 8-bit channel and the root mean
// square distance of the pixels from that mean (in the same units).
struct ColourStats
{
    int samples = 0; // 0: not measured
    double r = 0, g = 0, b = 0;
    double spread = 0;

    bool operator==(const ColourStats &) const = default;
};

// What video tracking reuses from the neutral photo (thesis 6.1-6.3: "some threshold values
// and parameters will be reserved for subsequent uses"): the thresholds of the hierarchical
// bi-level thresholding, the eyeball regions and eye distance, the division lines and the
// mouth region, and the colours of skin and hair. Image pixels of the neutral photo.
struct TrackingSeed
{
    bool valid = false;
    QRectF rect; // the central rectangle the thresholds were measured in (Algorithm 4.1)
    double m1 = 0, s1 = 0, t1 = 0; // intensity mean, deviation, threshold (eqs. 3.1-3.3)
    double m2 = 0, s2 = 0; // hue mean and deviation (eqs. 3.6-3.7): face where |H - m2| <= s2
    double d = 0; // eyeball distance
    QPointF eyeMid;
    QPointF eyeballs[2]; // image-left first
    double eyeballRadius[2] = {0, 0};
    double divEE = 0, divEN = 0, divNM = 0; // the division lines' y (Algorithm 4.5)
    QRectF mouth; // R_Mouth, the seed of mouth tracking (6.3)
    // Thesis 6.3 step 1: "the four threshold values of four parts of the edge image", Tsai's
    // threshold of the mirrored Sobel strength in each horizontal part of the 2d x 2d square
    // (square top, Div_EE, Div_EN, Div_NM, square bottom), top part first: a pixel whose strength
    // exceeds its part's value is an edge. Measured on the photo scaled as the classic method
    // scales it (at most 640 pixels on its longer side); all 0 when not measured.
    std::array<double, 4> edgeThresholds {};
    ColourStats skin;
    ColourStats hair;

    bool operator==(const TrackingSeed &) const = default;
};

// The regions that follow from the 72 points alone: the outlines through the contour and hair
// points, the boxes of the ears and of the feature groups.
// requires: face.isValid()
FaceRegions regionsFromPoints(const FaceModel &face);

// Fills the geometric part of a seed from the points: d and EyeMid from the eyeball centres
// 3.6/3.5, the eyeball radii from the lid heights, the division lines by the thesis' rules
// (Div_EE just above the eyeballs, Div_EN = EyeMid.y + d/3, Div_NM = EyeMid.y + d) and the
// mouth region from the mouth points. The thresholds and colours are left as they are.
void seedGeometryFromPoints(const FaceModel &face, TrackingSeed *seed);

} // namespace toonface
