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
// The result becomes a new clip on the audio track where the recording is wanted (or after the
// recordings already there, or replacing them, as the user chooses), with its syllables and
// mouth keys, as ONE undo step; then the dialog closes. The dialog starts from the clip under
// the playhead (its recording, script and place: lip-syncing it again replaces it), else
// empty at the playhead. A script that cannot fit the recording, or a file that cannot be read, is said in the dialog
// (which stays open) and changes nothing; so does cancelling.
class LipSyncDialog : public SpeechDialog
{
    Q_OBJECT

public:
    // Opens the dialog modally on `document`; true when the lip sync was applied.
    // `playhead` is where a new recording starts by default; *outcome (when given) receives
    // outcome().
    static bool run(QWidget *parent, Document *document, double playhead = 0, QString *outcome = nullptr);

    explicit LipSyncDialog(Document *document, QWidget *parent = nullptr, double playhead = 0);
    ~LipSyncDialog() override;

    // Loads a UTF-8 script file into the script box; false (with the error shown) when it
    // cannot be read.
    bool openScript(const QString &path);

Q_SIGNALS:
    // The script as it stands now was checked (its state is shown and Start is enabled or not);
    // not emitted while the check waits for the dictionary to load. The script is checked a
    // moment after typing stops.
    void scriptChecked();

protected:
    std::optional<SpeechTask::Job> prepare() override;
    bool apply(const LipsyncResult &result) override;
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
