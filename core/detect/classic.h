#pragma once

#include "detect/faceregions.h"
#include "detect/regions.h"
#include "face/facemodel.h"

#include <QImage>
#include <QMap>
#include <QRectF>
#include <QString>

#include <array>
#include <vector>

namespace toonface {

// The thesis' "classic" pipeline (chapters 3 and 4.3), one function per algorithm so each can
// be tested on its own; detectClassic() runs them in order.

// Eq. (3.5): Score = (A1 A2 - S^2) / 2 with S = A1 / A2, for the normalised box areas
// A1 >= A2 of the two regions (the caller normalises by the largest candidate's box area).
double eyePairScore(double area1, double area2);

// Chan et al.'s eye-pair generation on the dark regions, then the optimal pair.
struct EyePairCandidate
{
    int left = -1, right = -1; // indices into the dark regions; left is the image-left one
    double score = 0;
};
struct EyePairRules
{
    double maxSkewDegrees = 10.0; // the thesis' allowed tilt of the pair
    double maxAreaRatio = 3.0; // relative size: larger / smaller box area
    double minDistanceInWidths = 1.5; // centre distance in widths of the wider region
    double maxDistanceInWidths = 8.0;
    double minAspect = 0.6; // region width / height
    double maxAspect = 8.0;
    double minFill = 0.15; // area / box area
    double maxWidthFraction = 0.2; // region width / image width
    double minAreaFraction = 2e-5; // region area / image area
};
// Every pair of filtered dark regions that passes the pairing rules, with its eq. (3.5)
// score; sorted best first.
std::vector<EyePairCandidate> eyePairCandidates(
    const std::vector<Region> &dark, QSize imageSize, const EyePairRules &rules = {});

// Knowledge beyond eq. (3.5) for real photos (section 3.3.3 assumes the dark regions are eyes
// and hair only; photos add spectacle rims, nostrils, mouth corners and dark clothing).

// Loops: true when the pixels of `region` (label image `labels` of growRegions) enclose at
// least as many other pixels as they cover. Spectacle rims are loops, and so is an eye outlined
// by its lids: detectClassic() tells them apart by width (see there).
bool isRingShaped(const Region &region, const std::vector<int> &labels, QSize imageSize);

// The intensity relative to the person's own skin around each pixel (item: dark skin). Eyes and
// brows are darker than the skin around them by a share of it, whatever the skin's tone: on dark
// skin the brows' hair is little darker than the skin (a few levels), while the lash line and iris
// stay far darker than the eye white and the lids; a threshold on I itself (eq. 3.3) takes the
// brows, the shade of a cheek and the eye together. The local skin level is the grey closing of I
// (the brightest level a dark feature narrower than `featureSize` pixels is surrounded by); the
// result is 255 * I / that level (255: as light as the skin around, lower: darker than it).
Plane skinRelativeIntensity(const Plane &intensity, int featureSize);

// How much darker `region` is than its surround (the frame of half the box's size around the
// box), in intensity levels: mean(surround) - mean(region). Eyes and brows lie in lighter skin.
double darknessContrast(const Plane &intensity, const Region &region, const std::vector<int> &labels);

// Whether an eye pair at the centroids `left`, `right` (distance d) sits in the face region F
// as eyes do (sections 3.3.4-3.3.5 applied to the pair): the point between them is face; F
// reaches at least 1.2 d down the midline below them (nose, mouth and chin: a pair of mouth
// corners has only the chin below it) and 0.55 .. 1.6 d to each side along the eye line from
// the midpoint (a face is about 2.2 eye distances wide at the eyes; hair over a temple or a
// turned head shortens one side; nostrils, bits of the lips or of a fringe lie many of their
// own spacings from the face's sides). Reaches are capped at 3 d down and 3 d sideways.
inline constexpr double kMinReachBelow = 1.2;
inline constexpr double kMinReachSide = 0.55;
inline constexpr double kMaxReachSide = 1.6;
struct PairReach
{
    double below = 0; // in d
    double side = 0; // the shorter of the two sideways reaches, in d
};
bool eyePairInFace(const Mask &face, QPointF left, QPointF right, PairReach *reach = nullptr);

// The mouth below an eye pair (the thesis' Div_NM = EyeMid.y + d, section 3.4.2): over the band
// 0.8 d wide on the midline, 0.7 .. 1.5 d below the pair's centre, how much darker its darkest
// row is than its median row, as a share of the median (0 .. 1). The lips and the gap between
// them darken a row across; the skin under a pair of hair strands or nostrils stays even.
// *darkestRow receives that row's distance below the pair's centre in pixels (0 when no row).
double mouthRowContrast(const Plane &intensity, QPointF left, QPointF right, double *darkestRow = nullptr);
// The contrast from which a row counts as the mouth.
inline constexpr double kMinMouthRowContrast = 0.15;

// Section 3.4.1: the circle holding the most dark points of one eye region. The radius grows
// while the best-placed circle of that radius stays at least `minFill` dark; the largest such
// circle is the eyeball.
struct Eyeball
{
    QPointF centre;
    double radius = 0;
    double height() const { return 2 * radius; }
};
// `dark` marks the eye region's pixels (value 1); the search stays inside `box`.
Eyeball detectEyeball(const Mask &dark, QRect box, double minFill = 0.9);

// Eq. (3.13): S = |(z7 + 2 z8 + z9) - (z1 + 2 z2 + z3)| + |(z3 + 2 z6 + z9) - (z1 + 2 z4 + z7)|;
// the one-pixel frame is 0.
Plane sobelEdges(const Plane &intensity);

// Algorithm 4.5's edge image, whose four thresholds thesis 6.3 step 1 keeps for mouth tracking:
// the Sobel strength (eq. 3.13) in the 2d x 2d square (EyeMid.x -+ d, EyeMid.y - d/2 .. + 1.5 d,
// d the distance of the eyeball centres), mirrored about the vertical through EyeMid (each
// pixel keeps the stronger of itself and its mirror, so a feature seen on one side only counts
// on both), then Tsai's threshold per horizontal part: square top .. Div_EE .. Div_EN .. Div_NM
// .. square bottom (a part holds the rows from the ceiling of its upper line to below the
// ceiling of its lower one). A part without pixels or with one strength only has no edges; its
// threshold is then its highest strength (0 when empty).
struct FeatureEdges
{
    QRect square; // the square's pixels inside the plane
    Mask edges; // the plane's size; 1 where the strength exceeds its part's threshold (square only)
    std::array<double, 4> thresholds {}; // top part first
};
FeatureEdges featureEdges(
    const Plane &intensity, QPointF leftEye, QPointF rightEye, double divEE, double divEN, double divNM);

// The same for a face found otherwise (the landmark method): featureEdges() around the seed's
// eyeball centres with its division lines, on `image` scaled as detectClassic() scales it, into
// seed->edgeThresholds. Eyeball centres that coincide (no geometry) leave the thresholds as they are.
void measureEdgeThresholds(const QImage &image, TrackingSeed *seed);

// Algorithm 3.7 (eqs. 3.14-3.15): the x in [x1 + w/2, x2 - w/2] with the smallest left/right
// dissimilarity of `intensity` over rows y1..y2, w = (x2 - x1) / 2; columns outside the image
// are clamped.
int centralVerticalCut(const Plane &intensity, QRect region);

// Section 3.5: the cheek boundaries x = mid.x -+ k from the vertical projection of the face
// region F over the rows mid.y - d/2 .. mid.y + 1.5 d, made symmetric by adding the mirrored
// right side to the left. The face narrows toward its sides while ears add only short
// columns: k is the first offset from d/2 on where the symmetric projection has fallen to
// half its value at d/2 (1.5 d when it never does).
void cheekOffset(const Mask &face, QPointF mid, double d, double *left, double *right);

// Everything the pipeline found, in the pixels of the image given to detectClassic().
struct ClassicResult
{
    bool ok = false;
    QString error;
    FaceModel face;
    double t1 = 0; // the first-level threshold
    double eyeLevelK = 1; // the k of t = m1 - k s1 on which the eye pair was found
    QRect centralRect; // the rectangle of Algorithm 4.1 the result was found with
    // The chosen pair passed the face checks (eyePairInFace() and a mouth row, mouthRowContrast()
    // >= 0.15); false: no pair did, and the pair is the thesis' own choice by eq. (3.5).
    bool eyePairInFace = false;
    // When eyePairInFace is false: which face checks the chosen pair failed, in words, with the
    // pair's place in the input's pixels.
    QString faceCheck;
    QRectF eyeRegions[2]; // the chosen pair's boxes, image-left first
    int candidateCount = 0;
    Eyeball eyeballs[2]; // image-left first
    double d = 0; // eyeball distance
    QPointF eyeMid;
    QRectF square; // the 2d x 2d square
    double divEE = 0, divEN = 0, divNM = 0;
    QRectF browRegion, eyeRegion, noseRegion, mouthRegion; // the left brow and eye; nose; mouth
    double noseCut = 0, mouthCut = 0;
    std::array<double, 4> edgeThresholds {}; // featureEdges(), for TrackingSeed
    double cheekLeft = 0, cheekRight = 0;
    QMap<QString, double> timingMs;
    QMap<QString, QImage> debugImages; // name -> picture, when asked for
};

// `faceHint`, when valid, is a face box from elsewhere (a face detector, the previous video
// frame): Algorithm 4.1's central rectangle becomes the middle of that box instead of the
// middle of the image, and eye pairs must lie in its upper part. Without it the thesis'
// assumption holds: a large frontal face in the middle of the picture.
// requires: image is not null.
ClassicResult detectClassic(const QImage &image, bool withDebugImages = false, QRect faceHint = {});

} // namespace toonface
