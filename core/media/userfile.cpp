#include "media/userfile.h"

#include "i18n/coretext.h"

#include <QFile>
#include <QFileInfo>

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

} // namespace toonface
