#include "detect/detector.h"

#include "detect/classic.h"
#include "detect/grayview.h"
#include "detect/hairsearch.h"
#include "detect/headregions.h"
#include "detect/landmarkfit.h"
#include "detect/landmarkmap.h"
#include "detect/landmarkpredictor.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QGuiApplication>
#include <QPainter>

#include <dlib/image_processing.h>
#include <dlib/image_processing/frontal_face_detector.h>
#include <dlib/image_transforms.h>
#include <dlib/serialize.h>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <numbers>
#include <thread>

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

struct LoadedModel
{
    QString path;
    std::shared_ptr<const LandmarkPredictor> model;
};

std::mutex &modelMutex()
{
    static std::mutex m;
    return m;
}

LoadedModel &loadedModel()
{
    static LoadedModel model;
    return model;
}

// The model for landmarkModelPath(), loaded at most once per path (a test or the user may
// point TOONFACE_LANDMARK_MODEL elsewhere). Failures are not cached, so a file that appears
// later is found. The shared pointer keeps a model alive for detections still using it.
std::shared_ptr<const LandmarkPredictor> landmarkModel(QString *error, double *loadMs)
{
    const QString path = landmarkModelPath();
    std::lock_guard lock(modelMutex());
    LoadedModel &loaded = loadedModel();
    if (loadMs)
        *loadMs = 0;
    if (loaded.model && loaded.path == path)
        return loaded.model;

    QElapsedTimer timer;
    timer.start();
    auto model = LandmarkPredictor::read(path, error);
    if (!model)
        return {};
    loaded.path = path;
    loaded.model = model;
    if (loadMs)
        *loadMs = timer.nsecsElapsed() / 1e6;
    return loaded.model;
}

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

