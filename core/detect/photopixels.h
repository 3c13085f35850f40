#pragma once

// What the appearance's finders (appearance.cpp, glassesfind.cpp, facialhairfind.cpp) share: a
// photo's pixels read by box and profile, and small statistics over them. Private to core/detect.

#include "detect/appearance.h"
#include "detect/skintone.h"

#include <QColor>
#include <QImage>
#include <QRectF>

#include <algorithm>
#include <cmath>
#include <vector>

namespace toonface {

constexpr double kEdgeFloor = 2.0; // luma units: the texture floor of perfectly smooth skin

// A photo in RGB32, read by pixel, by box and by edge profiles.
class Pixels
{
public:
    explicit Pixels(const QImage &photo)
        : m_image(photo.convertToFormat(QImage::Format_RGB32))
    { }
    int height() const { return m_image.height(); }
    bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < m_image.width() && y < m_image.height(); }
    QRgb at(int x, int y) const { return reinterpret_cast<const QRgb *>(m_image.constScanLine(y))[x]; }
    double luma(int x, int y) const { return lumaOf(at(x, y)); }

    // The pixels of an axis-aligned box (clipped to the photo).
    std::vector<QRgb> box(QRectF r) const
    {
        std::vector<QRgb> out;
        r = r.normalized();
        const int x0 = std::max(0, int(std::floor(r.left()))), x1 = std::min(m_image.width() - 1, int(r.right()));
        const int y0 = std::max(0, int(std::floor(r.top()))), y1 = std::min(m_image.height() - 1, int(r.bottom()));
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x)
                out.push_back(at(x, y));
        }
        return out;
    }

    // The mean of |d luma / dy| along each row of the box (horizontal edges), top to bottom.
    std::vector<double> rowEdges(QRectF r) const
    {
        std::vector<double> rows;
        r = r.normalized();
        const int x0 = std::max(0, int(std::floor(r.left()))), x1 = std::min(m_image.width() - 1, int(r.right()));
        const int y0 = std::max(1, int(std::floor(r.top()))), y1 = std::min(m_image.height() - 2, int(r.bottom()));
        for (int y = y0; y <= y1; ++y) {
            double sum = 0;
            int n = 0;
            for (int x = x0; x <= x1; ++x, ++n)
                sum += std::abs(luma(x, y + 1) - luma(x, y - 1)) / 2.0;
            if (n > 0)
                rows.push_back(sum / n);
        }
        return rows;
    }

    // The mean of |d luma / dx| down each column of the box (vertical edges), left to right.
    std::vector<double> columnEdges(QRectF r) const
    {
        std::vector<double> columns;
        r = r.normalized();
        const int x0 = std::max(1, int(std::floor(r.left()))), x1 = std::min(m_image.width() - 2, int(r.right()));
        const int y0 = std::max(0, int(std::floor(r.top()))), y1 = std::min(m_image.height() - 1, int(r.bottom()));
        for (int x = x0; x <= x1; ++x) {
            double sum = 0;
            int n = 0;
            for (int y = y0; y <= y1; ++y, ++n)
                sum += std::abs(luma(x + 1, y) - luma(x - 1, y)) / 2.0;
            if (n > 0)
                columns.push_back(sum / n);
        }
        return columns;
    }

    // The mean luma gradient's size (|d/dx| + |d/dy|) over the box: how textured it is.
    double texture(QRectF r) const
    {
        r = r.normalized();
        const int x0 = std::max(1, int(std::floor(r.left()))), x1 = std::min(m_image.width() - 2, int(r.right()));
        const int y0 = std::max(1, int(std::floor(r.top()))), y1 = std::min(m_image.height() - 2, int(r.bottom()));
        double sum = 0;
        int n = 0;
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x, ++n)
                sum += (std::abs(luma(x + 1, y) - luma(x - 1, y)) + std::abs(luma(x, y + 1) - luma(x, y - 1))) / 2.0;
        }
        return n > 0 ? sum / n : 0.0;
    }

    // The share of the box's pixels brighter, or darker, than all eight neighbours by more than
    // `contrast` luma units: the fine light and dark points of hair strands finer than a pixel.
    double speckle(QRectF r, double contrast) const
    {
        r = r.normalized();
        const int x0 = std::max(1, int(std::floor(r.left()))), x1 = std::min(m_image.width() - 2, int(r.right()));
        const int y0 = std::max(1, int(std::floor(r.top()))), y1 = std::min(m_image.height() - 2, int(r.bottom()));
        int n = 0, points = 0;
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x, ++n) {
                const double c = luma(x, y);
                double lo = 1e9, hi = -1e9;
                for (int dy = -1; dy <= 1; ++dy) {
                    for (int dx = -1; dx <= 1; ++dx) {
                        if (dx == 0 && dy == 0)
                            continue;
                        const double v = luma(x + dx, y + dy);
                        lo = std::min(lo, v);
                        hi = std::max(hi, v);
                    }
                }
                points += c > hi + contrast || c < lo - contrast;
            }
        }
        return n > 0 ? double(points) / n : 0.0;
    }

    bool covers(QRectF r) const { return QRectF(m_image.rect()).contains(r.normalized()); }

private:
    QImage m_image;
};

QColor median(std::vector<QRgb> px);
// The darkest `share` of the pixels, as their median colour.
QColor darkest(std::vector<QRgb> px, double share);
QRectF around(QPointF c, double rx, double ry);
double percentile(std::vector<double> v, double q);

// haircolour.h's reading of facial hair, whose strands lie over the skin: of the pixels unlike the skin, those with
// less chroma than it (hair is less red than the skin it grows from; a pixel of strands blended
// with the skin between them is not), else as the head's hair.
HairColourReading readFacialHairColour(const std::vector<QRgb> &sample, const QColor &skin);
// Glasses (a frame's rims and bridge, glassesfind.cpp) and facial hair (facialhairfind.cpp) on a
// face upright in `px`; both read out->evidence, measured before.
void findGlasses(const Pixels &px, const FaceModel &face, double es0, double skinLuma, AppearanceFindings *out);
// `skin` (the skin's colour) is what the facial hair's colour is read against.
void findFacialHair(const Pixels &px, const FaceModel &face, double es0, double skinLuma, bool colourless,
    const QColor &skin, AppearanceFindings *out);

} // namespace toonface
