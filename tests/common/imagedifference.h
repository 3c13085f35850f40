#pragma once

#include <QImage>
#include <QRect>

#include <cstdlib>

namespace toonface::testing {

// The mean absolute difference per colour channel (0..255) of two images inside `box` (the
// whole images when it is null): 255 when an image is null, or when no box is given and their
// sizes differ; 0 when the box lies outside them.
inline double meanDifference(const QImage &a, const QImage &b, QRect box = {})
{
    if (a.isNull() || b.isNull())
        return 255;
    if (box.isNull()) {
        if (a.size() != b.size())
            return 255;
        box = a.rect();
    }
    const QRect r = box.intersected(a.rect()).intersected(b.rect());
    if (r.isEmpty())
        return 0;
    const QImage x = a.convertToFormat(QImage::Format_RGB32);
    const QImage y = b.convertToFormat(QImage::Format_RGB32);
    double sum = 0;
    for (int j = r.top(); j <= r.bottom(); ++j) {
        const QRgb *p = reinterpret_cast<const QRgb *>(x.constScanLine(j));
        const QRgb *q = reinterpret_cast<const QRgb *>(y.constScanLine(j));
        for (int i = r.left(); i <= r.right(); ++i) {
            sum += std::abs(qRed(p[i]) - qRed(q[i])) + std::abs(qGreen(p[i]) - qGreen(q[i]))
                + std::abs(qBlue(p[i]) - qBlue(q[i]));
        }
    }
    return sum / (3.0 * r.width() * r.height());
}

} // namespace toonface::testing
