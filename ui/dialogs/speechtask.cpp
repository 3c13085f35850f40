#include "dialogs/speechtask.h"

#include <QPromise>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <utility>

namespace toonface {

namespace {

constexpr int kProgressSteps = 1000;

} // namespace

SpeechTask::SpeechTask(QObject *parent)
    : QObject(parent)
{ }

SpeechTask::~SpeechTask() = default;

void SpeechTask::start(Job job)
{
    auto cancelFlag = m_job.newCancelFlag();
    QFuture<LipsyncOutcome> future
        = QtConcurrent::run([job = std::move(job), cancelFlag](QPromise<LipsyncOutcome> &promise) {
              promise.setProgressRange(0, kProgressSteps);
              const SpeechProgressFn report = [&promise](double fraction, const QString &stage) {
                  promise.setProgressValueAndText(int(std::clamp(fraction, 0.0, 1.0) * kProgressSteps), stage);
              };
              LipsyncOutcome outcome = job(report, cancelFlag.get());
              if (cancelFlag->load() && outcome.status != LipsyncStatus::Ok) {
                  outcome.status = LipsyncStatus::Cancelled;
                  outcome.error = QStringLiteral("cancelled");
              }
              promise.addResult(std::move(outcome));
          });

    m_job.watch(
        future,
        [this](const QFutureWatcher<LipsyncOutcome> &watcher) {
            Q_EMIT progress(double(watcher.progressValue()) / kProgressSteps, watcher.progressText());
        },
        [this](const QFuture<LipsyncOutcome> &done, bool cancelled) {
            LipsyncOutcome outcome;
            if (done.resultCount() > 0)
                outcome = done.result();
            // A cancel that came too late to stop the job still means "do not apply it".
            if (cancelled || done.resultCount() == 0) {
                outcome.status = LipsyncStatus::Cancelled;
                outcome.error = QStringLiteral("cancelled");
                outcome.result = {};
            }
            Q_EMIT finished(outcome);
        });
}

void SpeechTask::cancel()
{
    m_job.cancel();
}

} // namespace toonface
