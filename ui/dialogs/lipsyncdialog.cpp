#include "dialogs/lipsyncdialog.h"

#include "dialogs/dictionarywarmup.h"

#include "dialogs/animationedits.h"
#include "dialogs/jobstatus.h"
#include "dialogs/languagebox.h"
#include "dialogs/secondsbox.h"
#include "document/document.h"

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
#include <algorithm>

namespace toonface {

namespace {

constexpr int kScriptCheckDelayMs = 250;

} // namespace

bool LipSyncDialog::run(QWidget *parent, Document *document, double playhead, QString *outcome)
{
    LipSyncDialog dialog(document, parent, playhead);
    const bool applied = dialog.exec() == QDialog::Accepted;
    if (outcome)
        *outcome = dialog.outcome();
    return applied;
}

LipSyncDialog::LipSyncDialog(Document *document, QWidget *parent, double playhead)
    : SpeechDialog(document, tr("Lip Sync"), parent)
    , m_recording(new QLineEdit(this))
    , m_offset(new SecondsBox(this))
    , m_language(new LanguageBox(this))
    , m_script(new QPlainTextEdit(this))
    , m_scriptState(new QLabel(this))
    , m_scriptCheck(new QTimer(this))
    , m_dictionary(new DictionaryWarmUp(this))
{
    setWindowTitle(tr("Lip Sync from Recording"));
    const QString intro = tr("Aligns a recording with the script it speaks, syllable by syllable. The recording "
                             "becomes a clip on the audio track; the mouth keys and syllables where it plays are "
                             "replaced, the other recordings and the rest of the timeline are kept.");

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
    QList<QWidget *> inputs {m_recording, browse, m_offset, m_language, m_script, openScriptButton};
    addOverlapRow(form, &inputs);

    setBody(intro, form, inputs);

    m_scriptCheck->setSingleShot(true);
    m_scriptCheck->setInterval(kScriptCheckDelayMs);
    connect(m_scriptCheck, &QTimer::timeout, this, &LipSyncDialog::checkScript);
    connect(m_script, &QPlainTextEdit::textChanged, m_scriptCheck, qOverload<>(&QTimer::start));
    connect(m_language, &QComboBox::currentIndexChanged, this, &LipSyncDialog::checkScript);
    connect(m_dictionary, &DictionaryWarmUp::loaded, this, &LipSyncDialog::checkScript);
    connect(m_recording, &QLineEdit::textChanged, this, &LipSyncDialog::updateButtons);
    connect(browse, &QPushButton::clicked, this, &LipSyncDialog::browseRecording);
    connect(openScriptButton, &QPushButton::clicked, this, &LipSyncDialog::browseScript);

    // Start from the clip under the playhead (to lip-sync it again), else a new one there.
    const QVector<AudioClip> &clips = document->timeline().audioClips();
    if (const int at = document->timeline().audioClipAt(playhead); at >= 0) {
        const AudioClip &clip = clips[at];
        m_recording->setText(clip.path);
        m_offset->setValue(clip.offset);
        m_language->setLanguageCode(clip.language);
        m_script->setPlainText(clip.script);
    } else {
        m_offset->setValue(std::max(0.0, playhead));
    }
    checkScript();
}

LipSyncDialog::~LipSyncDialog() = default;

bool LipSyncDialog::openScript(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        status()->showError(tr("%1: cannot be read (%2)").arg(path, file.errorString()));
        return false;
    }
    QStringDecoder decode(QStringDecoder::Utf8);
    const QString text = decode(file.readAll());
    if (decode.hasError()) {
        status()->showError(tr("%1: not a UTF-8 text file").arg(path));
        return false;
    }
    status()->clear();
    m_script->setPlainText(text.trimmed());
    checkScript();
    return true;
}

void LipSyncDialog::browseRecording()
{
    const QString start = m_recording->text().isEmpty() ? QFileInfo(document()->filePath()).absolutePath()
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
    if (!text.trimmed().isEmpty() && !m_dictionary->ready()) {
        // Checked again when the dictionary has loaded.
        m_scriptState->setText(tr("Loading the character dictionary…"));
        m_scriptState->setStyleSheet(QString());
        updateButtons();
        return;
    }
    if (text.trimmed().isEmpty()) {
        m_scriptState->setText(tr("Type or open the script the recording speaks."));
        m_scriptState->setStyleSheet(QString());
    } else {
        const ScriptParse parse = parseScript(text, m_language->language());
        m_scriptOk = parse.ok() && !parse.script.syllables.isEmpty();
        if (parse.ok()) {
            const int n = int(parse.script.syllables.size());
            if (parse.script.language == Language::English)
                m_scriptState->setText(tr("%n word(s) in English", nullptr, n));
            else
                m_scriptState->setText(tr("%n syllable(s) in Mandarin", nullptr, n));
            m_scriptState->setStyleSheet(QString());
        } else {
            m_scriptState->setText(parse.error);
            m_scriptState->setStyleSheet(QStringLiteral("color: #b3261e;"));
        }
    }
    updateButtons();
    Q_EMIT scriptChecked();
}

bool LipSyncDialog::canStart() const
{
    return m_scriptOk && !m_recording->text().trimmed().isEmpty();
}

std::optional<SpeechTask::Job> LipSyncDialog::prepare()
{
    checkScript();
    if (!m_scriptOk)
        return std::nullopt;
    const ScriptParse parse = parseScript(m_script->toPlainText(), m_language->language());
    m_runAudio = QFileInfo(m_recording->text().trimmed()).absoluteFilePath();
    m_runScript = m_script->toPlainText();
    m_runOffset = m_offset->value();
    status()->showProgress(0, tr("Reading %1").arg(QFileInfo(m_runAudio).fileName()));
    return
        [audio = m_runAudio, script = parse.script, scriptName = tr("the script")](const SpeechProgressFn &progress,
            const std::atomic_bool *cancel) { return lipsyncRecording(audio, script, scriptName, progress, cancel); };
}

bool LipSyncDialog::apply(const LipsyncResult &result)
{
    return applySpeech(
        result, m_runAudio, m_runOffset, m_runScript, tr("Lip Sync from %1").arg(QFileInfo(m_runAudio).fileName()));
}

} // namespace toonface
