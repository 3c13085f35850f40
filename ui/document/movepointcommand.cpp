#include "document/movepointcommand.h"

#include "document/commandid.h"
#include "document/document.h"
#include "views/displaynames.h"

#include <QCoreApplication>

namespace toonface {

MovePointCommand::MovePointCommand(Document *document, int index, QPointF newPos, bool commit, QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_document(document)
    , m_index(index)
    , m_oldPos(document->face().point(index))
    , m_newPos(newPos)
    , m_oldHandPlaced(document->face().isHandPlaced(index))
    , m_commit(commit)
{
    setText(QCoreApplication::translate("MovePointCommand", "Move %1").arg(pointTitle(index)));
}

void MovePointCommand::undo()
{
    m_document->applyPoint(m_index, m_oldPos, m_oldHandPlaced);
}

void MovePointCommand::redo()
{
    m_document->applyPoint(m_index, m_newPos, true);
}

int MovePointCommand::id() const
{
    return int(CommandId::MovePoint);
}

bool MovePointCommand::mergeWith(const QUndoCommand *other)
{
    const auto *move = static_cast<const MovePointCommand *>(other);
    if (m_commit || move->m_index != m_index || move->m_document != m_document)
        return false;
    m_newPos = move->m_newPos;
    m_commit = move->m_commit;
    return true;
}

} // namespace toonface
