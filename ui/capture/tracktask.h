#pragma once

#include "window/backgroundjob.h"

#include "track/trackvideo.h"

#include <QFutureWatcher>
#include <QObject>

#include <atomic>
#include <memory>

namespace toonface {

// Tracks a whole clip (trackVideo) off the GUI thread and reports progress and the outcome by
// signals on the thread that owns the task. One job at a time: start() drops a running one,
// whose outcome is never reported; so does destroying the task.
class TrackTask : public QObject
{
    Q_OBJECT

public:
    explicit TrackTask(QObject *parent = nullptr);
    ~TrackTask() override;

    void start(const QString &path, const TrackVideoOptions &options);
    // Asks the running job to stop; finished() follows with TrackStatus::Cancelled.
    void cancel();
    bool isRunning() const { return m_job.isRunning(); }

Q_SIGNALS:
    // `total` is -1 when the file does not say how many frames it has.
    void progress(int done, int total);
    void finished(const toonface::TrackResult &result);

private:
    BackgroundJob<TrackResult> m_job {this};
};

} // namespace toonface
