#pragma once

#include "speech/lipsync.h"

#include <QDialog>

class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QPushButton;
class QTimer;

namespace toonface {

class Document;
class JobStatus;
class LanguageBox;
class SecondsBox;
class SpeechTask;

// Lip Sync from Recording…: a recording (an audio file, or a video's sound) and its script,
// typed or opened from a file, are aligned off the GUI thread with a progress bar and Cancel.
// The result replaces the mouth keys and the script's syllables in the recording's range, the
// recording becomes the timeline's sound, as ONE undo step; then the dialog closes. A script
// that cannot fit the recording, or a file that cannot be read, is said in the dialog (which
// stays open) and changes nothing; so does cancelling.
class LipSyncDialog : public QDialog
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
    bool isRunning() const;
    // The message shown under the form (an error, or a note), empty when none.
    QString message() const;

public Q_SLOTS:
    // Starts the alignment (what the Lip Sync button does).
    void start();
    // Stops a running alignment; nothing is changed.
    void cancel();
    void reject() override;

Q_SIGNALS:
    // The alignment ended: applied (the step is on the undo stack), failed (message() says
    // why) or cancelled.
    void applied();
    void failed(const QString &message);
    void cancelled();

private:
    void browseRecording();
    void browseScript();
    void checkScript();
    void updateButtons();
    void setRunning(bool running);
    void onFinished(const LipsyncOutcome &outcome);

    Document *m_document;
    SpeechTask *m_task;
    QLineEdit *m_recording;
    SecondsBox *m_offset;
    LanguageBox *m_language;
    QPlainTextEdit *m_script;
    QLabel *m_scriptState;
    QTimer *m_scriptCheck;
    JobStatus *m_status;
    QDialogButtonBox *m_buttons;
    QPushButton *m_startButton;
    QPushButton *m_cancelButton;
    QList<QWidget *> m_inputs;
    bool m_scriptOk = false;
    // What the running job was started with.
    QString m_runAudio;
    QString m_runScript;
    double m_runOffset = 0;
};

} // namespace toonface
