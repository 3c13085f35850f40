#pragma once

#include "detect/detector.h"
#include "io/facejson.h"

#include <QDir>
#include <QFile>
#include <QImage>
#include <QJsonDocument>
#include <QString>

#include <optional>

namespace toonface::bench {

// The face detected on `photo`, kept as DIR/NAME.json when TOONFACE_FACE_CACHE=DIR is set (a
// re-run reads it back and skips detection; a cache filled by another build of the detector
// measures that build's points). Nothing when no face is found.
inline std::optional<FaceModel> detectCached(const QImage &photo, const QString &name)
{
    const QString cache = qEnvironmentVariable("TOONFACE_FACE_CACHE");
    const QString path = cache.isEmpty() ? QString() : QDir(cache).filePath(name + QStringLiteral(".json"));
    if (!path.isEmpty()) {
        QFile f(path);
        if (f.open(QIODevice::ReadOnly)) {
            QString error;
            if (auto face = faceFromJson(QJsonDocument::fromJson(f.readAll()).object(), &error))
                return face;
        }
    }
    const DetectionResult r = detectFace(photo);
    if (r.status != DetectStatus::Ok)
        return std::nullopt;
    if (!path.isEmpty()) {
        QDir().mkpath(cache);
        QFile f(path);
        if (f.open(QIODevice::WriteOnly))
            f.write(QJsonDocument(faceToJson(r.face, name)).toJson(QJsonDocument::Compact));
    }
    return r.face;
}

} // namespace toonface::bench
