#include "document/document.h"

#include "document/changeanimationcommand.h"
#include "document/changestylecommand.h"
#include "document/loadedfile.h"
#include "document/movepointcommand.h"
#include "document/replacefacecommand.h"

#include <QFileInfo>
#include <QUndoStack>

namespace toonface {

Document::Document(QObject *parent)
    : QObject(parent)
    , m_undoStack(new QUndoStack(this))
{
    connect(m_undoStack, &QUndoStack::cleanChanged, this, [this] { emitChanged(Change::FileState); });
}

Document::~Document() = default;

void Document::reset(const Project &project, const QImage &photo, const QString &filePath, bool hasFace)
{
    m_undoStack->clear();
    m_project = project;
    m_photo = photo;
    m_hasFace = hasFace;
    m_filePath = filePath;
    stampDisk();
    m_undoStack->setClean();
    emitChanged(Change::Photo | Change::Face | Change::Points | Change::Style | Change::FileState | Change::Animation
        | Change::MouthShapes);
}

void Document::open(const LoadedFile &file)
{
    Q_ASSERT(file.ok());
    reset(file.project, file.photo, file.isProject ? file.path : QString(), file.isProject);
}

bool Document::load(const QString &path, QString *error, QString *photoWarning)
{
    const LoadedFile file = loadFile(path);
    if (!file.ok()) {
        if (error)
            *error = file.error;
        return false;
    }
    if (photoWarning)
        *photoWarning = file.photoWarning;
    open(file);
    return true;
}

bool Document::save(const QString &path, QString *error)
{
    if (!saveProject(m_project, path, error))
        return false;
    m_filePath = QFileInfo(path).absoluteFilePath();
    stampDisk();
    const bool wasClean = m_undoStack->isClean();
    m_undoStack->setClean();
    if (wasClean)
        emitChanged(Change::FileState); // the path may have changed although cleanChanged did not fire
    return true;
}

void Document::stampDisk()
{
    const QFileInfo info(m_filePath);
    m_diskTime = m_filePath.isEmpty() ? QDateTime() : info.lastModified();
    m_diskSize = m_filePath.isEmpty() ? -1 : info.size();
}

bool Document::changedOnDisk() const
{
    if (m_filePath.isEmpty())
        return false;
    const QFileInfo info(m_filePath);
    return info.exists() && (info.lastModified() != m_diskTime || info.size() != m_diskSize);
}

QSize Document::canvasSize() const
{
    if (!m_photo.isNull())
        return m_photo.size();
    return m_project.face.imageSize();
}

QString Document::displayName() const
{
    if (!m_filePath.isEmpty())
        return QFileInfo(m_filePath).fileName();
    if (!m_project.photoPath.isEmpty())
        return QFileInfo(m_project.photoPath).fileName();
    return tr("Untitled");
}

QString Document::projectName() const
{
    return m_filePath.isEmpty() ? tr("Untitled project") : QFileInfo(m_filePath).fileName();
}

bool Document::isModified() const
{
    return !m_undoStack->isClean();
}

void Document::markModified()
{
    m_undoStack->resetClean();
}

void Document::movePoint(int index, QPointF pos, bool commit)
{
    Q_ASSERT(m_hasFace && index >= 0 && index < kPointCount);
    m_undoStack->push(new MovePointCommand(this, index, pos, commit));
}

void Document::replaceFace(const FaceModel &face, bool keepHandPlaced, const QString &text)
{
    m_undoStack->push(new ReplaceFaceCommand(this, face, keepHandPlaced, text));
}

void Document::changeStyle(const Style &style, const QString &text)
{
    m_undoStack->push(new ChangeStyleCommand(this, style, text));
}

Animation Document::animation() const
{
    return Animation {m_project.timeline, m_project.syllables};
}

void Document::changeAnimation(const Animation &after, const QString &text, int mergeId, bool commit)
{
    if (mergeId == 0 && after == animation())
        return;
    m_undoStack->push(
        new ChangeAnimationCommand(this, &Document::applyAnimation, animation(), after, text, mergeId, commit));
}

void Document::changeMouthShapes(const MouthShapeSet &shapes, const QString &text, int mergeId, bool commit)
{
    if (mergeId == 0 && shapes == m_project.mouthShapes)
        return;
    m_undoStack->push(new ChangeMouthShapesCommand(
        this, &Document::applyMouthShapes, m_project.mouthShapes, shapes, text, mergeId, commit));
}

void Document::applyAnimation(const Animation &animation)
{
    m_project.timeline = animation.timeline;
    m_project.syllables = animation.syllables;
    emitChanged(Change::Animation);
}

void Document::applyMouthShapes(const MouthShapeSet &shapes)
{
    m_project.mouthShapes = shapes;
    emitChanged(Change::MouthShapes);
}

void Document::applyPoint(int index, QPointF pos, bool handPlaced)
{
    m_project.face.setPoint(index, pos, handPlaced);
    emitChanged(Change::Points);
}

void Document::applyFace(const FaceModel &face, bool hasFace)
{
    m_project.face = face;
    m_hasFace = hasFace;
    emitChanged(Change::Face | Change::Points);
}

void Document::applyStyle(const Style &style)
{
    m_project.style = style;
    emitChanged(Change::Style);
}

void Document::emitChanged(ChangeFlags what)
{
    ++m_revision;
    Q_EMIT changed(what);
}

} // namespace toonface
