#pragma once

#include <QImage>
#include <QString>

namespace toonface {

// Reads a photo for detection: EXIF orientation applied, converted to RGB32 (grayscale,
// alpha and 16-bit inputs included). Returns a null image and a message naming the file
// and the problem when it cannot be read (missing, not an image, truncated, too large).
QImage loadPhoto(const QString &path, QString *error);

} // namespace toonface
