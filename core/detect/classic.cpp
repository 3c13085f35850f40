#include "detect/classic.h"

#include "detect/tsai.h"
#include "i18n/coretext.h"

#include <QElapsedTimer>
#include <QLineF>
#include <QPainter>
#include <QStringList>

#include <algorithm>
#include <cmath>
#include <functional>
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

void cheekOffset(const Mask &F, QPointF mid, double d, double *left, double *right)
{
    const QSize size = F.size;
    const int y0 = std::max(0, int(mid.y() - d / 2)), y1 = std::min(size.height() - 1, int(mid.y() + 1.5 * d));
    std::vector<double> proj(size.width(), 0.0);
    for (int y = y0; y <= y1; ++y)
        for (int x = 0; x < size.width(); ++x)
            proj[x] += F.at(x, y);
    auto sym = [&](int k) {
        const int xl = int(std::lround(mid.x())) - k, xr = int(std::lround(mid.x())) + k;
        return (xl >= 0 && xl < size.width() ? proj[xl] : 0.0) + (xr >= 0 && xr < size.width() ? proj[xr] : 0.0);
    };
    const double reference = sym(int(0.5 * d));
    int bestK = int(1.5 * d);
    for (int k = int(0.5 * d); k <= int(1.5 * d); ++k) {
        if (sym(k) <= 0.5 * reference) {
            bestK = k;
            break;
        }
    }
    *left = std::lround(mid.x()) - bestK;
    *right = std::lround(mid.x()) + bestK;
}

namespace {

// The pixels of the edge components that reach into `seedRect`, kept inside `clip`.
struct FeatureRegion
{
    QRect box;
    std::vector<QPoint> pixels;
};

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

QPointF averageOf(const std::vector<QPoint> &pixels, const std::function<bool(QPoint)> &keep, QPointF fallback)
{
    QPointF sum;
    int n = 0;
    for (const QPoint &p : pixels) {
        if (keep(p)) {
            sum += p;
            ++n;
        }
    }
    return n ? sum / n : fallback;
}

// The average of the column centres (x, mean y of the column's pixels) over columns [a, b].
QPointF columnCentres(const std::vector<QPoint> &pixels, int a, int b, QPointF fallback)
{
    QPointF sum;
    int n = 0;
    for (int x = a; x <= b; ++x) {
        double ys = 0;
        int k = 0;
        for (const QPoint &p : pixels)
            if (p.x() == x) {
                ys += p.y();
                ++k;
            }
        if (k) {
            sum += QPointF(x, ys / k);
            ++n;
        }
    }
    return n ? sum / n : fallback;
}

// The thesis' "w" of Algorithms 4.2-4.5 (how many end columns or top rows are averaged) is
// not given: an eighth of the region.
int endColumns(const QRect &box)
{
    return std::max(1, int(std::lround(box.width() / 8.0)));
}

bool inMask(const Mask &m, QPointF p)
{
    const int x = int(std::lround(p.x())), y = int(std::lround(p.y()));
    return m.contains(x, y) && m.at(x, y);
}

// Walks from `start` by `step` while inside `m`; returns the first point outside, or
// `fallback` when `maxSteps` pass first or the image ends.
QPointF leave(const Mask &m, QPointF start, QPointF step, int maxSteps, QPointF fallback, bool *found = nullptr)
{
    QPointF p = start;
    for (int i = 0; i < maxSteps; ++i) {
        p += step;
        const int x = int(std::lround(p.x())), y = int(std::lround(p.y()));
        if (!m.contains(x, y))
            break;
        if (!m.at(x, y)) {
            if (found)
                *found = true;
            return p;
        }
    }
    if (found)
        *found = false;
    return fallback;
}

QImage maskImage(const Mask &m, QColor on, QColor off)
{
    QImage img(m.size, QImage::Format_RGB32);
    for (int y = 0; y < m.size.height(); ++y) {
        auto *row = reinterpret_cast<QRgb *>(img.scanLine(y));
        for (int x = 0; x < m.size.width(); ++x)
            row[x] = m.at(x, y) ? on.rgb() : off.rgb();
    }
    return img;
}

} // namespace

