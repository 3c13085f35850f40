#pragma once

#include <QByteArray>
#include <QFileDevice>
#include <QString>

#include <optional>

namespace toonface {

// The one rule for every file a project or a command names (photo, sound, video, layer): it
// must be a regular file. A folder, a device (/dev/zero), a pipe or a socket is refused before
// anything opens it, so nothing blocks on a FIFO or reads without end from a device.

// Why `path` is not a readable regular file ("no such file", "is a folder, not a file", "is a
// device, a pipe or a socket, not a file"); empty when it is one. Links are followed.
QString irregularFileProblem(const QString &path);

// The content of the regular file `path`, at most `maxBytes` of it: the limit is checked on the
// bytes read from the open file, not on the size the file system reports. nullopt with *problem
// (without the file's name) when the file is not regular, cannot be read or is larger.
std::optional<QByteArray> readUserFile(const QString &path, qint64 maxBytes, QString *problem);

// Why writing `file` failed, in words a user can act on: "no space left on the disk" when its
// disk is full (Qt reports that as "Unknown error" when the flush at commit fails), otherwise
// the file's own error.
QString writeProblem(const QFileDevice &file);

} // namespace toonface
