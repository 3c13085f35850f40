// The classic pipeline's eye-pair search (thesis 3.3.3-3.4.1): eq. (3.5), the pairing rules, the
// face checks of a pair, and the eyeball in an eye region.

#include "detect/classic.h"

#include <QLineF>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace toonface {

double eyePairScore(double area1, double area2)
{
    if (area1 < area2)
        std::swap(area1, area2);
    const double s = area2 > 0 ? area1 / area2 : 1e9;
    return (area1 * area2 - s * s) / 2.0;
}

namespace {

double boxArea(const Region &r)
{
    return double(r.box.width()) * r.box.height();
}

bool passesFilter(const Region &r, QSize size, const EyePairRules &rules)
{
    const double aspect = double(r.box.width()) / r.box.height();
    return !r.touchesBorder && r.area >= rules.minAreaFraction * size.width() * size.height()
        && r.box.width() <= rules.maxWidthFraction * size.width() && aspect >= rules.minAspect
        && aspect <= rules.maxAspect && r.area >= rules.minFill * boxArea(r);
}

} // namespace

std::vector<EyePairCandidate> eyePairCandidates(
    const std::vector<Region> &dark, QSize imageSize, const EyePairRules &rules)
{
    std::vector<int> kept;
    for (int i = 0; i < int(dark.size()); ++i)
        if (passesFilter(dark[i], imageSize, rules))
            kept.push_back(i);
    std::vector<EyePairCandidate> pairs;
    const double maxTan = std::tan(rules.maxSkewDegrees * std::numbers::pi / 180.0);
    for (size_t a = 0; a < kept.size(); ++a) {
        for (size_t b = a + 1; b < kept.size(); ++b) {
            const Region &ra = dark[kept[a]], &rb = dark[kept[b]];
            const double big = std::max(boxArea(ra), boxArea(rb)), small = std::min(boxArea(ra), boxArea(rb));
            if (big > rules.maxAreaRatio * small)
                continue;
            const QPointF delta = rb.centroid - ra.centroid;
            const double dist = std::hypot(delta.x(), delta.y());
            const double width = std::max(ra.box.width(), rb.box.width());
            if (dist < rules.minDistanceInWidths * width || dist > rules.maxDistanceInWidths * width)
                continue;
            if (std::abs(delta.y()) > maxTan * std::abs(delta.x()))
                continue;
            EyePairCandidate c;
            c.left = delta.x() >= 0 ? kept[a] : kept[b];
            c.right = delta.x() >= 0 ? kept[b] : kept[a];
            pairs.push_back(c);
        }
    }
    // Eq. (3.5) needs the areas normalised: by the largest box area among the paired regions.
    double norm = 0;
    for (const auto &c : pairs)
        norm = std::max({norm, boxArea(dark[c.left]), boxArea(dark[c.right])});
    for (auto &c : pairs)
        c.score = eyePairScore(boxArea(dark[c.left]) / norm, boxArea(dark[c.right]) / norm);
    std::stable_sort(pairs.begin(), pairs.end(), [](const auto &x, const auto &y) { return x.score > y.score; });
    return pairs;
}

bool isRingShaped(const Region &region, const std::vector<int> &labels, QSize imageSize)
{
    const QRect box = region.box;
    if (box.width() < 3 || box.height() < 3)
        return false;
    // The other pixels of the box that cannot reach the box's edge without crossing the region.
    Mask other {box.size(), std::vector<std::uint8_t>(size_t(box.width()) * box.height())};
    for (int y = 0; y < box.height(); ++y)
        for (int x = 0; x < box.width(); ++x)
            other.at(x, y) = labels[size_t(box.top() + y) * imageSize.width() + box.left() + x] != region.label;
    int enclosed = 0;
    for (const Region &r : growRegions(other, 1))
        if (!r.touchesBorder)
            enclosed += r.area;
    return enclosed >= region.area;
}

Plane skinRelativeIntensity(const Plane &I, int featureSize)
{
    Plane out {I.size, std::vector<float>(I.values.size())};
    if (I.values.empty())
        return out;
    const int k = std::max(3, featureSize | 1);
    const cv::Mat src(I.size.height(), I.size.width(), CV_32F, const_cast<float *>(I.values.data()));
    cv::Mat skin;
    cv::morphologyEx(src, skin, cv::MORPH_CLOSE, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(k, k)),
        cv::Point(-1, -1), 1, cv::BORDER_REPLICATE);
    for (int y = 0; y < I.size.height(); ++y) {
        const float *s = skin.ptr<float>(y);
        for (int x = 0; x < I.size.width(); ++x)
            out.at(x, y) = 255.0f * I.at(x, y) / std::max(s[x], 1.0f);
    }
    return out;
}

