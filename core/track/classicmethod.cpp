#include "detect/classic.h"

#include "detect/regions.h"
#include "i18n/coretext.h"
#include "track/facesearch.h"
#include "track/trackingmethod.h"

#include <QLineF>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

namespace toonface {

namespace {

// The intensity of a part of a frame, addressed in the frame's pixels.
struct Window
{
    QRect rect; // frame pixels
    Plane I;

    float at(int x, int y) const { return I.at(x - rect.left(), y - rect.top()); }
};

Window intensityWindow(const QImage &frame, const QRectF &area)
{
    Window w;
    w.rect = area.toAlignedRect().intersected(frame.rect());
    if (!w.rect.isEmpty())
        w.I = intensityPlane(frame.copy(w.rect));
    return w;
}

// The eye's window for its aperture: 0.44 d wide, 0.36 d high around the eyeball, below the
// brow (about 0.35 d above the eyeball) and above the cheek.
QRectF apertureBox(QPointF eyeball, double d)
{
    return {eyeball.x() - 0.22 * d, eyeball.y() - 0.18 * d, 0.44 * d, 0.36 * d};
}

double quantile(std::vector<float> values, double q)
{
    if (values.empty())
        return 0;
    const size_t i = std::min(values.size() - 1, size_t(q * double(values.size())));
    std::nth_element(values.begin(), values.begin() + i, values.end());
    return values[i];
}

double median(std::vector<float> values)
{
    return quantile(std::move(values), 0.5);
}

// The thickness of the dark across the window's middle: over the columns within `half` of its
// middle column, how many pixels each holds darker than `level`, mean over the columns. Between
// the lids: the iris and pupil, the lashes' line alone when they are shut; between the lips: the
// mouth's inside. With `ramp` > 0 a pixel counts in part
// within ramp / 2 of the level, so that sensor noise on pixels near it does not make the count
// jump.
double darkThickness(const Window &w, double level, int half, double ramp = 0)
{
    const int mid = w.I.size.width() / 2;
    double sum = 0;
    int columns = 0;
    for (int x = std::max(0, mid - half); x <= std::min(w.I.size.width() - 1, mid + half); ++x, ++columns) {
        for (int y = 0; y < w.I.size.height(); ++y) {
            const double below = level - w.I.at(x, y);
            sum += ramp > 0 ? std::clamp(below / ramp + 0.5, 0.0, 1.0) : below > 0 ? 1.0 : 0.0;
        }
    }
    return columns > 0 ? sum / columns : 0.0;
}

// The mouth's height in the middle of the mouth: over the central third of `seedBox`'s
// columns, the span from the first to the last edge pixel of `grown` (the edge regions grown
// from the seed), median over the columns; 0 when no column has an edge.
double centralHeight(const Mask &grown, const QRect &seedBox)
{
    std::vector<float> spans;
    const int x0 = std::max(0, seedBox.left() + seedBox.width() / 3);
    const int x1 = std::min(grown.size.width() - 1, seedBox.left() + 2 * seedBox.width() / 3);
    for (int x = x0; x <= x1; ++x) {
        int top = -1, bottom = -1;
        for (int y = 0; y < grown.size.height(); ++y) {
            if (grown.at(x, y)) {
                top = top < 0 ? y : top;
                bottom = y;
            }
        }
        if (top >= 0)
            spans.push_back(float(bottom - top + 1));
    }
    return median(std::move(spans));
}

// How far the mouth's relative edges wander on a still mouth (sensor noise).
constexpr double kMouthNoise = 0.1;
// The face's look is sampled on a grid this fine; a look correlating less than kLostLikeness
// with the neutral frame's is not the face.
constexpr int kLookGrid = 24;
constexpr double kLostLikeness = 0.5;
// A face searched for while lost is taken as found where its look correlates at least this well
// at the search's coarse scale (the look on the full grid then decides, as on every frame).
constexpr double kSearchLikeness = 0.6;

// Thesis chapter 6 on what the neutral face reserved (TrackingSeed): t1, the eyeball regions
// and their distance d, the edge thresholds and the mouth region R_Mouth. The first frame
// measured is the neutral one: its eyeballs, the dark between its lids and its mouth's edges
// are what later frames are compared with.
class ClassicMethod : public TrackingMethod
{
public:
    explicit ClassicMethod(const DetectionResult &neutral)
        : m_seed(neutral.tracking)
        , m_neutralPoints(neutral.face.points())
    {
        m_d = m_seed.d > 0 ? m_seed.d : QLineF(m_seed.eyeballs[0], m_seed.eyeballs[1]).length();
        for (int k = 0; k < 2; ++k) {
            m_radius[k] = std::clamp(m_seed.eyeballRadius[k], 0.04 * m_d, 0.12 * m_d);
            m_neutralEyes[k] = m_seed.eyeballs[k];
        }
        forget();
        m_stable = {pt::idx("3.6"), pt::idx("3.5")};
    }

