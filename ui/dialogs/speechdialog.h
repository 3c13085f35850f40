#pragma once

#include "dialogs/speechtask.h"

#include <QDialog>

#include <optional>

class QComboBox;
class QDialogButtonBox;
class QFormLayout;
class QLayout;
class QPushButton;

namespace toonface {

class Document;
class JobStatus;

// What Lip Sync from Recording and Say Text share: a form, a button that starts speech work
// off the GUI thread (SpeechTask), a progress bar with Cancel, and the outcome. On success the
// subclass applies the result as one undo step and the dialog closes; a failure is said in the
// dialog, which stays open, and changes nothing; so does cancelling. Cancel (or Escape) while
// the work runs stops the work and keeps the dialog open; pressed again it closes.
class SpeechDialog : public QDialog
{
    Q_OBJECT

public:
    ~SpeechDialog() override;

    bool isRunning() const;
    // The message shown under the form (an error, or a note such as "cancelled"), or empty.
    QString message() const;
    // After the result was applied: what became of the new recording, for the status line
    // ("Lip Sync: speech.wav at 2.00 s, placed after ..."), else empty.
    QString outcome() const { return m_outcome; }

public Q_SLOTS:
    // What the start button does.
    void start();
    // Stops the running work; nothing is changed.
    void cancel();
    void reject() override;

Q_SIGNALS:
    // The work ended: applied (the step is on the undo stack), failed (message() says why) or
    // cancelled.
    void applied();
    void failed(const QString &message);
    void cancelled();

protected:
    SpeechDialog(Document *document, const QString &startText, QWidget *parent);

    // Lays the dialog out: `intro`, the subclass's `form`, the status and the buttons.
    // `inputs` are locked while the work runs.
    void setBody(const QString &intro, QLayout *form, const QList<QWidget *> &inputs);
    // The work to run for the form as filled in, or nullopt after fail() said what is wrong.
    virtual std::optional<SpeechTask::Job> prepare() = 0;
    // Pushes the result onto the document as one step; false after fail() said why it cannot.
    virtual bool apply(const LipsyncResult &result) = 0;
    // A run that ended without being applied (cancelled or failed).
    virtual void discard() { }
    // Whether the form is filled in enough to start.
    virtual bool canStart() const = 0;

    // Re-reads canStart(); subclasses call it when their inputs change.
    void updateButtons();
    // Says what went wrong and that nothing changed; emits failed().
    void fail(const QString &message);
    Document *document() const { return m_document; }
    // Adds the row "If other recordings play there:" (place it after them, or replace them) to
    // `form` when the audio track has clips, and its box to `inputs`.
    void addOverlapRow(QFormLayout *form, QList<QWidget *> *inputs);
    // Puts `result` on the timeline as a new clip of `path` wanted at `offset` (withSpeech, with
    // the overlap row's choice) as one step named `undoText`; sets outcome(). False after fail()
    // when it cannot go there.
    bool applySpeech(const LipsyncResult &result, const QString &path, double offset, const QString &script,
        const QString &undoText);
    JobStatus *status() const { return m_status; }

private:
    void setRunning(bool running);
    void onFinished(const LipsyncOutcome &outcome);

    Document *m_document;
    SpeechTask *m_task;
    JobStatus *m_status;
    QDialogButtonBox *m_buttons;
    QPushButton *m_startButton;
    QPushButton *m_cancelButton;
    QList<QWidget *> m_inputs;
    QComboBox *m_overlap = nullptr;
    QString m_outcome;
};

} // namespace toonface
