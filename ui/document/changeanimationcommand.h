#pragma once

#include "document/animation.h"
#include "document/commandid.h"
#include "face/mouthshape.h"

#include <QUndoCommand>

namespace toonface {

class Document;

// Replaces one value of the document (the animation, the mouth-shape presets) in one undoable
// step, keeping the values before and after. Commands of the same kind pushed with the same
// non-zero merge id merge while the earlier one is not committed, so a drag that pushes
// commit = false on each move and commit = true on release is one undo step.
template<typename Value, CommandId Id>
class ReplaceValueCommand : public QUndoCommand
{
public:
    using Apply = void (Document::*)(const Value &);

    ReplaceValueCommand(Document *document, Apply apply, Value before, Value after, const QString &text, int mergeId,
        bool commit, QUndoCommand *parent = nullptr)
        : QUndoCommand(text, parent)
        , m_document(document)
        , m_apply(apply)
        , m_before(std::move(before))
        , m_after(std::move(after))
        , m_mergeId(mergeId)
        , m_commit(commit)
    { }

    void undo() override { (m_document->*m_apply)(m_before); }
    void redo() override { (m_document->*m_apply)(m_after); }
    int id() const override { return int(Id); }
    bool mergeWith(const QUndoCommand *other) override
    {
        const auto *change = static_cast<const ReplaceValueCommand *>(other);
        if (m_commit || m_mergeId == 0 || change->m_mergeId != m_mergeId || change->m_document != m_document)
            return false;
        m_after = change->m_after;
        m_commit = change->m_commit;
        return true;
    }

private:
    Document *m_document;
    Apply m_apply;
    Value m_before;
    Value m_after;
    int m_mergeId;
    bool m_commit;
};

using ChangeAnimationCommand = ReplaceValueCommand<Animation, CommandId::ChangeAnimation>;
using ChangeMouthShapesCommand = ReplaceValueCommand<MouthShapeSet, CommandId::ChangeMouthShapes>;

} // namespace toonface
