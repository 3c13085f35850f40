#include "detect/landmarkmap.h"

#include "i18n/coretext.h"

#include <QFile>
#include <QLineF>
#include <QRectF>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace toonface {

namespace {

using Ibug = std::array<QPointF, kIbugPointCount>;

QPointF meanOf(const Ibug &p, const std::vector<int> &indices)
{
    QPointF sum;
    for (int i : indices)
        sum += p[i];
    return sum / double(indices.size());
}

// The scored correspondences of shared/data/README.md: Toonface ID -> iBUG indices whose mean
// is the point. The mapping places these points exactly so.
struct Correspondence
{
    const char *id;
    std::vector<int> ibug;
};

const std::vector<Correspondence> &correspondences()
{
    static const std::vector<Correspondence> table = {
        {"3.12", {36}},
        {"3.7", {45}},
        {"3.8", {39}},
        {"3.11", {42}},
        {"3.2", {37, 38}},
        {"3.1", {43, 44}},
        {"3.4", {40, 41}},
        {"3.3", {46, 47}},
        {"3.6", {36, 37, 38, 39, 40, 41}},
        {"3.5", {42, 43, 44, 45, 46, 47}},
        {"4.6", {17}},
        {"4.5", {26}},
        {"4.2", {21}},
        {"4.1", {22}},
        {"9.4", {31}},
        {"9.5", {35}},
        {"9.15", {33}},
        {"2.1", {8}},
        {"8.4", {48}},
        {"8.3", {54}},
        {"8.9", {50}},
        {"8.10", {52}},
        {"8.1", {51}},
        {"8.2", {57}},
        {"2.2", {62}},
        {"2.3", {66}},
    };
    return table;
}

// The face's own frame: origin at EyeMid (between the eyeball centres), x along the eye line
// toward the image-right eye, y perpendicular to it pointing down the face. Rules written
// for an upright face ("at eye level", "above the brows") are applied in this frame.
struct FaceFrame
{
    QPointF origin;
    QPointF ex {1, 0};
    QPointF ey {0, 1};

    QPointF toLocal(QPointF p) const
    {
        const QPointF d = p - origin;
        return {d.x() * ex.x() + d.y() * ex.y(), d.x() * ey.x() + d.y() * ey.y()};
    }
    QPointF toImage(QPointF l) const { return origin + l.x() * ex + l.y() * ey; }
};

// One half of the jaw line in the face frame, from its upper end (iBUG 0 or 16) to the chin
// (iBUG 8), as a polyline that can be cut at a height or walked along.
class JawHalf
{
public:
    JawHalf(const Ibug &p, const FaceFrame &f, bool imageLeft)
    {
        for (int k = 0; k <= 8; ++k)
            m_pts.push_back(f.toLocal(p[imageLeft ? k : 16 - k]));
    }

    // The contour point at height y, as a polyline parameter (segment index + fraction).
    // Above the upper end the contour continues straight up (the head side above the jaw
    // is close to vertical up to the temples); below the chin it stops at the chin.
    double paramAtLevel(double y) const
    {
        if (y <= m_pts.front().y())
            return 0;
        for (size_t k = 0; k + 1 < m_pts.size(); ++k) {
            const double y0 = m_pts[k].y(), y1 = m_pts[k + 1].y();
            if ((y >= y0 && y <= y1) || (y <= y0 && y >= y1)) {
                const double span = y1 - y0;
                return double(k) + (std::abs(span) < 1e-9 ? 0.0 : (y - y0) / span);
            }
        }
        return double(m_pts.size() - 1);
    }

    QPointF atLevel(double y) const
    {
        if (y < m_pts.front().y())
            return {m_pts.front().x(), y};
        return at(paramAtLevel(y));
    }

    QPointF at(double t) const
    {
        const int k = std::clamp(int(std::floor(t)), 0, int(m_pts.size()) - 2);
        const double u = std::clamp(t - k, 0.0, 1.0);
        return m_pts[k] + u * (m_pts[k + 1] - m_pts[k]);
    }

