#pragma once

#include "detect/detector.h"
#include "window/backgroundjob.h"

#include <QFutureWatcher>
#include <QImage>
#include <QObject>

#include <atomic>
#include <memory>

namespace toonface {

// Runs detectFace() off the GUI thread (QtConcurrent::run) and reports its progress and
// result by signals on the thread that owns the task. One detection at a time: start()
// cancels a running one, whose result is then dropped.
//
// The points come first (pointsReady(), without images), so that they are on screen as soon
// as they are placed; then the worker runs the detection again keeping its intermediate
// images (DetectionResult::debugImages) for the editor's overlays, and finished() brings them,
// reduced in the worker to at most kMaxStepImagePixels each and converted for fast drawing, so
// that a large photo does not hold a dozen full-size copies. Drawing the steps (the thesis'
// figures beside the landmarks') costs several times the detection itself.
class DetectionTask : public QObject
{
    Q_OBJECT

public:
    static constexpr qint64 kMaxStepImagePixels = 4'000'000;
    // What the worker does to the intermediate images: each shrunk to at most
    // kMaxStepImagePixels with its aspect ratio kept (within a pixel), and converted to RGB32,
    // or premultiplied ARGB32 when it has alpha.
    static void reduceStepImages(QMap<QString, QImage> *images);

    explicit DetectionTask(QObject *parent = nullptr);
    // Cancels a running detection; the worker stops at its next stage and nothing is reported.
    ~DetectionTask() override;

    // image: a copy travels to the worker (QImage is implicitly shared and read-only there).
    // options.keepDebugImages is set whatever the caller asked.
    void start(const QImage &image, const DetectOptions &options = {});
    // Asks the running detection to stop; cancelled() follows.
    void cancel();
    // Stops the running detection and reports nothing about it (its document is gone).
    void abandon();
    bool isRunning() const;
    // Makes the landmark model and the face detector ready in the background (at once when the
    // application's start already began it), so that the first photo's points come as fast as
    // any later one's; preloadFailed() says when the model is unavailable.
    void preload();

Q_SIGNALS:
    void preloadFailed(const QString &error);
    void progress(double fraction, const QString &stage);
    // The detection's result without its intermediate images; finished() follows (or
    // cancelled(), when cancelled meanwhile).
    void pointsReady(const toonface::DetectionResult &result);
    // The same result with the intermediate images.
    void finished(const toonface::DetectionResult &result);
    void cancelled();

private:
    BackgroundJob<DetectionResult> m_job {this};
};

} // namespace toonface
