#pragma once

#include <QFutureWatcher>
#include <QObject>

#include <atomic>
#include <functional>
#include <memory>

namespace toonface {

// The one cancellable background job of a task object (DetectionTask, SpeechTask, TrackTask):
// its watcher and cancel flag, and the rule that a job that was dropped or replaced reports
// nothing. Lives on the owner's thread, as a member of the owner.
template<class Result>
class BackgroundJob
{
public:
    explicit BackgroundJob(QObject *owner)
        : m_owner(owner)
    { }
    ~BackgroundJob() { drop(); }
    BackgroundJob(const BackgroundJob &) = delete;
    BackgroundJob &operator=(const BackgroundJob &) = delete;

    // Drops a running job and gives the cancel flag of the next one (for the work to poll).
    std::shared_ptr<std::atomic_bool> newCancelFlag()
    {
        drop();
        m_cancel = std::make_shared<std::atomic_bool>(false);
        return m_cancel;
    }

    // Watches the job's future: `progress` on each progress change and `finished` (with
    // whether it was cancelled meanwhile) at its end, both only while it is the current job.
    // The watcher is returned for other connections, which check isCurrent().
    QFutureWatcher<Result> *watch(const QFuture<Result> &future,
        std::function<void(const QFutureWatcher<Result> &)> progress,
        std::function<void(const QFuture<Result> &, bool cancelled)> finished)
    {
        auto *watcher = new QFutureWatcher<Result>(m_owner);
        m_watcher = watcher;
        if (progress)
            QObject::connect(watcher, &QFutureWatcherBase::progressValueChanged, m_owner,
                [this, watcher, progress = std::move(progress)] {
                    if (isCurrent(watcher))
                        progress(*watcher);
                });
        QObject::connect(
            watcher, &QFutureWatcherBase::finished, m_owner, [this, watcher, finished = std::move(finished)] {
                watcher->deleteLater();
                if (!isCurrent(watcher))
                    return;
                m_watcher = nullptr;
                const bool wasCancelled = isCancelled();
                m_cancel.reset();
                finished(watcher->future(), wasCancelled);
            });
        watcher->setFuture(future);
        return watcher;
    }

    bool isCurrent(const QFutureWatcher<Result> *watcher) const { return watcher == m_watcher; }
    bool isRunning() const { return m_watcher != nullptr; }
    bool isCancelled() const { return m_cancel && m_cancel->load(); }
    // Asks the running job to stop; its end is still reported.
    void cancel()
    {
        if (m_cancel)
            m_cancel->store(true);
    }
    // Asks the running job to stop and forgets it: nothing of it is reported.
    void drop()
    {
        cancel();
        m_cancel.reset();
        if (m_watcher) {
            m_watcher->disconnect(m_owner);
            m_watcher->deleteLater();
            m_watcher = nullptr;
        }
    }

private:
    QObject *m_owner;
    QFutureWatcher<Result> *m_watcher = nullptr;
    std::shared_ptr<std::atomic_bool> m_cancel;
};

} // namespace toonface