    QString name() const override { return detectionMethodName(DetectionMethod::Classic); }

    void forget() override
    {
        for (int k = 0; k < 2; ++k)
            m_eyes[k] = m_neutralEyes[k];
    }

    FaceMeasurement measure(const QImage &frame) override
    {
        FaceMeasurement m;
        m.stable = m_stable;
        if (frame.isNull())
            return m;
        if (m_lost)
            searchFace(frame);
        trackEyePair(frame);
        if (!m_haveReference)
            trackEyePair(frame); // from where the neutral's eyeballs were found: the place later frames settle on

        // The head's motion since the neutral frame, from the eyeballs (thesis 6.4: the face
        // moves with them); the reserved regions are carried along.
        const HeadMotion head = motionTo(m_eyes[0], m_eyes[1]);
        const double scale = head.scale();

        double openness[2] = {1.0, 1.0};
        for (int k = 0; k < 2; ++k) {
            const Window w = intensityWindow(frame, apertureBox(m_eyes[k], m_d * scale));
            if (w.rect.isEmpty())
                continue;
            if (!m_haveReference) {
                m_eyeLevel[k] = (median(w.I.values) + quantile(w.I.values, 0.03)) / 2;
                m_eyeDarkness[k] = darkThickness(w, m_eyeLevel[k], int(m_radius[k] * scale));
            }
            const double dark = darkThickness(w, m_eyeLevel[k], int(m_radius[k] * scale));
            openness[k] = m_eyeDarkness[k] > 0 ? std::clamp(dark / m_eyeDarkness[k], 0.0, 2.0) : 1.0;
        }

        if (!m_haveReference)
            placeMouth(frame);
        const MouthFound mouth = trackMouth(frame, head);
        if (!m_haveReference) {
            m_mouthEdges = mouth.edges;
            m_mouthWidth = mouth.width;
            m_appearance = appearance(frame, HeadMotion {});
            m_search = std::make_unique<FaceSearch>(frame, lookBox());
            m_haveReference = true;
        } else if (likeness(appearance(frame, head), m_appearance) < kLostLikeness) {
            // What the head's place shows is no longer the face: lost (the tracker holds the last
            // pose); the next frames search the whole frame for it.
            m_lost = true;
            return m;
        }
        m_lost = false;
        // The opening: the dark between the lips in the mouth's middle (the gap's thickness,
        // 0 when shut), plus the growth of the middle's Sobel edges (the inner lips, the teeth:
        // they also see a gap the teeth fill) relative to the neutral's, above the least seen
        // so far (the neutral frame may show the mouth parted). A mouth opened wide about
        // doubles its edges; its lips' gap is then about 0.15 d.
        double opening = mouth.gap;
        if (m_mouthEdges > 0) {
            const double v = mouth.edges / m_mouthEdges;
            // Sensor noise moves v by a few hundredths from frame to frame: the floor follows
            // only drops beyond it, or it would sink with the noise and lift a still mouth.
            m_mouthShut = std::min(m_mouthShut, v + kMouthNoise);
            // Capped: a mouth shut on the neutral frame has few edges to grow from.
            opening += 0.15 * m_d * scale * std::clamp(v - m_mouthShut, 0.0, 2.0);
        }
        const double widening = mouth.found ? mouth.width - m_mouthWidth : 0.0;

        // 6.4: the points. The head carries the neutral face; the lids and the mouth move by
        // what was measured.
        for (int i = 0; i < kPointCount; ++i)
            m.points[i] = head.map(m_neutralPoints[i]);
        auto at = [&](const char *id) -> QPointF & { return m.points[pt::idx(id)]; };
        at("3.6") = m_eyes[0];
        at("3.5") = m_eyes[1];
        const char *lids[2][2] = {{"3.2", "3.4"}, {"3.1", "3.3"}};
        for (int k = 0; k < 2; ++k) {
            QPointF &upper = at(lids[k][0]);
            QPointF &lower = at(lids[k][1]);
            const QPointF shut = (lower - upper) * ((1.0 - openness[k]) / 2.0);
            upper += shut;
            lower -= shut;
        }
        at("2.3") = at("2.2") + QPointF(0, opening);
        at("8.2") += QPointF(0, opening);
        at("8.4") -= QPointF(widening / 2, 0);
        at("8.3") += QPointF(widening / 2, 0);
        m.found = true;
        // The old pair standing in (a blink, a lash line taken for an eyeball) is still the face.
        m.confidence = 0.5 * (m_pairFound ? 1.0 : 0.8) * (mouth.found ? 1.0 : 0.6) + 0.2;
        return m;
    }

private:
    // 6.2 steps 2-3 for eye k: B1' (dark: I <= t1) around `guess`, the dark region nearest it
    // (within 0.15 d), the eyeball in that region near the guess. Nothing where none is (a shut
    // eye leaves the lashes' line: no eyeball in it).
    std::optional<QPointF> findEyeball(const QImage &frame, int k, QPointF guess) const
    {
        const double d = m_d;
        const Window w = intensityWindow(frame, QRectF(guess.x() - 0.3 * d, guess.y() - 0.2 * d, 0.6 * d, 0.4 * d));
        if (w.rect.width() < 3 || w.rect.height() < 3)
            return std::nullopt;
        Mask dark {w.I.size, std::vector<std::uint8_t>(w.I.values.size(), 0)};
        for (size_t i = 0; i < dark.values.size(); ++i)
            dark.values[i] = w.I.values[i] <= m_seed.t1 ? 1 : 0;
        std::vector<int> labels;
        const std::vector<Region> regions = growRegions(dark, 1, &labels);
        const QPointF seed = guess - QPointF(w.rect.topLeft());
        int best = -1;
        double bestDistance = 0.15 * d;
        for (int i = 0; i < int(regions.size()); ++i) {
            const double dist = QLineF(regions[i].centroid, seed).length();
            if (regions[i].area >= 3 && dist < bestDistance) {
                bestDistance = dist;
                best = i;
            }
        }
        if (best < 0)
            return std::nullopt;
        Mask region {dark.size, std::vector<std::uint8_t>(dark.values.size(), 0)};
        for (size_t i = 0; i < labels.size(); ++i)
            region.values[i] = labels[i] == best + 1 ? 1 : 0;
        // The eyeball is searched for near the old one only: a region merged with a brow or
        // a rim would otherwise cost a search over all of it.
        const double r = m_radius[k];
        const QRect near = QRectF(seed.x() - 1.5 * r, seed.y() - 1.5 * r, 3 * r, 3 * r).toAlignedRect();
        const Eyeball ball = detectEyeball(region, regions[best].box.intersected(near), 0.8);
        if (ball.radius < 0.5 * r)
            return std::nullopt;
        return ball.centre + QPointF(w.rect.topLeft()) + QPointF(0.5, 0.5);
    }