// dlib's face detector scanning at most `levels` levels of its image pyramid (0: all of them,
// down to the smallest layer its window fits). Not thread-safe (it keeps scratch buffers), so
// one per thread and pyramid depth.
dlib::frontal_face_detector &threadDetector(unsigned long levels)
{
    // dlib decodes its detector from a compressed string (tens of milliseconds): once per process.
    static const dlib::frontal_face_detector all = dlib::get_frontal_face_detector();
    thread_local std::map<unsigned long, dlib::frontal_face_detector> detectors;
    auto it = detectors.find(levels);
    if (it == detectors.end()) {
        if (levels == 0) {
            it = detectors.emplace(levels, all).first;
        } else {
            dlib::frontal_face_detector::image_scanner_type scanner;
            scanner.copy_configuration(all.get_scanner());
            scanner.set_max_pyramid_levels(levels);
            std::vector<dlib::frontal_face_detector::feature_vector_type> filters;
            for (unsigned long i = 0; i < all.num_detectors(); ++i)
                filters.push_back(all.get_w(i));
            it = detectors.emplace(levels, dlib::frontal_face_detector(scanner, all.get_overlap_tester(), filters))
                     .first;
        }
    }
    return it->second;
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

struct FaceBox
{
    QRectF box; // in full-image pixels
    double score = 0;
};

// dlib's face detector allocates a hundred or so arrays per scan (the HOG planes of every
// pyramid level and their filtered copies), and its speed depends on where they fall: on
// this project's machines the same 320 x 240 scan took 5.6 ms or 19 ms from one detection to
// the next, following what the rest of the detection had allocated and freed on the thread's
// heap. Scanning on a thread of its own, whose heap (glibc's per-thread arena) holds only the
// scanner's arrays, gives the same layout every time: 5.6-6.3 ms. One such thread per calling
// thread, so that detections on several threads still run side by side.
class ScanThread
{
public:
    ScanThread()
        : m_thread([this] { loop(); })
    { }
    ~ScanThread()
    {
        {
            std::lock_guard lock(m_mutex);
            m_stop = true;
        }
        m_wake.notify_all();
        m_thread.join();
    }

    // Runs `job` on the scan thread and waits for it; an exception it throws is rethrown here.
    void run(const std::function<void()> &job)
    {
        std::unique_lock lock(m_mutex);
        m_job = &job;
        m_error = nullptr;
        m_wake.notify_all();
        m_wake.wait(lock, [this] { return m_job == nullptr; });
        if (m_error)
            std::rethrow_exception(m_error);
    }

private:
    void loop()
    {
        std::unique_lock lock(m_mutex);
        for (;;) {
            m_wake.wait(lock, [this] { return m_stop || m_job != nullptr; });
            if (m_stop)
                return;
            try {
                (*m_job)();
            } catch (...) {
                m_error = std::current_exception();
            }
            m_job = nullptr;
            m_wake.notify_all();
        }
    }

    std::mutex m_mutex;
    std::condition_variable m_wake;
    const std::function<void()> *m_job = nullptr;
    std::exception_ptr m_error;
    bool m_stop = false;
    std::thread m_thread; // last: started once the members it uses exist
};

// The faces in a copy of `gray` scaled by `scale`, scanning `levels` pyramid levels (0: all).
std::vector<FaceBox> findFaces(const QImage &gray, double scale, unsigned long levels)
{
    const QImage small = qFuzzyCompare(scale, 1.0) ? gray : resizedGray(gray, scale);
    std::vector<dlib::rect_detection> dets;
    thread_local ScanThread scanner;
    scanner.run([&] { threadDetector(levels)(viewOf(small), dets); });
    std::vector<FaceBox> out;
    for (const auto &d : dets) {
        // dlib's rectangles are inclusive: pixel columns left..right of the scaled copy,
        // which cover [left / scale, (right + 1) / scale) of the photo.
        const QRectF r(d.rect.left() / scale, d.rect.top() / scale, d.rect.width() / scale, d.rect.height() / scale);
        out.push_back({r, d.detection_confidence});
    }
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

void addLandmarkDebugImages(QMap<QString, QImage> *out, const QImage &image, const std::vector<FaceBox> &faces,
    int chosen, const std::array<QPointF, kIbugPointCount> &ibug, const FaceModel &geometric, const FaceModel &face,
    const HairSearchReport &hair, const HeadRegionReport &regions)
{
    QImage canvas = image.convertToFormat(QImage::Format_RGB32);
    QPainter p(&canvas);
    p.setRenderHint(QPainter::Antialiasing);
    const double unit = std::max(1.0, std::min(canvas.width(), canvas.height()) / 400.0);
    for (int i = 0; i < int(faces.size()); ++i) {
        p.setPen(QPen(i == chosen ? Qt::green : Qt::yellow, unit));
        p.drawRect(faces[i].box);
    }
    p.setPen(Qt::NoPen);
    p.setBrush(Qt::cyan);
    for (const QPointF &q : ibug)
        p.drawEllipse(q, unit, unit);
    p.end();
    out->insert(QStringLiteral("detect-landmarks"), canvas);

    // The points on a crop around the head, enlarged to about 800 px, labelled with their IDs;
    // the geometric estimates of hair and ears (before the photo search) in orange.
    QRectF head = face.bounds().united(geometric.bounds());
    head.adjust(-0.1 * head.width(), -0.1 * head.height(), 0.1 * head.width(), 0.1 * head.height());
    const double zoom = 800.0 / std::max(head.width(), head.height());
    QImage crop(QSize(std::lround(head.width() * zoom), std::lround(head.height() * zoom)), QImage::Format_RGB32);
    crop.fill(Qt::black);
    p.begin(&crop);
    p.setRenderHint(QPainter::Antialiasing);
    p.setRenderHint(QPainter::SmoothPixmapTransform);
    p.scale(zoom, zoom);
    p.translate(-head.topLeft());
    p.drawImage(QPointF(0, 0), image);
    p.setPen(QPen(QColor(255, 255, 255, 140), 1.0 / zoom));
    for (const QLineF &ray : regions.hairUsable ? regions.rays : hair.rays)
        p.drawLine(ray);
    // Text needs fonts, which need a QGuiApplication; a command-line run gets unlabelled points.
    const bool labels = qobject_cast<QGuiApplication *>(QCoreApplication::instance()) != nullptr;
    if (labels) {
        QFont font = p.font();
        font.setPointSizeF(7.0 / zoom);
        p.setFont(font);
    }
    const double r = 3.0 / zoom;
    for (int i = 0; i < kPointCount; ++i) {
        const PointGroup g = pointTable()[i].group;
        p.setPen(Qt::NoPen);
        if ((g == PointGroup::Hair || g == PointGroup::Ears) && geometric.point(i) != face.point(i)) {
            p.setBrush(QColor(255, 140, 0));
            p.drawEllipse(geometric.point(i), r, r);
        }
        p.setBrush(g == PointGroup::Hair ? Qt::magenta : g == PointGroup::Ears ? Qt::cyan : Qt::green);
        p.drawEllipse(face.point(i), r, r);
        if (labels) {
            p.setPen(Qt::yellow);
            p.drawText(face.point(i) + QPointF(r, -r), pointId(i));
        }
    }
    p.end();
    out->insert(QStringLiteral("detect-points-crop"), crop);
    if (!hair.regionMask.isNull())
        out->insert(QStringLiteral("detect-hair-region"), hair.regionMask);
    if (!regions.regionImage.isNull())
        out->insert(QStringLiteral("detect-head-regions"), regions.regionImage);
}

bool wantsDebugImages(const DetectOptions &options)
{
    return options.keepDebugImages || !options.debugDir.isEmpty();
}

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
    const ClassicResult c = detectClassic(image, wantsDebugImages(options));
    result.timingMs = c.timingMs;
    result.debugImages = c.debugImages;
    if (!c.ok || !c.eyePairInFace) {
        result.status = DetectStatus::NoFace;
        result.error = c.ok ? QStringLiteral("The classic method found no face: %1.").arg(c.faceCheck) : c.error;
        return result;
    }
    result.status = DetectStatus::Ok;
    result.face = c.face;
    result.faceCount = 1;
    result.faceBox = c.face.bounds().toAlignedRect().intersected(image.rect());
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
    // statistics, which it does not keep, are measured around the face it found.
    {
        FaceModel scratch = result.face;
        result.tracking = refineFromRegions(&scratch, image).seed;
    }
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

bool preloadLandmarkModel(QString *error, double *loadMs)
{
    return bool(landmarkModel(error, loadMs));
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
            result.error = QStringLiteral("Face detection was cancelled.");
            return true;
        }
        return false;
    };

    if (image.isNull()) {
        result.status = DetectStatus::BadImage;
        result.error = QStringLiteral("The image is empty.");
        return result;
    }
    if (options.method == DetectionMethod::Classic)
        return detectWithClassic(image, options, report);

    QString modelError;
    const auto model = landmarkModel(&modelError, nullptr);
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
        result.error = lastScale > 0
            ? QStringLiteral("No face was found in the image (%1 x %2 pixels). A frontal, upright "
                             "face at least %3 pixels wide is needed.")
                  .arg(image.width())
                  .arg(image.height())
                  .arg(std::ceil(kDetectorWindow / lastScale))
            : QStringLiteral("The image (%1 x %2 pixels) is too small to hold a face.")
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
    const GrayView view = viewOf(gray);
    const auto first = model->predict(view, pixelBox(face.box));
    const std::array<QPointF, kIbugPointCount> ibug = fitUpright(*model, view, face.box, first);
    const FaceModel geometric = faceFromLandmarks68(ibug, image.size());
    lap(QStringLiteral("landmarks"));
    if (cancelled())
        return result;

    // Hair and ears: the thesis' regions where they are usable; elsewhere the colour search of
    // hairsearch.h, which keeps the geometric estimate where the photo does not settle a point.
    report(0.7, QStringLiteral("hair"));
    FaceModel searched = geometric;
    HairSearchReport hair;
    refineFromPhoto(&searched, image, &hair, wantsDebugImages(options));
    lap(QStringLiteral("hair"));
    FaceModel fromRegions = searched;
    const HeadRegionReport head = refineFromRegions(&fromRegions, image, wantsDebugImages(options));
    FaceModel refined = searched;
    for (int i = 0; i < kPointCount; ++i) {
        const PointGroup g = pointTable()[i].group;
        const bool leftEar
            = i == pt::idx("10.2") || i == pt::idx("10.4") || i == pt::idx("10.6") || i == pt::idx("10.10");
        if ((g == PointGroup::Hair && head.hairUsable) || (g == PointGroup::Ears && head.earUsable[leftEar ? 0 : 1]))
            refined.setPoint(i, fromRegions.point(i));
    }
    // The seed for tracking: the regions' thresholds and colours, the geometry of the points,
    // and the edge thresholds of the classic method's square around them (thesis 6.3).
    TrackingSeed seed = head.seed;
    seedGeometryFromPoints(refined, &seed);
    measureEdgeThresholds(image, &seed);
    seed.valid = head.seed.valid;
    lap(QStringLiteral("regions"));
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
    result.tracking = seed;

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

std::shared_ptr<const LandmarkPredictor> sharedLandmarkModel(QString *error)
{
    return landmarkModel(error, nullptr);
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
