#include "dialogs/lipsyncdialog.h"

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
#include <QStringDecoder>
#include <QTimer>
#include <QVBoxLayout>

namespace toonface {

namespace {

constexpr int kScriptCheckDelayMs = 250;

} // namespace

bool LipSyncDialog::run(QWidget *parent, Document *document)
{
    LipSyncDialog dialog(document, parent);
    return dialog.exec() == QDialog::Accepted;
}

LipSyncDialog::LipSyncDialog(Document *document, QWidget *parent)
    : QDialog(parent)
    , m_document(document)
    , m_task(new SpeechTask(this))
    , m_recording(new QLineEdit(this))
    , m_offset(new SecondsBox(this))
    , m_language(new LanguageBox(this))
    , m_script(new QPlainTextEdit(this))
    , m_scriptState(new QLabel(this))
    , m_scriptCheck(new QTimer(this))
    , m_status(new JobStatus(this))
    , m_buttons(new QDialogButtonBox(this))
{
    setWindowTitle(tr("Lip Sync from Recording"));
    setMinimumWidth(600);

    auto *intro = new QLabel(tr("Aligns a recording with the script it speaks, syllable by syllable. The mouth keys "
                                "and the script's syllables where the recording plays are replaced; the rest of the "
                                "timeline is kept."),
        this);
    intro->setWordWrap(true);

    m_recording->setObjectName(QStringLiteral("recording"));
    m_recording->setPlaceholderText(tr("An audio file, or a video whose sound is used"));
    auto *browse = new QPushButton(tr("Browse…"), this);
    browse->setObjectName(QStringLiteral("browseRecording"));
    auto *recordingRow = new QHBoxLayout;
    recordingRow->addWidget(m_recording, 1);
    recordingRow->addWidget(browse);

    m_offset->setObjectName(QStringLiteral("offset"));
    m_offset->setToolTip(tr("Where the recording starts on the timeline"));
    m_language->setObjectName(QStringLiteral("language"));

    m_script->setObjectName(QStringLiteral("script"));
    m_script->setPlaceholderText(tr("Type the words spoken in the recording (Chinese characters, pinyin, Zhuyin or "
                                    "English), or open a text file."));
    m_script->setTabChangesFocus(true);
    m_script->setMinimumHeight(fontMetrics().lineSpacing() * 6);
    auto *openScriptButton = new QPushButton(tr("Open…"), this);
    openScriptButton->setObjectName(QStringLiteral("openScript"));
    m_scriptState->setObjectName(QStringLiteral("scriptState"));
    m_scriptState->setWordWrap(true);
    auto *scriptBox = new QVBoxLayout;
    scriptBox->addWidget(m_script, 1);
    auto *scriptFoot = new QHBoxLayout;
    scriptFoot->addWidget(m_scriptState, 1);
    scriptFoot->addWidget(openScriptButton, 0, Qt::AlignTop);
    scriptBox->addLayout(scriptFoot);

    auto *form = new QFormLayout;
    form->addRow(tr("&Recording:"), recordingRow);
    form->addRow(tr("&Starts at:"), m_offset);
    form->addRow(tr("&Language:"), m_language);
    form->addRow(tr("S&cript:"), scriptBox);
    static_cast<QLabel *>(form->labelForField(recordingRow))->setBuddy(m_recording);
    static_cast<QLabel *>(form->labelForField(scriptBox))->setBuddy(m_script);

    m_startButton = m_buttons->addButton(tr("Lip Sync"), QDialogButtonBox::AcceptRole);
    m_startButton->setObjectName(QStringLiteral("start"));
    m_startButton->setDefault(true);
    m_cancelButton = m_buttons->addButton(QDialogButtonBox::Cancel);
    m_cancelButton->setObjectName(QStringLiteral("cancel"));

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(form, 1);
    layout->addWidget(m_status);
    layout->addWidget(m_buttons);

    m_inputs = {m_recording, browse, m_offset, m_language, m_script, openScriptButton};

    m_scriptCheck->setSingleShot(true);
    m_scriptCheck->setInterval(kScriptCheckDelayMs);
    connect(m_scriptCheck, &QTimer::timeout, this, &LipSyncDialog::checkScript);
    connect(m_script, &QPlainTextEdit::textChanged, m_scriptCheck, qOverload<>(&QTimer::start));
    connect(m_language, &QComboBox::currentIndexChanged, this, &LipSyncDialog::checkScript);
    connect(m_recording, &QLineEdit::textChanged, this, &LipSyncDialog::updateButtons);
    connect(browse, &QPushButton::clicked, this, &LipSyncDialog::browseRecording);
    connect(openScriptButton, &QPushButton::clicked, this, &LipSyncDialog::browseScript);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &LipSyncDialog::start);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &LipSyncDialog::reject);
    connect(m_task, &SpeechTask::progress, m_status, &JobStatus::showProgress);
    connect(m_task, &SpeechTask::finished, this, &LipSyncDialog::onFinished);

    // Start from what the project has: its sound and its script.
    if (const std::optional<AudioClip> &clip = m_document->timeline().audio()) {
        m_recording->setText(clip->path);
        m_offset->setValue(clip->offset);
    }
    m_language->setLanguageCode(m_document->project().scriptLanguage);
    m_script->setPlainText(m_document->project().script);
    checkScript();
}

