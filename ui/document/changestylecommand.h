#pragma once

#include "render/style.h"

#include <QUndoCommand>

namespace toonface {

class Document;

// Sets the drawing style (a preset, or the user's overrides) in one undoable step.
class ChangeStyleCommand : public QUndoCommand
{
public:
    ChangeStyleCommand(Document *document, const Style &style, const QString &text, QUndoCommand *parent = nullptr);

    void undo() override;
    void redo() override;
    int id() const override;

private:
    Document *m_document;
    Style m_oldStyle;
    Style m_newStyle;
};

} // namespace toonface
