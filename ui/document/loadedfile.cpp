#include "document/loadedfile.h"

#include "io/imageio.h"

#include <QCoreApplication>
#include <QFileInfo>

namespace toonface {

bool isProjectPath(const QString &path)
{
    return QFileInfo(path).suffix().compare(QLatin1StringView("toonface"), Qt::CaseInsensitive) == 0;
}

LoadedFile loadFile(const QString &path)
{
    LoadedFile result;
    result.path = QFileInfo(path).absoluteFilePath();
    result.isProject = isProjectPath(path);
    if (result.isProject) {
        QString error;
        std::optional<Project> project = loadProject(result.path, &error);
        if (!project) {
            result.error = error;
            return result;
        }
        result.project = *project;
        result.outsideFiles = filesOutsideFolder(result.project, QFileInfo(result.path).absolutePath());
        if (!result.project.photoPath.isEmpty())
            result.photo = loadPhoto(result.project.photoPath, &result.photoWarning);
        return result;
    }
    QString error;
    result.photo = loadPhoto(result.path, &error);
    if (result.photo.isNull()) {
        result.error = error.isEmpty()
            ? QCoreApplication::translate("toonface", "%1: not a readable image").arg(result.path)
            : error;
        return result;
    }
    result.project.photoPath = result.path;
    result.project.style = Style::preset(QStringLiteral("normal"));
    result.project.face = FaceModel(result.photo.size());
    return result;
}

} // namespace toonface