    double arcLength(double t) const
    {
        double s = 0;
        const int whole = std::clamp(int(std::floor(t)), 0, int(m_pts.size()) - 1);
        for (int k = 0; k < whole; ++k)
            s += QLineF(m_pts[k], m_pts[k + 1]).length();
        if (whole < int(m_pts.size()) - 1)
            s += QLineF(m_pts[whole], at(t)).length();
        return s;
    }

    QPointF atArcLength(double s) const
    {
        for (size_t k = 0; k + 1 < m_pts.size(); ++k) {
            const double len = QLineF(m_pts[k], m_pts[k + 1]).length();
            if (s <= len)
                return len < 1e-9 ? m_pts[k] : m_pts[k] + (s / len) * (m_pts[k + 1] - m_pts[k]);
            s -= len;
        }
        return m_pts.back();
    }

    QPointF chin() const { return m_pts.back(); }

private:
    std::vector<QPointF> m_pts;
};

} // namespace

FaceModel faceFromLandmarks68(const Ibug &p, QSize imageSize)
{
    FaceModel face(imageSize);
    for (const Correspondence &c : correspondences())
        face.setPoint(pt::idx(c.id), meanOf(p, c.ibug));

    FaceFrame f;
    const QPointF eyeL = face.point("3.6"), eyeR = face.point("3.5");
    f.origin = (eyeL + eyeR) / 2;
    const double es0 = QLineF(eyeL, eyeR).length();
    if (es0 > 1e-6) {
        f.ex = (eyeR - eyeL) / es0;
        f.ey = QPointF(-f.ex.y(), f.ex.x());
    }
    auto L = [&](int i) { return f.toLocal(p[i]); };
    auto set = [&](const char *id, QPointF local) { face.setPoint(pt::idx(id), f.toImage(local)); };

    // Eyebrows (Algorithm 4.2): between the brow's ends, 4.4a and 4.4 are the centres of its
    // outer and inner halves; iBUG 18..20 run along the brow, so the halves' centres are the
    // midpoints 18-19 and 19-20 (23-24 and 24-25 on the image-right brow).
    face.setPoint(pt::idx("4.4a"), (p[18] + p[19]) / 2);
    face.setPoint(pt::idx("4.4"), (p[19] + p[20]) / 2);
    face.setPoint(pt::idx("4.3"), (p[23] + p[24]) / 2);
    face.setPoint(pt::idx("4.3a"), (p[24] + p[25]) / 2);

    // Nose (Algorithm 4.4). The nose region [x1, x2] x [y1, y2]: the nostril bottoms 9.4/9.5
    // (iBUG 31/35) lie an eighth of its width inside its sides, so x1 = 31.x - w/8 with
    // w = (35.x - 31.x) * 4/3; y2 is the nostril line (mean of iBUG 31..35); y1, the top of
    // the nose's sides, is iBUG 28, a third of the way down the bridge.
    const double x31 = L(31).x(), x35 = L(35).x();
    const double w = (x35 - x31) * 4.0 / 3.0;
    const double x1 = x31 - w / 8, x2 = x35 + w / 8;
    const double y1 = L(28).y();
    const double y2 = (L(31).y() + L(32).y() + L(33).y() + L(34).y() + L(35).y()) / 5;
    const double x38 = f.toLocal(face.point("3.8")).x(), x311 = f.toLocal(face.point("3.11")).x();
    set("9.6", {x38 + (x311 - x38) / 3, 0.0}); // step 3, at EyeMid.y (the frame's y = 0)
    set("9.7", {x311 - (x311 - x38) / 3, 0.0});
    set("9.14", {x1 + w / 8, y1}); // step 4
    set("9.13", {x2 - w / 8, y1});
    set("9.2", {x1, (y1 + 3 * y2) / 4}); // step 5
    set("9.1", {x2, (y1 + 3 * y2) / 4});

    // Contour: the cheeks 5.2/5.1 are the jaw line at eye level, the jaw points 2.14/2.13 the
    // jaw line at the level of the mouth corners (4.3.2 A step 2), and the lower jaw points
    // 2.12/2.11 lie halfway along the jaw line from there to the chin.
    const JawHalf jawL(p, f, true), jawR(p, f, false);
    const double mouthY = (L(48).y() + L(54).y()) / 2;
    set("5.2", jawL.atLevel(0));
    set("5.1", jawR.atLevel(0));
    set("2.14", jawL.atLevel(mouthY));
    set("2.13", jawR.atLevel(mouthY));
    const double tL = jawL.paramAtLevel(mouthY), tR = jawR.paramAtLevel(mouthY);
    set("2.12", jawL.atArcLength((jawL.arcLength(tL) + jawL.arcLength(8)) / 2));
    set("2.11", jawR.atArcLength((jawR.arcLength(tR) + jawR.arcLength(8)) / 2));

    // Forehead and hair: estimateForeheadAndHair().
    const HeadGeometry g = estimateForeheadAndHair(&face);
    const double cheekLX = g.toLocal(face.point("5.2")).x(), cheekRX = g.toLocal(face.point("5.1")).x();
    const double halfL = std::max(g.midX - cheekLX, 0.1 * es0), halfR = std::max(cheekRX - g.midX, 0.1 * es0);

    // Ears, by the usual frontal proportions: the ear's top is at brow level and its lobe's
    // bottom at the nose base; it stands out of the head contour by up to a fifth of the
    // half-face width (10.4, outermost, a third of the way down), its top (10.2) and lobe
    // bottom (10.6) less; the lobe meets the cheek (10.10) on the contour just above the
    // lobe's bottom.
    const double earH = std::max(g.noseBaseY - g.browY, 0.1 * es0);
    auto ear = [&](const JawHalf &jaw, double half, double side, const char *top, const char *outer, const char *lobe,
                   const char *junction) {
        const double out = 0.2 * half * side;
        set(top, jaw.atLevel(g.browY) + QPointF(0.3 * out, 0));
        set(outer, jaw.atLevel(g.browY + 0.35 * earH) + QPointF(out, 0));
        set(lobe, jaw.atLevel(g.noseBaseY) + QPointF(0.4 * out, 0));
        set(junction, jaw.atLevel(g.noseBaseY - 0.12 * earH));
    };
    ear(jawL, halfL, -1.0, "10.2", "10.4", "10.6", "10.10");
    ear(jawR, halfR, 1.0, "10.1", "10.3", "10.5", "10.9");

    // Ears beyond the photo's edge are not seen: kept on it. The hair and hairline go on beyond an
    // edge that cuts the head off (estimateForeheadAndHair).
    if (imageSize.isValid())
        keepInPhoto(&face, imageSize, [](int i) { return pointTable()[i].group == PointGroup::Ears; });
    return face;
}

