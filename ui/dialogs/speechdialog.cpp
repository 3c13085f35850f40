#include "dialogs/speechdialog.h"

#include "dialogs/animationedits.h"
#include "dialogs/jobstatus.h"
#include "document/document.h"

#include <QComboBox>
#include <QFileInfo>
#include <QFormLayout>

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
    if (!apply(outcome.result))
        return;
    m_status->clear();
    Q_EMIT applied();
    accept();
}

void SpeechDialog::addOverlapRow(QFormLayout *form, QList<QWidget *> *inputs)
{
    if (m_document->timeline().audioClips().isEmpty())
        return;
    m_overlap = new QComboBox(this);
    m_overlap->setObjectName(QStringLiteral("overlap"));
    m_overlap->addItem(tr("Place it after them"), int(ClipOverlap::PlaceAfter));
    m_overlap->addItem(tr("Replace them (with their syllables and mouth keys)"), int(ClipOverlap::Replace));
    m_overlap->setToolTip(tr("The timeline keeps every recording as a clip on the audio track. What to do when the "
                             "new one would play over others: nothing is replaced unless you choose so."));
    form->addRow(tr("If other recordings &play there:"), m_overlap);
    inputs->append(m_overlap);
}

bool SpeechDialog::applySpeech(
    const LipsyncResult &result, const QString &path, double offset, const QString &script, const QString &undoText)
{
    SpeechPlacement placement {path, offset, script, ClipOverlap::PlaceAfter};
    if (m_overlap)
        placement.overlap = ClipOverlap(m_overlap->currentData().toInt());
    const Timeline before = m_document->timeline();
    ClipPlace placed;
    const std::optional<Animation> after = withSpeech(m_document->animation(), result, placement, &placed);
    if (!after) {
        fail(tr("%1 (%2 s) does not fit on the timeline there: it would end past %3 hours.")
                 .arg(QFileInfo(path).fileName())
                 .arg(result.duration, 0, 'f', 1)
                 .arg(Timeline::kMaxSeconds / 3600));
        return false;
    }
    m_document->changeAnimation(*after, undoText);
    const QString note = placementNote(before, placed, offset);
    m_outcome = tr("%1: %2 at %3 s").arg(undoText, QFileInfo(path).fileName()).arg(placed.start, 0, 'f', 2);
    if (!note.isEmpty())
        m_outcome += QStringLiteral(", ") + note;
    return true;
}

} // namespace toonface