ClassicResult detectClassic(const QImage &input, bool withDebugImages, QRect faceHint)
{
    ClassicResult res;
    QElapsedTimer total, stage;
    total.start();
    stage.start();
    auto lap = [&](const char *name) {
        res.timingMs.insert(QString::fromLatin1(name), stage.nsecsElapsed() / 1e6);
        stage.restart();
    };
    if (input.isNull() || input.width() < 16 || input.height() < 16) {
        res.error = DetectText::tr("The image is too small for the classic method.");
        return res;
    }
    // The pipeline works on a copy at most 640 pixels on its longer side; points go back to
    // the input's pixels at the end.
    const double scale = std::min(1.0, 640.0 / std::max(input.width(), input.height()));
    const QImage image
        = (scale < 1.0 ? input.scaled(QSize(std::lround(input.width() * scale), std::lround(input.height() * scale)),
               Qt::IgnoreAspectRatio, Qt::SmoothTransformation)
                       : input)
              .convertToFormat(QImage::Format_RGB32);
    const QSize size = image.size();

    const Plane I = intensityPlane(image);
    const Plane H = huePlane(image);
    const QRectF hint = faceHint.isValid()
        ? QRectF(faceHint.x() * scale, faceHint.y() * scale, faceHint.width() * scale, faceHint.height() * scale)
        : QRectF();
    // Algorithm 4.1 assumes the face covers the central rectangle. Deviation for real photos
    // (thesis 3.3.2): when no eye pair found with it passes the face check below, the same
    // rectangle is tried higher up the central column (its centre at 1/3, then 1/4 of the
    // height), as portraits frame the face at or above the middle. With a face hint only the
    // middle of the hint is used.
    std::vector<QRect> rects;
    if (hint.isValid()) {
        rects.push_back(
            QRectF(hint.x() + hint.width() / 4, hint.y() + hint.height() / 4, hint.width() / 2, hint.height() / 2)
                .toAlignedRect()
                .intersected(QRect(QPoint(0, 0), size)));
    } else {
        const QRect c = centralRect(size);
        rects.push_back(c);
        for (double centreY : {1.0 / 3.0, 1.0 / 4.0}) {
            const QRect r = c.translated(0, int(std::lround(centreY * size.height())) - c.center().y());
            if (r.top() >= 0 && r != rects.back())
                rects.push_back(r);
        }
    }
    lap("hsi");

    // One try of sections 3.3.2-3.3.5 with one central rectangle and one darkness level k.
    struct Attempt
    {
        bool valid = false;
        QRect rect;
        double k = 1;
        FirstLevel first;
        SecondLevel second;
        RefinedRegions refined;
        std::vector<int> darkLabels;
        std::vector<Region> dark;
        std::vector<EyePairCandidate> candidates, eyes;
    };
    Attempt chosen, thesisChoice;
    double regionsMs = 0, eyePairMs = 0;
    for (const QRect &rect : rects) {
        QElapsedTimer t;
        t.start();
        Attempt a;
        a.rect = rect;
        a.first = firstLevelThreshold(I, rect);
        a.second = secondLevelThreshold(H, a.first.b1, rect);
        a.refined = refineRegions(a.first.b1, a.second.b2);
        regionsMs += t.nsecsElapsed() / 1e6;
        t.restart();
        // Eye pairs on B1 of eq. (3.3) first; where the eyes merge with brows or hair there (real
        // photos, dark make-up), again on stricter darkness levels t = m1 - k s1, k = 1.5, 2, 2.5:
        // the eyes are the darkest features of a face and separate first.
        for (double k : {1.0, 1.5, 2.0, 2.5}) {
            a.k = k;
            const Mask eyeB1 = k > 1.0 ? firstLevelThreshold(I, rect, k).b1 : a.first.b1;
            a.dark = growRegions(eyeB1, 0, &a.darkLabels);
            a.candidates = eyePairCandidates(a.dark, size);
            // Beyond Chan's rules (3.2): a region that is not clearly darker than its surround (a
            // patch of dark clothing or background that the threshold cut into pieces) is no
            // eye; "clearly": by half the spread s1 of the central rectangle's intensity. A loop
            // wider than 0.6 of the pair's spacing is a spectacle rim (lenses nearly meet at the
            // bridge, ~0.8 of the spacing wide), while an eye outlined by its lids is a loop
            // about 0.45 of it wide.
            std::vector<int> verdict(a.dark.size(), -1), ring(a.dark.size(), -1);
            auto eyeLike = [&](int i) {
                if (verdict[i] < 0)
                    verdict[i] = darknessContrast(I, a.dark[i], a.darkLabels) >= 0.5 * a.first.s1;
                return verdict[i] == 1;
            };
            auto rim = [&](int i, double spacing) {
                if (ring[i] < 0)
                    ring[i] = isRingShaped(a.dark[i], a.darkLabels, size);
                return ring[i] == 1 && a.dark[i].box.width() > 0.6 * spacing;
            };
            std::erase_if(a.candidates, [&](const EyePairCandidate &c) {
                const double spacing = QLineF(a.dark[c.left].centroid, a.dark[c.right].centroid).length();
                return !eyeLike(c.left) || !eyeLike(c.right) || rim(c.left, spacing) || rim(c.right, spacing);
            });
            if (hint.isValid()) {
                const QRectF upper(hint.x(), hint.y(), hint.width(), 0.6 * hint.height());
                std::erase_if(a.candidates, [&](const EyePairCandidate &c) {
                    return !upper.contains(a.dark[c.left].centroid) || !upper.contains(a.dark[c.right].centroid);
                });
            }
            // Knowledge beyond eq. (3.5): brows and spectacle rims pair as well as eyes do and are
            // larger, so a pair gives way to a pair that lies just below it (as wide apart, 0.7 ..
            // 1.3 times; 0.1 d .. 0.7 d lower, horizontally aligned) or inside its two boxes.
            a.eyes.clear();
            for (const auto &c : a.candidates) {
                const QPointF pa = a.dark[c.left].centroid, pb = a.dark[c.right].centroid;
                const double dist = QLineF(pa, pb).length();
                bool hasBelow = false;
                for (const auto &o : a.candidates) {
                    const QPointF oa = a.dark[o.left].centroid, ob = a.dark[o.right].centroid;
                    auto below = [&](QPointF top, QPointF bottom) {
                        return bottom.y() - top.y() > 0.1 * dist && bottom.y() - top.y() < 0.7 * dist
                            && std::abs(bottom.x() - top.x()) < 0.3 * dist;
                    };
                    if (&o == &c)
                        continue;
                    // A pair nested in this one's boxes (eyes inside spectacle rims, whose
                    // centroids lie farther apart, out toward the temples) wins at any spacing.
                    const bool inside
                        = QRectF(a.dark[c.left].box).contains(oa) && QRectF(a.dark[c.right].box).contains(ob);
                    const double ratio = QLineF(oa, ob).length() / std::max(dist, 1e-9);
                    if (inside || (ratio >= 0.7 && ratio <= 1.3 && below(pa, oa) && below(pb, ob)))
                        hasBelow = true;
                }
                if (!hasBelow)
                    a.eyes.push_back(c);
            }
            if (a.eyes.empty())
                continue;
            a.valid = true;
            if (!thesisChoice.valid)
                thesisChoice = a;
            // The face check (eyePairInFace): the eyes have the nose, mouth and chin of F_final
            // below them; the best-scoring pair that passes wins.
            std::erase_if(a.eyes, [&](const EyePairCandidate &c) {
                const QPointF l = a.dark[c.left].centroid, r = a.dark[c.right].centroid;
                return !eyePairInFace(a.refined.face, l, r) || mouthRowContrast(I, l, r) < kMinMouthRowContrast;
            });
            if (!a.eyes.empty()) {
                chosen = std::move(a);
                break;
            }
        }
        eyePairMs += t.nsecsElapsed() / 1e6;
        if (chosen.valid)
            break;
    }
    res.eyePairInFace = chosen.valid;
    if (!chosen.valid)
        chosen = std::move(thesisChoice); // no pair passes: the thesis' own choice, if any
    if (!chosen.valid) {
        // Nothing at all: the figures show the thesis' first try.
        chosen.rect = rects.front();
        chosen.first = firstLevelThreshold(I, chosen.rect);
        chosen.second = secondLevelThreshold(H, chosen.first.b1, chosen.rect);
        chosen.refined = refineRegions(chosen.first.b1, chosen.second.b2);
        chosen.dark = growRegions(chosen.first.b1, 0, &chosen.darkLabels);
    }
    res.timingMs.insert(QStringLiteral("regions"), regionsMs);
    const FirstLevel &first = chosen.first;
    const SecondLevel &second = chosen.second;
    const RefinedRegions &refined = chosen.refined;
    const std::vector<Region> &dark = chosen.dark;
    const std::vector<int> &darkLabels = chosen.darkLabels;
    const std::vector<EyePairCandidate> &candidates = chosen.candidates, &eyes = chosen.eyes;
    res.t1 = first.t1;
    res.eyeLevelK = chosen.k;
    res.centralRect = chosen.rect;
    if (withDebugImages) {
        res.debugImages.insert(QStringLiteral("classic-b1"), first.b1.toImage());
        res.debugImages.insert(QStringLiteral("classic-b2"), second.b2.toImage());
        res.debugImages.insert(QStringLiteral("classic-b3"), refined.b3.toImage());
        QImage fh = maskImage(refined.face, QColor(230, 190, 160), QColor(40, 60, 120));
        for (int y = 0; y < size.height(); ++y)
            for (int x = 0; x < size.width(); ++x)
                if (refined.hair.at(x, y))
                    fh.setPixel(x, y, qRgb(90, 50, 20));
        res.debugImages.insert(QStringLiteral("classic-face-hair"), fh);
    }
    res.candidateCount = int(candidates.size());
    if (withDebugImages) {
        QImage img = image;
        QPainter p(&img);
        p.setPen(QPen(Qt::white, 1, Qt::DashLine));
        p.drawRect(chosen.rect);
        p.setPen(QPen(Qt::yellow, 1));
        for (const auto &c : candidates) {
            p.drawRect(dark[c.left].box);
            p.drawRect(dark[c.right].box);
            p.drawLine(dark[c.left].centroid, dark[c.right].centroid);
        }
        if (!eyes.empty()) {
            p.setPen(QPen(Qt::red, 2));
            p.drawRect(dark[eyes.front().left].box);
            p.drawRect(dark[eyes.front().right].box);
        }
        p.end();
        res.debugImages.insert(QStringLiteral("classic-eye-pairs"), img);
    }
    res.timingMs.insert(QStringLiteral("eyePair"), eyePairMs);
    stage.restart();
    if (eyes.empty()) {
        res.error = DetectText::tr("No eye pair was found (the classic method needs a large frontal face "
                                   "on a plain background).");
        return res;
    }

    const Region *eyeRegion[2] = {&dark[eyes.front().left], &dark[eyes.front().right]};
    if (!res.eyePairInFace) {
        // Which of the face checks the thesis' own pair fails, for a caller that refuses it.
        const QPointF l = eyeRegion[0]->centroid, r = eyeRegion[1]->centroid;
        PairReach reach;
        eyePairInFace(refined.face, l, r, &reach);
        const double mouth = mouthRowContrast(I, l, r);
        QStringList failed;
        if (reach.below <= 0 && reach.side <= 0)
            failed << DetectText::tr("the point between the eyes is not in the face region");
        else if (reach.below < kMinReachBelow)
            failed << DetectText::tr("the face region reaches %1 eye distances below it (%2 needed)")
                          .arg(reach.below, 0, 'f', 2)
                          .arg(kMinReachBelow);
        if ((reach.below > 0 || reach.side > 0) && (reach.side < kMinReachSide || reach.side > kMaxReachSide))
            failed << DetectText::tr("%1 eye distances to its nearer side (%2 .. %3 needed)")
                          .arg(reach.side, 0, 'f', 2)
                          .arg(kMinReachSide)
                          .arg(kMaxReachSide);
        if (mouth < kMinMouthRowContrast)
            failed << DetectText::tr("no mouth row below it (the darkest row is %1% darker than the median, %2% "
                                     "needed)")
                          .arg(int(std::lround(100 * mouth)))
                          .arg(int(std::lround(100 * kMinMouthRowContrast)));
        res.faceCheck
            = DetectText::tr("the best eye pair by eq. (3.5), at (%1, %2) and (%3, %4), has no face around it: %5")
                  .arg(std::lround(l.x() / scale))
                  .arg(std::lround(l.y() / scale))
                  .arg(std::lround(r.x() / scale))
                  .arg(std::lround(r.y() / scale))
                  .arg(joinReasons(failed));
    }
    for (int k = 0; k < 2; ++k) {
        const Region &r = *eyeRegion[k];
        res.eyeRegions[k] = r.box;
        Mask m {size, std::vector<std::uint8_t>(size_t(size.width()) * size.height(), 0)};
        for (int y = r.box.top(); y <= r.box.bottom(); ++y)
            for (int x = r.box.left(); x <= r.box.right(); ++x)
                m.at(x, y) = darkLabels[size_t(y) * size.width() + x] == r.label;
        res.eyeballs[k] = detectEyeball(m, r.box);
        // Deviation from 3.4.1 for light irises: the dark points are then only the lids and
        // lashes, and the largest disc of them lies at the thick outer corner, not on the iris.
        // A frontal eye looks ahead, its iris in the middle of its outline: a circle found in
        // the outer quarters of the region's columns is replaced by the centre of the region's
        // box (the outline's centre), keeping the radius.
        if (std::abs(res.eyeballs[k].centre.x() - QRectF(r.box).center().x()) > r.box.width() / 4.0)
            res.eyeballs[k].centre = QRectF(r.box).center();
    }
    const Eyeball &ebL = res.eyeballs[0], &ebR = res.eyeballs[1];
    res.d = QLineF(ebL.centre, ebR.centre).length();
    const double d = res.d;
    res.eyeMid = (ebL.centre + ebR.centre) / 2;
    const QPointF mid = res.eyeMid;
    res.square = QRectF(mid.x() - d, mid.y() - d / 2, 2 * d, 2 * d);
    const QRect square = res.square.toAlignedRect().intersected(QRect(QPoint(0, 0), size));
    lap("eyeballs");
    if (withDebugImages) {
        QImage img = image;
        QPainter p(&img);
        p.setRenderHint(QPainter::Antialiasing);
        p.setPen(QPen(Qt::green, 1.5));
        for (const Eyeball &e : res.eyeballs)
            p.drawEllipse(e.centre, e.radius, e.radius);
        p.drawLine(ebL.centre, ebR.centre);
        p.setPen(QPen(Qt::red, 1.5));
        p.drawRect(res.square);
        p.end();
        res.debugImages.insert(QStringLiteral("classic-eyeballs"), img);
    }

    res.divEE = ebL.centre.y() - ebL.height() / 2 - 1;
    res.divEN = mid.y() + d / 3;
    // Div_NM: the thesis speculates EyeMid.y + d "by an experimental result"; faces vary
    // (a short face puts the upper lip above that line, and the mouth search then starts inside
    // the lips). Where the eye pair's mouth row is clear (mouthRowContrast), the line goes a
    // fifth of d above it (between the nose's base and the upper lip), never within d/4 of
    // Div_EN.
    res.divNM = mid.y() + d;
    {
        double row = 0;
        if (mouthRowContrast(I, ebL.centre, ebR.centre, &row) >= kMinMouthRowContrast)
            res.divNM = std::max(res.divEN + d / 4, mid.y() + row - 0.2 * d);
    }
    // Algorithm 4.5: Sobel edges, mirrored about the eyes' axis inside the square, then Tsai
    // per horizontal part.
    const FeatureEdges featureEdgeImage = featureEdges(I, ebL.centre, ebR.centre, res.divEE, res.divEN, res.divNM);
    const Mask &edges = featureEdgeImage.edges;
    res.edgeThresholds = featureEdgeImage.thresholds;
    lap("edges");
    if (withDebugImages) {
        QImage img = edges.toImage().convertToFormat(QImage::Format_RGB32);
        QPainter p(&img);
        p.setPen(QPen(Qt::red, 1));
        for (double y : {res.divEE, res.divEN, res.divNM})
            p.drawLine(QPointF(square.left(), y), QPointF(square.right(), y));
        p.setPen(QPen(Qt::green, 1));
        p.drawRect(res.square);
        p.end();
        res.debugImages.insert(QStringLiteral("classic-edges"), img);
    }

    // Algorithm 4.6 with the restrictions: inside the square; nose and mouth between the
    // eyeball centres; each feature kept between its division lines.
    const double hL = std::max(ebL.height(), 2.0);
    const QRectF eyeInit(QPointF(ebL.centre.x() - hL, ebL.centre.y() - 0.5 * hL),
        QPointF(ebL.centre.x() + hL, ebL.centre.y() + 0.5 * hL));
    // "The eye range translated above Div_EE": the same columns, ending at Div_EE, at least d/3
    // high so that brows set well above the eyes are still reached.
    const double browH = std::max(eyeInit.height(), d / 3);
    const QRectF browInit(QPointF(eyeInit.left(), res.divEE - browH), QPointF(eyeInit.right(), res.divEE));
    const QRectF noseInit(
        QPointF(ebL.centre.x(), res.divEN), QPointF(ebR.centre.x(), res.divEN + 0.7 * (res.divNM - res.divEN)));
    const QRectF mouthInit(QPointF(ebL.centre.x(), res.divNM), QPointF(ebR.centre.x(), res.divNM + d / 3));
    auto rows = [&](double top, double bottom, double left, double right) {
        return QRect(
            QPoint(int(std::ceil(left)), int(std::ceil(top))), QPoint(int(std::floor(right)), int(std::floor(bottom))))
            .intersected(square);
    };
    const FeatureRegion eye
        = growFeature(edges, eyeInit.toAlignedRect(), rows(res.divEE + 1, res.divEN, square.left(), mid.x()));
    const FeatureRegion brow
        = growFeature(edges, browInit.toAlignedRect(), rows(square.top(), res.divEE, square.left(), mid.x()));
    const FeatureRegion nose
        = growFeature(edges, noseInit.toAlignedRect(), rows(res.divEN, res.divNM, ebL.centre.x(), ebR.centre.x()));
    const FeatureRegion mouth = growFeature(
        edges, mouthInit.toAlignedRect(), rows(res.divNM, square.bottom(), ebL.centre.x(), ebR.centre.x()));
    res.eyeRegion = eye.box;
    res.browRegion = brow.box;
    res.noseRegion = nose.box;
    res.mouthRegion = mouth.box;
    res.noseCut = centralVerticalCut(I, nose.box);
    res.mouthCut = centralVerticalCut(I, mouth.box);
    lap("features");
    if (withDebugImages) {
        QImage img = image;
        QPainter p(&img);
        p.setPen(QPen(Qt::yellow, 1, Qt::DashLine));
        for (const QRectF &r : {eyeInit, browInit, noseInit, mouthInit})
            p.drawRect(r);
        p.setPen(QPen(Qt::cyan, 1.5));
        for (const QRectF &r : {res.eyeRegion, res.browRegion, res.noseRegion, res.mouthRegion})
            p.drawRect(r);
        p.setPen(QPen(Qt::magenta, 1));
        p.drawLine(QPointF(res.noseCut, res.noseRegion.top()), QPointF(res.noseCut, res.noseRegion.bottom()));
        p.drawLine(QPointF(res.mouthCut, res.mouthRegion.top()), QPointF(res.mouthCut, res.mouthRegion.bottom()));
        p.end();
        res.debugImages.insert(QStringLiteral("classic-feature-regions"), img);
    }

    // Section 4.3.1. The right side mirrors the left about the eyeballs' perpendicular bisector.
    const QPointF axis = ebR.centre - ebL.centre;
    const QPointF u = d > 0 ? axis / d : QPointF(1, 0);
    auto mirror = [&](QPointF p) {
        const double t = QPointF::dotProduct(p - mid, u);
        return p - 2 * t * u;
    };
    FaceModel face(size);
    auto set = [&](const char *id, QPointF p) { face.setPoint(pt::idx(id), p); };
    {
        const QRect b = brow.box;
        const int w = endColumns(b);
        const QPointF fallback = QRectF(b).center();
        const QPointF p46 = averageOf(
            brow.pixels, [&](QPoint p) { return p.x() < b.left() + w; }, QPointF(b.left(), fallback.y()));
        const QPointF p42 = averageOf(
            brow.pixels, [&](QPoint p) { return p.x() > b.right() - w; }, QPointF(b.right(), fallback.y()));
        const int inner0 = b.left() + w, inner1 = b.right() - w, half = (inner0 + inner1) / 2;
        const QPointF p44a = columnCentres(brow.pixels, inner0, half, (2 * p46 + p42) / 3);
        const QPointF p44 = columnCentres(brow.pixels, half + 1, inner1, (p46 + 2 * p42) / 3);
        set("4.6", p46);
        set("4.4a", p44a);
        set("4.4", p44);
        set("4.2", p42);
        set("4.5", mirror(p46));
        set("4.3a", mirror(p44a));
        set("4.3", mirror(p44));
        set("4.1", mirror(p42));
    }
    {
        const QRect b = eye.box;
        const int w = endColumns(b);
        const QPointF p312 = averageOf(
            eye.pixels, [&](QPoint p) { return p.x() < b.left() + w; }, QPointF(ebL.centre.x() - hL, ebL.centre.y()));
        const QPointF p38 = averageOf(
            eye.pixels, [&](QPoint p) { return p.x() > b.right() - w; }, QPointF(ebL.centre.x() + hL, ebL.centre.y()));
        set("3.12", p312);
        set("3.8", p38);
        set("3.2", ebL.centre - QPointF(0, ebL.height() / 2));
        set("3.4", ebL.centre + QPointF(0, ebL.height() / 2));
        set("3.6", ebL.centre);
        set("3.11", mirror(p38));
        set("3.7", mirror(p312));
        set("3.1", ebR.centre - QPointF(0, ebR.height() / 2));
        set("3.3", ebR.centre + QPointF(0, ebR.height() / 2));
        set("3.5", ebR.centre);
    }
    {
        const QRectF n = nose.box;
        const double x1 = n.left(), x2 = n.right(), y1 = n.top(), y2 = n.bottom();
        const QPointF p38 = face.point("3.8"), p311 = face.point("3.11");
        set("9.6", QPointF(p38.x() + (p311.x() - p38.x()) / 3, mid.y()));
        set("9.7", QPointF(p311.x() - (p311.x() - p38.x()) / 3, mid.y()));
        set("9.14", QPointF(x1 + (x2 - x1) / 8, y1));
        set("9.13", QPointF(x2 - (x2 - x1) / 8, y1));
        set("9.2", QPointF(x1, (y1 + 3 * y2) / 4));
        set("9.1", QPointF(x2, (y1 + 3 * y2) / 4));
        set("9.4", QPointF(x1 + (x2 - x1) / 8, y2));
        set("9.5", QPointF(x2 - (x2 - x1) / 8, y2));
        set("9.15", QPointF(res.noseCut, y2));
    }
    {
        const QRect b = mouth.box;
        const int w = endColumns(b);
        const double xm = res.mouthCut;
        const QPointF p84 = averageOf(
            mouth.pixels, [&](QPoint p) { return p.x() < b.left() + w; }, QPointF(b.left(), QRectF(b).center().y()));
        const int wr = std::max(1, int(std::lround(b.height() / 8.0)));
        const QPointF p89 = averageOf(
            mouth.pixels, [&](QPoint p) { return p.x() < xm && p.y() < b.top() + wr; },
            QPointF((b.left() + xm) / 2, b.top()));
        // Step 5 is garbled in the text; read as: 8.1 is the topmost edge pixel on the cut.
        double top = b.bottom();
        for (const QPoint &p : mouth.pixels)
            if (std::abs(p.x() - xm) <= 1)
                top = std::min<double>(top, p.y());
        auto mirrorM = [&](QPointF p) { return QPointF(2 * xm - p.x(), p.y()); };
        set("8.4", p84);
        set("8.9", p89);
        set("8.1", QPointF(xm, std::min(top, p84.y())));
        set("8.10", mirrorM(p89));
        set("8.3", mirrorM(p84));
        set("2.2", QPointF(xm, p84.y()));
        set("2.3", QPointF(xm, p84.y()));
        set("8.2", QPointF(xm, b.bottom()));
    }
    lap("featurePoints");

    const Mask &F = refined.face;
    cheekOffset(F, mid, d, &res.cheekLeft, &res.cheekRight);
    // Section 4.3.2 A: jaw and face points by searching out of F_final.
    {
        const int far = int(2 * d);
        const QPointF p82 = face.point("8.2"), p89 = face.point("8.9"), p810 = face.point("8.10");
        set("2.1", leave(F, p82, QPointF(0, 1), far, p82 + QPointF(0, 0.7 * d)));
        QPointF p214, p213;
        bool okL = false, okR = false;
        for (int dy = 0; dy < int(d / 2) && !okL; ++dy) {
            p214 = leave(F, p89 + QPointF(0, dy), QPointF(-1, 0), far, QPointF(res.cheekLeft, p89.y()), &okL);
            okL = okL && p214.x() >= res.cheekLeft - 1;
        }
        for (int dy = 0; dy < int(d / 2) && !okR; ++dy) {
            p213 = leave(F, p810 + QPointF(0, dy), QPointF(1, 0), far, QPointF(res.cheekRight, p810.y()), &okR);
            okR = okR && p213.x() <= res.cheekRight + 1;
        }
        if (!okL)
            p214 = QPointF(res.cheekLeft, p89.y());
        if (!okR)
            p213 = QPointF(res.cheekRight, p810.y());
        set("2.14", p214);
        set("2.13", p213);
        const QPointF mouthC((p214.x() + p213.x()) / 2, face.point("8.4").y());
        const QPointF p21 = face.point("2.1");
        set("2.12", leave(F, mouthC, QPointF(-0.7071, 0.7071), far, (p214 + p21) / 2));
        set("2.11", leave(F, mouthC, QPointF(0.7071, 0.7071), far, (p213 + p21) / 2));
        set("5.2", QPointF(res.cheekLeft, mid.y()));
        set("5.1", QPointF(res.cheekRight, mid.y()));
        set("11.2",
            leave(F, QPointF(p214.x() + 2, mid.y() + d / 2), QPointF(0, -1), far, QPointF(p214.x(), mid.y() - d)));
        set("11.3",
            leave(F, QPointF(p213.x() - 2, mid.y() + d / 2), QPointF(0, -1), far, QPointF(p213.x(), mid.y() - d)));
        // 11.1: the mean of the topmost rows of F_final between the jaw points.
        QPointF sum;
        int n = 0, topRow = -1;
        for (int y = 0; y < int(mid.y()) && n == 0; ++y)
            for (int x = int(p214.x()); x <= int(p213.x()); ++x)
                if (F.contains(x, y) && F.at(x, y)) {
                    topRow = y;
                    ++n;
                }
        n = 0;
        for (int y = std::max(0, topRow); topRow >= 0 && y < topRow + 4; ++y)
            for (int x = int(p214.x()); x <= int(p213.x()); ++x)
                if (F.contains(x, y) && F.at(x, y)) {
                    sum += QPointF(x, y);
                    ++n;
                }
        set("11.1", n ? sum / n : QPointF(mid.x(), mid.y() - d));
    }
    // Ears: the parts of F_final outside the cheek boundaries between the brow and nose
    // lines; a missing ear lies flat on the cheek.
    for (int side = 0; side < 2; ++side) {
        const double cheek = side == 0 ? res.cheekLeft : res.cheekRight;
        const int sign = side == 0 ? -1 : 1;
        const int y0 = std::max(0, int(res.divEE)), y1 = std::min(size.height() - 1, int(res.divNM));
        QPointF top, bottom, outer;
        bool any = false;
        for (int y = y0; y <= y1; ++y) {
            // Start a little outside the cheek line so the face's own curve is not an ear.
            for (int k = std::max(2, int(d / 20)); k < int(d / 2); ++k) {
                const int x = int(cheek) + sign * k;
                if (!F.contains(x, y) || !F.at(x, y))
                    break;
                const QPointF p(x, y);
                if (!any) {
                    top = bottom = outer = p;
                    any = true;
                }
                if (p.y() < top.y())
                    top = p;
                if (p.y() >= bottom.y())
                    bottom = p;
                if (sign * p.x() > sign * outer.x())
                    outer = p;
            }
        }
        if (!any) {
            top = QPointF(cheek, res.divEE);
            bottom = QPointF(cheek, res.divNM);
            outer = QPointF(cheek + sign * 2, (res.divEE + res.divNM) / 2);
        }
        const QPointF junction(cheek, bottom.y());
        set(side == 0 ? "10.2" : "10.1", top);
        set(side == 0 ? "10.4" : "10.3", outer);
        set(side == 0 ? "10.6" : "10.5", bottom);
        set(side == 0 ? "10.10" : "10.9", junction);
    }
    // Section 4.3.2 B: hair points on rays from EyeMid (10 degrees below the eye line on the
    // left, over the crown, to 10 degrees below on the right), leaving the face and then the
    // hair region; where there is no hair the point stays on the face's edge.
    for (int i = 0; i < 19; ++i) {
        const double a = (190.0 - i * (200.0 / 18.0)) * std::numbers::pi / 180.0;
        const QPointF step(std::cos(a), -std::sin(a));
        QPointF p = mid;
        int guard = 0;
        while (inMask(F, p) && guard++ < 4 * d)
            p += step;
        QPointF edge = p;
        while (guard++ < 6 * d) {
            const QPointF q = p + step;
            const int x = int(std::lround(q.x())), y = int(std::lround(q.y()));
            if (!refined.hair.contains(x, y))
                break;
            if (refined.hair.at(x, y))
                edge = q;
            else if (QLineF(edge, q).length() > d / 8)
                break;
            p = q;
        }
        face.setPoint(pt::idx("h.1") + i, edge);
    }
    lap("outline");

    if (withDebugImages) {
        QImage img = image;
        QPainter p(&img);
        p.setRenderHint(QPainter::Antialiasing);
        p.setPen(Qt::NoPen);
        for (int i = 0; i < kPointCount; ++i) {
            p.setBrush(pointTable()[i].group == PointGroup::Hair ? Qt::magenta : Qt::green);
            p.drawEllipse(face.point(i), 2.0, 2.0);
        }
        p.setPen(QPen(Qt::cyan, 1));
        p.drawLine(QPointF(res.cheekLeft, 0), QPointF(res.cheekLeft, size.height()));
        p.drawLine(QPointF(res.cheekRight, 0), QPointF(res.cheekRight, size.height()));
        p.end();
        res.debugImages.insert(QStringLiteral("classic-points"), img);
    }

    // Back to the input's pixels.
    if (scale < 1.0) {
        const double k = 1.0 / scale;
        for (int i = 0; i < kPointCount; ++i)
            face.setPoint(i, face.point(i) * k);
        for (auto &r : res.eyeRegions)
            r = QRectF(r.topLeft() * k, r.size() * k);
        for (auto &e : res.eyeballs) {
            e.centre *= k;
            e.radius *= k;
        }
        res.d *= k;
        res.eyeMid *= k;
        for (QRectF *r : {&res.square, &res.browRegion, &res.eyeRegion, &res.noseRegion, &res.mouthRegion})
            *r = QRectF(r->topLeft() * k, r->size() * k);
        for (double *v :
            {&res.divEE, &res.divEN, &res.divNM, &res.noseCut, &res.mouthCut, &res.cheekLeft, &res.cheekRight})
            *v *= k;
    }
    // Searches that end on the image's edge may round just outside it.
    for (int i = 0; i < kPointCount; ++i)
        face.setPoint(i,
            QPointF(std::clamp(face.point(i).x(), 0.0, input.width() - 1.0),
                std::clamp(face.point(i).y(), 0.0, input.height() - 1.0)));
    face.setImageSize(input.size());
    res.face = face;
    if (!face.isValid()) {
        res.error = DetectText::tr("The classic method found an eye pair but could not place a face around it "
                                   "(a feature collapsed to nothing).");
        res.timingMs.insert(QStringLiteral("total"), total.nsecsElapsed() / 1e6);
        return res;
    }
    res.timingMs.insert(QStringLiteral("total"), total.nsecsElapsed() / 1e6);
    res.ok = true;
    return res;
}

} // namespace toonface
