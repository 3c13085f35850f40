#pragma once

#include <QString>

class QWidget;

namespace toonface {

class Document;
struct RecoveryFile;

// The main window's questions to the user, each a message box of its own.

// Toonface did not close properly and kept unsaved work: restore it? True to restore; false
// (discard) leaves deleting the kept copy to the caller.
bool askToRestore(QWidget *parent, const RecoveryFile &kept);

// No face was found (`reason` says why): offers to place an average face in the middle of the
// photo, to be dragged into place by hand (one undo step when accepted).
void offerAverageFace(QWidget *parent, Document *document, const QString &reason);

} // namespace toonface
