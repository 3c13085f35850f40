#include "export/keptframes.h"

#include <cstring>

namespace toonface {

bool KeptFrames::holds(QSize size, int first, int count) const
{
    return size == m_size && first == m_first && count == m_count && m_frames.size() == count;
}

void KeptFrames::restart(QSize size, int first, int count)
{
    m_size = size;
    m_first = first;
    m_count = count;
    m_format = QImage::Format_Invalid;
    m_frames.clear();
    m_bytes = 0;
}

void KeptFrames::add(const QImage &frame)
{
    if (m_format == QImage::Format_Invalid)
        m_format = frame.format();
    const QImage same = frame.format() == m_format ? frame : frame.convertToFormat(m_format);
    // The rows without their padding: the frame is rebuilt at its own bytes per line.
    const qsizetype row = qsizetype(same.width()) * same.depth() / 8;
    QByteArray raw(row * same.height(), Qt::Uninitialized);
    for (int y = 0; y < same.height(); ++y)
        std::memcpy(raw.data() + row * y, same.constScanLine(y), size_t(row));
    // Level 1: the fastest; higher levels gain little on flat colours and cost the render's time.
    m_frames.append(qCompress(raw, 1));
    m_bytes += m_frames.constLast().size();
}

QImage KeptFrames::frame(int i) const
{
    const QByteArray raw = qUncompress(m_frames.at(i));
    QImage image(m_size, m_format);
    const qsizetype row = qsizetype(image.width()) * image.depth() / 8;
    if (raw.size() != row * image.height())
        return {};
    for (int y = 0; y < image.height(); ++y)
        std::memcpy(image.scanLine(y), raw.constData() + row * y, size_t(row));
    return image;
}

} // namespace toonface
