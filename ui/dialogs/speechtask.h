#pragma once

#include "window/backgroundjob.h"

#include "speech/lipsync.h"

#include <QFutureWatcher>
#include <QObject>

#include <atomic>
#include <functional>
#include <memory>

namespace toonface {

// Runs one piece of lip-sync work (alignment, or speech synthesis) off the GUI thread
// (QtConcurrent::run) and reports its progress and outcome by signals on the thread that owns
// the task. One job at a time: start() drops a running one, whose outcome is never reported.
class SpeechTask : public QObject
{
    Q_OBJECT

public:
    // The work: takes a progress callback (0..1) and a cancel flag to poll; runs on a pool
    // thread, so it must own (copy) everything it reads.
    using Job = std::function<LipsyncOutcome(const SpeechProgressFn &progress, const std::atomic_bool *cancel)>;

    explicit SpeechTask(QObject *parent = nullptr);
    // Drops a running job: it is asked to stop and its outcome is discarded.
    ~SpeechTask() override;

    void start(Job job);
    // Asks the running job to stop; finished() follows with LipsyncStatus::Cancelled (or with
    // the job's outcome when it had already ended).
    void cancel();
    bool isRunning() const { return m_job.isRunning(); }

Q_SIGNALS:
    void progress(double fraction, const QString &stage);
    void finished(const toonface::LipsyncOutcome &outcome);

private:
    BackgroundJob<LipsyncOutcome> m_job {this};
};

} // namespace toonface
