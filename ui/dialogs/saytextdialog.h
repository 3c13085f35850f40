#pragma once

#include "dialogs/speechdialog.h"

class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QSpinBox;

namespace toonface {

class DictionaryWarmUp;
class LanguageBox;
class SecondsBox;

// Say Text…: the built-in voice (espeak-ng; cmn-latn-pinyin for Mandarin) speaks a text. The
// sound is saved as a WAV file beside the project — or, for a project not saved yet, beside
// its photo (the dialog says which, and the user may choose another file) — and becomes a new
// clip on the audio track where the speech is wanted (by default at the playhead; after the
// recordings already there, or replacing them, as the user chooses); the mouth keys and
// syllables take the synthesizer's exact timings. One undo step. Runs off the GUI thread with a progress bar and
// Cancel; a cancelled or failed run changes nothing and leaves no new file.
class SayTextDialog : public SpeechDialog
{
    Q_OBJECT

public:
    // Opens the dialog modally on `document`; true when the speech was applied.
    // `playhead` is where the speech starts by default; *outcome (when given) receives outcome().
    static bool run(QWidget *parent, Document *document, double playhead = 0, QString *outcome = nullptr);

    explicit SayTextDialog(Document *document, QWidget *parent = nullptr, double playhead = 0);
    ~SayTextDialog() override;

    // Where the sound would be saved: beside the project, else beside the photo, else in the
    // user's documents; named after the project (or photo) and not taken yet.
    static QString defaultSoundPath(const Document &document);

    QString soundPath() const;

protected:
    std::optional<SpeechTask::Job> prepare() override;
    bool apply(const LipsyncResult &result) override;
    void discard() override;
    bool canStart() const override;

private:
    void chooseSoundPath();

    QPlainTextEdit *m_text;
    LanguageBox *m_language;
    QSpinBox *m_rate;
    QSpinBox *m_pitch;
    SecondsBox *m_offset;
    QLineEdit *m_soundPath;
    DictionaryWarmUp *m_dictionary;
    QLabel *m_soundNote;
    // What the running job was started with.
    QString m_runPath;
    QString m_runText;
    double m_runOffset = 0;
    bool m_runCreatesFile = false;
};

} // namespace toonface