HeadGeometry estimateForeheadAndHair(FaceModel *face)
{
    // 11.1 on the hairline of headGeometry(), on the face's midline (between the inner brow
    // ends); the temples 11.2/11.3 lie on the quarter-ellipse from the cheek at eye level to
    // 11.1, at 50 degrees above the eye line (each side with its own half-width, so a turned head
    // keeps its asymmetry); the hair points on the hair ellipse.
    const HeadGeometry g = headGeometry(*face);
    const double es0 = g.eyeDistance;
    const double cheekLX = g.toLocal(face->point("5.2")).x(), cheekRX = g.toLocal(face->point("5.1")).x();
    const double halfL = std::max(g.midX - cheekLX, 0.1 * es0), halfR = std::max(cheekRX - g.midX, 0.1 * es0);
    const double templeAngle = 50.0 * std::numbers::pi / 180.0;
    auto setG = [&](const char *id, QPointF local) { face->setPoint(pt::idx(id), g.toImage(local)); };
    setG("11.1", {g.midX, g.hairlineY});
    setG("11.2", {g.midX - halfL * std::cos(templeAngle), g.hairlineY * std::sin(templeAngle)});
    setG("11.3", {g.midX + halfR * std::cos(templeAngle), g.hairlineY * std::sin(templeAngle)});
    // Where the photo cuts the head off, these lie beyond its edge, where the head goes on: kept
    // on the edge they would draw a head with a flat top.
    for (int i = 0; i < 19; ++i)
        face->setPoint(pt::idx("h.1") + i, g.toImage(g.hairPoint(i)));
    return g;
}

