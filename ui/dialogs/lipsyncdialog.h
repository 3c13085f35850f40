#pragma once

#include "dialogs/speechdialog.h"

class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QTimer;

namespace toonface {

class DictionaryWarmUp;
class LanguageBox;
class SecondsBox;

// Lip Sync from Recording…: a recording (an audio file, or a video's sound) and its script,
// typed or opened from a file, are aligned off the GUI thread with a progress bar and Cancel.
// The result replaces the mouth keys and the script's syllables in the recording's range, the
// recording becomes the timeline's sound, as ONE undo step; then the dialog closes. A script
// that cannot fit the recording, or a file that cannot be read, is said in the dialog (which
// stays open) and changes nothing; so does cancelling.
class LipSyncDialog : public SpeechDialog
{
    Q_OBJECT

public:
    // Opens the dialog modally on `document`; true when the lip sync was applied.
    static bool run(QWidget *parent, Document *document);

    explicit LipSyncDialog(Document *document, QWidget *parent = nullptr);
    ~LipSyncDialog() override;

    // Loads a UTF-8 script file into the script box; false (with the error shown) when it
    // cannot be read.
    bool openScript(const QString &path);

protected:
    std::optional<SpeechTask::Job> prepare() override;
    void apply(const LipsyncResult &result) override;
    bool canStart() const override;

private:
    void browseRecording();
    void browseScript();
    void checkScript();

    QLineEdit *m_recording;
    SecondsBox *m_offset;
    LanguageBox *m_language;
    QPlainTextEdit *m_script;
    QLabel *m_scriptState;
    QTimer *m_scriptCheck;
    DictionaryWarmUp *m_dictionary;
    bool m_scriptOk = false;
    // What the running job was started with.
    QString m_runAudio;
    QString m_runScript;
    double m_runOffset = 0;
};

} // namespace toonface
