#include "render/colourbalance.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace toonface {

namespace {

constexpr int kMeasureSide = 320; // the estimate runs on a copy this large at most
constexpr double kEdgeNorm = 6.0; // Minkowski norm of the edge strengths (shades of grey)
constexpr double kGreyChroma = 3.0; // mean |r-g| + |g-b| below this: a greyscale photo
constexpr int kClipped = 250; // pixels this bright in a channel are clipped: no information

QColor mixRgb(QColor a, QColor b, double t)
{
    return QColor::fromRgbF(float(a.redF() + (b.redF() - a.redF()) * t),
        float(a.greenF() + (b.greenF() - a.greenF()) * t), float(a.blueF() + (b.blueF() - a.blueF()) * t));
}

QColor ramp(const std::array<std::pair<int, QColor>, 5> &stops, int grey)
{
    if (grey <= stops.front().first)
        return stops.front().second;
    for (size_t i = 1; i < stops.size(); ++i) {
        if (grey <= stops[i].first) {
            const double t = double(grey - stops[i - 1].first) / double(stops[i].first - stops[i - 1].first);
            return mixRgb(stops[i - 1].second, stops[i].second, t);
        }
    }
    return stops.back().second;
}

} // namespace

ColourBalance ColourBalance::measure(const QImage &photo, const QRectF &region)
{
    ColourBalance b;
    if (photo.isNull())
        return b;
    QImage small = photo.convertToFormat(QImage::Format_RGB32);
    if (!region.isEmpty()) {
        const QRect r = region.toAlignedRect().intersected(small.rect());
        if (r.width() >= 8 && r.height() >= 8)
            small = small.copy(r);
    }
    if (std::max(small.width(), small.height()) > kMeasureSide)
        small = small.scaled(kMeasureSide, kMeasureSide, Qt::KeepAspectRatio, Qt::SmoothTransformation);
    const int w = small.width(), h = small.height();
    double chroma = 0;
    std::array<double, 3> sum {};
    long count = 0;
    for (int y = 0; y < h; ++y) {
        const auto *line = reinterpret_cast<const QRgb *>(small.constScanLine(y));
        const auto *next = y + 1 < h ? reinterpret_cast<const QRgb *>(small.constScanLine(y + 1)) : nullptr;
        for (int x = 0; x < w; ++x) {
            const QRgb p = line[x];
            chroma += std::abs(qRed(p) - qGreen(p)) + std::abs(qGreen(p) - qBlue(p));
            if (!next || x + 1 >= w)
                continue;
            const QRgb r = line[x + 1], d = next[x];
            const int c[3] = {qRed(p), qGreen(p), qBlue(p)};
            const int cr[3] = {qRed(r), qGreen(r), qBlue(r)};
            const int cd[3] = {qRed(d), qGreen(d), qBlue(d)};
            bool clipped = false;
            for (int k = 0; k < 3; ++k)
                clipped = clipped || std::max({c[k], cr[k], cd[k]}) >= kClipped;
            if (clipped)
                continue;
            for (int k = 0; k < 3; ++k)
                sum[k] += std::pow(std::hypot(double(cr[k] - c[k]), double(cd[k] - c[k])), kEdgeNorm);
            ++count;
        }
    }
    b.greyscale = chroma / std::max(1, w * h) < kGreyChroma;
    if (b.greyscale || count == 0)
        return b;
    std::array<double, 3> e {};
    for (int k = 0; k < 3; ++k)
        e[k] = std::pow(sum[k] / double(count), 1.0 / kEdgeNorm);
    if (e[0] <= 0 || e[1] <= 0 || e[2] <= 0)
        return b;
    const double mean = (e[0] + e[1] + e[2]) / 3.0;
    double gains[3];
    for (int k = 0; k < 3; ++k)
        gains[k] = std::clamp(mean / e[k], 1.0 / kMaxGain, kMaxGain);
    const double norm = (gains[0] + gains[1] + gains[2]) / 3.0;
    for (int k = 0; k < 3; ++k)
        b.gain[k] = gains[k] / norm;
    return b;
}

QColor ColourBalance::apply(const QColor &c) const
{
    if (!c.isValid())
        return c;
    auto ch = [](double v) { return std::clamp(int(std::lround(v)), 0, 255); };
    QColor out(ch(c.red() * gain[0]), ch(c.green() * gain[1]), ch(c.blue() * gain[2]));
    out.setAlpha(c.alpha());
    return out;
}

QImage ColourBalance::apply(const QImage &photo) const
{
    QImage out = photo.convertToFormat(QImage::Format_RGB32);
    if (isIdentity())
        return out;
    std::array<std::array<uchar, 256>, 3> lut {};
    for (int k = 0; k < 3; ++k) {
        for (int v = 0; v < 256; ++v)
            lut[k][v] = uchar(std::clamp(int(std::lround(v * gain[k])), 0, 255));
    }
    for (int y = 0; y < out.height(); ++y) {
        auto *line = reinterpret_cast<QRgb *>(out.scanLine(y));
        for (int x = 0; x < out.width(); ++x) {
            const QRgb p = line[x];
            line[x] = qRgb(lut[0][qRed(p)], lut[1][qGreen(p)], lut[2][qBlue(p)]);
        }
    }
    return out;
}

QColor skinFromGrey(int grey)
{
    // Skin tones of every kind, by lightness: deep brown, brown, tan, light, pale.
    static const std::array<std::pair<int, QColor>, 5> stops
        = {{{45, QColor(0x5a, 0x3a, 0x2a)}, {95, QColor(0x8d, 0x5b, 0x3f)}, {145, QColor(0xc0, 0x8a, 0x68)},
            {195, QColor(0xe8, 0xbc, 0x9c)}, {240, QColor(0xf8, 0xe0, 0xcc)}}};
    return ramp(stops, grey);
}

QColor hairFromGrey(int grey)
{
    // Dark shades are brown-black to brown; light ones are grey and white hair, kept so.
    static const std::array<std::pair<int, QColor>, 5> stops
        = {{{30, QColor(0x1e, 0x17, 0x12)}, {80, QColor(0x4a, 0x34, 0x24)}, {120, QColor(0x7a, 0x62, 0x4e)},
            {170, QColor(0xa8, 0xa4, 0xa0)}, {230, QColor(0xee, 0xec, 0xea)}}};
    return ramp(stops, grey);
}

} // namespace toonface
