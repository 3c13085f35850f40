#pragma once

#include "face/facemodel.h"

#include <QUndoCommand>

namespace toonface {

class Document;

// Replaces the face's points in one undoable step: a (re-)detection result or the average
// face placed for manual work. With keepHandPlaced, points the user placed by hand stay
// (FaceModel::mergeDetection); on a document without a face, the new face is taken whole.
class ReplaceFaceCommand : public QUndoCommand
{
public:
    ReplaceFaceCommand(Document *document, const FaceModel &face, bool keepHandPlaced, const QString &text,
        QUndoCommand *parent = nullptr);

    void undo() override;
    void redo() override;
    int id() const override;

private:
    Document *m_document;
    FaceModel m_oldFace;
    bool m_hadFace;
    FaceModel m_newFace;
};

} // namespace toonface
