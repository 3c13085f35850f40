#pragma once

#include "anim/timeline.h"
#include "export/epubbook.h"

#include <QDialog>
#include <QFutureWatcher>
#include <QTemporaryDir>

#include <atomic>
#include <memory>

class QAction;
class QComboBox;
class QDialogButtonBox;
class QLineEdit;
class QPushButton;

namespace toonface {

class Document;
class JobStatus;

// Export Read-aloud Book…: a text (plain or Markdown) read by a recording of it or by the
// built-in voice, its language, title and author, what is highlighted, how the face moves (an
// animated drawing or a video of each page), and the book's file; the
// book is made in the background (exportBook through QtConcurrent) with progress and Cancel, and
// nothing is left behind when it is cancelled or fails.
//
// Takes everything by value (a BookRequest with the face, style, mouth shapes and layers, and
// the initial recording and file), so it depends on no document. A project whose audio track
// holds several recordings (or a trimmed one) is read by that whole track: "Read by" offers
// "The project's audio track (N recordings, mixed)", chosen by default, and the clips are mixed
// (media/audiomix.h) in the background before the book is made.
class BookDialog : public QDialog
{
    Q_OBJECT

public:
    explicit BookDialog(const BookRequest &base, QWidget *parent = nullptr);
    ~BookDialog() override;

    // Shows the dialog modally; returns the path written, or an empty string when nothing was.
    static QString run(QWidget *parent, const BookRequest &base);
    // The File menu's action: opens the dialog for the document's face and recording.
    static QAction *createAction(QWidget *window, Document *document);

    // The project's audio track (its clips); when it is more than one whole recording, "Read by"
    // offers it, mixed, and chooses it.
    void setProjectTrack(const QVector<AudioClip> &clips);
    // Where the mixed track is written when the book is read by it (valid during the dialog).
    QString mixedTrackPath() const;

    // The request the controls describe now (for the mixed track: mixedTrackPath()).
    BookRequest request() const;
    bool isRunning() const;
    const BookResult &lastResult() const { return m_result; }
    QString exportedPath() const { return m_exported; }

    // Starts making the book as the Export button does; false when one is running or the text or
    // the file is missing.
    bool start();
    void cancel();
    void reject() override;

    // The controls, for tests and callers that fill them in.
    QLineEdit *textEdit() const { return m_text; }
    QLineEdit *audioEdit() const { return m_audio; }
    QLineEdit *outputEdit() const { return m_output; }
    QComboBox *sourceBox() const { return m_source; }
    QComboBox *faceMediaBox() const { return m_faceMedia; }
    JobStatus *status() const { return m_status; }

Q_SIGNALS:
    // After each run, with lastResult() set.
    void finished();

private:
    void browse(QLineEdit *edit, const QString &filter, bool save);
    void updateControls();
    void bookFinished();
    bool readByTrack() const;
    bool readByRecording() const;

    BookRequest m_base;
    QLineEdit *m_text;
    QComboBox *m_source;
    QLineEdit *m_audio;
    QPushButton *m_audioBrowse;
    QComboBox *m_language;
    QLineEdit *m_title;
    QLineEdit *m_author;
    QComboBox *m_highlight;
    QComboBox *m_faceMedia;
    QLineEdit *m_output;
    JobStatus *m_status;
    QDialogButtonBox *m_buttons;
    QPushButton *m_export;
    QFutureWatcher<BookResult> m_watcher;
    std::shared_ptr<std::atomic_bool> m_cancel;
    BookResult m_result;
    QString m_exported;
    QVector<AudioClip> m_trackClips; // the project's clips to mix, or empty
    QTemporaryDir m_mixDir;
};

} // namespace toonface
