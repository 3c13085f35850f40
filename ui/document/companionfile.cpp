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

struct Place
{
    QString folder;
    QString base; // empty when the document has neither a file nor a photo
};

// The project's folder (else the photo's) when it can be written to, else `fallback`, else home.
Place placeFor(const Document &document, const QString &fallback)
{
    Place place;
    if (!document.filePath().isEmpty()) {
        const QFileInfo project(document.filePath());
        place = {project.absolutePath(), project.completeBaseName()};
    } else if (!document.project().photoPath.isEmpty()) {
        const QFileInfo photo(document.project().photoPath);
        place = {photo.absolutePath(), photo.completeBaseName()};
    }
    if (!writableFolder(place.folder))
        place.folder = fallback;
    if (!writableFolder(place.folder))
        place.folder = QDir::homePath();
    return place;
}

} // namespace

QString companionFile(const Document &document, const QString &tag, const QString &extension, const QString &fallback)
{
    Place place = placeFor(document, fallback);
    if (place.base.isEmpty())
        place.base = QStringLiteral("toonface");
    const QDir dir(place.folder);
    QString path = dir.absoluteFilePath(QStringLiteral("%1-%2.%3").arg(place.base, tag, extension));
    for (int n = 2; QFileInfo::exists(path); ++n)
        path = dir.absoluteFilePath(QStringLiteral("%1-%2-%3.%4").arg(place.base, tag).arg(n).arg(extension));
    return path;
}

QString exportFile(
    const Document &document, const QString &extension, const QString &untitledName, const QString &fallback)
{
    const Place place = placeFor(document, fallback);
    return QDir(place.folder)
        .absoluteFilePath((place.base.isEmpty() ? untitledName : place.base) + QLatin1Char('.') + extension);
}

} // namespace toonface
