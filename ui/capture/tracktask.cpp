#include "capture/tracktask.h"

#include <QPromise>
#include <QtConcurrent/QtConcurrentRun>

namespace toonface {

TrackTask::TrackTask(QObject *parent)
    : QObject(parent)
{ }

TrackTask::~TrackTask()
{
    drop();
}

void TrackTask::start(const QString &path, const TrackVideoOptions &options)
{
    drop();
    auto cancelFlag = std::make_shared<std::atomic_bool>(false);
    auto total = std::make_shared<std::atomic_int>(-1);
    m_cancel = cancelFlag;
    m_total = total;
    QFuture<TrackResult> future = QtConcurrent::run([path, options, cancelFlag, total](QPromise<TrackResult> &promise) {
        const auto report = [&promise, &total](int done, int count) {
            total->store(count);
            promise.setProgressValue(done);
        };
        TrackResult result = trackVideo(path, options, report, cancelFlag.get());
        if (cancelFlag->load() && result.status != TrackStatus::Ok) {
            result.status = TrackStatus::Cancelled;
            result.error = QStringLiteral("cancelled");
        }
        promise.addResult(std::move(result));
    });
    auto *watcher = new QFutureWatcher<TrackResult>(this);
    m_watcher = watcher;
    connect(watcher, &QFutureWatcherBase::progressValueChanged, this, [this, watcher, total](int done) {
        if (watcher == m_watcher)
            Q_EMIT progress(done, total->load());
    });
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher] { onFinished(watcher); });
    watcher->setFuture(future);
}

void TrackTask::cancel()
{
    if (m_cancel)
        m_cancel->store(true);
}

void TrackTask::onFinished(QFutureWatcher<TrackResult> *watcher)
{
    watcher->deleteLater();
    if (watcher != m_watcher)
        return;
    m_watcher = nullptr;
    const bool wasCancelled = m_cancel && m_cancel->load();
    m_cancel.reset();
    m_total.reset();
    const QFuture<TrackResult> future = watcher->future();
    TrackResult result;
    if (future.resultCount() > 0)
        result = future.result();
    // A cancel that came too late to stop the job still means "do not apply it".
    if (wasCancelled || future.resultCount() == 0) {
        result = TrackResult {};
        result.status = TrackStatus::Cancelled;
        result.error = QStringLiteral("cancelled");
    }
    Q_EMIT finished(result);
}

void TrackTask::drop()
{
    if (m_cancel)
        m_cancel->store(true);
    m_cancel.reset();
    m_total.reset();
    if (m_watcher) {
        m_watcher->disconnect(this);
        m_watcher->deleteLater();
        m_watcher = nullptr;
    }
}

} // namespace toonface
