#pragma once

#include "detect/faceregions.h"
#include "detect/modelcache.h"
#include "face/facemodel.h"

#include <QImage>
#include <QList>
#include <QMap>
#include <QRect>
#include <QString>

#include <atomic>
#include <functional>
#include <optional>

namespace toonface {

enum class DetectionMethod { Auto, Classic, Landmarks };
QString detectionMethodName(DetectionMethod m); // "auto", "classic", "landmarks"
bool detectionMethodFromName(const QString &name, DetectionMethod *m);

struct DetectOptions
{
    DetectionMethod method = DetectionMethod::Auto;
    QString debugDir; // when set, intermediate images are written there as PNGs
    bool keepDebugImages = false; // keep the intermediate images in DetectionResult::debugImages
    // With several faces: use the one whose box holds this point (photo pixels), looking for
    // smaller faces until one does; unset (or held by no face): the largest, most central one.
    // The classic method looks for its eye pair in that face's box (unset or held by no face:
    // in the middle of the picture, the thesis' assumption).
    std::optional<QPointF> faceAt;
};

// Unsupported: the requested method is not implemented in this build.
enum class DetectStatus { Ok, NoFace, ModelMissing, Cancelled, BadImage, Unsupported };

struct DetectionResult
{
    DetectStatus status = DetectStatus::NoFace;
    QString error; // a sentence for the user when status != Ok
    FaceModel face; // valid when status == Ok
    QString method; // the method that produced the points ("landmarks", "classic")
    QString note; // with auto: why the classic method was used instead of the landmarks
    int faceCount = 0; // faces seen in the image; the largest, most central one is used. Faces
                       // are looked for from large to small and the search stops at the size
                       // range where one is found: much smaller faces beside it are not counted
    QRect faceBox; // the chosen face's box in image pixels
    QList<QRect> otherFaces; // the boxes of the other faces counted in faceCount
    QMap<QString, double> timingMs; // per stage, plus "total" (model loading excluded)
    QMap<QString, double> groupConfidence; // per point group name, 0..1
    FaceRegions regions; // the chosen face's regions, valid when status == Ok
    TrackingSeed tracking; // what video tracking reuses; tracking.valid when it could be measured
    // The intermediate images of the method (the thesis' figures for "classic"), by file stem
    // ("classic-b1", "detect-points", ...); filled when keepDebugImages or debugDir is set. Each
    // has the photo's size unless its name ends in "-crop" (a zoomed view).
    QMap<QString, QImage> debugImages;
};

using ProgressFn = std::function<void(double fraction, const QString &stage)>;

// Finds the face in `image` and places the 72 points.
//
// Thread safety: may be called from several threads at once; the landmark model is loaded
// once per process and shared, the face detector is per thread.
// requires: image is not null. Cancel is polled between stages.
DetectionResult detectFace(const QImage &image, const DetectOptions &options = {}, const ProgressFn &progress = {},
    const std::atomic_bool *cancel = nullptr);

// Loads the landmark model now (it is otherwise loaded on first use), from its cache in
// detectionCacheDir() (modelcache.h, cachefile.h), writing that cache the first time. Returns false with
// *error when the model file is missing or unreadable. Thread-safe; loads only once; waits for
// a load under way (the warm-up's). *loadMs: this call's load, 0 when it found the model loaded.
bool preloadLandmarkModel(QString *error = nullptr, double *loadMs = nullptr);
QString landmarkModelPath(); // TOONFACE_LANDMARK_MODEL or Debian's libdlib-data file
// How the model in use was loaded (from its cache or not, how long it took); no model when
// none has been loaded yet.
LandmarkModelLoad landmarkModelLoad();

// Starts, in the background and once per process, what the first detection would otherwise
// do on its way, one thing after another: the landmark model's load, the face detector's
// decoding and its scan thread, and a first run of the stages after the scan (their tables,
// OpenCV's set-up, first allocations). It runs on two threads of its own, beside the caller's
// start-up; a detection started meanwhile waits only for what it needs. The editor starts it
// when its window opens. Calling it again does nothing.
void warmUpDetection();
// The same without the first run of the later stages: for a process whose detection starts at
// once (the CLI), which would only race that run for the cores and wait for it.
void warmUpDetectionModels();
// Waits until the warm-up has ended (returns at once when none was started). The warm-up's
// threads must not outlive what they use: QCoreApplication's destructor calls this, and a
// process without one calls it before it ends.
void waitForDetectionWarmUp();

} // namespace toonface
