#pragma once

#include <QPointF>
#include <QVector>

namespace toonface {

// Thesis Algorithm 4.1, corner-cutting subdivision of the two segments P0P1, P1P2.
// depth 0 returns {p0, p1, p2}; each level replaces the corner by two halves.
// Ensures: the first point is p0 and the last p2.
QVector<QPointF> cornerCut(QPointF p0, QPointF p1, QPointF p2, int depth);

// Corner-cutting of a whole polyline: every interior vertex is cut between the midpoints of
// its two segments. Open polylines keep their end points; closed ones wrap around.
QVector<QPointF> cornerCutPolyline(const QVector<QPointF> &points, int depth, bool closed);

struct CubicBezier
{
    QPointF q0, q1, q2, q3;
    QPointF at(double t) const;
    // R3 of thesis eqs. 4.5-4.9: the curve's point at t = 1/2.
    QPointF r3() const;
};

// Thesis 4.2.2.2: a cubic Bezier from q0 to q3 that passes through `target`, found by
// dragging Q1 and Q2 together (method A) until |R3 - target| < tolerance. `spread` places
// the inner control points along the chord (method B: < 1 sharper, > 1 flatter; 1 = thirds).
// Ensures: |result.r3() - target| < tolerance.
CubicBezier fitBezierThrough(QPointF q0, QPointF target, QPointF q3, double spread = 1.0,
                             double tolerance = 0.5, int *iterations = nullptr);

} // namespace toonface
