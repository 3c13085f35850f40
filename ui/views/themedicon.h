#pragma once

#include <QIcon>
#include <QString>

namespace toonface {

// The desktop theme's icon `themeName` (freedesktop naming), else the project's own SVG
// `:/toonface/icons/<bundledFile>` (resources/icons/, listed in ui/CMakeLists.txt).
inline QIcon themedIcon(const char *themeName, const char *bundledFile)
{
    return QIcon::fromTheme(
        QString::fromLatin1(themeName), QIcon(QStringLiteral(":/toonface/icons/") + QString::fromLatin1(bundledFile)));
}

} // namespace toonface
