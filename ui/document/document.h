#pragma once

#include "document/animation.h"
#include "io/project.h"

#include <QDateTime>
#include <QFlags>
#include <QImage>
#include <QObject>
#include <QString>

class QUndoStack;

namespace toonface {

struct LoadedFile;

// What a change touched, so that each view repaints only what it shows.
enum class Change : unsigned {
    Points = 0x01, // one or more points moved (or their hand-placed flags changed)
    Face = 0x02, // the whole face was replaced or removed (implies Points)
    Style = 0x04, // the drawing style
    Photo = 0x08, // the photo (a new document)
    FileState = 0x10, // file path or modified state
    Animation = 0x20, // the timeline, its audio track (clips and their scripts) or the syllables
    MouthShapes = 0x40, // the character's mouth-shape presets
};
Q_DECLARE_FLAGS(ChangeFlags, Change)
Q_DECLARE_OPERATORS_FOR_FLAGS(ChangeFlags)

// The open project in the editor: owns the Project, the loaded photo and the undo stack.
// Every user edit is a command on undoStack(); views observe changed() and read the state
// from here, holding no copies of it. The modified state is the undo stack's clean state.
//
// Lives on the GUI thread; not thread-safe. Background work copies what it needs from here
// and hands its result back as a command.
class Document : public QObject
{
    Q_OBJECT

public:
    explicit Document(QObject *parent = nullptr);
    ~Document() override;

    // Replaces the whole state (opening a photo or a project): clears the undo history and
    // leaves the document unmodified. `hasFace` is false for a photo not yet detected.
    void reset(const Project &project, const QImage &photo, const QString &filePath, bool hasFace);

    // Takes an opened file (see loadFile()): a project keeps its path and face; a photo starts
    // a new, untitled document without a face.
    void open(const LoadedFile &file);
    // loadFile() + open(), on the calling thread. A project whose photo cannot be read still
    // opens (*photoWarning says why the photo is absent); other failures return false.
    bool load(const QString &path, QString *error, QString *photoWarning = nullptr);

    // Writes the project atomically to `path`, which becomes filePath(); marks the document
    // unmodified. Requires hasFace().
    bool save(const QString &path, QString *error);

    const Project &project() const { return m_project; }
    const FaceModel &face() const { return m_project.face; }
    const Style &style() const { return m_project.style; }
    const Timeline &timeline() const { return m_project.timeline; }
    const QVector<LipsyncSyllable> &syllables() const { return m_project.syllables; }
    const MouthShapeSet &mouthShapes() const { return m_project.mouthShapes; }
    // The timeline (with its audio track) and the syllables as one value (what changeAnimation() replaces).
    Animation animation() const;
    bool hasFace() const { return m_hasFace; }
    const QImage &photo() const { return m_photo; }
    // The drawing's size: the photo's, else the face's image size.
    QSize canvasSize() const;

    QString filePath() const { return m_filePath; }
    // Whether the project file was written by someone else (another editor, a sync tool) since
    // this document opened or last saved it: its time or size on disk differ from then. The
    // window asks before overwriting such a file.
    bool changedOnDisk() const;
    // What messages about the face name: the project file's name, else the photo's, else "Untitled".
    QString displayName() const;
    // The document's name for the title bar: the project file's name, else "Untitled project"
    // (a photo is never written, so it is not what the title names).
    QString projectName() const;
    bool isModified() const;
    // Marks the document as modified although its history is clean (a restored recovery file
    // holds edits the file on disk does not).
    void markModified();

    QUndoStack *undoStack() const { return m_undoStack; }
    // Counts every change; autosave writes only when it moved since the last write.
    quint64 revision() const { return m_revision; }

    // User edits: each pushes one command.
    // While dragging push commit = false for each move and commit = true on release, so that
    // one drag is one undo step. The point becomes hand-placed.
    void movePoint(int index, QPointF pos, bool commit);
    // Re-detection or manual placement: replaces the points (keeping hand-placed ones when
    // keepHandPlaced is true and a face is present) in one undoable step.
    void replaceFace(const FaceModel &face, bool keepHandPlaced, const QString &text);
    void changeStyle(const Style &style, const QString &text);
    // Replaces the animation in one undoable step. While dragging, push commit = false for each
    // move and commit = true on release with one non-zero mergeId for the drag: the moves merge
    // into one step. mergeId 0 never merges. Pushes nothing when `after` equals the current
    // animation and no drag is under way.
    void changeAnimation(const Animation &after, const QString &text, int mergeId = 0, bool commit = true);
    void changeMouthShapes(const MouthShapeSet &shapes, const QString &text, int mergeId = 0, bool commit = true);

    // Applied by the commands only; each emits changed().
    void applyPoint(int index, QPointF pos, bool handPlaced);
    void applyFace(const FaceModel &face, bool hasFace);
    void applyStyle(const Style &style);
    void applyAnimation(const Animation &animation);
    void applyMouthShapes(const MouthShapeSet &shapes);

Q_SIGNALS:
    void changed(toonface::ChangeFlags what);

private:
    void emitChanged(ChangeFlags what);

    Project m_project;
    QImage m_photo;
    bool m_hasFace = false;
    QString m_filePath;
    QDateTime m_diskTime; // the project file's modification time when opened or saved
    qint64 m_diskSize = -1;
    void stampDisk();
    QUndoStack *m_undoStack;
    quint64 m_revision = 0;
};

} // namespace toonface
