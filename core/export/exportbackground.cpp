#include "export/exportbackground.h"

#include "i18n/coretext.h"
#include "io/imageio.h"

#include <QFileInfo>

namespace toonface {

std::optional<ExportBackground> parseExportBackground(const QString &text, QString *error)
{
    const QString t = text.trimmed();
    if (t.compare(u"transparent", Qt::CaseInsensitive) == 0)
        return ExportBackground::transparent();
    if (t.compare(u"auto", Qt::CaseInsensitive) == 0)
        return ExportBackground {};
    if (!t.isEmpty() && QFileInfo(t).isFile())
        return ExportBackground::ofPhoto(t);
    // Only names and #rgb / #rrggbb: QColor also reads #aarrggbb, whose alpha would make a
    // half-transparent background that no format shows the same way.
    const bool hex = t.startsWith(QLatin1Char('#')) && (t.size() == 4 || t.size() == 7);
    if ((hex || (!t.startsWith(QLatin1Char('#')) && QColor::isValidColorName(t))) && QColor(t).isValid()) {
        QColor colour(t);
        colour.setAlpha(255);
        return ExportBackground::ofColour(colour);
    }
    if (error)
        *error = ExportText::tr("'%1' is not a background: give a colour (a name such as white, or #rrggbb), "
                                "transparent, or an existing image file")
                     .arg(text);
    return std::nullopt;
}

QImage backgroundPicture(const QString &path, QSize size, QString *error)
{
    const QImage photo = loadPhoto(path, error);
    if (photo.isNull())
        return {};
    const QImage scaled = photo.scaled(size, Qt::KeepAspectRatioByExpanding, Qt::SmoothTransformation);
    return scaled
        .copy((scaled.width() - size.width()) / 2, (scaled.height() - size.height()) / 2, size.width(), size.height())
        .convertToFormat(QImage::Format_ARGB32_Premultiplied);
}

} // namespace toonface
