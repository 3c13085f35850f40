#include "media/userfile.h"

#include "i18n/coretext.h"

#include <QFile>
#include <QFileInfo>
#include <QStorageInfo>

namespace toonface {

QString irregularFileProblem(const QString &path)
{
    const QFileInfo info(path);
    if (path.isEmpty() || !info.exists())
        return ProjectText::tr("no such file");
    if (info.isDir())
        return ProjectText::tr("is a folder, not a file");
    if (!info.isFile())
        return ProjectText::tr("is a device, a pipe or a socket, not a file");
    return {};
}

std::optional<QByteArray> readUserFile(const QString &path, qint64 maxBytes, QString *problem)
{
    if (QString why = irregularFileProblem(path); !why.isEmpty()) {
        *problem = why;
        return std::nullopt;
    }
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *problem = ProjectText::tr("cannot read: %1").arg(file.errorString());
        return std::nullopt;
    }
    // One byte past the limit tells a file of exactly the limit from a larger one.
    QByteArray content = file.read(maxBytes + 1);
    if (content.size() > maxBytes) {
        *problem = ProjectText::tr("too large (more than %1 MB)").arg(maxBytes >> 20);
        return std::nullopt;
    }
    if (file.error() != QFileDevice::NoError) {
        *problem = ProjectText::tr("cannot read: %1").arg(file.errorString());
        return std::nullopt;
    }
    return content;
}

QString writeProblem(const QFileDevice &file)
{
    const QFileInfo info(file.fileName());
    const QStorageInfo disk(info.absolutePath());
    // Less than a block free is a full disk, whatever the error says.
    if (disk.isValid() && disk.bytesAvailable() < 64 * 1024)
        return ProjectText::tr("no space left on the disk (%1 KB free on %2)")
            .arg(disk.bytesAvailable() / 1024)
            .arg(disk.rootPath());
    const QString said = file.errorString();
    if (said.isEmpty() || said == QLatin1StringView("Unknown error"))
        return ProjectText::tr("the system gave no reason (is the disk full or removed?)");
    return said;
}

} // namespace toonface
