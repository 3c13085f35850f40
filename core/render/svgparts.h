#pragma once

// The pieces SvgFace's part builders share (svgface.cpp, svgfacebuild.cpp, svgfeatures.cpp):
// compact SVG numbers and path data, small vector helpers and the Part record. Internal to
// core/render.

#include "face/pointtable.h"
#include "render/curves.h"

#include <QByteArray>
#include <QPointF>
#include <QRectF>
#include <QVector>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace toonface::svgparts {

using Points = std::array<QPointF, kPointCount>;

// ---- compact SVG text ----

// At most two decimals, no trailing zeros, no "-0". Written into a buffer and appended once:
// a drawing of a pose appends a few hundred numbers, and the SMIL export draws thousands of poses.
inline void appendNumber(QByteArray &out, double v)
{
    if (!std::isfinite(v))
        v = 0;
    v = std::clamp(v, -1e12, 1e12);
    long long n = std::llround(v * 100.0);
    char buf[32];
    char *end = buf + sizeof buf;
    char *p = end;
    const bool negative = n < 0;
    if (negative)
        n = -n;
    const int frac = int(n % 100);
    if (frac != 0) {
        if (frac % 10 != 0)
            *--p = char('0' + frac % 10);
        *--p = char('0' + frac / 10);
        *--p = '.';
    }
    long long whole = n / 100;
    do {
        *--p = char('0' + whole % 10);
        whole /= 10;
    } while (whole > 0);
    if (negative)
        *--p = '-';
    out.append(p, end - p);
}

inline QByteArray number(double v)
{
    QByteArray s;
    appendNumber(s, v);
    return s;
}

inline void appendPoint(QByteArray &out, QPointF p)
{
    appendNumber(out, p.x());
    out += ',';
    appendNumber(out, p.y());
}

// An SVG path "d" built from absolute commands.
class PathData
{
public:
    PathData() { m_d.reserve(160); }
    PathData &moveTo(QPointF p) { return command('M', p); }
    PathData &lineTo(QPointF p) { return command('L', p); }
    PathData &cubic(const CubicBezier &b)
    {
        m_d += 'C';
        appendPoint(m_d, b.q1);
        m_d += ' ';
        appendPoint(m_d, b.q2);
        m_d += ' ';
        appendPoint(m_d, b.q3);
        return *this;
    }
    PathData &cubics(const QVector<CubicBezier> &chain)
    {
        for (const CubicBezier &b : chain)
            cubic(b);
        return *this;
    }
    PathData &horizontalTo(double x)
    {
        m_d += 'H';
        appendNumber(m_d, x);
        return *this;
    }
    PathData &verticalTo(double y)
    {
        m_d += 'V';
        appendNumber(m_d, y);
        return *this;
    }
    PathData &close()
    {
        m_d += 'Z';
        return *this;
    }
    QByteArray data() const { return m_d; }

private:
    PathData &command(char c, QPointF p)
    {
        m_d += c;
        appendPoint(m_d, p);
        return *this;
    }
    QByteArray m_d;
};

inline QByteArray pointList(const QVector<QPointF> &points)
{
    QByteArray s;
    s.reserve(points.size() * 12);
    for (qsizetype i = 0; i < points.size(); ++i) {
        if (i)
            s += ' ';
        appendPoint(s, points[i]);
    }
    return s;
}

// ---- geometry helpers ----

inline double length(QPointF v)
{
    return std::hypot(v.x(), v.y());
}

inline QPointF unit(QPointF v)
{
    const double l = length(v);
    return l > 1e-12 ? v / l : QPointF();
}

inline QPointF lerp(QPointF a, QPointF b, double t)
{
    return a + (b - a) * t;
}

inline QPointF perpendicular(QPointF v)
{
    return {-v.y(), v.x()};
}

inline CubicBezier reversed(const CubicBezier &b)
{
    return {b.q3, b.q2, b.q1, b.q0};
}

// The curve whose control points are (1 - t) a + t b: at every parameter, the point that far
// from a's point toward b's.
inline CubicBezier blend(const CubicBezier &a, const CubicBezier &b, double t)
{
    return {lerp(a.q0, b.q0, t), lerp(a.q1, b.q1, t), lerp(a.q2, b.q2, t), lerp(a.q3, b.q3, t)};
}

// Exact bounding box of a cubic Bezier: its end points and the extrema where a coordinate's
// derivative vanishes.
inline QRectF bezierBounds(const CubicBezier &b)
{
    double minX = std::min(b.q0.x(), b.q3.x()), maxX = std::max(b.q0.x(), b.q3.x());
    double minY = std::min(b.q0.y(), b.q3.y()), maxY = std::max(b.q0.y(), b.q3.y());
    auto extrema = [&](double p0, double p1, double p2, double p3, bool isX) {
        // d/dt of the cubic = 3[(a t^2 + b t + c)] with:
        const double a = -p0 + 3 * p1 - 3 * p2 + p3;
        const double bb = 2 * (p0 - 2 * p1 + p2);
        const double c = p1 - p0;
        double roots[2];
        int count = 0;
        if (std::abs(a) < 1e-12) {
            if (std::abs(bb) > 1e-12)
                roots[count++] = -c / bb;
        } else {
            const double disc = bb * bb - 4 * a * c;
            if (disc >= 0) {
                const double s = std::sqrt(disc);
                roots[count++] = (-bb + s) / (2 * a);
                roots[count++] = (-bb - s) / (2 * a);
            }
        }
        for (int i = 0; i < count; ++i) {
            const double t = roots[i];
            if (t > 0 && t < 1) {
                const QPointF p = b.at(t);
                if (isX) {
                    minX = std::min(minX, p.x());
                    maxX = std::max(maxX, p.x());
                } else {
                    minY = std::min(minY, p.y());
                    maxY = std::max(maxY, p.y());
                }
            }
        }
    };
    extrema(b.q0.x(), b.q1.x(), b.q2.x(), b.q3.x(), true);
    extrema(b.q0.y(), b.q1.y(), b.q2.y(), b.q3.y(), false);
    return QRectF(QPointF(minX, minY), QPointF(maxX, maxY));
}

// ---- parts ----

enum Paint { FillAndStroke, FillOnly, StrokeOnly };

// A part while it is being built; parts() and svg() both read these.
struct Part
{
    const char *id;
    bool dynamic;
    const char *element;
    std::vector<std::pair<const char *, QByteArray>> geometry; // in attribute order
    const char *styleKey;
    Paint paint = FillAndStroke;
    const char *clipPath = nullptr;
};

// Curves of moving parts are fitted through their targets to this tolerance (pixels), not the
// fitting functions' default 0.5 px: with a loose tolerance a control point jumps by up to 2/3 px
// when the fitting error crosses it, so an animated mouth or lid would pop between frames and
// its geometry would not follow the pose continuously (which SMIL interpolation relies on).
constexpr double kMovingFitTolerance = 1e-3;

struct Pt
{
    const Points &p;
    QPointF operator()(const char *id) const { return p[pt::idx(id)]; }
};

} // namespace toonface::svgparts