QPointF HeadGeometry::toLocal(QPointF image) const
{
    const QPointF d = image - origin;
    return {d.x() * ex.x() + d.y() * ex.y(), d.x() * ey.x() + d.y() * ey.y()};
}

QPointF HeadGeometry::toImage(QPointF local) const
{
    return origin + local.x() * ex + local.y() * ey;
}

// The hair arc runs from 10 degrees below the eye line on the image left, over the crown
// (h.10 at the top centre), to 10 degrees below it on the image right.
QPointF HeadGeometry::hairPoint(int i) const
{
    const double a = (190.0 - i * (200.0 / 18.0)) * std::numbers::pi / 180.0;
    return {hairCentre.x() + hairAx * std::cos(a), hairCentre.y() - hairAy * std::sin(a)};
}

HeadGeometry headGeometry(const FaceModel &face)
{
    HeadGeometry g;
    const QPointF eyeL = face.point("3.6"), eyeR = face.point("3.5");
    g.origin = (eyeL + eyeR) / 2;
    g.eyeDistance = QLineF(eyeL, eyeR).length();
    if (g.eyeDistance > 1e-6) {
        g.ex = (eyeR - eyeL) / g.eyeDistance;
        g.ey = QPointF(-g.ex.y(), g.ex.x());
    }
    const double d = std::max(g.eyeDistance, 1e-6);
    auto L = [&](const char *id) { return g.toLocal(face.point(id)); };

    for (const char *id : {"4.6", "4.4a", "4.4", "4.2", "4.1", "4.3", "4.3a", "4.5"})
        g.browY += L(id).y() / 8;
    g.noseBaseY = L("9.15").y();
    // Rule of thirds of face proportions: hairline-brows = brows-nose base = nose base-chin.
    const double third = std::max(g.noseBaseY - g.browY, 0.1 * d);
    g.hairlineY = g.browY - third;
    // The midline at the brows: between the inner brow ends.
    g.midX = (L("4.2").x() + L("4.1").x()) / 2;

    // Hair: an ellipse around the skull, centred between the cheeks at eye level. The eyes
    // lie about halfway between the chin and the top of the skull, and the hair adds a tenth
    // of that height on top (at least a little above the hairline) and a tenth of the face
    // width on each side.
    const double cheekLX = L("5.2").x(), cheekRX = L("5.1").x();
    const double chinY = L("2.1").y();
    g.hairCentre = QPointF((cheekLX + cheekRX) / 2, 0);
    g.hairAx = 1.1 * std::max((cheekRX - cheekLX) / 2, 0.2 * d);
    g.hairAy = -std::min(-1.1 * chinY, g.hairlineY - 0.15 * third);
    return g;
}

bool scoredReference(int pointIndex, const Ibug &ibug, QPointF *pos)
{
    for (const Correspondence &c : correspondences()) {
        if (pt::idx(c.id) == pointIndex) {
            *pos = meanOf(ibug, c.ibug);
            return true;
        }
    }
    return false;
}

