#pragma once

#include <QByteArray>
#include <QImage>
#include <QSize>
#include <QVector>

namespace toonface {

// An export's frames drawn once and kept, each losslessly compressed (zlib), so that the same
// export can be encoded again at another quality without drawing them again: a preset's size
// limit tries lower qualities from the frames of its first try (exportWithPreset). A cartoon's
// flat colours compress about twentyfold, so three seconds of 512-pixel frames hold a few
// megabytes, not the hundred of raw pictures.
//
// Keyed by the frames' size, first frame and count; the caller keeps the rest of the request
// (face, timeline, background) the same between the exports that share it. Not thread-safe:
// one export at a time fills or reads it.
class KeptFrames
{
public:
    // Whether it holds all `count` frames of size `size` from frame `first`.
    bool holds(QSize size, int first, int count) const;
    // Forgets what it held and starts keeping `count` frames of `size` from frame `first`.
    void restart(QSize size, int first, int count);
    // Keeps the next frame. requires: restart() called; frame.size() == the size given to it.
    void add(const QImage &frame);
    int count() const { return int(m_frames.size()); }
    // Frame i of those kept, as it was added (pixels and format).
    QImage frame(int i) const;
    // The bytes the kept frames take.
    qint64 bytes() const { return m_bytes; }

private:
    QSize m_size;
    int m_first = 0;
    int m_count = 0;
    QImage::Format m_format = QImage::Format_Invalid;
    QVector<QByteArray> m_frames;
    qint64 m_bytes = 0;
};

} // namespace toonface
