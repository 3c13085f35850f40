#pragma once

#include <QString>
#include <QUndoStack>

namespace toonface {

// Groups every command pushed during its lifetime into one undo step named `text`, and closes
// the group however the scope is left.
class UndoMacro
{
public:
    UndoMacro(QUndoStack *stack, const QString &text)
        : m_stack(stack)
    {
        m_stack->beginMacro(text);
    }
    ~UndoMacro() { m_stack->endMacro(); }

    UndoMacro(const UndoMacro &) = delete;
    UndoMacro &operator=(const UndoMacro &) = delete;

private:
    QUndoStack *m_stack;
};

} // namespace toonface
