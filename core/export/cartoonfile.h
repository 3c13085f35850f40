#pragma once

#include <QByteArray>
#include <QSize>
#include <QString>

namespace toonface {

// Writes a still cartoon (an SVG document) to `path`: a .svg file as it is, any other suffix
// (.png, .jpg, ...) drawn at `size` in that format; `rasterFormat` ("png") draws it whatever
// the suffix. Atomic: a failure leaves no partial file and an older file at `path` intact.
// False with *error "<path>: <problem>".
bool writeCartoonFile(
    const QByteArray &svg, QSize size, const QString &path, QString *error, const char *rasterFormat = nullptr);

} // namespace toonface
