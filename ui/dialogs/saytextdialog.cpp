#include "dialogs/saytextdialog.h"

#include "dialogs/animationedits.h"
#include "dialogs/jobstatus.h"
#include "dialogs/languagebox.h"
#include "dialogs/secondsbox.h"
#include "dialogs/speechtask.h"
#include "document/document.h"

#include <QDialogButtonBox>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QStandardPaths>
#include <QVBoxLayout>

namespace toonface {

namespace {

bool writableFolder(const QString &folder)
{
    const QFileInfo info(folder);
    return !folder.isEmpty() && info.isDir() && info.isWritable();
}

} // namespace

bool SayTextDialog::run(QWidget *parent, Document *document)
{
    SayTextDialog dialog(document, parent);
    return dialog.exec() == QDialog::Accepted;
}

QString SayTextDialog::defaultSoundPath(const Document &document)
{
    QString folder;
    QString base;
    if (!document.filePath().isEmpty()) {
        const QFileInfo project(document.filePath());
        folder = project.absolutePath();
        base = project.completeBaseName();
    } else if (!document.project().photoPath.isEmpty()) {
        const QFileInfo photo(document.project().photoPath);
        folder = photo.absolutePath();
        base = photo.completeBaseName();
    }
    if (!writableFolder(folder))
        folder = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    if (!writableFolder(folder))
        folder = QDir::homePath();
    if (base.isEmpty())
        base = QStringLiteral("toonface");
    const QDir dir(folder);
    QString path = dir.absoluteFilePath(base + QStringLiteral("-speech.wav"));
    for (int n = 2; QFileInfo::exists(path); ++n)
        path = dir.absoluteFilePath(QStringLiteral("%1-speech-%2.wav").arg(base).arg(n));
    return path;
}

SayTextDialog::SayTextDialog(Document *document, QWidget *parent)
    : QDialog(parent)
    , m_document(document)
    , m_task(new SpeechTask(this))
    , m_text(new QPlainTextEdit(this))
    , m_language(new LanguageBox(this))
    , m_rate(new QSpinBox(this))
    , m_pitch(new QSpinBox(this))
    , m_offset(new SecondsBox(this))
    , m_soundPath(new QLineEdit(this))
    , m_soundNote(new QLabel(this))
    , m_status(new JobStatus(this))
    , m_buttons(new QDialogButtonBox(this))
{
    setWindowTitle(tr("Say Text"));
    setMinimumWidth(600);

    auto *intro = new QLabel(tr("The built-in voice speaks the text and the face says it with the voice's exact "
                                "timings. The mouth keys and syllables where the speech plays are replaced."),
        this);
    intro->setWordWrap(true);

    m_text->setObjectName(QStringLiteral("text"));
    m_text->setPlaceholderText(tr("Chinese characters, pinyin, Zhuyin or English, e.g. 您好，我是葛麗絲。"));
    m_text->setTabChangesFocus(true);
    m_text->setMinimumHeight(fontMetrics().lineSpacing() * 5);
    m_language->setObjectName(QStringLiteral("language"));
    m_rate->setObjectName(QStringLiteral("rate"));
    m_rate->setRange(80, 450);
    m_rate->setValue(TtsOptions().rate);
    m_rate->setSuffix(tr(" words/min"));
    m_pitch->setObjectName(QStringLiteral("pitch"));
    m_pitch->setRange(0, 100);
    m_pitch->setValue(TtsOptions().pitch);
    m_offset->setObjectName(QStringLiteral("offset"));
    m_offset->setToolTip(tr("Where the speech starts on the timeline"));
    auto *voiceRow = new QHBoxLayout;
    voiceRow->addWidget(m_rate);
    voiceRow->addSpacing(12);
    voiceRow->addWidget(new QLabel(tr("Pitch:"), this));
    voiceRow->addWidget(m_pitch);
    voiceRow->addStretch(1);

    m_soundPath->setObjectName(QStringLiteral("soundPath"));
    m_soundPath->setText(QDir::toNativeSeparators(defaultSoundPath(*m_document)));
    auto *choose = new QPushButton(tr("Choose…"), this);
    choose->setObjectName(QStringLiteral("chooseSound"));
    auto *soundRow = new QHBoxLayout;
    soundRow->addWidget(m_soundPath, 1);
    soundRow->addWidget(choose);
    m_soundNote->setObjectName(QStringLiteral("soundNote"));
    m_soundNote->setWordWrap(true);
    m_soundNote->setText(!m_document->filePath().isEmpty()
            ? tr("The sound is saved beside the project.")
            : (m_document->project().photoPath.isEmpty()
                    ? tr("The project is not saved yet: the sound is saved in your documents folder.")
                    : tr("The project is not saved yet: the sound is saved beside the photo. Save the project "
                         "in the same folder to keep them together.")));
    m_soundNote->setEnabled(false); // drawn as a secondary note
    auto *soundBox = new QVBoxLayout;
    soundBox->addLayout(soundRow);
    soundBox->addWidget(m_soundNote);

    auto *form = new QFormLayout;
    form->addRow(tr("&Text:"), m_text);
    form->addRow(tr("&Language:"), m_language);
    form->addRow(tr("&Speed:"), voiceRow);
    form->addRow(tr("Starts &at:"), m_offset);
    form->addRow(tr("Save the s&ound as:"), soundBox);
    static_cast<QLabel *>(form->labelForField(voiceRow))->setBuddy(m_rate);
    static_cast<QLabel *>(form->labelForField(soundBox))->setBuddy(m_soundPath);

    m_startButton = m_buttons->addButton(tr("Say"), QDialogButtonBox::AcceptRole);
    m_startButton->setObjectName(QStringLiteral("start"));
    m_startButton->setDefault(true);
    m_cancelButton = m_buttons->addButton(QDialogButtonBox::Cancel);
    m_cancelButton->setObjectName(QStringLiteral("cancel"));

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(form, 1);
    layout->addWidget(m_status);
    layout->addWidget(m_buttons);

    m_inputs = {m_text, m_language, m_rate, m_pitch, m_offset, m_soundPath, choose};

    connect(m_text, &QPlainTextEdit::textChanged, this, &SayTextDialog::updateButtons);
    connect(m_soundPath, &QLineEdit::textChanged, this, &SayTextDialog::updateButtons);
    connect(choose, &QPushButton::clicked, this, &SayTextDialog::chooseSoundPath);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &SayTextDialog::start);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &SayTextDialog::reject);
    connect(m_task, &SpeechTask::progress, m_status, &JobStatus::showProgress);
    connect(m_task, &SpeechTask::finished, this, &SayTextDialog::onFinished);

    m_language->setLanguageCode(m_document->project().scriptLanguage);
    updateButtons();
}

