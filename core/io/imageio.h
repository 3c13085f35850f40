#pragma once

#include <QImage>
#include <QString>

namespace toonface {

// Larger photos are refused before decoding (a 100-megapixel RGB32 image is 400 MB).
inline constexpr qint64 kMaxPhotoPixels = 100'000'000;

// Reads a photo for detection: EXIF orientation applied, converted to RGB32 (grayscale,
// alpha and 16-bit inputs included; transparency is composited on white; an embedded colour
// profile other than sRGB is converted to sRGB). Returns a null image and a message naming the
// file and the problem when it cannot be read (missing, not an image, truncated or corrupt,
// more than kMaxPhotoPixels pixels, empty). The format is recognised from the content, not the
// file name. Reentrant.
QImage loadPhoto(const QString &path, QString *error);

} // namespace toonface
