#pragma once

#include <QPointF>
#include <QVector>

namespace toonface {

// Thesis Algorithm 4.1, corner-cutting subdivision of the two segments P0P1, P1P2.
// depth 0 returns {p0, p1, p2}; each level replaces the corner by two halves.
// Ensures: the first point is p0 and the last p2.
QVector<QPointF> cornerCut(QPointF p0, QPointF p1, QPointF p2, int depth);

// Corner-cutting of a whole polyline: every interior vertex is cut between the midpoints of
// its two segments. Open polylines keep their end points; closed ones wrap around (the result
// lists each point once, not repeating the first at the end). depth <= 0, or fewer than three
// points, returns `points` unchanged. The number of points depends only on the input's
// count, depth and closedness.
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
CubicBezier fitBezierThrough(
    QPointF q0, QPointF target, QPointF q3, double spread = 1.0, double tolerance = 0.5, int *iterations = nullptr);

// How the ends of a fitBezierChain are shaped. A null tangent leaves that end free.
struct BezierChainEnds
{
    QPointF startTangent; // direction the chain leaves anchors.first()
    QPointF endTangent; // direction the chain arrives at anchors.last()
    bool closed = false; // anchors.last() == anchors.first(): one joint there, no ends
};

// Cubic Beziers joined smoothly (G1): segment i runs from anchors[i] to anchors[i + 1] and passes
// through targets[i] at its R3 (t = 1/2). At each joint both handles lie along one tangent,
// parallel to the line between the neighbouring targets; the handle lengths are solved so that
// R3 lands on the target, and method A takes up any remainder (then only that joint may bend).
// Requires: anchors.size() == targets.size() + 1 >= 2, else returns an empty vector.
// Ensures: |segment[i].r3() - targets[i]| < tolerance for finite input.
QVector<CubicBezier> fitBezierChain(const QVector<QPointF> &anchors, const QVector<QPointF> &targets,
    const BezierChainEnds &ends = {}, double tolerance = 0.5);

} // namespace toonface