SayTextDialog::~SayTextDialog() = default;

bool SayTextDialog::isRunning() const
{
    return m_task->isRunning();
}

QString SayTextDialog::message() const
{
    return m_status->message();
}

QString SayTextDialog::soundPath() const
{
    return QFileInfo(QDir::fromNativeSeparators(m_soundPath->text().trimmed())).absoluteFilePath();
}

void SayTextDialog::chooseSoundPath()
{
    const QString path
        = QFileDialog::getSaveFileName(this, tr("Save the Sound As"), soundPath(), tr("WAV sound (*.wav)"));
    if (!path.isEmpty())
        m_soundPath->setText(QDir::toNativeSeparators(path));
}

void SayTextDialog::updateButtons()
{
    m_startButton->setEnabled(
        !m_task->isRunning() && !m_text->toPlainText().trimmed().isEmpty() && !m_soundPath->text().trimmed().isEmpty());
}

void SayTextDialog::setRunning(bool running)
{
    for (QWidget *w : std::as_const(m_inputs))
        w->setEnabled(!running);
    m_cancelButton->setEnabled(true);
    updateButtons();
}

void SayTextDialog::start()
{
    if (m_task->isRunning() || !m_startButton->isEnabled())
        return;
    const ScriptParse parse = parseScript(m_text->toPlainText(), m_language->language());
    if (!parse.ok() || parse.script.syllables.isEmpty()) {
        m_status->showError(parse.ok() ? tr("The text has nothing to say.") : parse.error);
        Q_EMIT failed(m_status->message());
        return;
    }
    m_runPath = soundPath();
    m_runText = m_text->toPlainText();
    m_runOffset = m_offset->value();
    m_runCreatesFile = !QFileInfo::exists(m_runPath);
    TtsOptions options;
    options.rate = m_rate->value();
    options.pitch = m_pitch->value();
    const Script script = parse.script;
    const QString path = m_runPath;
    m_status->showProgress(0, tr("Speaking"));
    m_task->start([script, options, path](const SpeechProgressFn &progress, const std::atomic_bool *cancel) {
        LipsyncOutcome out;
        const TtsResult spoken = synthesize(script, options, progress, cancel);
        if (isCancelled(cancel)) {
            out.status = LipsyncStatus::Cancelled;
            return out;
        }
        if (!spoken.ok()) {
            out.error = spoken.error;
            return out;
        }
        if (!QDir().mkpath(QFileInfo(path).absolutePath())) {
            out.error = QStringLiteral("%1: cannot create its folder").arg(path);
            return out;
        }
        if (!writeAudio(path, spoken.audio, &out.error))
            return out;
        out.status = LipsyncStatus::Ok;
        out.result = lipsyncResult(script, spoken);
        return out;
    });
    setRunning(true);
}

void SayTextDialog::cancel()
{
    if (!m_task->isRunning())
        return;
    m_task->cancel();
    m_cancelButton->setEnabled(false);
    m_status->showProgress(0, tr("Cancelling…"));
}

void SayTextDialog::reject()
{
    if (m_task->isRunning()) {
        cancel();
        return;
    }
    QDialog::reject();
}

void SayTextDialog::onFinished(const LipsyncOutcome &outcome)
{
    setRunning(false);
    if (!outcome.ok()) {
        // A sound written just before the cancel is not the user's: leave no new file.
        if (m_runCreatesFile)
            QFile::remove(m_runPath);
        if (outcome.status == LipsyncStatus::Cancelled) {
            m_status->showNote(tr("Cancelled: nothing was changed."));
            Q_EMIT cancelled();
        } else {
            m_status->showError(outcome.error + QLatin1Char('\n') + tr("Nothing was changed."));
            Q_EMIT failed(m_status->message());
        }
        return;
    }
    const Animation after
        = withSpeech(m_document->animation(), outcome.result, SpeechPlacement {m_runPath, m_runOffset, m_runText});
    m_document->changeAnimation(after, tr("Say Text"));
    m_status->clear();
    Q_EMIT applied();
    accept();
}

} // namespace toonface
