#include "document/replacefacecommand.h"

#include "document/commandid.h"
#include "document/document.h"

namespace toonface {

ReplaceFaceCommand::ReplaceFaceCommand(
    Document *document, const FaceModel &face, bool keepHandPlaced, const QString &text, QUndoCommand *parent)
    : QUndoCommand(text, parent)
    , m_document(document)
    , m_oldFace(document->face())
    , m_hadFace(document->hasFace())
    , m_newFace(face)
{
    if (m_hadFace) {
        m_newFace = m_oldFace;
        m_newFace.mergeDetection(face, keepHandPlaced);
    }
}

void ReplaceFaceCommand::undo()
{
    m_document->applyFace(m_oldFace, m_hadFace);
}

void ReplaceFaceCommand::redo()
{
    m_document->applyFace(m_newFace, true);
}

int ReplaceFaceCommand::id() const
{
    return int(CommandId::ReplaceFace);
}

} // namespace toonface
