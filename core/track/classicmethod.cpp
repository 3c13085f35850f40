#include "detect/classic.h"

#include "detect/regions.h"
#include "i18n/coretext.h"
#include "track/trackingmethod.h"

#include <QLineF>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace toonface {

namespace {

// Thesis chapter 6. What the neutral face reserved (TrackingSeed) is carried from frame to
// frame: the eyeball regions, their distance d, the mouth region; t1 and the edge thresholds
// stay the neutral's.
class ClassicMethod : public TrackingMethod
{
public:
    explicit ClassicMethod(const DetectionResult &neutral)
        : m_seed(neutral.tracking)
        , m_neutralPoints(neutral.face.points())
    {
        for (int k = 0; k < 2; ++k)
            m_eyes[k] = m_seed.eyeballs[k];
        m_mouth = m_seed.mouth;
        m_d = m_seed.d > 0 ? m_seed.d : QLineF(m_eyes[0], m_eyes[1]).length();
        for (int k = 0; k < 2; ++k) {
            const double r = std::max(2.0, m_seed.eyeballRadius[k]);
            m_eyeBoxes[k] = QRectF(m_eyes[k] - QPointF(1.6 * r, r), QSizeF(3.2 * r, 2 * r));
        }
        m_stable = {pt::idx("3.6"), pt::idx("3.5")};
    }

    QString name() const override { return detectionMethodName(DetectionMethod::Classic); }

    void forget() override
    {
        for (int k = 0; k < 2; ++k)
            m_eyes[k] = m_seed.eyeballs[k];
        m_mouth = m_seed.mouth;
    }

