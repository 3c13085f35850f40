#include "document/changemouthshapescommand.h"

#include "document/commandid.h"
#include "document/document.h"

namespace toonface {

ChangeMouthShapesCommand::ChangeMouthShapesCommand(Document *document, const MouthShapeSet &shapes, const QString &text,
    int mergeId, bool commit, QUndoCommand *parent)
    : QUndoCommand(text, parent)
    , m_document(document)
    , m_before(document->mouthShapes())
    , m_after(shapes)
    , m_mergeId(mergeId)
    , m_commit(commit)
{ }

void ChangeMouthShapesCommand::undo()
{
    m_document->applyMouthShapes(m_before);
}

void ChangeMouthShapesCommand::redo()
{
    m_document->applyMouthShapes(m_after);
}

int ChangeMouthShapesCommand::id() const
{
    return int(CommandId::ChangeMouthShapes);
}

bool ChangeMouthShapesCommand::mergeWith(const QUndoCommand *other)
{
    const auto *change = static_cast<const ChangeMouthShapesCommand *>(other);
    if (m_commit || m_mergeId == 0 || change->m_mergeId != m_mergeId || change->m_document != m_document)
        return false;
    m_after = change->m_after;
    m_commit = change->m_commit;
    return true;
}

} // namespace toonface