double darknessContrast(const Plane &I, const Region &region, const std::vector<int> &labels)
{
    const QRect box = region.box;
    const QRect frame
        = box.adjusted(-box.width() / 2 - 1, -box.height() / 2 - 1, box.width() / 2 + 1, box.height() / 2 + 1)
              .intersected(QRect(QPoint(0, 0), I.size));
    double inside = 0, outside = 0;
    int nIn = 0, nOut = 0;
    for (int y = frame.top(); y <= frame.bottom(); ++y) {
        for (int x = frame.left(); x <= frame.right(); ++x) {
            if (labels[size_t(y) * I.size.width() + x] == region.label) {
                inside += I.at(x, y);
                ++nIn;
            } else if (!box.contains(x, y)) {
                outside += I.at(x, y);
                ++nOut;
            }
        }
    }
    if (nIn == 0 || nOut == 0)
        return 0;
    return outside / nOut - inside / nIn;
}

bool eyePairInFace(const Mask &F, QPointF left, QPointF right, PairReach *reach)
{
    PairReach r;
    const double d = QLineF(left, right).length();
    const QPointF mid = (left + right) / 2;
    auto inFace = [&](QPointF p) {
        const int x = int(std::lround(p.x())), y = int(std::lround(p.y()));
        return F.contains(x, y) && F.at(x, y);
    };
    // Steps of one pixel from the midpoint while F holds, in d.
    auto walk = [&](QPointF step) {
        int n = 0;
        const int maxSteps = int(std::ceil(3 * d));
        while (n < maxSteps && inFace(mid + (n + 1) * step))
            ++n;
        return n / d;
    };
    if (d > 0 && inFace(mid)) {
        const QPointF along = (right - left) / d;
        const QPointF perp(-along.y(), along.x());
        r.below = walk(perp.y() >= 0 ? perp : -perp);
        r.side = std::min(walk(along), walk(-along));
    }
    if (reach)
        *reach = r;
    return r.below >= kMinReachBelow && r.side >= kMinReachSide && r.side <= kMaxReachSide;
}

double mouthRowContrast(const Plane &I, QPointF left, QPointF right, double *darkestRow)
{
    if (darkestRow)
        *darkestRow = 0;
    const double d = QLineF(left, right).length();
    if (d <= 0)
        return 0;
    const QPointF mid = (left + right) / 2;
    const QPointF along = (right - left) / d;
    QPointF down(-along.y(), along.x());
    if (down.y() < 0)
        down = -down;
    std::vector<double> rows;
    std::vector<int> offsets;
    const int half = std::max(1, int(std::lround(0.4 * d)));
    for (int t = int(std::floor(0.7 * d)); t <= int(std::ceil(1.5 * d)); ++t) {
        double sum = 0;
        int n = 0;
        for (int s = -half; s <= half; ++s) {
            const QPointF p = mid + t * down + s * along;
            const int x = int(std::lround(p.x())), y = int(std::lround(p.y()));
            if (I.contains(x, y)) {
                sum += I.at(x, y);
                ++n;
            }
        }
        if (n > half) { // rows mostly outside the image say nothing
            rows.push_back(sum / n);
            offsets.push_back(t);
        }
    }
    if (rows.size() < 3)
        return 0;
    std::vector<double> sorted = rows;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    const double median = sorted[sorted.size() / 2];
    const auto darkest = std::min_element(rows.begin(), rows.end());
    if (darkestRow)
        *darkestRow = offsets[size_t(darkest - rows.begin())];
    return median > 0 ? (median - *darkest) / median : 0;
}

Eyeball detectEyeball(const Mask &dark, QRect box, double minFill)
{
    box = box.intersected(QRect(QPoint(0, 0), dark.size));
    Eyeball best;
    if (box.isEmpty())
        return best;
    best.centre = QRectF(box).center();
    const int maxR = std::max(1, std::min(box.width(), box.height()) / 2 + 1);
    for (int r = 1; r <= maxR; ++r) {
        int bestCount = -1, total = 0;
        QPoint bestCentre;
        for (int dy = -r; dy <= r; ++dy)
            for (int dx = -r; dx <= r; ++dx)
                total += dx * dx + dy * dy <= r * r;
        for (int cy = box.top(); cy <= box.bottom(); ++cy) {
            for (int cx = box.left(); cx <= box.right(); ++cx) {
                int count = 0;
                for (int dy = -r; dy <= r; ++dy)
                    for (int dx = -r; dx <= r; ++dx)
                        if (dx * dx + dy * dy <= r * r && dark.contains(cx + dx, cy + dy) && dark.at(cx + dx, cy + dy))
                            ++count;
                if (count > bestCount) {
                    bestCount = count;
                    bestCentre = QPoint(cx, cy);
                }
            }
        }
        if (bestCount < minFill * total)
            break;
        best.centre = bestCentre;
        best.radius = r;
    }
    return best;
}

} // namespace toonface
