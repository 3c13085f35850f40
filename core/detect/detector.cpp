#include "detect/detector.h"

#include "detect/classic.h"
#include "detect/detectionruntime.h"
#include "detect/facescan.h"
#include "detect/grayview.h"
#include "detect/hairoutline.h"
#include "detect/hairsearch.h"
#include "detect/headparse.h"
#include "detect/headregions.h"
#include "detect/landmarkfigures.h"
#include "detect/landmarkfit.h"
#include "detect/landmarkmap.h"
#include "detect/landmarkpredictor.h"
#include "face/averageface.h"
#include "i18n/coretext.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>

#include <dlib/image_processing.h>
#include <dlib/image_transforms.h>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>

namespace toonface {

namespace {

// The HOG detector's sliding window is 80x80 pixels; it finds faces from that size up.
constexpr double kDetectorWindow = 80.0;
// Its image pyramid shrinks by 5/6 a level.
constexpr double kPyramidStep = 6.0 / 5.0;
// Detection runs in passes, each on a copy of the photo scaled so that faces of at least
// a given fraction of its shorter side fill the window: first the large faces of portraits
// and webcam frames (a third of the shorter side, so the copy's shorter side is 240 px
// whatever the photo's resolution: cheap), then, only when nothing was found, smaller ones.
// Each later pass doubles the scale, so costs four times the one before.
constexpr double kPassFaceFractions[] = {1.0 / 3.0, 1.0 / 4.0, 1.0 / 8.0, 1.0 / 16.0};
// Upsampling beyond 2x invents no detail; more than 4 megapixels costs too long.
constexpr double kMaxUpsampling = 2.0;
constexpr double kMaxPassPixels = 4.0e6;

// Where the landmarks put the detector's box: the similarity transform (scale, rotation,
// translation; least squares) that carries the model's mean shape onto `pts`.
struct Similarity
{
    double a = 1, b = 0; // scale * (cos, sin) of the rotation
    QPointF t;
    double scale() const { return std::hypot(a, b); }
    double angle() const { return std::atan2(b, a); }
    QPointF map(QPointF p) const { return {a * p.x() - b * p.y() + t.x(), b * p.x() + a * p.y() + t.y()}; }
};

Similarity fitMeanShape(
    const std::array<QPointF, kIbugPointCount> &mean, const std::array<QPointF, kIbugPointCount> &pts)
{
    QPointF cm, cp;
    for (int i = 0; i < kIbugPointCount; ++i) {
        cm += mean[i] / kIbugPointCount;
        cp += pts[i] / kIbugPointCount;
    }
    double sxx = 0, sdot = 0, scross = 0;
    for (int i = 0; i < kIbugPointCount; ++i) {
        const QPointF u = mean[i] - cm, v = pts[i] - cp;
        sxx += u.x() * u.x() + u.y() * u.y();
        sdot += u.x() * v.x() + u.y() * v.y();
        scross += u.x() * v.y() - u.y() * v.x();
    }
    Similarity s;
    if (sxx <= 0)
        return s;
    s.a = sdot / sxx;
    s.b = scross / sxx;
    s.t = cp - QPointF(s.a * cm.x() - s.b * cm.y(), s.b * cm.x() + s.a * cm.y());
    return s;
}

// The predictor's accuracy depends on the box it starts from, and it was trained on upright
// faces in boxes of the detector's making. The HOG box is coarse (8-pixel cells, pyramid steps
// of 5/6) and ignores the head's roll, so after a first fit the face is cut out upright, in
// the box the first fit's landmarks imply (fitMeanShape), and fitted again. On the shared
// research photos this halves the error's spread over jittered detector boxes.
//
// When the implied box already matches the one the first fit started from (roll under 3
// degrees, centre and size within 3% of the box), the re-fit would start where the first did,
// and is skipped.
// The 68 points fitted in the upright box of the similarity `s` (the mean shape carried onto a
// face): the face cut out upright, twice the box around its centre, at most 600 px across
// (larger faces are sampled down: the predictor needs no more detail than that). `fallback` when
// the box is degenerate or a point comes out non-finite.
std::array<QPointF, kIbugPointCount> fitInUprightBox(const LandmarkPredictor &model, const GrayView &image,
    const Similarity &s, const std::array<QPointF, kIbugPointCount> &fallback)
{
    const double box = s.scale();
    if (!(box > 8) || !std::isfinite(box))
        return fallback;
    const QPointF centre = s.map(QPointF(0.5, 0.5));
    const long side = std::lround(std::min(2.0 * box, 600.0));
    const double zoom = side / (2.0 * box);
    const dlib::chip_details chip(
        dlib::drectangle(centre.x() - box, centre.y() - box, centre.x() + box, centre.y() + box),
        dlib::chip_dims(side, side), s.angle());
    dlib::array2d<unsigned char> upright;
    dlib::extract_image_chip(image, chip, upright);
    const double inner = box * zoom;
    const QRect rect(QPoint(std::lround(0.5 * inner), std::lround(0.5 * inner)),
        QPoint(std::lround(1.5 * inner) - 1, std::lround(1.5 * inner) - 1));
    const LandmarkPredictor::Shape shape
        = model.predict(GrayView {static_cast<const unsigned char *>(dlib::image_data(upright)), upright.nr(),
                            upright.nc(), dlib::width_step(upright)},
            rect);
    const dlib::point_transform_affine back = dlib::inv(dlib::get_mapping_to_chip(chip));
    std::array<QPointF, kIbugPointCount> p {};
    for (int i = 0; i < kIbugPointCount; ++i) {
        const dlib::dpoint q = back(dlib::dpoint(shape[i].x(), shape[i].y()));
        p[i] = QPointF(q.x(), q.y());
        if (!std::isfinite(p[i].x()) || !std::isfinite(p[i].y()))
            return fallback;
    }
    return p;
}

std::array<QPointF, kIbugPointCount> fitUpright(const LandmarkPredictor &model, const GrayView &image,
    const QRectF &startBox, const std::array<QPointF, kIbugPointCount> &first)
{
    const Similarity s = fitMeanShape(model.meanShape(), first);
    const double box = s.scale();
    if (!(box > 8) || !std::isfinite(box))
        return first;
    const QPointF implied = s.map(QPointF(0.5, 0.5));
    const double size = std::max(startBox.width(), 1.0);
    if (std::abs(s.angle()) < 3.0 * std::numbers::pi / 180.0
        && QLineF(implied, startBox.center()).length() < 0.03 * size && std::abs(box / size - 1.0) < 0.03)
        return first;
    return fitInUprightBox(model, image, s, first);
}

QImage resizedGray(const QImage &gray, double scale)
{
    const int w = std::max(1, int(std::lround(gray.width() * scale)));
    const int h = std::max(1, int(std::lround(gray.height() * scale)));
    QImage out(w, h, QImage::Format_Grayscale8);
    const cv::Mat src(
        gray.height(), gray.width(), CV_8UC1, const_cast<uchar *>(gray.constBits()), size_t(gray.bytesPerLine()));
    cv::Mat dst(h, w, CV_8UC1, out.bits(), size_t(out.bytesPerLine()));
    cv::resize(src, dst, dst.size(), 0, 0, scale < 1 ? cv::INTER_AREA : cv::INTER_LINEAR);
    return out;
}

// Grey levels as dlib makes them from colour, (R + G + B) / 3, which is what its detector
// and the landmark model were trained on; and the same whatever the pixel format (Qt's own
// conversions to Format_Grayscale8 weigh the channels differently, and differently per
// format, which would make the landmarks depend on how a photo was stored).
QImage toGray(const QImage &image)
{
    if (image.format() == QImage::Format_Grayscale8)
        return image;
    if (image.format() == QImage::Format_Grayscale16)
        return image.convertToFormat(QImage::Format_Grayscale8);
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    QImage gray(rgb.size(), QImage::Format_Grayscale8);
    for (int y = 0; y < rgb.height(); ++y) {
        const QRgb *in = reinterpret_cast<const QRgb *>(rgb.constScanLine(y));
        uchar *out = gray.scanLine(y);
        for (int x = 0; x < rgb.width(); ++x)
            out[x] = uchar((unsigned(qRed(in[x])) + unsigned(qGreen(in[x])) + unsigned(qBlue(in[x]))) / 3);
    }
    return gray;
}

// The faces in a copy of `gray` scaled by `scale`, scanning `levels` pyramid levels (0: all).
std::vector<FaceBox> findFaces(const QImage &gray, double scale, unsigned long levels)
{
    const QImage small = qFuzzyCompare(scale, 1.0) ? gray : resizedGray(gray, scale);
    std::vector<FaceBox> out = scanFaces(small, levels);
    // dlib's rectangles are inclusive: pixel columns left..right of the scaled copy, which
    // cover [left / scale, (right + 1) / scale) of the photo.
    for (FaceBox &f : out)
        f.box = QRectF(f.box.left() / scale, f.box.top() / scale, f.box.width() / scale, f.box.height() / scale);
    return out;
}

// A box of the photo as dlib's rectangles have it: whole pixels, right and bottom inclusive.
QRect pixelBox(const QRectF &box)
{
    return QRect(QPoint(std::lround(box.left()), std::lround(box.top())),
        QPoint(std::lround(box.left() + box.width()) - 1, std::lround(box.top() + box.height()) - 1));
}

// The face whose box holds `at` (the one whose centre is nearest when boxes overlap), or -1.
int faceHolding(const std::vector<FaceBox> &faces, QPointF at)
{
    int best = -1;
    for (int i = 0; i < int(faces.size()); ++i) {
        if (faces[i].box.contains(at)
            && (best < 0 || QLineF(faces[i].box.center(), at).length() < QLineF(faces[best].box.center(), at).length()))
            best = i;
    }
    return best;
}

// The face to use: the one asked for (faceHolding), else the largest, preferring central ones.
// Size counts most (a passer-by in the corner is smaller than the subject); a face at the
// image's corner weighs half as much as the same face at its centre.
int chooseFace(const std::vector<FaceBox> &faces, QSize imageSize, const std::optional<QPointF> &at)
{
    if (at) {
        if (const int asked = faceHolding(faces, *at); asked >= 0)
            return asked;
    }
    const QPointF centre(imageSize.width() / 2.0, imageSize.height() / 2.0);
    const double halfDiag = std::hypot(imageSize.width(), imageSize.height()) / 2;
    int best = -1;
    double bestScore = -1;
    for (int i = 0; i < int(faces.size()); ++i) {
        const QRectF &b = faces[i].box;
        const double off = QLineF(b.center(), centre).length() / std::max(halfDiag, 1.0);
        const double score = b.width() * b.height() * (1.0 - 0.5 * std::min(off, 1.0));
        if (score > bestScore) {
            bestScore = score;
            best = i;
        }
    }
    return best;
}

// Adds the faces of one detection pass to those of the passes before, leaving out a face that
// is already there: one whose box shares more than a third of its area with a kept box, or
// whose centre lies in one (the same face seen at another scale, its box a little shifted).
void mergeFaces(std::vector<FaceBox> *kept, const std::vector<FaceBox> &found)
{
    const size_t before = kept->size();
    for (const FaceBox &f : found) {
        bool seen = false;
        for (size_t i = 0; i < before && !seen; ++i) {
            const QRectF &k = (*kept)[i].box;
            const QRectF common = k.intersected(f.box);
            const double overlap = common.width() * common.height();
            const double smaller = std::min(k.width() * k.height(), f.box.width() * f.box.height());
            seen = overlap > smaller / 3 || k.contains(f.box.center()) || f.box.contains(k.center());
        }
        if (!seen)
            kept->push_back(f);
    }
}

// The faces of `gray` by passes from large faces to small ones. Every pass runs until one finds
// a face (and the face `faceAt` asks for, when set), so that faces much smaller than the first
// one found are counted too; a face seen by several passes counts once. *lastScale receives the
// scale of the last pass (0: the image is too small for any).
std::vector<FaceBox> scanForFaces(const QImage &gray, const std::optional<QPointF> &faceAt,
    const std::function<bool()> &cancelled, double *lastScaleOut)
{
    const double shortSide = std::min(gray.width(), gray.height());
    std::vector<FaceBox> faces;
    double lastScale = 0;
    for (double fraction : kPassFaceFractions) {
        double scale = std::min(kDetectorWindow / (fraction * shortSide), kMaxUpsampling);
        scale = std::min(scale, std::sqrt(kMaxPassPixels / (double(gray.width()) * gray.height())));
        if (scale < lastScale * 1.2 || shortSide * scale < kDetectorWindow)
            continue;
        // A finer pass need not look again for the faces the pass before looked for: its
        // pyramid stops at the first level (of 5/6) at or past the scale where the coarser
        // pass's began, so the two overlap by less than a level.
        const unsigned long levels = lastScale > 0
            ? 1 + (unsigned long)std::ceil(std::log(scale / lastScale) / std::log(kPyramidStep) - 1e-9)
            : 0;
        mergeFaces(&faces, findFaces(gray, scale, levels));
        lastScale = scale;
        // Each finer pass costs about four times the one before: once a pass has found a face,
        // smaller faces are not looked for (the 30 ms budget of a 640x480 photo), unless the
        // face asked for is not among them yet.
        const bool asked = !faceAt || faceHolding(faces, *faceAt) >= 0;
        if ((!faces.empty() && asked) || (cancelled && cancelled()))
            break;
    }
    *lastScaleOut = lastScale;
    return faces;
}

double logistic(double x)
{
    return 1.0 / (1.0 + std::exp(-x));
}

bool wantsDebugImages(const DetectOptions &options)
{
    return options.keepDebugImages || !options.debugDir.isEmpty();
}

// What placeFace() found: the 68 landmarks, the 72 points mapped from them, the same refined
// with the photo (hair, ears), and what tracking reuses.
struct PlacedFace
{
    std::array<QPointF, kIbugPointCount> ibug {};
    FaceModel geometric;
    FaceModel refined;
    HairSearchReport hair;
    HeadRegionReport head;
    TrackingSeed seed;
};

// Hair and ears of out->geometric: the thesis' regions where they are usable; elsewhere the
// colour search of hairsearch.h, which keeps the geometric estimate where the photo does not
// settle a point. Then what tracking reuses.
bool refineFace(const QImage &image, bool withDebugImages, PlacedFace *out,
    const std::function<bool(const QString &stage)> &endStage)
{
    FaceModel searched = out->geometric;
    refineFromPhoto(&searched, image, &out->hair, withDebugImages);
    if (!endStage(QStringLiteral("hair")))
        return false;
    FaceModel fromRegions = searched;
    out->head = refineFromRegions(&fromRegions, image, withDebugImages);
    out->refined = searched;
    for (int i = 0; i < kPointCount; ++i) {
        const PointGroup g = pointTable()[i].group;
        const bool leftEar
            = i == pt::idx("10.2") || i == pt::idx("10.4") || i == pt::idx("10.6") || i == pt::idx("10.10");
        if ((g == PointGroup::Hair && out->head.hairUsable)
            || (g == PointGroup::Ears && out->head.earUsable[leftEar ? 0 : 1]))
            out->refined.setPoint(i, fromRegions.point(i));
    }
    // The hair outline and the hairline from the parse of the head where it sees the whole
    // head (long hair to the shoulders, a fringe, a wide head of curls); elsewhere the search's
    // outline stays, its lower ends following the parse's fall (hairoutline.h).
    const HeadParse parse = parseHead(image, out->refined);
    outlineHairFromParse(&out->refined, parse);
    placeHairlineFromParse(&out->refined, parse);
    // The seed for tracking: the regions' thresholds and colours, the geometry of the points,
    // and the edge thresholds of the classic method's square around them (thesis 6.3).
    out->seed = out->head.seed;
    seedGeometryFromPoints(out->refined, &out->seed);
    measureEdgeThresholds(image, &out->seed);
    out->seed.valid = out->head.seed.valid;
    return endStage(QStringLiteral("regions"));
}

// Places the 72 points of the face the detector boxed in `box`: the landmarks, then hair and
// ears from the photo (refineFace). `endStage` is told as each stage ends ("landmarks",
// "hair", "regions"); when it answers false the work stops there and false is returned.
bool placeFace(const LandmarkPredictor &model, const QImage &image, const QImage &gray, const QRectF &box,
    bool withDebugImages, PlacedFace *out, const std::function<bool(const QString &stage)> &endStage)
{
    const GrayView view = viewOf(gray);
    const auto first = model.predict(view, pixelBox(box));
    out->ibug = fitUpright(model, view, box, first);
    out->geometric = faceFromLandmarks68(out->ibug, image.size());
    if (!endStage(QStringLiteral("landmarks")))
        return false;
    awaitFaceRefinementWarmUp();
    return refineFace(image, withDebugImages, out, endStage);
}

// How far below the eye line, in eye distances, a chin is believed for the hair's estimate.
constexpr double kMaxChinDrop = 2.3;

// The thesis pipeline (classic.h): one face, found by its eye pair. Only a pair that passed the
// face checks (ClassicResult::eyePairInFace) is a face: where none did, the thesis' own choice
// by eq. (3.5) is a dark pair anywhere in the photo (a sleeve, a curtain's folds), and 72 points
// drawn around it would be confident garbage, so the result is "no face" with the failed check
// named, for `--method classic` as for auto's last resort.
DetectionResult detectWithClassic(
    const QImage &image, const DetectOptions &options, const std::function<void(double, const QString &)> &report)
{
    DetectionResult result;
    result.method = detectionMethodName(DetectionMethod::Classic);
    report(0.0, QStringLiteral("classic"));
    // The classic method assumes one large face in the middle of the picture. With a face asked
    // for (faceAt), the face detector's box holding that point is its hint (Algorithm 4.1's
    // central rectangle in that box, the eyes in its upper part); a point no face holds leaves
    // the assumption.
    QRect hint;
    if (options.faceAt) {
        double lastScale = 0;
        const std::vector<FaceBox> faces = scanForFaces(toGray(image), options.faceAt, {}, &lastScale);
        if (const int asked = faceHolding(faces, *options.faceAt); asked >= 0)
            hint = faces[asked].box.toAlignedRect().intersected(image.rect());
    }
    const ClassicResult c = detectClassic(image, wantsDebugImages(options), hint);
    result.timingMs = c.timingMs;
    result.debugImages = c.debugImages;
    if (!c.ok || !c.eyePairInFace) {
        result.status = DetectStatus::NoFace;
        result.error = c.ok ? DetectText::tr("The classic method found no face: %1.").arg(c.faceCheck) : c.error;
        return result;
    }
    // Hair and forehead as landmark faces get them: the classic method's own 11.x lie at the top
    // of F_final (the top of the hair where it is dark enough to join the face region), its
    // outline on H_final, which misses the hair that is not dark. From its measured points (eyes,
    // brows, nose, mouth, contour) the estimate of estimateForeheadAndHair(), then the photo
    // search and the regions of refineFace(); its ears, measured on F_final, stay where the
    // photo does not place them.
    //
    // The hair's size follows the chin's drop below the eyes (headGeometry(): the eyes lie halfway
    // between chin and crown), and the classic chin is where F_final ends, often on the neck or a
    // collar of the skin's hue: for the hair the chin is held within 2.3 eye distances of the eye
    // line (an adult's chin lies about 1.9 below it), then the measured one is put back.
    PlacedFace placed;
    placed.geometric = c.face;
    const QPointF measuredChin = c.face.point("2.1");
    {
        const QPointF eyeL = c.face.point("3.6"), eyeR = c.face.point("3.5"), mid = (eyeL + eyeR) / 2;
        const double d = QLineF(eyeL, eyeR).length();
        const QPointF down = d > 0 ? QPointF(eyeL.y() - eyeR.y(), eyeR.x() - eyeL.x()) / d : QPointF(0, 1);
        const double drop = QPointF::dotProduct(measuredChin - mid, down);
        if (drop > kMaxChinDrop * d)
            placed.geometric.setPoint(pt::idx("2.1"), measuredChin - (drop - kMaxChinDrop * d) * down);
    }
    estimateForeheadAndHair(&placed.geometric);
    awaitFaceRefinementWarmUp();
    // Without their figures: a classic run's steps are the thesis' (classic-*).
    QElapsedTimer stage;
    stage.start();
    refineFace(image, false, &placed, [&](const QString &name) {
        const double ms = stage.nsecsElapsed() / 1e6;
        result.timingMs.insert(name, ms);
        result.timingMs[QStringLiteral("total")] += ms;
        stage.restart();
        return true;
    });
    placed.refined.setPoint(pt::idx("2.1"), measuredChin);
    result.status = DetectStatus::Ok;
    result.face = placed.refined;
    result.faceCount = 1;
    result.faceBox = result.face.bounds().toAlignedRect().intersected(image.rect());
    // The classic method has no score of its own: fixed figures ranking how directly each
    // group is measured (eyeballs and feature edges first, rule-placed points last).
    result.groupConfidence.insert(groupName(PointGroup::Eyes), 0.5);
    result.groupConfidence.insert(groupName(PointGroup::Eyebrows), 0.45);
    result.groupConfidence.insert(groupName(PointGroup::Nose), 0.35);
    result.groupConfidence.insert(groupName(PointGroup::Mouth), 0.45);
    result.groupConfidence.insert(groupName(PointGroup::Contour), 0.35);
    result.groupConfidence.insert(groupName(PointGroup::Ears), 0.2);
    result.groupConfidence.insert(groupName(PointGroup::Hair), 0.3);
    result.regions = regionsFromPoints(result.face);
    result.regions.nose = c.noseRegion;
    result.regions.mouth = c.mouthRegion;
    // The classic method's own thresholds and regions where it keeps them; the hue and colour
    // statistics, which it does not keep, as refineFace() measured them around the face it found.
    result.tracking = placed.seed;
    result.tracking.valid = true;
    result.tracking.t1 = c.t1;
    result.tracking.d = c.d;
    result.tracking.eyeMid = c.eyeMid;
    for (int k = 0; k < 2; ++k) {
        result.tracking.eyeballs[k] = c.eyeballs[k].centre;
        result.tracking.eyeballRadius[k] = c.eyeballs[k].radius;
    }
    result.tracking.divEE = c.divEE;
    result.tracking.divEN = c.divEN;
    result.tracking.divNM = c.divNM;
    result.tracking.mouth = c.mouthRegion;
    result.tracking.edgeThresholds = c.edgeThresholds;
    report(1.0, QStringLiteral("done"));
    return result;
}

} // namespace

QString detectionMethodName(DetectionMethod m)
{
    switch (m) {
    case DetectionMethod::Auto: return QStringLiteral("auto");
    case DetectionMethod::Classic: return QStringLiteral("classic");
    case DetectionMethod::Landmarks: return QStringLiteral("landmarks");
    }
    return {};
}

bool detectionMethodFromName(const QString &name, DetectionMethod *m)
{
    for (DetectionMethod candidate : {DetectionMethod::Auto, DetectionMethod::Classic, DetectionMethod::Landmarks}) {
        if (name == detectionMethodName(candidate)) {
            *m = candidate;
            return true;
        }
    }
    return false;
}

QString landmarkModelPath()
{
    const QString env = qEnvironmentVariable("TOONFACE_LANDMARK_MODEL");
    if (!env.isEmpty())
        return env;
    return QStringLiteral("/usr/share/dlib/shape_predictor_68_face_landmarks.dat");
}

namespace {

DetectionResult runDetection(
    const QImage &image, const DetectOptions &options, const ProgressFn &progress, const std::atomic_bool *cancel)
{
    DetectionResult result;
    result.method = detectionMethodName(DetectionMethod::Landmarks);
    auto report = [&](double fraction, const QString &stage) {
        if (progress)
            progress(fraction, stage);
    };
    auto cancelled = [&] {
        if (cancel && cancel->load()) {
            result.status = DetectStatus::Cancelled;
            result.error = DetectText::tr("Face detection was cancelled.");
            return true;
        }
        return false;
    };

    if (image.isNull()) {
        result.status = DetectStatus::BadImage;
        result.error = DetectText::tr("The image is empty.");
        return result;
    }
    if (options.method == DetectionMethod::Classic)
        return detectWithClassic(image, options, report);

    QString modelError;
    const auto model = sharedLandmarkModel(&modelError);
    if (!model) {
        result.status = DetectStatus::ModelMissing;
        result.error = modelError;
        return result;
    }
    if (cancelled())
        return result;

    QElapsedTimer total, stage;
    total.start();
    stage.start();
    auto lap = [&](const QString &name) {
        result.timingMs.insert(name, stage.nsecsElapsed() / 1e6);
        stage.restart();
    };

    report(0.0, QStringLiteral("prepare"));
    const QImage gray = toGray(image);
    lap(QStringLiteral("prepare"));
    if (cancelled())
        return result;

    report(0.1, QStringLiteral("faces"));
    double lastScale = 0;
    const std::vector<FaceBox> faces = scanForFaces(gray, options.faceAt, cancelled, &lastScale);
    lap(QStringLiteral("faces"));
    if (cancelled())
        return result;
    result.faceCount = int(faces.size());
    if (faces.empty()) {
        result.status = DetectStatus::NoFace;
        result.error = lastScale > 0 ? QCoreApplication::translate("toonface::Detector",
                           "No face was found in the image (%1 x %2 pixels). A frontal, upright "
                           "face at least %3 pixels wide is needed.")
                                           .arg(image.width())
                                           .arg(image.height())
                                           .arg(std::ceil(kDetectorWindow / lastScale))
                                     : QCoreApplication::translate("toonface::Detector",
                                         "The image (%1 x %2 pixels) is too small to hold a face.")
                                           .arg(image.width())
                                           .arg(image.height());
        return result;
    }
    const int chosen = chooseFace(faces, image.size(), options.faceAt);
    const FaceBox &face = faces[chosen];
    result.faceBox = face.box.toAlignedRect().intersected(image.rect());
    for (int i = 0; i < int(faces.size()); ++i) {
        if (i != chosen)
            result.otherFaces.append(faces[i].box.toAlignedRect().intersected(image.rect()));
    }

    report(0.5, QStringLiteral("landmarks"));
    PlacedFace placed;
    const bool whole
        = placeFace(*model, image, gray, face.box, wantsDebugImages(options), &placed, [&](const QString &stage) {
              lap(stage);
              if (stage == QLatin1StringView("landmarks")) {
                  if (cancelled())
                      return false;
                  report(0.7, QStringLiteral("hair"));
              }
              return true;
          });
    if (!whole)
        return result;
    const auto &ibug = placed.ibug;
    const FaceModel &geometric = placed.geometric;
    const FaceModel &refined = placed.refined;
    const HairSearchReport &hair = placed.hair;
    const HeadRegionReport &head = placed.head;
    result.timingMs.insert(QStringLiteral("total"), total.nsecsElapsed() / 1e6);
    if (cancelled())
        return result;

    // Confidence: the detector's margin (0 at its threshold) drives the measured groups; the
    // contour's jaw comes from the landmarks too but its cheeks and forehead are partly rule;
    // hair and ears are estimated, better when the photo search found the hair boundary.
    const double base = 0.5 + 0.5 * logistic(2.0 * face.score);
    result.groupConfidence.insert(groupName(PointGroup::Eyes), base);
    result.groupConfidence.insert(groupName(PointGroup::Eyebrows), 0.95 * base);
    result.groupConfidence.insert(groupName(PointGroup::Nose), 0.9 * base);
    result.groupConfidence.insert(groupName(PointGroup::Mouth), base);
    result.groupConfidence.insert(groupName(PointGroup::Contour), 0.75 * base);
    // Hair and ears from the regions are measured on their edges: a little more trusted than
    // the colour search, whose share of found points is its own figure.
    const double earFraction
        = ((head.earUsable[0] ? 1.0 : hair.earFraction) + (head.earUsable[1] ? 1.0 : hair.earFraction)) / 2;
    const double earRegions = (int(head.earUsable[0]) + int(head.earUsable[1])) / 2.0;
    result.groupConfidence.insert(groupName(PointGroup::Ears), (0.25 + 0.2 * earFraction + 0.1 * earRegions) * base);
    result.groupConfidence.insert(groupName(PointGroup::Hair),
        (head.hairUsable ? 0.4 + 0.5 * head.hairFraction : 0.3 + 0.5 * hair.hairFraction) * base);

    result.regions = regionsFromPoints(refined);
    result.tracking = placed.seed;

    if (wantsDebugImages(options))
        addLandmarkDebugImages(&result.debugImages, image, faces, chosen, ibug, geometric, refined, hair, head);

    result.face = refined;
    result.status = DetectStatus::Ok;
    report(1.0, QStringLiteral("done"));
    return result;
}

} // namespace

DetectionResult detectFace(
    const QImage &image, const DetectOptions &options, const ProgressFn &progress, const std::atomic_bool *cancel)
{
    DetectionResult result = runDetection(image, options, progress, cancel);
    // Auto: the thesis' pipeline where the landmarks cannot serve (no model, or no face their
    // detector accepts: a face turned or lit beyond its training).
    if (options.method == DetectionMethod::Auto
        && (result.status == DetectStatus::NoFace || result.status == DetectStatus::ModelMissing)
        && !(cancel && cancel->load())) {
        DetectionResult classic = detectWithClassic(image, options, [&](double fraction, const QString &stage) {
            if (progress)
                progress(fraction, stage);
        });
        if (classic.status == DetectStatus::Ok) {
            classic.note = result.error;
            result = classic;
        } else if (wantsDebugImages(options)) {
            result.debugImages.insert(classic.debugImages);
        }
    }
    // Auto placed the points by the landmarks: the thesis' figures (B1, B2, B3, eye pairs, the
    // eyeballs and the 2d square, edges, feature regions, its points) are drawn too when the
    // steps are asked for, so that they can be compared with the landmarks' on the same photo.
    if (options.method == DetectionMethod::Auto && result.status == DetectStatus::Ok
        && result.method == detectionMethodName(DetectionMethod::Landmarks) && wantsDebugImages(options)
        && !(cancel && cancel->load())) {
        const ClassicResult c = detectClassic(image, true);
        for (auto it = c.debugImages.cbegin(); it != c.debugImages.cend(); ++it)
            result.debugImages.insert(it.key(), it.value());
    }
    if (!options.debugDir.isEmpty() && QDir().mkpath(options.debugDir)) {
        for (auto it = result.debugImages.cbegin(); it != result.debugImages.cend(); ++it)
            it.value().save(QDir(options.debugDir).filePath(it.key() + QStringLiteral(".png")));
    }
    if (!options.keepDebugImages)
        result.debugImages.clear();
    return result;
}

void warmUpFaceRefinement()
{
    // A made-up portrait at a webcam's size: a skin-coloured oval under a dark cap of hair on a
    // grey-blue wall, so that every stage finds something to work on, and the average face on it.
    constexpr int kWidth = 640, kHeight = 480;
    QImage photo(kWidth, kHeight, QImage::Format_RGB32);
    const QPointF centre(kWidth / 2.0, kHeight / 2.0 + 20);
    for (int y = 0; y < kHeight; ++y) {
        auto *row = reinterpret_cast<QRgb *>(photo.scanLine(y));
        for (int x = 0; x < kWidth; ++x) {
            const double fx = (x - centre.x()) / 110.0, fy = (y - centre.y()) / 140.0;
            const double hx = (x - centre.x()) / 125.0, hy = (y - centre.y() + 40) / 150.0;
            if (fx * fx + fy * fy < 1)
                row[x] = qRgb(215, 170, 140);
            else if (hx * hx + hy * hy < 1 && y < centre.y())
                row[x] = qRgb(60, 40, 30);
            else
                row[x] = qRgb(120, 130, 150);
        }
    }
    resizedGray(toGray(photo), 0.5);
    PlacedFace placed;
    placed.geometric = averageFace(QRectF(centre.x() - 110, centre.y() - 140, 220, 280), photo.size());
    refineFace(photo, false, &placed, [](const QString &) { return true; });
}

QImage landmarkGray(const QImage &image)
{
    return toGray(image);
}

std::vector<FaceCandidate> findFaceCandidates(const QImage &gray)
{
    double lastScale = 0;
    std::vector<FaceCandidate> out;
    for (const FaceBox &f : scanForFaces(gray, std::nullopt, {}, &lastScale))
        out.push_back({f.box, f.score});
    return out;
}

FaceCandidate verifyFace(const QImage &gray, const QRectF &region, double faceSize)
{
    const QRect crop = region.toAlignedRect().intersected(gray.rect());
    if (crop.isEmpty() || !(faceSize > 0))
        return {};
    // The face 1.15 windows across at the first pyramid level; four levels reach faces 1.6x
    // the expected size, the detector's tolerance faces a little smaller.
    const double scale = std::min(kMaxUpsampling, 1.15 * kDetectorWindow / faceSize);
    const QImage cut = gray.copy(crop);
    if (std::min(cut.width(), cut.height()) * scale < kDetectorWindow)
        return {};
    FaceCandidate best;
    for (const FaceBox &f : findFaces(cut, scale, 4)) {
        if (best.box.isEmpty() || f.score > best.score)
            best = {f.box.translated(crop.topLeft()), f.score};
    }
    return best;
}

Landmarks68 fitLandmarksInBox(const LandmarkPredictor &model, const QImage &gray, const QRectF &box)
{
    const GrayView view = viewOf(gray);
    return fitUpright(model, view, box, model.predict(view, pixelBox(box)));
}

Landmarks68 fitLandmarksFrom(const LandmarkPredictor &model, const QImage &gray, const Landmarks68 &previous)
{
    const Similarity s = fitMeanShape(model.meanShape(), previous);
    const GrayView view = viewOf(gray);
    if (std::abs(s.angle()) < 3.0 * std::numbers::pi / 180.0) {
        // Upright enough: the implied box itself, no cut-out (the model tolerates a few degrees).
        const double side = s.scale();
        const QPointF c = s.map(QPointF(0.5, 0.5));
        if (!(side > 8) || !std::isfinite(side))
            return previous;
        const Landmarks68 shape = model.predict(view, pixelBox(QRectF(c.x() - side / 2, c.y() - side / 2, side, side)));
        for (const QPointF &q : shape) {
            if (!std::isfinite(q.x()) || !std::isfinite(q.y()))
                return previous;
        }
        return shape;
    }
    return fitInUprightBox(model, view, s, previous);
}

ImpliedBox impliedBox(const LandmarkPredictor &model, const Landmarks68 &points)
{
    const Similarity s = fitMeanShape(model.meanShape(), points);
    ImpliedBox out;
    const double side = s.scale();
    const QPointF c = s.map(QPointF(0.5, 0.5));
    out.box = QRectF(c.x() - side / 2, c.y() - side / 2, side, side);
    out.rollDeg = s.angle() * 180.0 / std::numbers::pi;
    double sum = 0;
    for (int i = 0; i < kIbugPointCount; ++i)
        sum += QLineF(s.map(model.meanShape()[i]), points[i]).length();
    out.residual = side > 0 ? sum / kIbugPointCount / side : 1.0;
    return out;
}

} // namespace toonface
