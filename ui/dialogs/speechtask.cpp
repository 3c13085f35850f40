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

SpeechTask::~SpeechTask()
{
    drop();
}

void SpeechTask::start(Job job)
{
    drop();
    auto cancelFlag = std::make_shared<std::atomic_bool>(false);
    m_cancel = cancelFlag;
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

    auto *watcher = new QFutureWatcher<LipsyncOutcome>(this);
    m_watcher = watcher;
    connect(watcher, &QFutureWatcherBase::progressValueChanged, this, [this, watcher](int value) {
        if (watcher == m_watcher)
            Q_EMIT progress(double(value) / kProgressSteps, watcher->progressText());
    });
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher] { onFinished(watcher); });
    watcher->setFuture(future);
}

void SpeechTask::cancel()
{
    if (m_cancel)
        m_cancel->store(true);
}

void SpeechTask::onFinished(QFutureWatcher<LipsyncOutcome> *watcher)
{
    watcher->deleteLater();
    if (watcher != m_watcher)
        return;
    m_watcher = nullptr;
    const bool wasCancelled = m_cancel && m_cancel->load();
    m_cancel.reset();
    const QFuture<LipsyncOutcome> future = watcher->future();
    LipsyncOutcome outcome;
    if (future.resultCount() > 0)
        outcome = future.result();
    // A cancel that came too late to stop the job still means "do not apply it".
    if (wasCancelled || future.resultCount() == 0) {
        outcome.status = LipsyncStatus::Cancelled;
        outcome.error = QStringLiteral("cancelled");
        outcome.result = {};
    }
    Q_EMIT finished(outcome);
}

void SpeechTask::drop()
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
