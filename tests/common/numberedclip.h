#pragma once

#include "export/videoencoder.h"

#include <QColor>
#include <QImage>
#include <QString>

// A clip whose frames show their own index as a row of black and white blocks (bit k of the
// index white or black), so a test can tell which frame a decoder delivered — through any lossy
// codec — however far into a long clip it jumped.
namespace toonface::numberedclip {

inline constexpr int kBits = 16;
inline constexpr int kBlock = 8;

inline QImage frameOf(int index)
{
    QImage image(kBits * kBlock, 2 * kBlock, QImage::Format_RGB32);
    for (int bit = 0; bit < kBits; ++bit) {
        const QColor colour = (index >> bit) & 1 ? Qt::white : Qt::black;
        for (int y = 0; y < image.height(); ++y)
            for (int x = bit * kBlock; x < (bit + 1) * kBlock; ++x)
                image.setPixelColor(x, y, colour);
    }
    return image;
}

// The index a frame of such a clip shows (read at each block's centre); -1 for another picture.
inline int indexOf(const QImage &image)
{
    if (image.width() != kBits * kBlock || image.height() != 2 * kBlock)
        return -1;
    int index = 0;
    for (int bit = 0; bit < kBits; ++bit) {
        if (qGray(image.pixel(bit * kBlock + kBlock / 2, kBlock)) > 128)
            index |= 1 << bit;
    }
    return index;
}

// Writes `frames` numbered frames at `fps` to `path` (MP4: a key frame every 2 s); the error or empty.
inline QString write(const QString &path, int frames, double fps)
{
    VideoWriter writer;
    QString error;
    if (!writer.open(path, VideoFormat::Mp4, frameOf(0).size(), fps, AudioSource {}, &error))
        return error;
    for (int i = 0; i < frames; ++i) {
        if (!writer.addFrame(frameOf(i), &error))
            return error;
    }
    return writer.finish(&error) ? QString() : error;
}

} // namespace toonface::numberedclip