    // 6.2 steps 2-5: the eyeballs near the old ones (findEyeball); step 4: the pair must still
    // look like the eye pair (distance, tilt, a small step from the pair before), else the old
    // pair stands in.
    void trackEyePair(const QImage &frame)
    {
        QPointF found[2];
        bool ok[2] = {false, false};
        const double d = m_d;
        for (int k = 0; k < 2; ++k) {
            if (const std::optional<QPointF> ball = findEyeball(frame, k, m_eyes[k])) {
                found[k] = *ball;
                ok[k] = true;
            }
        }
        m_pairFound = false;
        if (ok[0] && ok[1]) {
            const QLineF line(found[0], found[1]);
            const QLineF old(m_eyes[0], m_eyes[1]);
            const double tilt = std::abs(std::atan2(line.dy(), line.dx())) * 180.0 / std::numbers::pi;
            // The eyes move together: a head turns, nods and leans a little between frames. One
            // eye stepping alone has lost its eyeball to a lash line, a brow or a rim.
            const QPointF step0 = found[0] - m_eyes[0], step1 = found[1] - m_eyes[1];
            m_pairFound = line.dx() > 0 && tilt < 20.0 && std::abs(line.length() - old.length()) < 0.1 * d
                && QLineF(step0, QPointF()).length() < 0.15 * d && QLineF(step1, QPointF()).length() < 0.15 * d
                && QLineF(step0, step1).length() < 0.06 * d;
        }
        if (!m_haveReference) {
            // The neutral frame: the eyeballs found on it are where later frames start from
            // (the detection's may lie a pixel or more off on the pixels found here).
            for (int k = 0; k < 2; ++k) {
                if (ok[k])
                    m_eyes[k] = m_neutralEyes[k] = found[k];
            }
            m_pairFound = ok[0] && ok[1];
        } else if (m_pairFound) {
            m_eyes[0] = found[0];
            m_eyes[1] = found[1];
        }
    }

