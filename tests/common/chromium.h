#pragma once

// Where headless Chromium is, for the tests that load exports in a browser.

#include <QStandardPaths>
#include <QString>

namespace toonface::test {

// The Chromium program (Debian's package chromium, or chromium-browser elsewhere); empty when
// it is not installed.
inline QString chromiumPath()
{
    QString path = QStandardPaths::findExecutable(QStringLiteral("chromium"));
    if (path.isEmpty())
        path = QStandardPaths::findExecutable(QStringLiteral("chromium-browser"));
    return path;
}

} // namespace toonface::test
