#pragma once

#include <QPointF>
#include <QUndoCommand>

namespace toonface {

class Document;

// Moves one point and marks it hand-placed. While a drag runs, each mouse move pushes an
// uncommitted command that merges into the previous one of the same point; the release pushes
// a committed one, which merges too and then closes the step: one drag = one undo step.
class MovePointCommand : public QUndoCommand
{
public:
    MovePointCommand(Document *document, int index, QPointF newPos, bool commit, QUndoCommand *parent = nullptr);

    void undo() override;
    void redo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand *other) override;

    int index() const { return m_index; }
    bool isCommitted() const { return m_commit; }

private:
    Document *m_document;
    int m_index;
    QPointF m_oldPos;
    QPointF m_newPos;
    bool m_oldHandPlaced;
    bool m_commit;
};

} // namespace toonface