    FaceMeasurement measure(const QImage &frame) override
    {
        FaceMeasurement m;
        m.stable = m_stable;
        const double d = m_d;
        const QPointF mid = (m_eyes[0] + m_eyes[1]) / 2;
        // The working crop: the face around the eyes and the mouth.
        const QRect crop
            = QRectF(mid.x() - 1.5 * d, mid.y() - d, 3 * d, 3.2 * d).toAlignedRect().intersected(frame.rect());
        if (crop.width() < 8 || crop.height() < 8)
            return m;
        const Plane I = intensityPlane(frame.copy(crop));
        const QPointF origin = crop.topLeft();

        // 6.2 steps 2-5: B1' (dark: I <= t1) around each old eyeball, the region grown from it.
        struct EyeFound
        {
            bool ok = false;
            QRectF box;
            QPointF centre;
        } eyes[2];
        for (int k = 0; k < 2; ++k) {
            const QPointF c = m_eyes[k] - origin;
            const QRect window = QRectF(c.x() - 0.4 * d, c.y() - 0.3 * d, 0.8 * d, 0.6 * d)
                                     .toAlignedRect()
                                     .intersected(QRect(QPoint(0, 0), I.size));
            if (window.isEmpty())
                continue;
            Mask dark {window.size(), std::vector<std::uint8_t>(size_t(window.width()) * window.height(), 0)};
            for (int y = 0; y < window.height(); ++y)
                for (int x = 0; x < window.width(); ++x)
                    dark.at(x, y) = I.at(window.left() + x, window.top() + y) <= m_seed.t1 ? 1 : 0;
            std::vector<int> labels;
            const std::vector<Region> regions = growRegions(dark, 1, &labels);
            const QPointF seed = c - QPointF(window.topLeft());
            int best = -1;
            double bestDistance = 0.3 * d;
            for (int i = 0; i < int(regions.size()); ++i) {
                const double dist = QLineF(regions[i].centroid, seed).length();
                if (regions[i].area >= 3 && dist < bestDistance) {
                    bestDistance = dist;
                    best = i;
                }
            }
            if (best < 0)
                continue;
            Mask region {dark.size, std::vector<std::uint8_t>(dark.values.size(), 0)};
            for (size_t i = 0; i < labels.size(); ++i)
                region.values[i] = labels[i] == best + 1 ? 1 : 0;
            const Eyeball ball = detectEyeball(region, regions[best].box, 0.8);
            eyes[k].ok = true;
            eyes[k].box = QRectF(regions[best].box).translated(window.topLeft() + origin);
            eyes[k].centre = ball.centre + QPointF(window.topLeft()) + origin;
        }
        // Step 4: the pair must still look like an eye pair (distance and tilt); else the old
        // pair stands in.
        bool pair = eyes[0].ok && eyes[1].ok;
        if (pair) {
            const QLineF line(eyes[0].centre, eyes[1].centre);
            const double tilt = std::abs(std::atan2(line.dy(), line.dx())) * 180.0 / std::numbers::pi;
            pair = line.length() > 0.7 * d && line.length() < 1.3 * d && tilt < 20.0 && line.dx() > 0;
        }
        if (pair) {
            for (int k = 0; k < 2; ++k) {
                m_eyes[k] = eyes[k].centre;
                m_eyeBoxes[k] = eyes[k].box;
            }
        }

        // 6.3: the Sobel image thresholded by the part below Div_NM, grown from the old mouth region.
        const QRectF old = m_mouth.translated(-origin);
        const QRect mouthWindow
            = old.adjusted(-0.35 * old.width(), -0.6 * old.height(), 0.35 * old.width(), 0.9 * old.height())
                  .toAlignedRect()
                  .intersected(QRect(QPoint(0, 0), I.size));
        bool mouthFound = false;
        if (mouthWindow.width() > 4 && mouthWindow.height() > 4) {
            Plane sub {mouthWindow.size(), std::vector<float>(size_t(mouthWindow.width()) * mouthWindow.height())};
            for (int y = 0; y < sub.size.height(); ++y)
                for (int x = 0; x < sub.size.width(); ++x)
                    sub.at(x, y) = I.at(mouthWindow.left() + x, mouthWindow.top() + y);
            const Plane strength = sobelEdges(sub);
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
            Mask edges {sub.size, std::vector<std::uint8_t>(sub.values.size(), 0)};
            for (size_t i = 0; i < edges.values.size(); ++i)
                edges.values[i] = strength.values[i] > threshold ? 1 : 0;
            std::vector<int> labels;
            const std::vector<Region> regions = growRegions(edges, 1, &labels);
            // Seeds: the old region's central half.
            const QRectF seedBox
                = old.translated(-QPointF(mouthWindow.topLeft()))
                      .adjusted(0.2 * old.width(), 0.25 * old.height(), -0.2 * old.width(), -0.25 * old.height());
            QRect grown;
            for (const Region &r : regions) {
                if (r.area >= 4 && QRectF(r.box).intersects(seedBox))
                    grown = grown.united(r.box);
            }
            if (!grown.isEmpty() && grown.width() > 0.3 * old.width() && grown.width() < 2.0 * old.width()) {
                m_mouth = QRectF(grown).translated(QPointF(mouthWindow.topLeft()) + origin);
                mouthFound = true;
            }
        }

        // 6.4: the points. The head moves with the eyeballs; the rest of the face follows it.
        std::array<QPointF, kPointCount> neutralAtEyes = m_neutralPoints;
        const HeadMotion head = fitHeadMotion(neutralEyes(), eyesNow(), QVector<int> {pt::idx("3.6"), pt::idx("3.5")});
        for (int i = 0; i < kPointCount; ++i)
            neutralAtEyes[i] = head.map(m_neutralPoints[i]);
        m.points = neutralAtEyes;
        auto set = [&](const char *id, QPointF p) { m.points[pt::idx(id)] = p; };
        const char *ids[2][5] = {{"3.6", "3.12", "3.8", "3.2", "3.4"}, {"3.5", "3.11", "3.7", "3.1", "3.3"}};
        for (int k = 0; k < 2; ++k) {
            const QRectF &b = m_eyeBoxes[k];
            set(ids[k][0], m_eyes[k]);
            set(ids[k][1], QPointF(k == 0 ? b.left() : b.right(), m_eyes[k].y()));
            set(ids[k][2], QPointF(k == 0 ? b.right() : b.left(), m_eyes[k].y()));
            set(ids[k][3], QPointF(m_eyes[k].x(), b.top()));
            set(ids[k][4], QPointF(m_eyes[k].x(), b.bottom() + 1));
        }
        const QRectF &mb = m_mouth;
        const double cy = mb.center().y();
        set("8.4", QPointF(mb.left(), cy));
        set("8.3", QPointF(mb.right() + 1, cy));
        set("8.9", QPointF(mb.center().x() - mb.width() / 6, mb.top()));
        set("8.10", QPointF(mb.center().x() + mb.width() / 6, mb.top()));
        set("8.1", QPointF(mb.center().x(), mb.top()));
        set("8.2", QPointF(mb.center().x(), mb.bottom() + 1));
        // The inner lips: the dark rows (I <= t1) across the mouth's middle third.
        double gapTop = cy, gapBottom = cy;
        bool gap = false;
        const QRect inner = mb.translated(-origin).toAlignedRect().intersected(QRect(QPoint(0, 0), I.size));
        for (int y = inner.top(); y <= inner.bottom(); ++y) {
            double sum = 0;
            int n = 0;
            for (int x = inner.left() + inner.width() / 3; x < inner.left() + 2 * inner.width() / 3; ++x, ++n)
                sum += I.at(x, y);
            if (n > 0 && sum / n <= m_seed.t1) {
                gapTop = gap ? gapTop : y + origin.y();
                gapBottom = y + 1 + origin.y();
                gap = true;
            }
        }
        set("2.2", QPointF(mb.center().x(), gapTop));
        set("2.3", QPointF(mb.center().x(), gapBottom));
        m.found = true;
        m.confidence = 0.5 * (pair ? 1.0 : 0.5) * (mouthFound ? 1.0 : 0.6) + 0.2;
        return m;
    }

private:
    std::array<QPointF, kPointCount> neutralEyes() const { return m_neutralPoints; }
    std::array<QPointF, kPointCount> eyesNow() const
    {
        std::array<QPointF, kPointCount> p = m_neutralPoints;
        p[pt::idx("3.6")] = m_eyes[0];
        p[pt::idx("3.5")] = m_eyes[1];
        return p;
    }

    TrackingSeed m_seed;
    std::array<QPointF, kPointCount> m_neutralPoints;
    QPointF m_eyes[2];
    QRectF m_eyeBoxes[2];
    QRectF m_mouth;
    double m_d = 0;
    QVector<int> m_stable;
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