    // The neutral face's eyes, brows and mouth, frame pixels.
    QRectF lookBox() const
    {
        const QPointF mid = (m_neutralEyes[0] + m_neutralEyes[1]) / 2;
        return {mid.x() - 0.8 * m_d, mid.y() - 0.35 * m_d, 1.6 * m_d, 1.7 * m_d};
    }

    // A lost face may come back anywhere and at another size: where its look is found, the eyes
    // are searched for next (they stay where they were when it is not). The look, a small grey
    // picture, may prefer a size a step off (a mouth opened since the neutral frame stretches the
    // face), and the eyes put by a wrong size lie a tenth of d off: the pair's distance would be
    // wrong on every later frame and the mouth looked for in the wrong place. So the eyes decide:
    // at each size whose look is still the face's (kLostLikeness) the eyeballs are looked for
    // around where that size puts them, and of the pairs found the one under which the face's
    // look (the full grid, as on every frame) is likest the neutral's is taken; where no size
    // finds both eyeballs, the best look's place.
    void searchFace(const QImage &frame)
    {
        if (!m_search || !m_search->isValid())
            return;
        const std::vector<FaceSearchHit> hits = m_search->findEachSize(frame);
        const auto best = std::max_element(
            hits.begin(), hits.end(), [](const auto &a, const auto &b) { return a.likeness < b.likeness; });
        if (best == hits.end() || best->likeness < kSearchLikeness)
            return;
        const QRectF neutral = lookBox();
        auto eyesOf = [&](const FaceSearchHit &hit, int k) {
            const double s = hit.box.width() / neutral.width();
            return hit.box.topLeft() + (m_neutralEyes[k] - neutral.topLeft()) * s;
        };
        for (int k = 0; k < 2; ++k)
            m_eyes[k] = eyesOf(*best, k);
        double bestLook = kLostLikeness;
        for (const FaceSearchHit &hit : hits) {
            if (hit.likeness < kLostLikeness)
                continue;
            const std::optional<QPointF> l = findEyeball(frame, 0, eyesOf(hit, 0)),
                                         r = findEyeball(frame, 1, eyesOf(hit, 1));
            if (!l || !r || !(r->x() > l->x()))
                continue;
            const double look = likeness(appearance(frame, motionTo(*l, *r)), m_appearance);
            if (look > bestLook) {
                bestLook = look;
                m_eyes[0] = *l;
                m_eyes[1] = *r;
            }
        }
    }

    // The head's motion that carries the neutral eyeballs to `left` and `right`.
    HeadMotion motionTo(QPointF left, QPointF right) const
    {
        std::array<QPointF, kPointCount> from = m_neutralPoints, to = m_neutralPoints;
        from[pt::idx("3.6")] = m_neutralEyes[0];
        from[pt::idx("3.5")] = m_neutralEyes[1];
        to[pt::idx("3.6")] = left;
        to[pt::idx("3.5")] = right;
        return fitHeadMotion(from, to, m_stable);
    }

    // The face's look: the grey levels on a grid over the eyes and the mouth of the neutral
    // face, carried by `head`.
    std::vector<float> appearance(const QImage &frame, const HeadMotion &head) const
    {
        const QRectF box = lookBox();
        std::vector<float> out;
        out.reserve(size_t(kLookGrid) * kLookGrid);
        for (int v = 0; v < kLookGrid; ++v) {
            for (int u = 0; u < kLookGrid; ++u) {
                const QPointF at = head.map(
                    box.topLeft() + QPointF((u + 0.5) * box.width() / kLookGrid, (v + 0.5) * box.height() / kLookGrid));
                const QPoint p = at.toPoint();
                out.push_back(frame.rect().contains(p) ? float(qGray(frame.pixel(p))) : 0.0f);
            }
        }
        return out;
    }

