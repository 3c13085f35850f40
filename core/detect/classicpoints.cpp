// The classic pipeline's point placement (thesis 3.5 and 4.3): the 72 points from the feature
// regions, the face region F_final and the hair region H_final.

#include "detect/classic.h"
#include "detect/classicsteps.h"

#include <QLineF>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

namespace toonface {

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

} // namespace

FaceModel placeFeaturePoints(const ClassicFeatures &features, const ClassicResult &res, QSize size)
{
    const FeatureRegion &eye = features.eye, &brow = features.brow, &nose = features.nose, &mouth = features.mouth;
    const Eyeball &ebL = res.eyeballs[0], &ebR = res.eyeballs[1];
    const double d = res.d;
    const QPointF mid = res.eyeMid;
    const double hL = std::max(ebL.height(), 2.0);
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
    return face;
}

void placeOutline(FaceModel *out, const RefinedRegions &refined, QSize size, ClassicResult *result)
{
    FaceModel &face = *out;
    ClassicResult &res = *result;
    const double d = res.d;
    const QPointF mid = res.eyeMid;
    auto set = [&](const char *id, QPointF p) { face.setPoint(pt::idx(id), p); };
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
}

} // namespace toonface
