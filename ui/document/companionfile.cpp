#include "document/companionfile.h"

#include "document/document.h"

#include <QDir>
#include <QFileInfo>

namespace toonface {

namespace {

bool writableFolder(const QString &folder)
{
    const QFileInfo info(folder);
    return !folder.isEmpty() && info.isDir() && info.isWritable();
}

} // namespace

QString companionFile(const Document &document, const QString &tag, const QString &extension, const QString &fallback)
{
    QString folder;
    QString base;
    if (!document.filePath().isEmpty()) {
        const QFileInfo project(document.filePath());
        folder = project.absolutePath();
        base = project.completeBaseName();
    } else if (!document.project().photoPath.isEmpty()) {
        const QFileInfo photo(document.project().photoPath);
        folder = photo.absolutePath();
        base = photo.completeBaseName();
    }
    if (!writableFolder(folder))
        folder = fallback;
    if (!writableFolder(folder))
        folder = QDir::homePath();
    if (base.isEmpty())
        base = QStringLiteral("toonface");
    const QDir dir(folder);
    QString path = dir.absoluteFilePath(QStringLiteral("%1-%2.%3").arg(base, tag, extension));
    for (int n = 2; QFileInfo::exists(path); ++n)
        path = dir.absoluteFilePath(QStringLiteral("%1-%2-%3.%4").arg(base, tag).arg(n).arg(extension));
    return path;
}

} // namespace toonface
