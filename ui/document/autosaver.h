#pragma once

#include <QDateTime>
#include <QList>
#include <QLockFile>
#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>

namespace toonface {

class Document;
struct LoadedFile;

// A recovery file left by an editor that ended without cleaning up (a crash, a kill).
struct RecoveryFile
{
    QString path; // the recovery .toonface
    QString originalPath; // the project it was editing, or empty for an untitled one
    QDateTime written;
};

// Every interval, writes the modified document to a recovery file (atomically, through
// saveProject), so that a crash loses at most one interval of work. Each running editor has
// its own file, guarded by a lock file it holds while it lives; a recovery file whose lock is
// free belongs to an editor that is gone, and leftovers() lists it.
//
// Lives on the GUI thread with its Document. Removes its file when the document becomes
// unmodified (saved, or another file opened) and on discard(); keeps it on destruction, so
// a crash and an ordinary destruction without discard() look the same to the next start.
class Autosaver : public QObject
{
    Q_OBJECT

public:
    // directory: where recovery files live (created when missing); see defaultDirectory().
    Autosaver(Document *document, const QString &directory, QObject *parent = nullptr);
    ~Autosaver() override;

    // Seconds between writes; 0 turns autosave off.
    void setInterval(int seconds);
    int interval() const;

    QString recoveryPath() const { return m_recoveryPath; }

    // Writes now when the document is modified and changed since the last write; returns
    // false with *error when the write failed (true when there was nothing to write).
    bool autosave(QString *error = nullptr);
    // Removes this editor's recovery file.
    void discard();

    // AppLocalDataLocation/recovery.
    static QString defaultDirectory();
    // Recovery files in `directory` that no running editor owns, newest first.
    static QList<RecoveryFile> leftovers(const QString &directory);
    // Reads a leftover (off the GUI thread if need be): the project it holds, its photo, and
    // as path the original project's path (empty for an untitled one).
    static LoadedFile load(const RecoveryFile &file);
    // Puts a loaded leftover into `document`: modified, titled after the original file.
    static void restoreInto(Document *document, const LoadedFile &loaded);
    static void remove(const RecoveryFile &file);

Q_SIGNALS:
    void written(const QString &path);
    void failed(const QString &error);

private:
    void onTimeout();
    QString infoPath() const;

    Document *m_document;
    QString m_directory;
    QString m_recoveryPath;
    std::unique_ptr<QLockFile> m_lock;
    QTimer m_timer;
    quint64 m_writtenRevision = 0;
};

} // namespace toonface
