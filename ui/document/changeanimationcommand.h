#pragma once

#include "document/animation.h"

#include <QUndoCommand>

namespace toonface {

class Document;

// Replaces the animation (timeline, syllables, script) in one undoable step. Commands pushed
// with the same non-zero merge id merge while the earlier one is not committed, so a drag that
// pushes commit = false on each move and commit = true on release is one undo step.
class ChangeAnimationCommand : public QUndoCommand
{
public:
    ChangeAnimationCommand(Document *document, const Animation &after, const QString &text, int mergeId, bool commit,
        QUndoCommand *parent = nullptr);

    void undo() override;
    void redo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand *other) override;

private:
    Document *m_document;
    Animation m_before;
    Animation m_after;
    int m_mergeId;
    bool m_commit;
};

} // namespace toonface
