// A photo as every way into Toonface reads it (loadPhoto: the format from the content, EXIF
// orientation, colour profiles, alpha, 16 bits, the size limit). A photo read is RGB32 and not
// empty; a refused one is named.

#include "fuzzinput.h"

#include "io/imageio.h"

using namespace toonface;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QString path = fuzz::scratchFile(data, size, QStringLiteral("input.photo"));
    QString error;
    const QImage image = loadPhoto(path, &error);
    if (image.isNull()) {
        TOONFACE_FUZZ_CHECK(error.contains(path));
        return 0;
    }
    TOONFACE_FUZZ_CHECK(image.format() == QImage::Format_RGB32 && image.width() > 0 && image.height() > 0);
    TOONFACE_FUZZ_CHECK(qint64(image.width()) * image.height() <= kMaxPhotoPixels);
    return 0;
}