    // Normalised cross-correlation of two looks: 1 the same up to brightness and contrast, 0 for
    // nothing in common (or a flat picture).
    static double likeness(const std::vector<float> &a, const std::vector<float> &b)
    {
        if (a.size() != b.size() || a.empty())
            return 0;
        double ma = 0, mb = 0;
        for (size_t i = 0; i < a.size(); ++i) {
            ma += a[i];
            mb += b[i];
        }
        ma /= double(a.size());
        mb /= double(b.size());
        double ab = 0, aa = 0, bb = 0;
        for (size_t i = 0; i < a.size(); ++i) {
            ab += (a[i] - ma) * (b[i] - mb);
            aa += (a[i] - ma) * (a[i] - ma);
            bb += (b[i] - mb) * (b[i] - mb);
        }
        return aa > 0 && bb > 0 ? ab / std::sqrt(aa * bb) : 0.0;
    }

    struct MouthFound
    {
        bool found = false;
        double height = 0; // in the mouth's middle, frame pixels
        double width = 0;
        double edges = 0; // Sobel strength in the mouth's middle, per pixel
        double gap = 0; // the dark between the lips, frame pixels
    };

    // The neutral frame's mouth: R_Mouth where it holds the lip line (the darkest row below the
    // eye pair, mouthRowContrast()), else a box of a mouth's size on that line.
    void placeMouth(const QImage &frame)
    {
        m_mouthBox = m_seed.mouth;
        const QPointF mid = (m_eyes[0] + m_eyes[1]) / 2;
        const double d = QLineF(m_eyes[0], m_eyes[1]).length();
        const Window w = intensityWindow(frame, QRectF(mid.x() - 0.6 * d, mid.y() - 0.1 * d, 1.2 * d, 1.8 * d));
        if (w.rect.isEmpty())
            return;
        double row = 0;
        const QPointF o(w.rect.topLeft());
        if (mouthRowContrast(w.I, m_eyes[0] - o, m_eyes[1] - o, &row) < 0.5 * kMinMouthRowContrast)
            return;
        const QPointF lip = mid + QPointF(0, row);
        if (m_mouthBox.adjusted(0, -0.1 * m_mouthBox.height(), 0, 0.1 * m_mouthBox.height()).contains(lip)
            && std::abs(m_mouthBox.center().x() - mid.x()) < 0.1 * d)
            return;
        m_mouthBox = QRectF(lip.x() - 0.3 * d, lip.y() - 0.12 * d, 0.6 * d, 0.24 * d);
    }

