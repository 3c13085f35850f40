#pragma once

// An 8-bit grey image as dlib's generic image interface wants it, viewing pixels that
// belong to someone else (a QImage, rows padded to bytesPerLine) without copying. Private to
// core/detect: only the files that hand images to dlib include it.

#include <dlib/image_processing/generic_image.h>

#include <QImage>

namespace toonface {

struct GrayView
{
    const unsigned char *data = nullptr;
    long rows = 0;
    long cols = 0;
    long stride = 0;
};

inline GrayView viewOf(const QImage &gray)
{
    return {gray.constBits(), gray.height(), gray.width(), long(gray.bytesPerLine())};
}

inline long num_rows(const GrayView &v)
{
    return v.rows;
}
inline long num_columns(const GrayView &v)
{
    return v.cols;
}
inline const void *image_data(const GrayView &v)
{
    return v.data;
}
inline long width_step(const GrayView &v)
{
    return v.stride;
}

} // namespace toonface

namespace dlib {
template<>
struct image_traits<toonface::GrayView>
{
    using pixel_type = unsigned char;
};
} // namespace dlib
