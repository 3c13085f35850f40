#include "capture/tracktask.h"

#include <QPromise>
#include <QtConcurrent/QtConcurrentRun>

namespace toonface {

TrackTask::TrackTask(QObject *parent)
    : QObject(parent)
{ }

TrackTask::~TrackTask() = default;

void TrackTask::start(const QString &path, const TrackVideoOptions &options)
{
    auto cancelFlag = m_job.newCancelFlag();
    auto total = std::make_shared<std::atomic_int>(-1);
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
    m_job.watch(
        future,
        [this, total](
            const QFutureWatcher<TrackResult> &watcher) { Q_EMIT progress(watcher.progressValue(), total->load()); },
        [this](const QFuture<TrackResult> &done, bool cancelled) {
            TrackResult result;
            if (done.resultCount() > 0)
                result = done.result();
            // A cancel that came too late to stop the job still means "do not apply it".
            if (cancelled || done.resultCount() == 0) {
                result = TrackResult {};
                result.status = TrackStatus::Cancelled;
                result.error = QStringLiteral("cancelled");
            }
            Q_EMIT finished(result);
        });
}

void TrackTask::cancel()
{
    m_job.cancel();
}

} // namespace toonface
