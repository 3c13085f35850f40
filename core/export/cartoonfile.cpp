#include "export/cartoonfile.h"

#include "render/svgface.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QImage>
#include <QSaveFile>

namespace toonface {

namespace {

// The context of this file's messages in the translations.
struct CartoonFile
{
    Q_DECLARE_TR_FUNCTIONS(toonface::CartoonFile)
};

bool failed(QString *error, const QString &text)
{
    if (error)
        *error = text;
    return false;
}

} // namespace

bool writeCartoonFile(const QByteArray &svg, QSize size, const QString &path, QString *error, const char *rasterFormat)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return failed(error, CartoonFile::tr("%1: cannot write: %2").arg(path, file.errorString()));
    const QString suffix = rasterFormat ? QString::fromLatin1(rasterFormat) : QFileInfo(path).suffix();
    if (suffix.isEmpty())
        return failed(error, CartoonFile::tr("%1: no image format: give the file a suffix (.svg, .png)").arg(path));
    if (suffix.compare(QLatin1StringView("svg"), Qt::CaseInsensitive) == 0) {
        if (file.write(svg) != svg.size())
            return failed(error, CartoonFile::tr("%1: cannot write: %2").arg(path, file.errorString()));
    } else {
        const QImage image = rasterizeSvg(svg, size);
        if (image.isNull())
            return failed(error, CartoonFile::tr("%1: the cartoon could not be drawn").arg(path));
        if (!image.save(&file, suffix.toLatin1().constData()))
            return failed(error, CartoonFile::tr("%1: cannot encode the image as %2").arg(path, suffix));
    }
    if (!file.commit())
        return failed(error, CartoonFile::tr("%1: cannot write: %2").arg(path, file.errorString()));
    return true;
}

} // namespace toonface
