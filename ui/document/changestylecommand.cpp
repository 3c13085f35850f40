#include "document/changestylecommand.h"

#include "document/commandid.h"
#include "document/document.h"

namespace toonface {

ChangeStyleCommand::ChangeStyleCommand(
    Document *document, const Style &style, const QString &text, QUndoCommand *parent)
    : QUndoCommand(text, parent)
    , m_document(document)
    , m_oldStyle(document->style())
    , m_newStyle(style)
{ }

void ChangeStyleCommand::undo()
{
    m_document->applyStyle(m_oldStyle);
}

void ChangeStyleCommand::redo()
{
    m_document->applyStyle(m_newStyle);
}

int ChangeStyleCommand::id() const
{
    return int(CommandId::ChangeStyle);
}

} // namespace toonface
