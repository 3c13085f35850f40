#pragma once

namespace toonface {

// The ids QUndoCommand::id() returns, one per mergeable command class, so that mergeWith()
// only ever sees commands of its own kind.
enum class CommandId : int {
    MovePoint = 1,
    ReplaceFace,
    ChangeStyle,
    ChangeAnimation,
    ChangeMouthShapes,
};

} // namespace toonface
