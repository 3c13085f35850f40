#pragma once

#include <QDir>
#include <QString>

namespace toonface::testing {

// The shared research data (photos, speech, video): TOONFACE_DATA_DIR, else the build's
// default (../shared/data). Tests that read it skip when what they need is absent.
inline QString sharedDataDir()
{
    const QString env = qEnvironmentVariable("TOONFACE_DATA_DIR");
    return env.isEmpty() ? QStringLiteral(TOONFACE_SHARED_DATA) : env;
}

// Its folder of research photos.
inline QString sharedFacesDir()
{
    return QDir(sharedDataDir()).filePath(QStringLiteral("faces"));
}

} // namespace toonface::testing
