#include "render/curves.h"

#include <QLineF>

#include <algorithm>
#include <cmath>

namespace toonface {

namespace {

void cornerCutInto(QPointF p0, QPointF p1, QPointF p2, int depth, QVector<QPointF> *out)
{
    if (depth <= 0) {
        out->append(p1);
        out->append(p2);
        return;
    }
    const QPointF p01 = (p0 + p1) / 2.0; // eq. 4.1
    const QPointF p12 = (p1 + p2) / 2.0; // eq. 4.2
    const QPointF pm = (p01 + p12) / 2.0; // eq. 4.3
    cornerCutInto(p0, p01, pm, depth - 1, out);
    cornerCutInto(pm, p12, p2, depth - 1, out);
}

double length(QPointF v)
{
    return std::hypot(v.x(), v.y());
}

QPointF unit(QPointF v)
{
    const double l = length(v);
    return l > 1e-12 ? v / l : QPointF();
}

double dot(QPointF a, QPointF b)
{
    return a.x() * b.x() + a.y() * b.y();
}

// Method A: drags Q1 and Q2 together until R3 lies within `tolerance` of `target`. Both inner
// control points move by the same vector, and R3 moves 3/4 as far (eqs. 4.5-4.9), so each drag
// moves them by 4/3 of the remaining error; exact arithmetic would need one drag, rounding a
// second at most. The cap only guards against non-finite input.
int dragTogether(CubicBezier *b, QPointF target, double tolerance)
{
    int drags = 0;
    for (; drags < 64; ++drags) {
        const QPointF error = target - b->r3();
        if (!(length(error) >= tolerance))
            break;
        const QPointF drag = error * (4.0 / 3.0);
        b->q1 += drag;
        b->q2 += drag;
    }
    return drags;
}

} // namespace

QVector<QPointF> cornerCut(QPointF p0, QPointF p1, QPointF p2, int depth)
{
    QVector<QPointF> out;
    out.reserve((2 << std::clamp(depth, 0, 20)) + 1);
    out.append(p0);
    cornerCutInto(p0, p1, p2, depth, &out);
    return out;
}

QVector<QPointF> cornerCutPolyline(const QVector<QPointF> &points, int depth, bool closed)
{
    const qsizetype n = points.size();
    if (depth <= 0 || n < 3)
        return points;
    auto mid = [&](qsizetype a, qsizetype b) { return (points[(a + n) % n] + points[(b + n) % n]) / 2.0; };
    QVector<QPointF> out;
    const qsizetype first = closed ? 0 : 1;
    const qsizetype last = closed ? n - 1 : n - 2;
    if (!closed)
        out.append(points.first());
    for (qsizetype i = first; i <= last; ++i) {
        const QVector<QPointF> corner = cornerCut(mid(i - 1, i), points[i], mid(i, i + 1), depth);
        // Consecutive corners share the midpoint of the segment between them.
        out.append(i == first ? corner : corner.mid(1));
    }
    if (closed)
        out.removeLast(); // the last corner ends where the first began
    else
        out.append(points.last());
    return out;
}

QPointF CubicBezier::at(double t) const
{
    const double s = 1.0 - t;
    return q0 * (s * s * s) + q1 * (3 * s * s * t) + q2 * (3 * s * t * t) + q3 * (t * t * t);
}

QPointF CubicBezier::r3() const
{
    const QPointF r1 = (q0 + q1) / 2.0; // eq. 4.5
    const QPointF s2 = (q2 + q3) / 2.0; // eq. 4.6
    const QPointF r2 = r1 / 2.0 + (q1 + q2) / 4.0; // eq. 4.7
    const QPointF s1 = s2 / 2.0 + (q1 + q2) / 4.0; // eq. 4.8
    return (r2 + s1) / 2.0; // eq. 4.9
}

CubicBezier fitBezierThrough(QPointF q0, QPointF target, QPointF q3, double spread, double tolerance, int *iterations)
{
    const QPointF mid = (q0 + q3) / 2.0;
    const QPointF half = (q3 - q0) * (std::max(0.0, spread) / 6.0);
    CubicBezier b {q0, mid - half, mid + half, q3};
    const int drags = dragTogether(&b, target, tolerance);
    if (iterations)
        *iterations = drags;
    return b;
}

QVector<CubicBezier> fitBezierChain(
    const QVector<QPointF> &anchors, const QVector<QPointF> &targets, const BezierChainEnds &ends, double tolerance)
{
    const qsizetype segments = targets.size();
    if (segments < 1 || anchors.size() != segments + 1)
        return {};
    const qsizetype n = anchors.size();

    // Unit tangent at every anchor, pointing along the chain: at a joint, parallel to the
    // line between the two neighbouring targets (as Catmull-Rom does), so both segments meet
    // with one direction; at a free end, the direction a method-A fit of that segment starts
    // (or ends) with.
    QVector<QPointF> tangent(n);
    for (qsizetype i = 1; i + 1 < n; ++i)
        tangent[i] = unit(targets[i] - targets[i - 1]);
    if (ends.closed && n > 2) {
        const QPointF t = unit(targets.first() - targets.last());
        tangent.first() = t;
        tangent.last() = t;
    } else {
        const CubicBezier firstFit = fitBezierThrough(anchors[0], targets[0], anchors[1]);
        const CubicBezier lastFit = fitBezierThrough(anchors[n - 2], targets[segments - 1], anchors[n - 1]);
        tangent.first() = ends.startTangent.isNull() ? unit(firstFit.q1 - firstFit.q0) : unit(ends.startTangent);
        tangent.last() = ends.endTangent.isNull() ? unit(lastFit.q3 - lastFit.q2) : unit(ends.endTangent);
    }

    QVector<CubicBezier> chain;
    chain.reserve(segments);
    for (qsizetype i = 0; i < segments; ++i) {
        const QPointF a = anchors[i];
        const QPointF b = anchors[i + 1];
        const QPointF u = tangent[i];
        const QPointF v = tangent[i + 1];
        const double chord = length(b - a);
        const double natural = chord / 3.0;
        // R3 = (a + b)/2 + 3/8 (ha u - hb v) with q1 = a + ha u, q2 = b - hb v: solve for the
        // handle lengths ha, hb, least squares with a weak pull toward thirds of the chord so
        // parallel tangents (a straight run) stay well defined.
        const QPointF w = (targets[i] - (a + b) / 2.0) * (8.0 / 3.0);
        const double lambda = 1e-3;
        const double m11 = dot(u, u) + lambda;
        const double m12 = -dot(u, v);
        const double m22 = dot(v, v) + lambda;
        const double r1 = dot(u, w) + lambda * natural;
        const double r2 = -dot(v, w) + lambda * natural;
        const double det = m11 * m22 - m12 * m12;
        double ha = natural;
        double hb = natural;
        if (std::abs(det) > 1e-12) {
            ha = (r1 * m22 - m12 * r2) / det;
            hb = (m11 * r2 - m12 * r1) / det;
        }
        // Handles that point backwards or overshoot would loop; keep them sane and let
        // method A take up what is left (giving up a little smoothness at that joint).
        const double lo = 0.02 * chord;
        const double hi = 1.5 * chord + length(w);
        ha = std::isfinite(ha) ? std::clamp(ha, lo, std::max(lo, hi)) : natural;
        hb = std::isfinite(hb) ? std::clamp(hb, lo, std::max(lo, hi)) : natural;
        CubicBezier seg {a, a + u * ha, b - v * hb, b};
        dragTogether(&seg, targets[i], tolerance);
        chain.append(seg);
    }
    return chain;
}

} // namespace toonface
