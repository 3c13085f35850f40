#pragma once

#include "document/document.h"
#include "face/averageface.h"
#include "render/style.h"
#include "testmain.h"

#include <QCoreApplication>
#include <QImage>
#include <QPainter>
#include <QStandardPaths>
#include <QString>

// Fixtures shared by the UI tests: a synthetic photo and a face on it, made in code so that
// the tests need no data files.
namespace toonface::fixture {

inline constexpr QSize kPhotoSize(400, 500);

inline QImage photo()
{
    QImage image(kPhotoSize, QImage::Format_RGB32);
    image.fill(QColor(90, 120, 160));
    QPainter p(&image);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(70, 50, 30));
    p.drawEllipse(QRectF(80, 60, 240, 260));
    p.setBrush(QColor(230, 190, 160));
    p.drawEllipse(QRectF(100, 150, 200, 240));
    return image;
}

inline FaceModel face()
{
    return averageFace(QRectF(100, 150, 200, 240), kPhotoSize);
}

// A document holding the fixture face on the fixture photo (photoPath as given), unmodified.
inline void fill(Document &document, const QString &photoPath = {})
{
    Project project;
    project.photoPath = photoPath;
    project.face = face();
    project.style = Style::preset(QStringLiteral("normal"));
    document.reset(project, photo(), {}, true);
}

// Settings and AppLocalDataLocation in the test sandbox (~/.qttest), never the user's, and each
// suite's its own: ctest runs suites side by side, and two of them writing one settings file (the
// recent files) made each other's checks fail.
inline void isolateSettings()
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("ToonfaceTest"));
    const QString suite = toonface::test::suiteArguments().value(0);
    QCoreApplication::setApplicationName(
        suite.isEmpty() ? QStringLiteral("toonface-test") : QStringLiteral("toonface-test-%1").arg(suite));
}

} // namespace toonface::fixture
