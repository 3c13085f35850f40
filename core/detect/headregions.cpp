#include "detect/headregions.h"

#include "detect/landmarkmap.h"
#include "detect/regions.h"
#include "i18n/coretext.h"

#include <QPainter>
#include <QPolygonF>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

// The thesis finds the face and hair regions around an eye pair it first has to find, with
// thresholds measured in the middle of the photo. Here the face is known (landmarks), so:
//
// 1. The head's surroundings are cut out (3.3 eye distances d each side of the midline, from
//    3.3 d above the eyes to 4.5 d below) and scaled so that d is kWorkEyeDistance pixels:
//    every length is a multiple of d and the cost does not grow with the photo. The cut-out's
//    border plays the image border of Algorithm 4.4.
// 2. Algorithm 4.1's central rectangle is the face's own: from the outer eye corners' columns,
//    from the brows down to the mouth corners. m1, s1 and t1 = m1 - s1 are measured there;
//    m2 and s2 of the hue over its light pixels (B1 = 1: the dark brows, eyes and nostrils
//    have no skin hue, and eq. 3.9 only makes light pixels face anyway). A flat, synthetic
//    face would give s1 = 0 or s2 = 0: both have a floor (kMinIntensitySpread, kMinHueSpread).
// 3. B1, B2, then Algorithm 4.4 gives F_final and H_final - F_final. The face is F_final's
//    component under the nose bridge; the head's hair is the hair components touching it.
//    The hair's colour is measured beside the temples; dark pixels far from it are not hair.
// 4. Outline: from the geometric hair ellipse's centre (between the cheeks at eye level),
//    rays over each side of the head from 10 degrees below the horizontal to straight up,
//    each walking out of the head (face, then hair) until it has left it for d/6 (a parting
//    or a highlight is crossed). Below, row by row, the hair that goes on beside the face
//    (long hair); it ends where a row has no hair beside the contour for 0.35 d (a row whose
//    edge jumps inward is a gap in the hair), where the outer edge jumps outward (the
//    shoulders) or runs beyond 2.6 d of the midline. Each side's polyline, bottom to crown,
//    is resampled by arc length into ten points (h.10 shared).
// 5. Ears: as Algorithm 4.3.2 A step 6 and section 3.5 read it, the face region (of skin colour)
//    beyond the cheek line between the brow and nose lines; the cheek line is the landmark
//    contour (5.2 to 2.14), which the cheek projection of 3.5 approximates. A bulge of
//    plausible width (0.08..0.45 d) and height (0.4..1.6 ear heights) that ends in a
//    non-face pixel is the ear.

namespace toonface {

namespace {

constexpr double kWorkEyeDistance = 40.0;
constexpr double kMinIntensitySpread = 8.0; // grey levels
constexpr double kMinHueSpread = 4.0; // hue units of huePlane(), about 5.6 degrees
// Gaps in the head's regions that a search crosses, in eye distances: a parting, a highlight.
constexpr double kRayGap = 1.0 / 6.0;
constexpr double kRowGap = 1.0 / 4.0; // beside the face, where strands part more
constexpr double kNeckGap = 0.6; // below the jaw, between the neck and long hair
constexpr double kMinHairDistance = 40.0; // RGB distance always within the hair's (or skin's) colour

struct Work
{
    QRect crop; // in the photo
    double scale = 1; // work pixels per photo pixel
    QSize size;
    HeadGeometry g;

