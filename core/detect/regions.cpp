#include "detect/regions.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>

namespace toonface {

QImage Mask::toImage() const
{
    QImage out(size, QImage::Format_Grayscale8);
    for (int y = 0; y < size.height(); ++y) {
        uchar *row = out.scanLine(y);
        for (int x = 0; x < size.width(); ++x)
            row[x] = at(x, y) ? 255 : 0;
    }
    return out;
}

Plane intensityPlane(const QImage &image)
{
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    Plane p {rgb.size(), std::vector<float>(size_t(rgb.width()) * rgb.height())};
    for (int y = 0; y < rgb.height(); ++y) {
        const auto *row = reinterpret_cast<const QRgb *>(rgb.constScanLine(y));
        for (int x = 0; x < rgb.width(); ++x)
            p.at(x, y) = float(qRed(row[x]) + qGreen(row[x]) + qBlue(row[x])) / 3.0f;
    }
    return p;
}

namespace {

// The HSI hue angle (Gonzalez & Woods): theta = acos(((r-g)+(r-b)) / (2 sqrt((r-g)^2 + (r-b)(g-b)))),
// negated when b > g, kept signed in (-180, 180] and scaled to [-127, 128]. The same angle is
// atan2(sqrt(3) (g-b), 2r-g-b) (the numerator is its cosine side, the root its length), so it
// depends on u = g-b and v = 2r-g-b only: a table over their 511 x 1021 integer values replaces
// a trigonometric call per pixel. Filling all of it takes half a million atan2 calls (20 ms, more
// than a whole detection's regions stage, paid by the first detection of a process), while a
// photo holds a few ten thousand of those pairs: each entry is computed the first time a pixel
// needs it. Entries are atomic because detections on several threads share the table; a race
// writes the same value twice.
class HueTable
{
public:
    HueTable()
        : m_values(size_t(kU) * kV)
    {
        for (auto &v : m_values)
            v.store(kUnset, std::memory_order_relaxed);
    }
    float at(int r, int g, int b)
    {
        const int u = g - b, v = 2 * r - g - b;
        std::atomic<float> &slot = m_values[size_t(u + 255) * kV + size_t(v + 510)];
        float value = slot.load(std::memory_order_relaxed);
        if (value == kUnset) {
            const double theta = std::atan2(std::numbers::sqrt3 * u, v) * 180.0 / std::numbers::pi;
            value = float(std::clamp(theta * 255.0 / 360.0, -127.0, 128.0));
            slot.store(value, std::memory_order_relaxed);
        }
        return value;
    }

private:
    static constexpr int kU = 511, kV = 1021;
    static constexpr float kUnset = 1000.0f; // outside [-127, 128]
    std::vector<std::atomic<float>> m_values;
};

} // namespace

Plane huePlane(const QImage &image)
{
    static HueTable table;
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    Plane p {rgb.size(), std::vector<float>(size_t(rgb.width()) * rgb.height())};
    for (int y = 0; y < rgb.height(); ++y) {
        const auto *row = reinterpret_cast<const QRgb *>(rgb.constScanLine(y));
        for (int x = 0; x < rgb.width(); ++x) {
            const int r = qRed(row[x]), g = qGreen(row[x]), b = qBlue(row[x]);
            const int sum = r + g + b;
            const double s = sum > 0 ? 1.0 - 3.0 * std::min({r, g, b}) / double(sum) : 0.0;
            p.at(x, y) = s < kMinSaturation ? 128.0f : table.at(r, g, b);
        }
    }
    return p;
}

QRect centralRect(QSize size)
{
    return QRect(size.width() / 3, size.height() / 3, std::max(1, size.width() / 3), std::max(1, size.height() / 3));
}

namespace {

void meanStd(const Plane &plane, QRect rect, double *mean, double *sd)
{
    rect = rect.intersected(QRect(QPoint(0, 0), plane.size));
    double sum = 0, sum2 = 0;
    const double n = double(rect.width()) * rect.height();
    for (int y = rect.top(); y <= rect.bottom(); ++y)
        for (int x = rect.left(); x <= rect.right(); ++x)
            sum += plane.at(x, y);
    *mean = n > 0 ? sum / n : 0;
    for (int y = rect.top(); y <= rect.bottom(); ++y)
        for (int x = rect.left(); x <= rect.right(); ++x)
            sum2 += (plane.at(x, y) - *mean) * (plane.at(x, y) - *mean);
    *sd = n > 1 ? std::sqrt(sum2 / (n - 1)) : 0;
}

} // namespace

FirstLevel firstLevelThreshold(const Plane &intensity, QRect rect, double k)
{
    FirstLevel f;
    f.rect = rect.intersected(QRect(QPoint(0, 0), intensity.size));
    meanStd(intensity, f.rect, &f.m1, &f.s1);
    f.t1 = f.m1 - k * f.s1;
    f.b1 = {intensity.size, std::vector<std::uint8_t>(intensity.values.size())};
    for (size_t i = 0; i < intensity.values.size(); ++i)
        f.b1.values[i] = intensity.values[i] > f.t1 ? 1 : 0;
    return f;
}

SecondLevel secondLevelThreshold(const Plane &hue, const Mask &b1, QRect rect)
{
    SecondLevel s;
    meanStd(hue, rect, &s.m2, &s.s2);
    s.b2 = {hue.size, std::vector<std::uint8_t>(hue.values.size())};
    for (size_t i = 0; i < hue.values.size(); ++i)
        s.b2.values[i] = (std::abs(hue.values[i] - s.m2) <= s.s2 && b1.values[i]) ? 0 : 1;
    return s;
}

std::vector<Region> growRegions(const Mask &mask, std::uint8_t value, std::vector<int> *labels)
{
    const int w = mask.size.width(), h = mask.size.height();
    cv::Mat bin(h, w, CV_8U);
    for (int y = 0; y < h; ++y) {
        auto *row = bin.ptr<uchar>(y);
        for (int x = 0; x < w; ++x)
            row[x] = mask.at(x, y) == value ? 1 : 0;
    }
    cv::Mat lab, stats, centroids;
    const int n = w > 0 && h > 0 ? cv::connectedComponentsWithStats(bin, lab, stats, centroids, 8, CV_32S) : 1;
    std::vector<Region> regions;
    regions.reserve(std::max(0, n - 1));
    for (int k = 1; k < n; ++k) {
        Region r;
        r.label = k;
        r.area = stats.at<int>(k, cv::CC_STAT_AREA);
        r.box = QRect(stats.at<int>(k, cv::CC_STAT_LEFT), stats.at<int>(k, cv::CC_STAT_TOP),
            stats.at<int>(k, cv::CC_STAT_WIDTH), stats.at<int>(k, cv::CC_STAT_HEIGHT));
        r.centroid = QPointF(centroids.at<double>(k, 0), centroids.at<double>(k, 1));
        r.touchesBorder = r.box.left() == 0 || r.box.top() == 0 || r.box.right() == w - 1 || r.box.bottom() == h - 1;
        regions.push_back(r);
    }
    if (labels) {
        labels->assign(size_t(w) * h, 0);
        for (int y = 0; y < h; ++y) {
            const int *row = lab.ptr<int>(y);
            std::copy(row, row + w, labels->begin() + size_t(y) * w);
        }
    }
    return regions;
}

namespace {

// The pixels of `mask` == value that are connected to the image border.
Mask borderConnected(const Mask &mask, std::uint8_t value)
{
    std::vector<int> labels;
    const std::vector<Region> regions = growRegions(mask, value, &labels);
    Mask out {mask.size, std::vector<std::uint8_t>(mask.values.size(), 0)};
    for (size_t i = 0; i < labels.size(); ++i)
        if (labels[i] > 0 && regions[labels[i] - 1].touchesBorder)
            out.values[i] = 1;
    return out;
}

} // namespace

RefinedRegions refineRegions(const Mask &b1, const Mask &b2)
{
    RefinedRegions r;
    const Mask bgBorder = borderConnected(b2, 1); // Bg'
    r.face = {b2.size, std::vector<std::uint8_t>(b2.values.size())};
    for (size_t i = 0; i < b2.values.size(); ++i)
        r.face.values[i] = bgBorder.values[i] ? 0 : 1; // F u (Bg - Bg')
    r.b3 = {b1.size, std::vector<std::uint8_t>(b1.values.size())};
    for (size_t i = 0; i < b1.values.size(); ++i)
        r.b3.values[i] = (b1.values[i] && b2.values[i]) ? 1 : 0;
    const Mask outside = borderConnected(r.b3, 1); // H'
    r.hair = {b1.size, std::vector<std::uint8_t>(b1.values.size())};
    for (size_t i = 0; i < b1.values.size(); ++i)
        r.hair.values[i] = (!outside.values[i] && !r.face.values[i]) ? 1 : 0;
    return r;
}

} // namespace toonface
