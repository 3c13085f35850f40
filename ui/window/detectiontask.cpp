#include "window/detectiontask.h"

#include <QPromise>
#include <QtConcurrent/QtConcurrentRun>

namespace toonface {

namespace {

constexpr int kProgressSteps = 1000;

} // namespace

DetectionTask::DetectionTask(QObject *parent)
    : QObject(parent)
{ }

DetectionTask::~DetectionTask()
{
    drop();
}

void DetectionTask::start(const QImage &image, const DetectOptions &options)
{
    drop();
    auto cancelFlag = std::make_shared<std::atomic_bool>(false);
    m_cancel = cancelFlag;
    QFuture<DetectionResult> future
        = QtConcurrent::run([image, options, cancelFlag](QPromise<DetectionResult> &promise) {
              promise.setProgressRange(0, kProgressSteps);
              const ProgressFn report = [&promise](double fraction, const QString &stage) {
                  promise.setProgressValueAndText(int(fraction * kProgressSteps), stage);
              };
              promise.addResult(detectFace(image, options, report, cancelFlag.get()));
          });

    auto *watcher = new QFutureWatcher<DetectionResult>(this);
    m_watcher = watcher;
    connect(watcher, &QFutureWatcherBase::progressValueChanged, this, [this, watcher](int value) {
        if (watcher == m_watcher)
            Q_EMIT progress(double(value) / kProgressSteps, watcher->progressText());
    });
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher] { onFinished(watcher); });
    watcher->setFuture(future);
}

void DetectionTask::cancel()
{
    if (m_cancel)
        m_cancel->store(true);
}

void DetectionTask::abandon()
{
    drop();
}

bool DetectionTask::isRunning() const
{
    return m_watcher != nullptr;
}

void DetectionTask::onFinished(QFutureWatcher<DetectionResult> *watcher)
{
    watcher->deleteLater();
    if (watcher != m_watcher)
        return;
    m_watcher = nullptr;
    const bool wasCancelled = m_cancel && m_cancel->load();
    m_cancel.reset();
    const QFuture<DetectionResult> future = watcher->future();
    if (wasCancelled || future.resultCount() == 0) {
        Q_EMIT cancelled();
        return;
    }
    const DetectionResult result = future.result();
    if (result.status == DetectStatus::Cancelled)
        Q_EMIT cancelled();
    else
        Q_EMIT finished(result);
}

void DetectionTask::drop()
{
    if (m_cancel)
        m_cancel->store(true);
    m_cancel.reset();
    if (m_watcher) {
        m_watcher->disconnect(this);
        m_watcher->deleteLater();
        m_watcher = nullptr;
    }
}

} // namespace toonface
