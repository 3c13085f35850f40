#include "document/changeanimationcommand.h"

#include "document/commandid.h"
#include "document/document.h"

namespace toonface {

ChangeAnimationCommand::ChangeAnimationCommand(
    Document *document, const Animation &after, const QString &text, int mergeId, bool commit, QUndoCommand *parent)
    : QUndoCommand(text, parent)
    , m_document(document)
    , m_before(document->animation())
    , m_after(after)
    , m_mergeId(mergeId)
    , m_commit(commit)
{ }

void ChangeAnimationCommand::undo()
{
    m_document->applyAnimation(m_before);
}

void ChangeAnimationCommand::redo()
{
    m_document->applyAnimation(m_after);
}

int ChangeAnimationCommand::id() const
{
    return int(CommandId::ChangeAnimation);
}

bool ChangeAnimationCommand::mergeWith(const QUndoCommand *other)
{
    const auto *change = static_cast<const ChangeAnimationCommand *>(other);
    if (m_commit || m_mergeId == 0 || change->m_mergeId != m_mergeId || change->m_document != m_document)
        return false;
    m_after = change->m_after;
    m_commit = change->m_commit;
    return true;
}

} // namespace toonface
