#include "dialogs/saytextdialog.h"

#include "dialogs/dictionarywarmup.h"

#include "dialogs/animationedits.h"
#include "dialogs/jobstatus.h"
#include "dialogs/languagebox.h"
#include "dialogs/secondsbox.h"
#include "document/companionfile.h"
#include "document/document.h"

#include <QCoreApplication>
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
#include <algorithm>

namespace toonface {

bool SayTextDialog::run(QWidget *parent, Document *document, double playhead, QString *outcome)
{
    SayTextDialog dialog(document, parent, playhead);
    const bool applied = dialog.exec() == QDialog::Accepted;
    if (outcome)
        *outcome = dialog.outcome();
    return applied;
}

QString SayTextDialog::defaultSoundPath(const Document &document)
{
    return companionFile(document, QStringLiteral("speech"), QStringLiteral("wav"),
        QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation));
}

SayTextDialog::SayTextDialog(Document *document, QWidget *parent, double playhead)
    : SpeechDialog(document, tr("Say"), parent)
    , m_text(new QPlainTextEdit(this))
    , m_language(new LanguageBox(this))
    , m_rate(new QSpinBox(this))
    , m_pitch(new QSpinBox(this))
    , m_offset(new SecondsBox(this))
    , m_soundPath(new QLineEdit(this))
    , m_dictionary(new DictionaryWarmUp(this))
    , m_soundNote(new QLabel(this))
{
    setWindowTitle(tr("Say Text"));
    const QString intro
        = tr("The built-in voice speaks the text and the face says it with the voice's exact "
             "timings. The speech becomes a clip on the audio track; the mouth keys and syllables where "
             "it plays are replaced, the other recordings are kept.");

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
    m_soundPath->setText(QDir::toNativeSeparators(defaultSoundPath(*document)));
    auto *choose = new QPushButton(tr("Choose…"), this);
    choose->setObjectName(QStringLiteral("chooseSound"));
    auto *soundRow = new QHBoxLayout;
    soundRow->addWidget(m_soundPath, 1);
    soundRow->addWidget(choose);
    m_soundNote->setObjectName(QStringLiteral("soundNote"));
    m_soundNote->setWordWrap(true);
    m_soundNote->setText(!document->filePath().isEmpty()
            ? tr("The sound is saved beside the project.")
            : (document->project().photoPath.isEmpty()
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

    QList<QWidget *> inputs {m_text, m_language, m_rate, m_pitch, m_offset, m_soundPath, choose};
    addOverlapRow(form, &inputs);
    m_offset->setValue(std::max(0.0, playhead));
    setBody(intro, form, inputs);

    connect(m_text, &QPlainTextEdit::textChanged, this, &SayTextDialog::updateButtons);
    connect(m_dictionary, &DictionaryWarmUp::loaded, this, &SayTextDialog::updateButtons);
    connect(m_soundPath, &QLineEdit::textChanged, this, &SayTextDialog::updateButtons);
    connect(choose, &QPushButton::clicked, this, &SayTextDialog::chooseSoundPath);

    // A new text, not the last script: its language is read from it (Chinese characters, pinyin,
    // Zhuyin or English).
    m_language->setLanguage(Language::Auto);
}

SayTextDialog::~SayTextDialog() = default;

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

bool SayTextDialog::canStart() const
{
    // (The character dictionary started loading in the background when the dialog opened.)
    return !m_text->toPlainText().trimmed().isEmpty() && !m_soundPath->text().trimmed().isEmpty();
}

std::optional<SpeechTask::Job> SayTextDialog::prepare()
{
    const ScriptParse parse = parseScript(m_text->toPlainText(), m_language->language());
    if (!parse.ok() || parse.script.syllables.isEmpty()) {
        fail(parse.ok() ? tr("The text has nothing to say.") : parse.error);
        return std::nullopt;
    }
    m_runPath = soundPath();
    m_runText = m_text->toPlainText();
    m_runOffset = m_offset->value();
    m_runCreatesFile = !QFileInfo::exists(m_runPath);
    TtsOptions options;
    options.rate = m_rate->value();
    options.pitch = m_pitch->value();
    status()->showProgress(0, tr("Speaking"));
    return [script = parse.script, options, path = m_runPath](
               const SpeechProgressFn &progress, const std::atomic_bool *cancel) {
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
            out.error
                = QCoreApplication::translate("toonface::SayTextDialog", "%1: cannot create its folder").arg(path);
            return out;
        }
        if (!writeAudio(path, spoken.audio, &out.error))
            return out;
        out.status = LipsyncStatus::Ok;
        out.result = lipsyncResult(script, spoken);
        return out;
    };
}

bool SayTextDialog::apply(const LipsyncResult &result)
{
    if (applySpeech(result, m_runPath, m_runOffset, m_runText, tr("Say Text")))
        return true;
    discard();
    return false;
}

// A sound written just before a cancel is not the user's: leave no new file.
void SayTextDialog::discard()
{
    if (m_runCreatesFile && !m_runPath.isEmpty())
        QFile::remove(m_runPath);
}

} // namespace toonface
