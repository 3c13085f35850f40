#include "window/detectiontask.h"

#include <QPromise>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <cmath>
#include <utility>

namespace toonface {

namespace {

constexpr int kProgressSteps = 1000;

} // namespace

// Each image is drawn stretched over the photo, so its resolution only limits sharpness.
void DetectionTask::reduceStepImages(QMap<QString, QImage> *images)
{
    for (auto it = images->begin(); it != images->end(); ++it) {
        QImage image = it.value();
        const qint64 pixels = qint64(image.width()) * image.height();
        if (pixels > kMaxStepImagePixels) {
            const double k = std::sqrt(double(kMaxStepImagePixels) / double(pixels));
            image = image.scaled(std::max(1, int(image.width() * k)), std::max(1, int(image.height() * k)),
                Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
        }
        *it = image.convertToFormat(
            image.hasAlphaChannel() ? QImage::Format_ARGB32_Premultiplied : QImage::Format_RGB32);
    }
}

DetectionTask::DetectionTask(QObject *parent)
    : QObject(parent)
{ }

DetectionTask::~DetectionTask() = default;

void DetectionTask::start(const QImage &image, const DetectOptions &options)
{
    auto cancelFlag = m_job.newCancelFlag();
    QFuture<DetectionResult> future
        = QtConcurrent::run([image, options, cancelFlag](QPromise<DetectionResult> &promise) {
              promise.setProgressRange(0, kProgressSteps);
              auto reporter = [&promise](double from, const QString &label) {
                  return ProgressFn([&promise, from, label](double fraction, const QString &stage) {
                      promise.setProgressValueAndText(
                          int((from + 0.5 * fraction) * kProgressSteps), label.isEmpty() ? stage : label);
                  });
              };
              // Result 0: the points alone.
              DetectOptions pointsOnly = options;
              pointsOnly.keepDebugImages = false;
              pointsOnly.debugDir.clear();
              DetectionResult points = detectFace(image, pointsOnly, reporter(0.0, {}), cancelFlag.get());
              const bool stop = points.status == DetectStatus::Cancelled || cancelFlag->load();
              promise.addResult(std::move(points));
              if (stop)
                  return;
              // Result 1: the same with the intermediate images.
              DetectOptions withSteps = options;
              withSteps.keepDebugImages = true;
              DetectionResult steps
                  = detectFace(image, withSteps, reporter(0.5, QStringLiteral("steps")), cancelFlag.get());
              reduceStepImages(&steps.debugImages);
              promise.addResult(std::move(steps));
          });

    QFutureWatcher<DetectionResult> *watcher = m_job.watch(
        future,
        [this](const QFutureWatcher<DetectionResult> &w) {
            Q_EMIT progress(double(w.progressValue()) / kProgressSteps, w.progressText());
        },
        [this](const QFuture<DetectionResult> &done, bool wasCancelled) {
            if (wasCancelled || done.resultCount() < 2) {
                Q_EMIT cancelled();
                return;
            }
            const DetectionResult result = done.resultAt(1);
            if (result.status == DetectStatus::Cancelled)
                Q_EMIT cancelled();
            else
                Q_EMIT finished(result);
        });
    // The points as soon as they are there (result 0).
    connect(watcher, &QFutureWatcherBase::resultReadyAt, this, [this, watcher](int index) {
        if (!m_job.isCurrent(watcher) || index != 0 || m_job.isCancelled())
            return;
        const DetectionResult points = watcher->resultAt(0);
        if (points.status != DetectStatus::Cancelled)
            Q_EMIT pointsReady(points);
    });
}

void DetectionTask::cancel()
{
    m_job.cancel();
}

void DetectionTask::abandon()
{
    m_job.drop();
}

void DetectionTask::preload()
{
    warmUpDetection();
    // The watcher only waits for the model, to say when it is unavailable.
    auto *watcher = new QFutureWatcher<QString>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher] {
        watcher->deleteLater();
        if (const QString error = watcher->result(); !error.isEmpty())
            Q_EMIT preloadFailed(error);
    });
    watcher->setFuture(QtConcurrent::run([] {
        QString error;
        return preloadLandmarkModel(&error) ? QString() : error;
    }));
}

bool DetectionTask::isRunning() const
{
    return m_job.isRunning();
}

} // namespace toonface