double normalizedMeanError(const FaceModel &face, const Ibug &ibug)
{
    const double norm = QLineF(ibug[36], ibug[45]).length();
    double sum = 0;
    int n = 0;
    for (const Correspondence &c : correspondences()) {
        sum += QLineF(face.point(c.id), meanOf(ibug, c.ibug)).length();
        ++n;
    }
    return norm > 0 ? sum / n / norm : std::numeric_limits<double>::infinity();
}

bool placeEarFromProfile(FaceModel *face, bool left, const std::vector<double> &ys, const std::vector<double> &widths,
    double step, const EarProfileLimits &limits, const std::function<QPointF(double, double)> &at)
{
    auto plausible = [&](double w) { return w >= limits.minWidth && w <= limits.maxWidth; };
    int bestStart = -1, bestLen = 0;
    const int rows = int(std::min(ys.size(), widths.size()));
    for (int i = 0; i < rows;) {
        if (!plausible(widths[i])) {
            ++i;
            continue;
        }
        int j = i;
        while (j < rows && plausible(widths[j]))
            ++j;
        if (j - i > bestLen) {
            bestLen = j - i;
            bestStart = i;
        }
        i = j;
    }
    if (bestStart < 0 || bestLen * step < limits.minLength || bestLen * step > limits.maxLength)
        return false;
    const int bestEnd = bestStart + bestLen - 1;
    int widest = bestStart;
    for (int i = bestStart; i <= bestEnd; ++i)
        if (widths[i] > widths[widest])
            widest = i;
    const double topY = ys[bestStart], bottomY = ys[bestEnd];
    face->setPoint(pt::idx(left ? "10.2" : "10.1"), at(topY, 0.3 * widths[bestStart]));
    face->setPoint(pt::idx(left ? "10.4" : "10.3"), at(ys[widest], widths[widest]));
    face->setPoint(pt::idx(left ? "10.6" : "10.5"), at(bottomY, 0.5 * widths[bestEnd]));
    face->setPoint(pt::idx(left ? "10.10" : "10.9"), at(bottomY - 0.12 * (bottomY - topY), 0));
    return true;
}

void keepInPhoto(FaceModel *face, QSize size, const std::function<bool(int)> &which)
{
    const QRectF bounds(0, 0, size.width() - 1, size.height() - 1);
    for (int i = 0; i < kPointCount; ++i) {
        if (!which(i))
            continue;
        const QPointF q = face->point(i);
        face->setPoint(i,
            QPointF(
                std::clamp(q.x(), bounds.left(), bounds.right()), std::clamp(q.y(), bounds.top(), bounds.bottom())));
    }
}

bool readIbugPts(const QString &path, std::array<QPointF, kIbugPointCount> *pts, QString *error)
{
    auto fail = [&](const QString &why) {
        if (error)
            *error = withProblem(path, why);
        return false;
    };
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
        return fail(file.errorString());
    const QString text = QString::fromUtf8(file.read(1 << 20));
    const qsizetype open = text.indexOf(QLatin1Char('{')), close = text.indexOf(QLatin1Char('}'));
    if (open < 0 || close < open)
        return fail(DetectText::tr("no { } block of points"));
    static const QRegularExpression space(QStringLiteral("\\s+"));
    const QStringList nums = text.mid(open + 1, close - open - 1).split(space, Qt::SkipEmptyParts);
    if (nums.size() != 2 * kIbugPointCount)
        return fail(
            DetectText::tr("%1 numbers where %2 coordinates were expected").arg(nums.size()).arg(2 * kIbugPointCount));
    for (int i = 0; i < kIbugPointCount; ++i) {
        bool okX = false, okY = false;
        const double x = nums[2 * i].toDouble(&okX), y = nums[2 * i + 1].toDouble(&okY);
        if (!okX || !okY)
            return fail(DetectText::tr("point %1 is not two numbers").arg(i + 1));
        (*pts)[i] = QPointF(x - 1, y - 1);
    }
    return true;
}

} // namespace toonface
