// The classic pipeline's feature edges and regions (thesis Algorithms 3.7, 4.5 and 4.6): the Sobel
// strength, its thresholds per part of the 2d x 2d square, the central vertical cut, and the
// feature regions grown from the edges.

#include "detect/classic.h"
#include "detect/classicsteps.h"
#include "detect/tsai.h"

#include <QLineF>

#include <algorithm>
#include <cmath>

namespace toonface {

namespace {

// Eq. (3.13) at an inner pixel (not on the image's one-pixel frame).
float sobelAt(const Plane &I, int x, int y)
{
    const float z1 = I.at(x - 1, y - 1), z2 = I.at(x, y - 1), z3 = I.at(x + 1, y - 1);
    const float z4 = I.at(x - 1, y), z6 = I.at(x + 1, y);
    const float z7 = I.at(x - 1, y + 1), z8 = I.at(x, y + 1), z9 = I.at(x + 1, y + 1);
    return std::abs((z7 + 2 * z8 + z9) - (z1 + 2 * z2 + z3)) + std::abs((z3 + 2 * z6 + z9) - (z1 + 2 * z4 + z7));
}

} // namespace

Plane sobelEdges(const Plane &I)
{
    Plane s {I.size, std::vector<float>(I.values.size(), 0.0f)};
    for (int y = 1; y + 1 < I.size.height(); ++y)
        for (int x = 1; x + 1 < I.size.width(); ++x)
            s.at(x, y) = sobelAt(I, x, y);
    return s;
}

FeatureEdges featureEdges(const Plane &I, QPointF leftEye, QPointF rightEye, double divEE, double divEN, double divNM)
{
    FeatureEdges out;
    out.edges = Mask {I.size, std::vector<std::uint8_t>(I.values.size(), 0)};
    const double d = QLineF(leftEye, rightEye).length();
    const QPointF mid = (leftEye + rightEye) / 2;
    const QRect square
        = QRectF(mid.x() - d, mid.y() - d / 2, 2 * d, 2 * d).toAlignedRect().intersected(QRect(QPoint(0, 0), I.size));
    out.square = square;
    if (square.isEmpty())
        return out;
    // Eq. (3.13) over the square and the columns its mirror reaches; the image's one-pixel frame is 0.
    const int mirrorLeft = int(std::lround(2 * mid.x() - square.right()));
    const int mirrorRight = int(std::lround(2 * mid.x() - square.left()));
    const int x0 = std::max(0, std::min(square.left(), mirrorLeft));
    const int x1 = std::min(I.size.width() - 1, std::max(square.right(), mirrorRight));
    const int w = x1 - x0 + 1;
    std::vector<float> raw(size_t(w) * square.height(), 0.0f);
    for (int y = square.top(); y <= square.bottom(); ++y) {
        if (y < 1 || y + 1 >= I.size.height())
            continue;
        for (int x = std::max(x0, 1); x <= std::min(x1, I.size.width() - 2); ++x)
            raw[size_t(y - square.top()) * w + (x - x0)] = sobelAt(I, x, y);
    }
    // The mirrored strength as a level per pixel of the square; the mirror column depends on x only.
    // Sobel strengths of 8-bit intensities lie in 0 .. 2040.
    constexpr int kLevels = 2041;
    std::vector<int> mirrorColumn(size_t(square.width()));
    for (int x = square.left(); x <= square.right(); ++x) {
        const int mx = int(std::lround(2 * mid.x() - x));
        mirrorColumn[size_t(x - square.left())] = mx >= x0 && mx <= x1 ? mx - x0 : -1;
    }
    std::vector<int> level(size_t(square.width()) * square.height());
    for (int y = 0; y < square.height(); ++y) {
        const float *row = raw.data() + size_t(y) * w;
        for (int i = 0; i < square.width(); ++i) {
            const int m = mirrorColumn[size_t(i)];
            const float own = row[square.left() + i - x0];
            level[size_t(y) * square.width() + i]
                = std::clamp(int(m >= 0 ? std::max(own, row[m]) : own), 0, kLevels - 1);
        }
    }
    const double cuts[5] = {double(square.top()), divEE, divEN, divNM, double(square.bottom() + 1)};
    std::vector<double> hist(kLevels);
    for (int part = 0; part < 4; ++part) {
        const int y0 = std::max(square.top(), int(std::ceil(cuts[part])));
        const int y1 = std::min(square.bottom(), int(std::ceil(cuts[part + 1])) - 1);
        std::fill(hist.begin(), hist.end(), 0.0);
        int highest = 0;
        for (int y = y0; y <= y1; ++y) {
            for (int i = 0; i < square.width(); ++i) {
                const int v = level[size_t(y - square.top()) * square.width() + i];
                hist[size_t(v)] += 1;
                highest = std::max(highest, v);
            }
        }
        const TsaiThreshold t = tsaiThreshold(hist);
        const int threshold = t.valid ? t.threshold : highest;
        out.thresholds[size_t(part)] = threshold;
        for (int y = y0; y <= y1; ++y)
            for (int i = 0; i < square.width(); ++i)
                out.edges.at(square.left() + i, y) = level[size_t(y - square.top()) * square.width() + i] > threshold;
    }
    return out;
}

void measureEdgeThresholds(const QImage &image, TrackingSeed *seed)
{
    const double d = QLineF(seed->eyeballs[0], seed->eyeballs[1]).length();
    if (image.isNull() || !(d > 0))
        return;
    // detectClassic()'s scale, and the square with a margin so that the Sobel operator sees the
    // photo around it rather than the crop's edge.
    const double scale = std::min(1.0, 640.0 / std::max(image.width(), image.height()));
    const QPointF mid = (seed->eyeballs[0] + seed->eyeballs[1]) / 2;
    const int margin = int(std::ceil(2 / scale));
    const QRect crop = QRectF(mid.x() - d, mid.y() - d / 2, 2 * d, 2 * d)
                           .toAlignedRect()
                           .adjusted(-margin, -margin, margin, margin)
                           .intersected(image.rect());
    if (crop.isEmpty())
        return;
    QImage part = image.copy(crop);
    if (scale < 1.0)
        part = part.scaled(
            QSize(std::max(1L, std::lround(part.width() * scale)), std::max(1L, std::lround(part.height() * scale))),
            Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
    auto local = [&](QPointF p) { return (p - QPointF(crop.topLeft())) * scale; };
    auto localY = [&](double y) { return (y - crop.top()) * scale; };
    const FeatureEdges e = featureEdges(intensityPlane(part), local(seed->eyeballs[0]), local(seed->eyeballs[1]),
        localY(seed->divEE), localY(seed->divEN), localY(seed->divNM));
    seed->edgeThresholds = e.thresholds;
}

int centralVerticalCut(const Plane &I, QRect region)
{
    const int x1 = region.left(), x2 = region.right(), y1 = region.top(), y2 = region.bottom();
    const int w = std::max(1, (x2 - x1) / 2); // eq. (3.14)
    auto value = [&](int x, int y) {
        return double(I.at(std::clamp(x, 0, I.size.width() - 1), std::clamp(y, 0, I.size.height() - 1)));
    };
    const int mid = (x1 + x2) / 2;
    int bestX = mid;
    double bestD = -1;
    // Steps 6.1 and 6.2: from the middle outward, left and right alternately, so ties keep
    // the cut nearest the middle.
    for (int k = 0; k <= w / 2; ++k) {
        for (int x : {mid - k, mid + k}) {
            double dx = 0;
            for (int j = y1; j <= y2; ++j)
                for (int i = 1; i <= w; ++i)
                    dx += std::abs(value(x - i, j) - value(x + i, j)); // eq. (3.15)
            if (bestD < 0 || dx < bestD) {
                bestD = dx;
                bestX = x;
            }
        }
    }
    return bestX;
}

FeatureRegion growFeature(const Mask &edges, QRect seedRect, QRect clip)
{
    FeatureRegion out;
    clip = clip.intersected(QRect(QPoint(0, 0), edges.size));
    seedRect = seedRect.intersected(clip);
    out.box = seedRect;
    if (clip.isEmpty() || seedRect.isEmpty())
        return out;
    Mask sub {clip.size(), std::vector<std::uint8_t>(size_t(clip.width()) * clip.height())};
    for (int y = 0; y < clip.height(); ++y)
        for (int x = 0; x < clip.width(); ++x)
            sub.at(x, y) = edges.at(clip.left() + x, clip.top() + y);
    std::vector<int> labels;
    const auto regions = growRegions(sub, 1, &labels);
    std::vector<bool> seeded(regions.size() + 1, false);
    for (int y = seedRect.top(); y <= seedRect.bottom(); ++y)
        for (int x = seedRect.left(); x <= seedRect.right(); ++x)
            seeded[labels[size_t(y - clip.top()) * clip.width() + (x - clip.left())]] = true;
    seeded[0] = false;
    QRect box;
    for (int y = 0; y < clip.height(); ++y) {
        for (int x = 0; x < clip.width(); ++x) {
            if (seeded[labels[size_t(y) * clip.width() + x]]) {
                const QPoint p(clip.left() + x, clip.top() + y);
                out.pixels.push_back(p);
                box = box.united(QRect(p, QSize(1, 1)));
            }
        }
    }
    if (!box.isEmpty())
        out.box = box;
    return out;
}

} // namespace toonface