LipSyncDialog::~LipSyncDialog() = default;

bool LipSyncDialog::isRunning() const
{
    return m_task->isRunning();
}

QString LipSyncDialog::message() const
{
    return m_status->message();
}

bool LipSyncDialog::openScript(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        m_status->showError(tr("%1: cannot be read (%2)").arg(path, file.errorString()));
        return false;
    }
    QStringDecoder decode(QStringDecoder::Utf8);
    const QString text = decode(file.readAll());
    if (decode.hasError()) {
        m_status->showError(tr("%1: not a UTF-8 text file").arg(path));
        return false;
    }
    m_status->clear();
    m_script->setPlainText(text.trimmed());
    checkScript();
    return true;
}

void LipSyncDialog::browseRecording()
{
    const QString start = m_recording->text().isEmpty() ? QFileInfo(m_document->filePath()).absolutePath()
                                                        : QFileInfo(m_recording->text()).absolutePath();
    const QString path = QFileDialog::getOpenFileName(this, tr("Recording"), start,
        tr("Sound and video (*.wav *.flac *.mp3 *.ogg *.opus *.m4a *.aac *.mp4 *.mov *.mkv *.webm *.avi);;"
           "All files (*)"));
    if (!path.isEmpty())
        m_recording->setText(QDir::toNativeSeparators(path));
}

void LipSyncDialog::browseScript()
{
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Script"), QFileInfo(m_recording->text()).absolutePath(), tr("Text (*.txt);;All files (*)"));
    if (!path.isEmpty())
        openScript(path);
}

void LipSyncDialog::checkScript()
{
    m_scriptCheck->stop();
    const QString text = m_script->toPlainText();
    m_scriptOk = false;
    if (text.trimmed().isEmpty()) {
        m_scriptState->setText(tr("Type or open the script the recording speaks."));
        m_scriptState->setStyleSheet(QString());
    } else {
        const ScriptParse parse = parseScript(text, m_language->language());
        m_scriptOk = parse.ok() && !parse.script.syllables.isEmpty();
        if (parse.ok()) {
            const int n = int(parse.script.syllables.size());
            if (parse.script.language == Language::English)
                m_scriptState->setText(n == 1 ? tr("1 word in English") : tr("%1 words in English").arg(n));
            else
                m_scriptState->setText(n == 1 ? tr("1 syllable in Mandarin") : tr("%1 syllables in Mandarin").arg(n));
            m_scriptState->setStyleSheet(QString());
        } else {
            m_scriptState->setText(parse.error);
            m_scriptState->setStyleSheet(QStringLiteral("color: #b3261e;"));
        }
    }
    updateButtons();
}

void LipSyncDialog::updateButtons()
{
    const bool running = m_task->isRunning();
    m_startButton->setEnabled(!running && m_scriptOk && !m_recording->text().trimmed().isEmpty());
}

void LipSyncDialog::setRunning(bool running)
{
    for (QWidget *w : std::as_const(m_inputs))
        w->setEnabled(!running);
    m_cancelButton->setEnabled(true);
    updateButtons();
}

void LipSyncDialog::start()
{
    checkScript();
    if (m_task->isRunning() || !m_startButton->isEnabled())
        return;
    const ScriptParse parse = parseScript(m_script->toPlainText(), m_language->language());
    m_runAudio = QFileInfo(m_recording->text().trimmed()).absoluteFilePath();
    m_runScript = m_script->toPlainText();
    m_runOffset = m_offset->value();
    const QString audio = m_runAudio;
    const Script script = parse.script;
    const QString scriptName = tr("the script");
    m_status->showProgress(0, tr("Reading %1").arg(QFileInfo(audio).fileName()));
    m_task->start([audio, script, scriptName](const SpeechProgressFn &progress, const std::atomic_bool *cancel) {
        return lipsyncRecording(audio, script, scriptName, progress, cancel);
    });
    setRunning(true);
}

void LipSyncDialog::cancel()
{
    if (!m_task->isRunning())
        return;
    m_task->cancel();
    m_cancelButton->setEnabled(false);
    m_status->showProgress(0, tr("Cancelling…"));
}

void LipSyncDialog::reject()
{
    // Escape or Cancel while aligning stops the alignment and keeps the dialog open.
    if (m_task->isRunning()) {
        cancel();
        return;
    }
    QDialog::reject();
}

void LipSyncDialog::onFinished(const LipsyncOutcome &outcome)
{
    setRunning(false);
    switch (outcome.status) {
    case LipsyncStatus::Cancelled:
        m_status->showNote(tr("Cancelled: nothing was changed."));
        Q_EMIT cancelled();
        return;
    case LipsyncStatus::BadInput:
    case LipsyncStatus::CannotAlign:
        m_status->showError(outcome.error + QLatin1Char('\n') + tr("Nothing was changed."));
        Q_EMIT failed(m_status->message());
        return;
    case LipsyncStatus::Ok: break;
    }
    const Animation after
        = withSpeech(m_document->animation(), outcome.result, SpeechPlacement {m_runAudio, m_runOffset, m_runScript});
    m_document->changeAnimation(after, tr("Lip Sync from %1").arg(QFileInfo(m_runAudio).fileName()));
    m_status->clear();
    Q_EMIT applied();
    accept();
}

} // namespace toonface