    // 6.3: the Sobel image thresholded by the reserved edge threshold of the part below Div_NM,
    // the regions grown from the reserved R_Mouth (carried by the head), their extent.
    MouthFound trackMouth(const QImage &frame, const HeadMotion &head)
    {
        MouthFound out;
        const QRectF reserved = m_mouthBox;
        const double s = head.scale();
        const QPointF centre = head.map(reserved.center());
        const QSizeF size = reserved.size() * s;
        const QRectF mapped(centre - QPointF(size.width(), size.height()) / 2, size);
        const QRectF area = mapped.adjusted(
            -0.3 * size.width(), -0.6 * size.height(), 0.3 * size.width(), 1.2 * size.height() + 0.25 * m_d * s);
        const Window w = intensityWindow(frame, area);
        if (w.rect.width() < 5 || w.rect.height() < 5)
            return out;
        const Plane strength = sobelEdges(w.I);
        double threshold = m_seed.edgeThresholds[3];
        if (!(threshold > 0)) {
            double sum = 0, sq = 0;
            for (float v : strength.values) {
                sum += v;
                sq += double(v) * v;
            }
            const double n = double(strength.values.size());
            threshold = sum / n + std::sqrt(std::max(0.0, sq / n - (sum / n) * (sum / n)));
        }
        Mask edges {strength.size, std::vector<std::uint8_t>(strength.values.size(), 0)};
        for (size_t i = 0; i < edges.values.size(); ++i)
            edges.values[i] = strength.values[i] > threshold ? 1 : 0;
        std::vector<int> labels;
        const std::vector<Region> regions = growRegions(edges, 1, &labels);
        // Seeds: the reserved region's central part.
        const QRect seedBox
            = mapped.translated(-QPointF(w.rect.topLeft()))
                  .adjusted(0.2 * size.width(), 0.2 * size.height(), -0.2 * size.width(), -0.2 * size.height())
                  .toAlignedRect();
        std::vector<bool> keep(regions.size() + 1, false);
        QRect grownBox;
        for (const Region &r : regions) {
            if (r.area >= 4 && r.box.intersects(seedBox)) {
                keep[size_t(r.label)] = true;
                grownBox = grownBox.united(r.box);
            }
        }
        Mask grown {edges.size, std::vector<std::uint8_t>(edges.values.size(), 0)};
        for (size_t i = 0; i < labels.size(); ++i)
            grown.values[i] = labels[i] > 0 && keep[size_t(labels[i])] ? 1 : 0;
        out.height = centralHeight(grown, seedBox.adjusted(-seedBox.width() / 2, 0, seedBox.width() / 2, 0));
        out.width = grownBox.width();
        out.found = out.height > 0;
        // The mouth's middle: 0.4 d wide, from above the lip line down to where an open mouth's
        // lower lip reaches. Opening darkens it (the gap) and adds edges (the inner lips, the teeth).
        const double dd = m_d * s;
        const QRect band = QRectF(centre.x() - 0.2 * dd, centre.y() - 0.12 * dd, 0.4 * dd, 0.45 * dd)
                               .toAlignedRect()
                               .translated(-w.rect.topLeft())
                               .intersected(QRect(QPoint(1, 1), w.I.size - QSize(2, 2)));
        if (band.isEmpty())
            return out;
        std::vector<float> values;
        values.reserve(size_t(band.width()) * band.height());
        double edgeSum = 0;
        for (int y = band.top(); y <= band.bottom(); ++y) {
            for (int x = band.left(); x <= band.right(); ++x) {
                edgeSum += strength.at(x, y);
                values.push_back(w.I.at(x, y));
            }
        }
        if (!m_haveReference)
            m_mouthLevel = median(values);
        out.edges = edgeSum / double(values.size());
        if (!m_haveReference)
            m_gapLevel = (m_mouthLevel + quantile(values, 0.03)) / 2;
        {
            Window middle;
            middle.I = Plane {band.size(), std::vector<float>(values.begin(), values.end())};
            out.gap = darkThickness(middle, m_gapLevel, int(0.1 * dd), m_mouthLevel - m_gapLevel);
        }
        return out;
    }

    TrackingSeed m_seed;
    std::array<QPointF, kPointCount> m_neutralPoints;
    QPointF m_eyes[2];
    QPointF m_neutralEyes[2]; // the eyeballs on the neutral frame
    double m_radius[2] = {1, 1};
    double m_d = 0;
    bool m_pairFound = false;
    QVector<int> m_stable;
    // Measured on the neutral (first) frame.
    bool m_haveReference = false;
    std::vector<float> m_appearance; // the neutral frame's look (appearance())
    std::unique_ptr<FaceSearch> m_search; // the same look, searched for over a frame
    bool m_lost = false;
    double m_eyeLevel[2] = {0, 0};
    double m_eyeDarkness[2] = {0, 0};
    double m_mouthWidth = 0;
    double m_mouthLevel = 0;
    double m_mouthEdges = 0;
    double m_gapLevel = 0;
    double m_mouthShut = 1.0; // the least relative edges seen (plus kMouthNoise)
    QRectF m_mouthBox;
};

} // namespace

std::unique_ptr<TrackingMethod> makeClassicMethod(const DetectionResult &neutral, QString *error)
{
    if (!neutral.tracking.valid || neutral.tracking.mouth.isEmpty()
        || QLineF(neutral.tracking.eyeballs[0], neutral.tracking.eyeballs[1]).length() < 4) {
        if (error)
            *error = VideoText::tr("the neutral face's detection kept no tracking seed (thresholds, eyeballs, "
                                   "mouth region) for the classic method");
        return nullptr;
    }
    return std::make_unique<ClassicMethod>(neutral);
}

} // namespace toonface