    QPointF toWork(QPointF local) const { return (g.toImage(local) - QPointF(crop.topLeft())) * scale; }
    QPointF workToImage(QPointF w) const { return QPointF(crop.topLeft()) + w / scale; }
    QRectF workToImage(const QRectF &r) const { return QRectF(workToImage(r.topLeft()), r.size() / scale); }
    bool inWork(QPointF w) const
    {
        const int x = int(std::lround(w.x())), y = int(std::lround(w.y()));
        return x >= 0 && y >= 0 && x < size.width() && y < size.height();
    }
    bool at(const Mask &m, QPointF local) const
    {
        const QPointF w = toWork(local);
        const int x = int(std::lround(w.x())), y = int(std::lround(w.y()));
        return m.contains(x, y) && m.at(x, y);
    }
};

double median(std::vector<double> v)
{
    if (v.empty())
        return 0;
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
}

struct ColourSum
{
    double r = 0, g = 0, b = 0, rr = 0, gg = 0, bb = 0;
    int n = 0;
    void add(QRgb c)
    {
        r += qRed(c);
        g += qGreen(c);
        b += qBlue(c);
        rr += double(qRed(c)) * qRed(c);
        gg += double(qGreen(c)) * qGreen(c);
        bb += double(qBlue(c)) * qBlue(c);
        ++n;
    }
    ColourStats stats() const
    {
        ColourStats s;
        if (n == 0)
            return s;
        s.samples = n;
        s.r = r / n;
        s.g = g / n;
        s.b = b / n;
        const double var = (rr / n - s.r * s.r) + (gg / n - s.g * s.g) + (bb / n - s.b * s.b);
        s.spread = std::sqrt(std::max(0.0, var));
        return s;
    }
};

double colourDistance(QRgb c, const ColourStats &s)
{
    return std::sqrt(std::pow(qRed(c) - s.r, 2) + std::pow(qGreen(c) - s.g, 2) + std::pow(qBlue(c) - s.b, 2));
}

// The result of walking outward through the head mask.
struct Walk
{
    bool ok = false; // left the head (or the photo) after having been in it
    bool leftPhoto = false; // ended on the photo's edge, still on the head
    double length = 0; // distance from the start to the last head pixel
    double hair = 0; // length of the walk spent on hair pixels
};

} // namespace

HeadRegionReport refineFromRegions(FaceModel *face, const QImage &image, bool withDebugImages)
{
    HeadRegionReport rep;
    if (image.isNull() || !face->isValid()) {
        rep.hairProblem = DetectText::tr("no face to search around");
        return rep;
    }
    Work w;
    w.g = headGeometry(*face);
    const HeadGeometry &g = w.g;
    const double d = g.eyeDistance;
    if (d < 6) {
        rep.hairProblem = DetectText::tr("the face is too small");
        return rep;
    }
    auto L = [&](const char *id) { return g.toLocal(face->point(id)); };

    // 1. The cut-out.
    {
        QPolygonF corners;
        for (const QPointF c : {QPointF(g.midX - 3.3 * d, -3.3 * d), QPointF(g.midX + 3.3 * d, -3.3 * d),
                 QPointF(g.midX - 3.3 * d, 4.5 * d), QPointF(g.midX + 3.3 * d, 4.5 * d)})
            corners << g.toImage(c);
        w.crop = corners.boundingRect().toAlignedRect().intersected(image.rect());
    }
    if (w.crop.width() < 16 || w.crop.height() < 16) {
        rep.hairProblem = DetectText::tr("the head is outside the photo");
        return rep;
    }
    w.scale = std::min(1.0, kWorkEyeDistance / d);
    w.size = QSize(std::max(1, int(std::lround(w.crop.width() * w.scale))),
        std::max(1, int(std::lround(w.crop.height() * w.scale))));
    const QImage work = image.copy(w.crop)
                            .convertToFormat(QImage::Format_RGB32)
                            .scaled(w.size, Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
    w.size = work.size();
    const double step = 1.0 / w.scale; // one work pixel in photo (and face-frame) pixels
    auto pixel = [&](QPointF local) {
        const QPointF p = w.toWork(local);
        return work.pixel(std::clamp(int(std::lround(p.x())), 0, w.size.width() - 1),
            std::clamp(int(std::lround(p.y())), 0, w.size.height() - 1));
    };

    // 2. Thresholds in the face's central rectangle.
    const double mouthY = (L("8.4").y() + L("8.3").y()) / 2;
    QRect rect;
    {
        QPolygonF corners;
        for (const QPointF c : {QPointF(L("3.12").x(), g.browY), QPointF(L("3.7").x(), g.browY),
                 QPointF(L("3.12").x(), mouthY), QPointF(L("3.7").x(), mouthY)})
            corners << w.toWork(c);
        rect = corners.boundingRect().toAlignedRect().intersected(QRect(QPoint(0, 0), w.size));
    }
    if (rect.width() < 3 || rect.height() < 3) {
        rep.hairProblem = DetectText::tr("the face is outside the photo");
        return rep;
    }
    const Plane I = intensityPlane(work);
    const Plane H = huePlane(work);
    FirstLevel first = firstLevelThreshold(I, rect);
    if (first.s1 < kMinIntensitySpread) {
        first.t1 = first.m1 - kMinIntensitySpread;
        for (size_t i = 0; i < I.values.size(); ++i)
            first.b1.values[i] = I.values[i] > first.t1 ? 1 : 0;
    }
    double m2 = 0, s2 = 0;
    {
        double sum = 0, sum2 = 0;
        int n = 0;
        for (int y = rect.top(); y <= rect.bottom(); ++y)
            for (int x = rect.left(); x <= rect.right(); ++x)
                if (first.b1.at(x, y)) {
                    sum += H.at(x, y);
                    ++n;
                }
        if (n < 10) {
            rep.hairProblem = DetectText::tr("the face's central rectangle is dark");
            return rep;
        }
        m2 = sum / n;
        for (int y = rect.top(); y <= rect.bottom(); ++y)
            for (int x = rect.left(); x <= rect.right(); ++x)
                if (first.b1.at(x, y))
                    sum2 += (H.at(x, y) - m2) * (H.at(x, y) - m2);
        s2 = std::max(kMinHueSpread, std::sqrt(sum2 / std::max(1, n - 1)));
    }
    Mask b2 {w.size, std::vector<std::uint8_t>(H.values.size())};
    for (size_t i = 0; i < H.values.size(); ++i)
        b2.values[i] = (std::abs(H.values[i] - m2) <= s2 && first.b1.values[i]) ? 0 : 1;
    const RefinedRegions refined = refineRegions(first.b1, b2);

    rep.seed.valid = true;
    rep.seed.rect = w.workToImage(QRectF(rect));
    rep.seed.m1 = first.m1;
    rep.seed.s1 = first.s1;
    rep.seed.t1 = first.t1;
    rep.seed.m2 = m2;
    rep.seed.s2 = s2;
    // The skin's colour: the face pixels of the central rectangle. Pixels farther from it than
    // three times the samples' median distance (at least kMinHairDistance) are not skin.
    double skinLimit = 0;
    {
        ColourSum skin;
        std::vector<QRgb> samples;
        for (int y = rect.top(); y <= rect.bottom(); ++y)
            for (int x = rect.left(); x <= rect.right(); ++x)
                if (!b2.at(x, y)) {
                    skin.add(work.pixel(x, y));
                    samples.push_back(work.pixel(x, y));
                }
        rep.seed.skin = skin.stats();
        std::vector<double> dist;
        for (QRgb c : samples)
            dist.push_back(colourDistance(c, rep.seed.skin));
        skinLimit = std::max(3.0 * median(dist), kMinHairDistance);
    }

    // 3. The face component and the head's hair.
    Mask faceC {w.size, std::vector<std::uint8_t>(b2.values.size(), 0)};
    {
        std::vector<int> labels;
        const std::vector<Region> regions = growRegions(refined.face, 1, &labels);
        int label = 0;
        const double cheekY = (std::max(L("3.4").y(), L("3.3").y()) + L("9.15").y()) / 2;
        for (const QPointF seed : {QPointF(g.midX, 0.5 * g.noseBaseY), QPointF(L("3.6").x(), cheekY),
                 QPointF(L("3.5").x(), cheekY), QPointF(g.midX, g.browY - 0.2 * d)}) {
            const QPointF p = w.toWork(seed);
            const int x = int(std::lround(p.x())), y = int(std::lround(p.y()));
            if (refined.face.contains(x, y) && labels[size_t(y) * w.size.width() + x] > 0) {
                label = labels[size_t(y) * w.size.width() + x];
                break;
            }
        }
        if (label == 0) {
            rep.hairProblem = DetectText::tr("the face region misses the face");
            return rep;
        }
        for (size_t i = 0; i < labels.size(); ++i)
            faceC.values[i] = labels[i] == label ? 1 : 0;
        rep.faceRegion = w.workToImage(QRectF(regions[label - 1].box));
    }
    Mask hairC {w.size, std::vector<std::uint8_t>(b2.values.size(), 0)};
    {
        const cv::Mat fc(w.size.height(), w.size.width(), CV_8U, faceC.values.data());
        cv::Mat grown;
        cv::dilate(fc, grown, cv::Mat::ones(5, 5, CV_8U));
        std::vector<int> labels;
        const std::vector<Region> regions = growRegions(refined.hair, 1, &labels);
        std::vector<bool> touching(regions.size() + 1, false);
        for (size_t i = 0; i < labels.size(); ++i)
            if (labels[i] > 0 && grown.data[i])
                touching[labels[i]] = true;
        for (size_t i = 0; i < labels.size(); ++i)
            hairC.values[i] = touching[labels[i]] && labels[i] > 0 ? 1 : 0;
    }
    // The hair's colour beside the temples (where a hat does not reach), else over the forehead.
    const double cheekLX = L("5.2").x(), cheekRX = L("5.1").x();
    // Pixels farther from the hair's mean colour than three times the median distance of the
    // samples (at least kMinHairDistance) are not hair: the median, because the samples
    // include the hair's blended edges.
    double hairLimit = 0;
    {
        ColourSum hair;
        std::vector<QRgb> samples;
        auto sample = [&](double x0, double x1, double y0, double y1) {
            for (double y = y0; y <= y1; y += step)
                for (double x = x0; x <= x1; x += step)
                    if (w.at(hairC, QPointF(x, y))) {
                        hair.add(pixel(QPointF(x, y)));
                        samples.push_back(pixel(QPointF(x, y)));
                    }
        };
        sample(cheekLX - 0.5 * d, cheekLX + 0.2 * d, g.browY - 0.8 * d, 0);
        sample(cheekRX - 0.2 * d, cheekRX + 0.5 * d, g.browY - 0.8 * d, 0);
        if (hair.n < 15)
            sample(g.midX - 0.6 * d, g.midX + 0.6 * d, g.hairlineY - 0.5 * d, g.hairlineY + 0.2 * d);
        rep.seed.hair = hair.n >= 15 ? hair.stats() : ColourStats();
        if (rep.seed.hair.samples > 0) {
            std::vector<double> dist;
            for (QRgb c : samples)
                dist.push_back(colourDistance(c, rep.seed.hair));
            hairLimit = std::max(3.0 * median(dist), kMinHairDistance);
        }
    }
    if (hairLimit > 0) {
        for (int y = 0; y < w.size.height(); ++y)
            for (int x = 0; x < w.size.width(); ++x)
                if (hairC.at(x, y) && colourDistance(work.pixel(x, y), rep.seed.hair) > hairLimit)
                    hairC.at(x, y) = 0;
    }
    Mask head {w.size, std::vector<std::uint8_t>(b2.values.size(), 0)};
    {
        QRect hairBox;
        for (int y = 0; y < w.size.height(); ++y)
            for (int x = 0; x < w.size.width(); ++x) {
                head.at(x, y) = faceC.at(x, y) || hairC.at(x, y);
                if (hairC.at(x, y))
                    hairBox = hairBox.united(QRect(x, y, 1, 1));
            }
        if (!hairBox.isEmpty())
            rep.hairRegion = w.workToImage(QRectF(hairBox));
    }

    // Walks from `start` along `dir` (a unit vector of the face frame) through the head:
    // ends when the head has been left for `gap`, or fails when the walk runs `maxLen` without
    // leaving it or leaves the cut-out inside the photo (the head's region goes on: a
    // background merged with it). Leaving the photo ends the walk where it left.
    const QRectF photo(image.rect());
    auto walk = [&](QPointF start, QPointF dir, double maxLen, double gap) {
        Walk r;
        double last = -1;
        for (double t = 0; t <= maxLen; t += step) {
            const QPointF q = start + t * dir;
            const QPointF wp = w.toWork(q);
            if (!w.inWork(wp)) {
                r.ok = r.leftPhoto = last >= 0 && !photo.contains(g.toImage(q));
                r.length = std::max(last, 0.0);
                return r;
            }
            if (w.at(head, q)) {
                last = t;
                if (w.at(hairC, q))
                    r.hair += step;
            } else if (last >= 0 && t - last > gap) {
                r.ok = true;
                r.length = last;
                return r;
            } else if (last < 0 && t > gap) {
                return r; // the start is not on the head
            }
        }
        r.length = std::max(last, 0.0);
        return r;
    };

    // 4. The outline.
    const QPointF centre = g.hairCentre;
    // The geometric hair ellipse's radius in the direction of angle a (above the horizontal).
    auto ellipseRadius = [&](double a) { return 1.0 / std::hypot(std::cos(a) / g.hairAx, std::sin(a) / g.hairAy); };
    constexpr int kRays = 21; // per side, 5 degrees apart
    std::array<std::array<double, kRays>, 2> radius {};
    std::array<std::array<bool, kRays>, 2> found {}, atEdge {};
    int foundCount = 0;
    for (int side = 0; side < 2; ++side) {
        const double sx = side == 0 ? -1.0 : 1.0;
        for (int k = 0; k < kRays; ++k) {
            const double a = (-10.0 + 5.0 * k) * std::numbers::pi / 180.0;
            const QPointF dir(sx * std::cos(a), -std::sin(a));
            const Walk r = walk(centre, dir, 3.0 * d, kRayGap * d);
            radius[side][k] = r.length;
            // A head smaller than 0.7 or larger than 1.7 times the geometric estimate is the
            // region's mistake (a dark background joining the hair, hair the face's colour),
            // unless the head goes on beyond the photo's edge.
            const double ratio = r.length / ellipseRadius(a);
            atEdge[side][k] = r.leftPhoto;
            found[side][k] = r.ok && ratio >= 0.7 && (ratio <= 1.7 || r.leftPhoto);
            rep.rays.emplace_back(g.toImage(centre), g.toImage(centre + r.length * dir));
        }
    }
    // A frontal head is nearly symmetric: of two mirrored rays that disagree by more than 30%,
    // the one farther from the estimate is not believed.
    for (int k = 0; k < kRays; ++k) {
        const double a = (-10.0 + 5.0 * k) * std::numbers::pi / 180.0;
        const double l = radius[0][k] / ellipseRadius(a), r = radius[1][k] / ellipseRadius(a);
        if (found[0][k] && found[1][k] && !atEdge[0][k] && !atEdge[1][k] && std::abs(l - r) > 0.3 * std::min(l, r))
            found[std::abs(l - 1.0) > std::abs(r - 1.0) ? 0 : 1][k] = false;
    }
    for (int side = 0; side < 2; ++side)
        for (int k = 0; k < kRays; ++k)
            foundCount += found[side][k];
    rep.hairFraction = foundCount / double(2 * kRays);
    // Each side's radii, smoothed: a failed ray or one more than 15% off the median of its
    // found neighbours (three each side) takes that median (the estimate's radius when no
    // neighbour was found).
    for (int side = 0; side < 2; ++side) {
        std::array<double, kRays> smooth {};
        for (int k = 0; k < kRays; ++k) {
            std::vector<double> nb;
            for (int j = std::max(0, k - 3); j <= std::min(kRays - 1, k + 3); ++j)
                if (found[side][j])
                    nb.push_back(radius[side][j]);
            const double m = nb.empty() ? ellipseRadius((-10.0 + 5.0 * k) * std::numbers::pi / 180.0) : median(nb);
            smooth[k]
                = found[side][k] && (nb.size() < 3 || std::abs(radius[side][k] - m) <= 0.15 * m) ? radius[side][k] : m;
        }
        radius[side] = smooth;
    }
    if (foundCount < int(0.7 * 2 * kRays)) {
        rep.hairProblem = DetectText::tr("the head's outline could not be followed (%1 of %2 searches ended on it)")
                              .arg(foundCount)
                              .arg(2 * kRays);
    } else {
        // Long hair: rows below the lowest ray's end.
        std::array<std::vector<QPointF>, 2> lower;
        std::array<bool, 2> merged {}; // the side's region ran into the background at once
        for (int side = 0; side < 2; ++side) {
            const double sx = side == 0 ? -1.0 : 1.0;
            const double a = -10.0 * std::numbers::pi / 180.0;
            const double y0 = radius[side][0] * std::sin(-a);
            const QPointF cheek = L(side == 0 ? "5.2" : "5.1"), jaw = L(side == 0 ? "2.14" : "2.13"),
                          lowJaw = L(side == 0 ? "2.12" : "2.11");
            auto contourX = [&](double y) {
                auto lerp = [&](QPointF a0, QPointF a1) {
                    const double t = std::clamp((y - a0.y()) / std::max(a1.y() - a0.y(), 1e-6), 0.0, 1.0);
                    return a0.x() + t * (a1.x() - a0.x());
                };
                if (y <= jaw.y())
                    return y <= cheek.y() ? cheek.x() : lerp(cheek, jaw);
                if (y <= lowJaw.y())
                    return lerp(jaw, lowJaw);
                // Below the lower jaw the walks start at the neck's side, about as wide as the
                // lower jaw, not at the chin (which would start them in the neck's middle).
                return lowJaw.x();
            };
            // A row goes on when the head reaches beyond the contour (hair, or an ear hiding
            // it); the hair goes down as far as the last row with hair in it.
            std::vector<QPointF> rows;
            size_t lastHairy = 0;
            double miss = 0, prevOuter = std::nan("");
            for (double y = y0 + step; y <= 4.4 * d; y += step) {
                const double cx = contourX(y);
                const double maxLen = std::max(0.0, 2.6 * d - sx * (cx - g.midX)) + 0.05 * d;
                // Below the jaw the neck lies between the contour and the hair, often with a
                // strip of collar or background between them: the walk may cross more of it.
                const double gap = (y > lowJaw.y() ? kNeckGap : kRowGap) * d;
                const Walk r = walk(QPointF(cx - sx * 0.05 * d, y), QPointF(sx, 0), maxLen, gap);
                const double outer = cx - sx * 0.05 * d + sx * r.length;
                const bool beyond = r.ok && sx * (outer - cx) >= 0.1 * d;
                const double jump = std::isnan(prevOuter) ? 0.0 : sx * (outer - prevOuter);
                if (beyond && jump > 0.25 * d)
                    break; // the shoulders
                if (!beyond || jump < -0.25 * d) { // nothing beside the face, or a gap in the hair
                    miss += step;
                    if (miss > 0.35 * d || !r.ok) {
                        merged[side] = !r.ok && rows.empty();
                        break;
                    }
                    continue;
                }
                miss = 0;
                prevOuter = outer;
                rows.emplace_back(outer, y);
                if (r.hair >= 0.1 * d)
                    lastHairy = rows.size();
            }
            rows.resize(lastHairy);
            if (!rows.empty() && rows.back().y() > g.noseBaseY + 0.2 * d && rows.back().y() - y0 > 0.5 * d) {
                lower[side] = rows;
                rep.longHair = true;
            }
        }
        // Long hair on one side, and on the other a region that merges with the background
        // beside the face (nothing can be read there): the other side mirrors it about the
        // midline rather than end at eye level.
        for (int side = 0; side < 2; ++side) {
            const int other = 1 - side;
            if (lower[side].empty() && merged[side] && !lower[other].empty()) {
                for (const QPointF &q : lower[other])
                    lower[side].emplace_back(2 * g.midX - q.x(), q.y());
            }
        }
        // Each side bottom to crown, resampled into ten points: evenly, except that long hair's
        // part below the cheek takes its share of them but at most three, so that at least
        // seven describe the head's outline above it (long hair falls in a simple line; the
        // crown's shape is what makes the head).
        std::array<std::array<QPointF, 10>, 2> pts {};
        for (int side = 0; side < 2; ++side) {
            const double sx = side == 0 ? -1.0 : 1.0;
            std::vector<QPointF> line(lower[side].rbegin(), lower[side].rend());
            for (int k = 0; k < kRays; ++k) {
                const double a = (-10.0 + 5.0 * k) * std::numbers::pi / 180.0;
                line.push_back(centre + radius[side][k] * QPointF(sx * std::cos(a), -std::sin(a)));
            }
            std::vector<double> arc(line.size(), 0.0);
            for (size_t i = 1; i < line.size(); ++i)
                arc[i] = arc[i - 1] + QLineF(line[i - 1], line[i]).length();
            const double junction = arc[lower[side].size()];
            const int nLow = lower[side].empty() ? 0 : std::clamp(int(std::lround(9.0 * junction / arc.back())), 1, 3);
            size_t seg = 0;
            for (int k = 0; k < 10; ++k) {
                const double s = k <= nLow && nLow > 0 ? junction * k / nLow
                                                       : junction + (arc.back() - junction) * (k - nLow) / (9.0 - nLow);
                while (seg + 2 < line.size() && arc[seg + 1] < s)
                    ++seg;
                const double len = arc[seg + 1] - arc[seg];
                const double u = len > 1e-9 ? std::clamp((s - arc[seg]) / len, 0.0, 1.0) : 0.0;
                pts[side][k] = line[seg] + u * (line[seg + 1] - line[seg]);
            }
        }
        for (int k = 0; k < 9; ++k) {
            face->setPoint(pt::idx("h.1") + k, g.toImage(pts[0][k]));
            face->setPoint(pt::idx("h.19") - k, g.toImage(pts[1][k]));
        }
        face->setPoint(pt::idx("h.10"), g.toImage((pts[0][9] + pts[1][9]) / 2));
        rep.hairUsable = true;
    }

    // 5. Ears: the face region of skin colour (F_final also holds the background regions it
    // encloses, such as grey hair between a hat and the cheeks).
    Mask earC = faceC;
    if (rep.seed.skin.samples > 0) {
        for (int y = 0; y < w.size.height(); ++y)
            for (int x = 0; x < w.size.width(); ++x)
                if (earC.at(x, y) && colourDistance(work.pixel(x, y), rep.seed.skin) > skinLimit)
                    earC.at(x, y) = 0;
    }
    const double earH = std::max(g.noseBaseY - g.browY, 0.1 * d);
    const double run = std::max(2.0 * step, 0.06 * d);
    for (int side = 0; side < 2; ++side) {
        const double sx = side == 0 ? -1.0 : 1.0;
        const QPointF cheek = L(side == 0 ? "5.2" : "5.1"), jaw = L(side == 0 ? "2.14" : "2.13");
        auto contourX = [&](double y) {
            if (y <= cheek.y())
                return cheek.x();
            const double t = (y - cheek.y()) / std::max(jaw.y() - cheek.y(), 1e-6);
            return cheek.x() + std::min(t, 1.0) * (jaw.x() - cheek.x());
        };
        std::vector<double> ys, widths;
        int open = 0;
        for (double y = g.browY - 0.25 * earH; y <= g.noseBaseY + 0.25 * earH; y += step) {
            const double cx = contourX(y);
            double wd = 0, gapLen = 0;
            bool ended = false;
            for (double t = -0.05 * d; t <= 0.5 * d + run; t += step) {
                const QPointF q(cx + sx * t, y);
                if (!w.inWork(w.toWork(q)))
                    break;
                if (w.at(earC, q)) {
                    wd = t;
                    gapLen = 0;
                } else if ((gapLen += step) >= run) {
                    ended = true;
                    break;
                }
            }
            if (!ended) {
                wd = 0;
                ++open;
            }
            ys.push_back(y);
            widths.push_back(wd);
        }
        // The face region that does not end beside the cheek over half the rows is a
        // background of skin colour: no ear can be told from it.
        if (ys.empty() || open > int(ys.size()) / 2)
            continue;
        auto at = [&](double y, double out) { return g.toImage(QPointF(contourX(y) + sx * out, y)); };
        if (!placeEarFromProfile(face, side == 0, ys, widths, step, {0.08 * d, 0.45 * d, 0.4 * earH, 1.6 * earH}, at))
            continue;
        rep.earUsable[side] = true;
    }

    // Moved points stay in the photo, like the estimates.
    keepInPhoto(face, image.size(), [](int i) {
        const PointGroup grp = pointTable()[i].group;
        return grp == PointGroup::Hair || grp == PointGroup::Ears;
    });

    if (withDebugImages) {
        QImage mask(w.size, QImage::Format_ARGB32);
        mask.fill(Qt::transparent);
        for (int y = 0; y < w.size.height(); ++y)
            for (int x = 0; x < w.size.width(); ++x) {
                if (faceC.at(x, y))
                    mask.setPixel(x, y, qRgba(240, 200, 160, 170));
                else if (hairC.at(x, y))
                    mask.setPixel(x, y, qRgba(120, 60, 20, 200));
                else if (refined.hair.at(x, y))
                    mask.setPixel(x, y, qRgba(60, 60, 200, 120)); // dark, but not the head's hair
            }
        QImage canvas(image.size(), QImage::Format_ARGB32_Premultiplied);
        canvas.fill(Qt::transparent);
        QPainter p(&canvas);
        p.drawImage(QRectF(w.crop), mask);
        p.setPen(QPen(Qt::yellow, std::max(1.0, 1.0 / w.scale)));
        p.setBrush(Qt::NoBrush);
        p.drawRect(rep.seed.rect);
        p.end();
        rep.regionImage = canvas;
    }
    return rep;
}

} // namespace toonface
