#pragma once

#include <QString>
#include <QStringList>

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

// The project file was changed on disk by another program since it was opened: overwrite it,
// save under another name, or cancel.
enum class DiskConflict { Overwrite, SaveAs, Cancel };
DiskConflict askOverwriteChanged(QWidget *parent, const QString &project);

// A project from someone else names files outside its folder (`files`, "what: path"): says
// which, in a message box that does not wait (the project is open behind it), so the user
// knows what its sound, photo, video and layers will read before playing or exporting it.
void showOutsideFiles(QWidget *parent, const QString &project, const QStringList &files);

} // namespace toonface
