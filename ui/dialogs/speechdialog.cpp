#include "dialogs/speechdialog.h"

#include "dialogs/jobstatus.h"

#include <QDialogButtonBox>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace toonface {

SpeechDialog::SpeechDialog(Document *document, const QString &startText, QWidget *parent)
    : QDialog(parent)
    , m_document(document)
    , m_task(new SpeechTask(this))
    , m_status(new JobStatus(this))
    , m_buttons(new QDialogButtonBox(this))
{
    setMinimumWidth(600);
    m_startButton = m_buttons->addButton(startText, QDialogButtonBox::AcceptRole);
    m_startButton->setObjectName(QStringLiteral("start"));
    m_startButton->setDefault(true);
    m_cancelButton = m_buttons->addButton(QDialogButtonBox::Cancel);
    m_cancelButton->setObjectName(QStringLiteral("cancel"));
    connect(m_buttons, &QDialogButtonBox::accepted, this, &SpeechDialog::start);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &SpeechDialog::reject);
    connect(m_task, &SpeechTask::progress, m_status, &JobStatus::showProgress);
    connect(m_task, &SpeechTask::finished, this, &SpeechDialog::onFinished);
}

SpeechDialog::~SpeechDialog() = default;

void SpeechDialog::setBody(const QString &intro, QLayout *form, const QList<QWidget *> &inputs)
{
    auto *introLabel = new QLabel(intro, this);
    introLabel->setWordWrap(true);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(introLabel);
    layout->addLayout(form, 1);
    layout->addWidget(m_status);
    layout->addWidget(m_buttons);
    m_inputs = inputs;
    updateButtons();
}

bool SpeechDialog::isRunning() const
{
    return m_task->isRunning();
}

QString SpeechDialog::message() const
{
    return m_status->message();
}

void SpeechDialog::updateButtons()
{
    m_startButton->setEnabled(!m_task->isRunning() && canStart());
}

void SpeechDialog::fail(const QString &message)
{
    m_status->showError(message + QLatin1Char('\n') + tr("Nothing was changed."));
    Q_EMIT failed(m_status->message());
}

void SpeechDialog::setRunning(bool running)
{
    for (QWidget *w : std::as_const(m_inputs))
        w->setEnabled(!running);
    m_cancelButton->setEnabled(true);
    updateButtons();
}

void SpeechDialog::start()
{
    if (m_task->isRunning() || !canStart())
        return;
    std::optional<SpeechTask::Job> job = prepare();
    if (!job)
        return;
    m_task->start(std::move(*job));
    setRunning(true);
}

void SpeechDialog::cancel()
{
    if (!m_task->isRunning())
        return;
    m_task->cancel();
    m_cancelButton->setEnabled(false);
    m_status->showProgress(0, tr("Cancelling…"));
}

void SpeechDialog::reject()
{
    if (m_task->isRunning()) {
        cancel();
        return;
    }
    QDialog::reject();
}

void SpeechDialog::onFinished(const LipsyncOutcome &outcome)
{
    setRunning(false);
    if (outcome.status == LipsyncStatus::Cancelled) {
        discard();
        m_status->showNote(tr("Cancelled: nothing was changed."));
        Q_EMIT cancelled();
        return;
    }
    if (!outcome.ok()) {
        discard();
        fail(outcome.error);
        return;
    }
    apply(outcome.result);
    m_status->clear();
    Q_EMIT applied();
    accept();
}

} // namespace toonface
