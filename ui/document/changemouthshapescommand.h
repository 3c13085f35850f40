#pragma once

#include "face/mouthshape.h"

#include <QUndoCommand>

namespace toonface {

class Document;

// Sets the character's nine mouth-shape presets in one undoable step; consecutive edits of
// one preset editor session (same non-zero merge id, earlier one not committed) merge.
class ChangeMouthShapesCommand : public QUndoCommand
{
public:
    ChangeMouthShapesCommand(Document *document, const MouthShapeSet &shapes, const QString &text, int mergeId,
        bool commit, QUndoCommand *parent = nullptr);

    void undo() override;
    void redo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand *other) override;

private:
    Document *m_document;
    MouthShapeSet m_before;
    MouthShapeSet m_after;
    int m_mergeId;
    bool m_commit;
};

} // namespace toonface
