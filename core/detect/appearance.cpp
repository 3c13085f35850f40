#include "detect/appearance.h"

#include "detect/headparse.h"
#include "detect/labcolour.h"
#include "detect/skintone.h"
#include "face/fapu.h"

#include <QLineF>
#include <QPainter>
#include <QPolygonF>
#include <QTransform>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <numbers>
#include <numeric>
#include <optional>
#include <vector>

namespace toonface {

namespace {

constexpr double kDarkRatio = 0.72; // a pixel this much darker than the skin is hair-dark
// Hair colours: hues from red through orange to yellow (kHairHues[0] .. 360 and 0 .. kHairHues[1]),
// and any colour too dark or too grey to have a hue that shows.
constexpr double kHairHues[2] = {345.0, 55.0};
constexpr double kDarkest = 0.2;
constexpr double kGreyest = 0.2;
constexpr int kColourless = 4; // a skin whose channels differ by less has no colour (a greyscale photo)
constexpr double kEdgeFloor = 2.0; // luma units: the texture floor of perfectly smooth skin
// Luma units a hair's point stands out from its neighbours by (above rounding and a JPEG's faint noise).
constexpr double kSpeckleContrast = 3.0;
// ES0 above the brows: a forehead's skin reaching higher is scalp (hairlines lie 0.6 to 1.2 ES0
// above the brows on the shared photos' haired heads).
constexpr double kScalpAboveBrows = 1.4;
constexpr double kTempleHairShare = 0.2; // share of the temples' samples that must be other than skin
constexpr double kBarDark = 0.8; // a frame's bar is darker than this share of the skin's luma
constexpr double kBarAbove = 0.3; // ES0: how far above the eyes' centres a frame's bar is looked for
// Skin reaching farther above the head's outline than this share means the outline is not the head's.
constexpr double kMaxSkinReach = 1.3;
// A rim's edge stands this many times above the profile's median, and the one nearest the eye
// is taken among those at least this share of the strongest.
constexpr double kRimContrast = 2.0;
constexpr double kRimEdgeShare = 0.6;
constexpr double kLensReach = 0.85; // ES0 past the eyes' centres where a frame's outer edge may be
// A frame's top rim is looked for between these heights above the eye's centre (ES0; and below
// the brow), and is darker than this share of the skin's luma.
constexpr double kRimAbove[2] = {0.4, 0.1};
constexpr double kRimDark = 0.55;
constexpr double kRimDrift = 0.12; // ES0 a top rim may rise or fall from over the eye's corner to its end
// A face tilted further than this (degrees) is measured upright: across a box as wide as the
// mouth, its tilt already moves a point a twentieth of the box's width up or down.
constexpr double kUprightRoll = 3.0;

// A skin without colour: a greyscale photo.
bool colourless(const QColor &skin)
{
    return std::max({skin.red(), skin.green(), skin.blue()}) - std::min({skin.red(), skin.green(), skin.blue()})
        < kColourless;
}

class Pixels
{
public:
    explicit Pixels(const QImage &photo)
        : m_image(photo.convertToFormat(QImage::Format_RGB32))
    { }
    int height() const { return m_image.height(); }
    bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < m_image.width() && y < m_image.height(); }
    QRgb at(int x, int y) const { return reinterpret_cast<const QRgb *>(m_image.constScanLine(y))[x]; }
    double luma(int x, int y) const { return lumaOf(at(x, y)); }

    // The pixels of an axis-aligned box (clipped to the photo).
    std::vector<QRgb> box(QRectF r) const
    {
        std::vector<QRgb> out;
        r = r.normalized();
        const int x0 = std::max(0, int(std::floor(r.left()))), x1 = std::min(m_image.width() - 1, int(r.right()));
        const int y0 = std::max(0, int(std::floor(r.top()))), y1 = std::min(m_image.height() - 1, int(r.bottom()));
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x)
                out.push_back(at(x, y));
        }
        return out;
    }

    // The mean of |d luma / dy| along each row of the box (horizontal edges), top to bottom.
    std::vector<double> rowEdges(QRectF r) const
    {
        std::vector<double> rows;
        r = r.normalized();
        const int x0 = std::max(0, int(std::floor(r.left()))), x1 = std::min(m_image.width() - 1, int(r.right()));
        const int y0 = std::max(1, int(std::floor(r.top()))), y1 = std::min(m_image.height() - 2, int(r.bottom()));
        for (int y = y0; y <= y1; ++y) {
            double sum = 0;
            int n = 0;
            for (int x = x0; x <= x1; ++x, ++n)
                sum += std::abs(luma(x, y + 1) - luma(x, y - 1)) / 2.0;
            if (n > 0)
                rows.push_back(sum / n);
        }
        return rows;
    }

    // The mean of |d luma / dx| down each column of the box (vertical edges), left to right.
    std::vector<double> columnEdges(QRectF r) const
    {
        std::vector<double> columns;
        r = r.normalized();
        const int x0 = std::max(1, int(std::floor(r.left()))), x1 = std::min(m_image.width() - 2, int(r.right()));
        const int y0 = std::max(0, int(std::floor(r.top()))), y1 = std::min(m_image.height() - 1, int(r.bottom()));
        for (int x = x0; x <= x1; ++x) {
            double sum = 0;
            int n = 0;
            for (int y = y0; y <= y1; ++y, ++n)
                sum += std::abs(luma(x + 1, y) - luma(x - 1, y)) / 2.0;
            if (n > 0)
                columns.push_back(sum / n);
        }
        return columns;
    }

    // The mean luma gradient's size (|d/dx| + |d/dy|) over the box: how textured it is.
    double texture(QRectF r) const
    {
        r = r.normalized();
        const int x0 = std::max(1, int(std::floor(r.left()))), x1 = std::min(m_image.width() - 2, int(r.right()));
        const int y0 = std::max(1, int(std::floor(r.top()))), y1 = std::min(m_image.height() - 2, int(r.bottom()));
        double sum = 0;
        int n = 0;
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x, ++n)
                sum += (std::abs(luma(x + 1, y) - luma(x - 1, y)) + std::abs(luma(x, y + 1) - luma(x, y - 1))) / 2.0;
        }
        return n > 0 ? sum / n : 0.0;
    }

    // The share of the box's pixels brighter, or darker, than all eight neighbours by more than
    // `contrast` luma units: the fine light and dark points of hair strands finer than a pixel.
    double speckle(QRectF r, double contrast) const
    {
        r = r.normalized();
        const int x0 = std::max(1, int(std::floor(r.left()))), x1 = std::min(m_image.width() - 2, int(r.right()));
        const int y0 = std::max(1, int(std::floor(r.top()))), y1 = std::min(m_image.height() - 2, int(r.bottom()));
        int n = 0, points = 0;
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x, ++n) {
                const double c = luma(x, y);
                double lo = 1e9, hi = -1e9;
                for (int dy = -1; dy <= 1; ++dy) {
                    for (int dx = -1; dx <= 1; ++dx) {
                        if (dx == 0 && dy == 0)
                            continue;
                        const double v = luma(x + dx, y + dy);
                        lo = std::min(lo, v);
                        hi = std::max(hi, v);
                    }
                }
                points += c > hi + contrast || c < lo - contrast;
            }
        }
        return n > 0 ? double(points) / n : 0.0;
    }

    bool covers(QRectF r) const { return QRectF(m_image.rect()).contains(r.normalized()); }

private:
    QImage m_image;
};

QColor median(std::vector<QRgb> px)
{
    if (px.empty())
        return {};
    auto channel = [&](int (*f)(QRgb)) {
        std::vector<int> v;
        v.reserve(px.size());
        for (QRgb p : px)
            v.push_back(f(p));
        std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
        return v[v.size() / 2];
    };
    return QColor(channel(qRed), channel(qGreen), channel(qBlue));
}

// The darkest `share` of the pixels, as their median colour.
QColor darkest(std::vector<QRgb> px, double share)
{
    std::sort(px.begin(), px.end(), [](QRgb a, QRgb b) { return lumaOf(a) < lumaOf(b); });
    px.resize(std::max<size_t>(1, size_t(px.size() * share)));
    return median(px);
}

double darkShare(const std::vector<QRgb> &px, double skinLuma)
{
    if (px.empty())
        return 0;
    const auto n = std::count_if(px.begin(), px.end(), [&](QRgb p) { return lumaOf(p) < kDarkRatio * skinLuma; });
    return double(n) / double(px.size());
}

QRectF around(QPointF c, double rx, double ry)
{
    return QRectF(c.x() - rx, c.y() - ry, 2 * rx, 2 * ry);
}

double percentile(std::vector<double> v, double q)
{
    if (v.empty())
        return 0;
    auto it = v.begin() + qsizetype(q * double(v.size() - 1));
    std::nth_element(v.begin(), it, v.end());
    return *it;
}

// A dark frame's bridge joins the lenses: the pixels clearly darker than the skin connected to
// the bridge (over the nose, between the eyes' inner corners, at eye level) reach over both
// eyes. Brows stop short of each other, and the nose's shadow runs down, not across.
struct DarkBridge
{
    double span = 0; // share of the way from one eye's centre to the other's that it spans
    std::vector<QRgb> pixels;
    QRect bounds; // in the photo
};

// The widest part of `box` darker than kBarDark of the skin's luma that is connected to the
// nose's middle column (between the eyes' inner corners).
DarkBridge bridgedDark(const Pixels &px, const FaceModel &face, const QRect &box, double skinLuma)
{
    const QPointF a = face.point("3.6"), b = face.point("3.5");
    const QPointF in1 = face.point("3.8"), in2 = face.point("3.11");
    DarkBridge out;
    if (box.width() < 4 || box.height() < 2)
        return out;
    std::vector<std::uint8_t> dark(size_t(box.width() * box.height()), 0), seen(dark.size(), 0);
    for (int y = 0; y < box.height(); ++y)
        for (int x = 0; x < box.width(); ++x) {
            const int X = box.left() + x, Y = box.top() + y;
            dark[size_t(y * box.width() + x)] = px.inside(X, Y) && px.luma(X, Y) < kBarDark * skinLuma;
        }
    const int mx = int(std::lround((in1.x() + in2.x()) / 2.0)) - box.left();
    for (int y0 = 0; y0 < box.height(); ++y0) {
        const size_t start = size_t(y0 * box.width() + mx);
        if (mx < 0 || mx >= box.width() || !dark[start] || seen[start])
            continue;
        int minX = mx, maxX = mx, minY = y0, maxY = y0;
        std::vector<QRgb> pixels;
        std::vector<size_t> stack {start};
        seen[start] = 1;
        while (!stack.empty()) {
            const size_t i = stack.back();
            stack.pop_back();
            const int x = int(i % size_t(box.width())), y = int(i / size_t(box.width()));
            minX = std::min(minX, x);
            maxX = std::max(maxX, x);
            minY = std::min(minY, y);
            maxY = std::max(maxY, y);
            pixels.push_back(px.at(box.left() + x, box.top() + y));
            for (const auto &[dx, dy] : {std::pair {1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
                const int nx = x + dx, ny = y + dy;
                if (nx < 0 || ny < 0 || nx >= box.width() || ny >= box.height())
                    continue;
                const size_t j = size_t(ny * box.width() + nx);
                if (dark[j] && !seen[j]) {
                    seen[j] = 1;
                    stack.push_back(j);
                }
            }
        }
        const double span = (std::min(double(maxX + box.left()), std::max(a.x(), b.x()))
                                - std::max(double(minX + box.left()), std::min(a.x(), b.x())))
            / std::max(1.0, std::abs(b.x() - a.x()));
        if (span > out.span || (span == out.span && maxX - minX + 1 > out.bounds.width())) {
            out.span = span;
            out.pixels = std::move(pixels);
            out.bounds = QRect(QPoint(minX, minY) + box.topLeft(), QPoint(maxX, maxY) + box.topLeft());
        }
    }
    return out;
}

// Where a frame's bar is looked for: at eye level and a little above, from one eye's centre to
// the other's (and `reach` ES0 beyond them), `below` ES0 down from the eyes' centres.
QRect barBox(const FaceModel &face, double es0, double reach, double below)
{
    const QPointF a = face.point("3.6"), b = face.point("3.5");
    const double eyeY = (a.y() + b.y()) / 2.0;
    return QRectF(QPointF(std::min(a.x(), b.x()) - reach * es0, eyeY - kBarAbove * es0),
        QPointF(std::max(a.x(), b.x()) + reach * es0, eyeY + below * es0))
        .toAlignedRect();
}

// Where in `edges` (a profile along x or y, its first entry at `from`, one entry a pixel) the
// frame's rim is: the first strong edge (at least kRimEdgeShare of the strongest) met when the
// profile is read forward (`step` +1) or from its end (-1). Empty when the profile is flat
// (nothing stands out of it: no rim there to measure).
std::optional<double> rimAt(const std::vector<double> &edges, double from, int step)
{
    if (edges.size() < 3)
        return std::nullopt;
    const double best = *std::max_element(edges.begin(), edges.end());
    if (best < kRimContrast * percentile(edges, 0.5) || best < kEdgeFloor)
        return std::nullopt;
    for (size_t i = 0; i < edges.size(); ++i) {
        const size_t k = step > 0 ? i : edges.size() - 1 - i;
        if (edges[k] >= kRimEdgeShare * best)
            return from + double(k);
    }
    return std::nullopt;
}

// Where a dark frame's top rim ends out from an eye, in the photo's x; empty when no rim clearly
// darker than the skin runs above that eye. Found from the photo alone, not from the face's
// sides (wide frames reach past the cheek points the landmarks give): seeded at the darkest row
// above the eye's outer corner (below the brow, above the lashes), the rim is followed column by
// column outward, within a little of the row it was last seen at, while a pixel darker than
// halfway from the rim's to the skin's luma shows; it ends at a gap, or where the dark fills the
// column far above and below the rim (hair or the room beside the face; a rim is thin).
std::optional<double> topRimEnd(const Pixels &px, const FaceModel &face, bool left, double es0, double skinLuma)
{
    const QPointF o = face.point(left ? "3.12" : "3.7"), i = face.point(left ? "3.8" : "3.11");
    const QPointF ball = face.point(left ? "3.6" : "3.5");
    const int step = o.x() < i.x() ? -1 : 1;
    const double brow = face.point(left ? "4.4" : "4.3").y();
    const int y0 = int(std::ceil(std::max(brow + 0.04 * es0, ball.y() - kRimAbove[0] * es0)));
    const int y1 = int(std::floor(ball.y() - kRimAbove[1] * es0));
    if (y1 - y0 < 2)
        return std::nullopt;
    // The seed: the darkest row (by its mean over a few columns at the corner).
    const int cx = int(std::lround(o.x())), width = std::max(2, int(0.05 * es0));
    double seedLuma = 1e9;
    int row = -1;
    for (int y = y0; y <= y1; ++y) {
        double sum = 0;
        int n = 0;
        for (int k = 0; k < width; ++k) {
            const int x = cx - step * k;
            if (px.inside(x, y)) {
                sum += px.luma(x, y);
                ++n;
            }
        }
        if (n == width && sum / n < seedLuma) {
            seedLuma = sum / n;
            row = y;
        }
    }
    if (row < 0 || seedLuma > kRimDark * skinLuma)
        return std::nullopt;
    const double dark = seedLuma + 0.5 * (skinLuma - seedLuma);
    // A rim is smooth (its row moves by a pixel or two a column) and stays near the seed's row.
    const int near = std::max(1, int(std::lround(0.02 * es0))), far = std::max(near + 2, int(std::lround(0.2 * es0)));
    const int seedRow = row, drift = std::max(near, int(std::lround(kRimDrift * es0)));
    const int gap = std::max(2, int(std::lround(0.04 * es0)));
    const int last = int(std::lround(ball.x() + step * kLensReach * es0));
    int end = cx, missed = 0;
    for (int x = cx; step > 0 ? x <= last : x >= last; x += step) {
        int best = -1;
        double bestLuma = dark;
        for (int y = std::max(row - near, seedRow - drift); y <= std::min(row + near, seedRow + drift); ++y) {
            if (px.inside(x, y) && px.luma(x, y) < bestLuma) {
                bestLuma = px.luma(x, y);
                best = y;
            }
        }
        if (best < 0) {
            if (++missed > gap)
                break;
            continue;
        }
        // Dark all the way from far above the rim to far below it: not a rim.
        bool filled = true;
        for (int y = best - far; y <= best + far && filled; y += std::max(1, far / 4))
            filled = px.inside(x, y) && px.luma(x, y) < dark;
        if (filled)
            break;
        missed = 0;
        row = best;
        end = x;
    }
    return end + (step > 0 ? 1.0 : 0.0);
}

// The lenses' size and place (GlassesFit), from the rims about each eye: the outer rim, the
// first strong vertical edge out from the eye's outer corner (or the end of a dark frame's top
// rims, followed from the bridge within the face's sides); the inner rim, between the inner
// corner and the nose's middle; the top rim, the first strong horizontal edge up from the eye
// (a brow lies above it; or the dark frame's top); the bottom rim, the lowest strong one below
// the eye (a lid's crease or a bag lies above it). Averaged over both eyes; a side found on
// neither keeps the usual proportion. Clamped to what glasses are.
GlassesFit measureLenses(const Pixels &px, const FaceModel &face, double es0, double skinLuma)
{
    auto p = [&](const char *id) { return face.point(id); };
    const double midX = (p("3.8").x() + p("3.11").x()) / 2.0;
    std::vector<double> outer, inner, top, bottom;
    // A dark frame's top rims and bridge, followed out past the eyes: their ends are the lenses'
    // outer edges, their top the lenses' top (unless it runs into the brows, to the box's top).
    // Within the face's sides at the temples and cheeks: beyond them are hair and the room.
    const QRect wide
        = barBox(face, es0, kLensReach, 0.1)
              .intersected(QRectF(QPointF(p("10.10").x(), 0), QPointF(p("10.9").x(), px.height())).toAlignedRect());
    const DarkBridge bar = bridgedDark(px, face, wide, skinLuma);
    const bool barred = bar.span >= AppearanceFindings::kBridgedThreshold;
    std::array<bool, 2> outerFromBar {false, false};
    bool topFromBar = false;
    for (bool left : {true, false}) {
        const QPointF o = p(left ? "3.12" : "3.7"), i = p(left ? "3.8" : "3.11");
        const QPointF mid = (o + i) / 2.0;
        double end = o.x() < i.x() ? double(bar.bounds.left()) : double(bar.bounds.right()) + 1;
        if (barred) {
            if (const auto rim = topRimEnd(px, face, left, es0, skinLuma))
                end = *rim;
            outer.push_back(std::abs(end - mid.x()) / es0);
            outerFromBar[left ? 0 : 1] = true;
        }
        if (barred && bar.bounds.top() > wide.top()) {
            top.push_back((mid.y() - bar.bounds.top()) / es0);
            topFromBar = true;
        }
    }
    for (bool left : {true, false}) {
        const QPointF o = p(left ? "3.12" : "3.7"), i = p(left ? "3.8" : "3.11"), ball = p(left ? "3.6" : "3.5");
        const QPointF mid = (o + i) / 2.0;
        const double out = o.x() < i.x() ? -1.0 : 1.0; // toward the temple
        const double x0 = std::min(o.x(), i.x()), x1 = std::max(o.x(), i.x());
        const double rows[2] = {ball.y() - 0.15 * es0, ball.y() + 0.2 * es0};
        // Outer rim: from just past the corner outward.
        if (!outerFromBar[left ? 0 : 1]) {
            const double a = o.x() + out * 0.04 * es0, b = o.x() + out * 0.35 * es0;
            const QRectF r(QPointF(std::min(a, b), rows[0]), QPointF(std::max(a, b), rows[1]));
            if (px.covers(r))
                if (const auto at = rimAt(px.columnEdges(r), std::max(1.0, std::floor(r.left())), out > 0 ? 1 : -1))
                    outer.push_back(out * (*at - mid.x()) / es0);
        }
        // Inner rim: from just inside the inner corner toward the nose's middle.
        {
            const double a = i.x() - out * 0.03 * es0, b = midX + out * 0.02 * es0;
            const QRectF r(QPointF(std::min(a, b), rows[0]), QPointF(std::max(a, b), rows[1]));
            if (px.covers(r) && r.width() >= 3)
                if (const auto at = rimAt(px.columnEdges(r), std::max(1.0, std::floor(r.left())), out > 0 ? -1 : 1))
                    inner.push_back(out * (mid.x() - *at) / es0);
        }
        // Bottom rim below the lower lid; top rim above the upper lid.
        const QRectF below(QPointF(x0, ball.y() + 0.16 * es0), QPointF(x1, ball.y() + 0.55 * es0));
        if (px.covers(below))
            if (const auto at = rimAt(px.rowEdges(below), std::max(1.0, std::floor(below.top())), -1))
                bottom.push_back((*at - mid.y()) / es0);
        const QRectF above(QPointF(x0, ball.y() - 0.4 * es0), QPointF(x1, ball.y() - 0.12 * es0));
        if (!topFromBar && px.covers(above))
            if (const auto at = rimAt(px.rowEdges(above), std::max(1.0, std::floor(above.top())), -1))
                top.push_back((mid.y() - *at) / es0);
    }
    auto mean = [](const std::vector<double> &v, double otherwise) {
        return v.empty() ? otherwise : std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
    };
    const double o = std::clamp(mean(outer, 0.39), 0.3, 0.75), i = std::clamp(mean(inner, 0.35), 0.25, 0.48);
    const double t = std::clamp(mean(top, 0.21), 0.1, 0.4), b = std::clamp(mean(bottom, 0.27), 0.18, 0.6);
    GlassesFit fit;
    fit.halfWidth = (o + i) / 2.0;
    fit.outward = (o - i) / 2.0;
    fit.halfHeight = (t + b) / 2.0;
    fit.down = (b - t) / 2.0;
    return fit;
}

void findGlasses(const Pixels &px, const FaceModel &face, double es0, double skinLuma, AppearanceFindings *out)
{
    const DarkBridge bar = bridgedDark(px, face, barBox(face, es0, 0.1, 0.1), skinLuma);
    out->bridgedDark = bar.span;
    auto p = [&](const char *id) { return face.point(id); };
    // Skin texture: horizontal edges on the cheeks well below any rim.
    std::vector<double> reference;
    std::vector<QRgb> rimPixels;
    double rimScore = 0;
    double rimCurve = 0;
    for (bool left : {true, false}) {
        const QPointF outer = p(left ? "3.12" : "3.7"), inner = p(left ? "3.8" : "3.11");
        const QPointF ball = p(left ? "3.6" : "3.5");
        const double x0 = std::min(outer.x(), inner.x()), x1 = std::max(outer.x(), inner.x());
        const QRectF band(QPointF(x0, ball.y() + 0.16 * es0), QPointF(x1, ball.y() + 0.42 * es0));
        const QRectF cheek(QPointF(x0, ball.y() + 0.5 * es0), QPointF(x1, ball.y() + 0.62 * es0));
        if (!px.covers(band) || !px.covers(cheek))
            return;
        const std::vector<double> rows = px.rowEdges(band);
        const std::vector<double> ref = px.rowEdges(cheek);
        reference.insert(reference.end(), ref.begin(), ref.end());
        const auto best = std::max_element(rows.begin(), rows.end());
        if (best == rows.end())
            return;
        rimScore += *best / 2.0;
        const double rimY = band.top() + double(best - rows.begin()) + 1;
        const double w = x1 - x0;
        // The rim's row in narrow column strips across the lens, which reaches past the eye's
        // corners: a round lens curves up toward its sides, a rectangular one stays level.
        std::vector<double> middle, ends;
        const double reach = 0.1 * es0, l0 = x0 - reach, span = w + 2 * reach;
        const double strip = std::max(2.0, span / 12.0);
        for (double xa = l0; xa + strip <= l0 + span; xa += strip / 2) {
            const std::vector<double> r = px.rowEdges(
                QRectF(QPointF(xa, band.top()), QPointF(xa + strip, std::min(band.bottom(), rimY + 0.04 * es0))));
            if (r.empty())
                continue;
            const double row = double(std::max_element(r.begin(), r.end()) - r.begin());
            const double at = (xa + strip / 2 - l0) / span;
            if (at > 0.33 && at < 0.67)
                middle.push_back(row);
            else if (at < 0.2 || at > 0.8)
                ends.push_back(row);
        }
        if (!middle.empty() && !ends.empty())
            rimCurve += (percentile(middle, 0.5) - percentile(ends, 0.5)) / es0 / 2.0;
        for (int x = int(x0); x <= int(x1); ++x) {
            for (int dy = -1; dy <= 1; ++dy) {
                if (px.inside(x, int(rimY) + dy))
                    rimPixels.push_back(px.at(x, int(rimY) + dy));
            }
        }
    }
    // The bridge: a horizontal edge over the nose between the inner corners, at eye level.
    const QPointF in1 = p("3.8"), in2 = p("3.11");
    const double eyeY = (p("3.6").y() + p("3.5").y()) / 2.0;
    const QRectF bridge(QPointF(in1.x() + 0.3 * (in2.x() - in1.x()), eyeY - 0.2 * es0),
        QPointF(in1.x() + 0.7 * (in2.x() - in1.x()), eyeY + 0.06 * es0));
    if (!px.covers(bridge))
        return;
    const std::vector<double> bridgeRows = px.rowEdges(bridge);
    const double bridgeEdge = bridgeRows.empty() ? 0 : *std::max_element(bridgeRows.begin(), bridgeRows.end());
    const double texture = percentile(reference, 0.9) + kEdgeFloor;
    // Both must show: a rim alone may be a lid's crease or a bag, a bridge alone a brow or a fold.
    out->glassesScore = std::sqrt(std::max(0.0, rimScore) * std::max(0.0, bridgeEdge)) / texture;
    // A frame: a thin line over the nose's middle (its bridge) and rims, under the eyes or
    // beside them. Dark lids, a brow or a shadow are no thin line across the nose; a crease at
    // the nose's root has no rims.
    // (Or strong rim and bridge edges over smooth skin.) A dark bar across the eyes alone is
    // what dark lids and brows show too: it is no evidence.
    const AppearanceEvidence &e = out->evidence;
    const bool frameLines = e.bridgeLine >= AppearanceFindings::kBridgeLine
        && (e.lowerRims >= AppearanceFindings::kLowerRims || e.sideRims >= AppearanceFindings::kSideRims);
    if (!frameLines && out->glassesScore < AppearanceFindings::kGlassesThreshold)
        return;
    const bool bridged = out->bridgedDark >= AppearanceFindings::kBridgedThreshold;
    out->appearance.glasses = rimCurve > 0.035 ? GlassesShape::Round : GlassesShape::Rectangular;
    out->appearance.lens = measureLenses(px, face, es0, skinLuma);
    out->glassesFrame = bridged ? median(bar.pixels) : darkest(rimPixels, 0.3);
}

void findFacialHair(
    const Pixels &px, const FaceModel &face, double es0, double skinLuma, bool colourless, AppearanceFindings *out)
{
    auto p = [&](const char *id) { return face.point(id); };
    const Fapu f = face.fapu();
    // Moustache: between the nose's bottom and the upper lip, the lip's middle half wide.
    const double noseBottom = std::max({p("9.15").y(), p("9.4").y(), p("9.5").y()});
    const double lipTop = std::min({p("8.9").y(), p("8.1").y(), p("8.10").y()});
    const double gap = lipTop - noseBottom;
    std::vector<QRgb> lipHair, chinHair, jawHair;
    const double xl = p("8.4").x() + 0.2 * f.mw0, xr = p("8.3").x() - 0.2 * f.mw0;
    const QRectF lipBox(QPointF(xl, noseBottom + 0.35 * gap), QPointF(xr, lipTop - 0.1 * gap));
    if (gap > 2)
        lipHair = px.box(lipBox);
    // Beard: the chin below the lip's shadow, and both jaw sides inside the contour.
    const double jawH = p("2.1").y() - p("8.2").y();
    const QRectF chinBox = around(QPointF(p("2.1").x(), p("8.2").y() + 0.6 * jawH), 0.2 * f.mw0, 0.2 * jawH);
    if (jawH > 2) {
        const auto c = px.box(chinBox);
        chinHair.insert(chinHair.end(), c.begin(), c.end());
        const QPointF mid = (p("5.2") + p("5.1")) / 2.0;
        for (const char *side : {"2.12", "2.11"}) {
            const QPointF s = p(side) + (mid - p(side)) * 0.12;
            const auto j = px.box(around(s, 0.05 * es0, 0.05 * es0));
            chinHair.insert(chinHair.end(), j.begin(), j.end());
            jawHair.insert(jawHair.end(), j.begin(), j.end());
        }
    }
    // Texture and speckle, against the cheeks' under the eyes.
    {
        double cheeks = 0, cheekSpeckle = 0;
        for (bool left : {true, false}) {
            const QPointF outer = p(left ? "3.12" : "3.7"), inner = p(left ? "3.8" : "3.11");
            const QPointF ball = p(left ? "3.6" : "3.5");
            const QRectF cheek(QPointF(std::min(outer.x(), inner.x()), ball.y() + 0.5 * es0),
                QPointF(std::max(outer.x(), inner.x()), ball.y() + 0.62 * es0));
            cheeks += px.texture(cheek) / 2.0;
            cheekSpeckle += px.speckle(cheek, kSpeckleContrast) / 2.0;
        }
        cheeks += kEdgeFloor;
        if (gap > 2) {
            out->moustacheTexture = px.texture(lipBox) / cheeks;
            out->moustacheSpeckle = px.speckle(lipBox, kSpeckleContrast);
            out->cheekSpeckle = cheekSpeckle;
        }
        if (jawH > 2)
            out->beardTexture = px.texture(chinBox) / cheeks;
    }
    // Goatee: the chin alone, from under the lower lip's shadow to above the chin's point.
    std::vector<QRgb> goateeHair;
    if (jawH > 2)
        goateeHair = px.box(around(QPointF(p("2.1").x(), p("8.2").y() + 0.6 * jawH), 0.2 * f.mw0, 0.15 * jawH));
    out->goateeScore = darkShare(goateeHair, skinLuma);
    out->moustacheScore = darkShare(lipHair, skinLuma);
    out->beardScore = darkShare(chinHair, skinLuma);
    out->jawScore = darkShare(jawHair, skinLuma);
    // Hair, dark or not, is textured where skin is smooth: stubble and a sparse or grey beard are
    // a part darker than the skin with much more texture than the cheeks.
    auto stubble = [](double dark, double texture) {
        return dark >= AppearanceFindings::kStubbleDarkShare && texture >= AppearanceFindings::kStubbleTexture;
    };
    // Grey and white hair, no darker than the skin, still shows its strands: finer than a pixel
    // on a small face, many of the lip's pixels stand out from all their neighbours, where the
    // cheeks' are smooth.
    const bool speckled = out->moustacheSpeckle >= AppearanceFindings::kHairSpeckle
        && out->moustacheSpeckle >= AppearanceFindings::kSpeckleOverCheeks * out->cheekSpeckle;
    const bool darkMoustache = out->moustacheScore >= AppearanceFindings::kMoustacheThreshold
        || stubble(out->moustacheScore, out->moustacheTexture);
    // Hair is less red than the skin it grows from; a shadow under the nose or the lip, or a dark
    // jaw line, keeps the skin's redness. (Stubble seen only as a share of dark, textured pixels
    // is left out: on the labelled faces that rule drew stubble on clean-shaven men.) A faint loss on the lip counts
    // only where the lip or the chin shows it clearly. On the chin the hair is also textured. Without colour, the
    // strands (speckle) are the only evidence.
    const AppearanceEvidence &e = out->evidence;
    // Hair far darker than any shadow on the face is hair, whatever its colour.
    const bool hairyLip = (e.lipRedLoss >= AppearanceFindings::kLipRedLoss
                              && std::max(e.lipRedLoss, e.chinRedLoss) >= AppearanceFindings::kRedLossSure)
        || e.lipDL <= -AppearanceFindings::kLipDarker;
    const bool hairyChin
        = (e.chinRedLoss >= AppearanceFindings::kChinRedLoss && e.chinDetail >= AppearanceFindings::kChinDetail)
        || e.chinDL <= -AppearanceFindings::kChinDarker;
    out->appearance.moustache = hairyLip || (colourless && speckled);
    // A beard covers the jaw's sides too; hair on the chin alone is a goatee.
    out->appearance.beard
        = hairyChin && (e.jawRedLoss >= AppearanceFindings::kJawRedLoss || e.jawDL <= -AppearanceFindings::kChinDarker);
    out->appearance.goatee = hairyChin && !out->appearance.beard;
    std::vector<QRgb> hair;
    if (out->appearance.moustache)
        hair.insert(hair.end(), lipHair.begin(), lipHair.end());
    if (out->appearance.beard)
        hair.insert(hair.end(), chinHair.begin(), chinHair.end());
    if (out->appearance.goatee)
        hair.insert(hair.end(), goateeHair.begin(), goateeHair.end());
    // Grey or white hair seen by its strands alone is the colour of most of it, not of the
    // shadows between the strands.
    out->lightFacialHair
        = out->appearance.moustache && !darkMoustache && !out->appearance.beard && !out->appearance.goatee;
    if (!hair.empty())
        out->facialHair = out->lightFacialHair ? median(hair) : darkest(hair, 0.5);
}

// CIE Lab (D65) of an sRGB colour, L* in 0..100 (through labcolour.h's 8-bit tables).
std::array<double, 3> labOf(const QColor &c)
{
    const cv::Mat rgb(1, 1, CV_8UC3, cv::Scalar(c.red(), c.green(), c.blue()));
    cv::Mat lab;
    rgbToLab8(rgb, lab);
    const cv::Vec3b v = lab.at<cv::Vec3b>(0, 0);
    return {v[0] * 100.0 / 255.0, v[1] - 128.0, v[2] - 128.0};
}

double labDistance(const QColor &a, const QColor &b)
{
    const auto p = labOf(a), q = labOf(b);
    return std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
}

// The hair that shows beside the temples, under a hat as without one: between the face's contour
// (from the temple 11.2 / 11.3 down to the cheek 5.2 / 5.1) and the hair outline at the same
// heights, what is not skin; its lighter half's median (a dark hat's side may share the place
// with the hair below it). Invalid when too little shows (a bald head, ears).
QColor templeHair(const Pixels &px, const FaceModel &face, double es0, const QColor &skin)
{
    std::vector<QRgb> hair;
    int all = 0;
    for (bool left : {true, false}) {
        const QPointF temple = face.point(left ? "11.2" : "11.3"), cheek = face.point(left ? "5.2" : "5.1");
        for (double t : {0.2, 0.4, 0.6, 0.8}) {
            const QPointF q = temple + (cheek - temple) * t;
            // The outline's side (h.1..h.9 image-left, h.19..h.11 right) at q's height.
            std::optional<double> outlineX;
            for (int k = 0; k + 1 < 9 && !outlineX; ++k) {
                const QPointF a = face.point(pt::idx(left ? "h.1" : "h.19") + (left ? k : -k));
                const QPointF b = face.point(pt::idx(left ? "h.1" : "h.19") + (left ? k + 1 : -k - 1));
                if ((a.y() - q.y()) * (b.y() - q.y()) <= 0 && std::abs(a.y() - b.y()) > 1e-9)
                    outlineX = a.x() + (b.x() - a.x()) * (q.y() - a.y()) / (b.y() - a.y());
            }
            if (!outlineX || (left ? q.x() - *outlineX : *outlineX - q.x()) < 0.06 * es0)
                continue;
            for (double across : {0.3, 0.5, 0.7}) {
                const auto b
                    = px.box(around(QPointF(q.x() + (*outlineX - q.x()) * across, q.y()), 0.03 * es0, 0.03 * es0));
                all += int(b.size());
                std::copy_if(b.begin(), b.end(), std::back_inserter(hair), [&](QRgb c) { return !skinLike(c, skin); });
            }
        }
    }
    if (all == 0 || double(hair.size()) < kTempleHairShare * all)
        return {};
    std::sort(hair.begin(), hair.end(), [](QRgb a, QRgb b) { return lumaOf(a) < lumaOf(b); });
    return median(std::vector<QRgb>(hair.begin() + qsizetype(hair.size() / 2), hair.end()));
}

// The forehead's top edge: up each column between the temples from the brows, the first row
// that is not skin (for a run). A hat's brim leaves a straight edge across the forehead; a
// hairline curves (higher in the middle or at the temples) and strands break it. The edge's
// spread about its best straight line (80th percentile of the distances), in ES0; negative when
// the edge is not found across most of the forehead.
double foreheadEdgeSpread(const Pixels &px, const FaceModel &face, double es0, const QColor &skin)
{
    const QPointF l = face.point("11.2"), r = face.point("11.3");
    const double browY = std::min(face.point("4.2").y(), face.point("4.1").y());
    const int need = std::max(2, int(0.03 * es0));
    std::vector<QPointF> ends;
    int columns = 0;
    for (double x = l.x() + 0.1 * (r.x() - l.x()); x <= r.x() - 0.1 * (r.x() - l.x()); x += std::max(1.0, 0.02 * es0)) {
        ++columns;
        int run = 0;
        for (double y = browY - 0.1 * es0; y > browY - 2.0 * es0 && px.inside(int(x), int(y)); y -= 1.0) {
            if (skinLike(px.at(int(x), int(y)), skin)) {
                run = 0;
            } else if (++run >= need) {
                ends.emplace_back(x, y + need - 1);
                break;
            }
        }
    }
    if (columns == 0 || double(ends.size()) < 0.8 * columns)
        return -1;
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const QPointF &e : ends) {
        sx += e.x();
        sy += e.y();
        sxx += e.x() * e.x();
        sxy += e.x() * e.y();
    }
    const double n = double(ends.size());
    const double b = (n * sxy - sx * sy) / std::max(1e-9, n * sxx - sx * sx), a = (sy - b * sx) / n;
    std::vector<double> off;
    for (const QPointF &e : ends)
        off.push_back(std::abs(e.y() - (a + b * e.x())));
    return percentile(off, 0.8) / es0;
}

void findHead(const Pixels &px, const FaceModel &face, double es0, const QColor &skin, AppearanceFindings *out)
{
    // Between the face's top contour and the hair outline over the crown (h.8..h.12 above the
    // hairline 11.1 and the temples).
    // The inner part of that band is scalp on a bald head, hair or a hat otherwise, even when
    // the outline strayed into the background.
    int sampled = 0, seen = 0; // boxes in the band, and those the photo shows whole
    auto band = [&](int first, int last, const std::vector<const char *> &contour, double t0, double t1) {
        std::vector<QRgb> pxs;
        for (int k = first; k <= last; ++k) {
            const QPointF h = face.point(pt::idx("h.1") + k - 1);
            QPointF base = face.point(contour.front());
            for (const char *id : contour) {
                if (QLineF(h, face.point(id)).length() < QLineF(h, base).length())
                    base = face.point(id);
            }
            for (int i = 0; i < 4; ++i) {
                const QRectF r = around(base + (h - base) * (t0 + (t1 - t0) * i / 3.0), 0.025 * es0, 0.025 * es0);
                const auto b = px.box(r);
                pxs.insert(pxs.end(), b.begin(), b.end());
                ++sampled;
                seen += px.covers(r);
            }
        }
        return pxs;
    };
    const std::vector<QRgb> crown = band(8, 12, {"11.2", "11.1", "11.3"}, 0.15, 0.5);
    const QPointF hairline = face.point("11.1");
    const double browY = (face.point("4.2").y() + face.point("4.1").y()) / 2.0;
    // A crown the photo cuts off (most of the band beyond its edge) is not seen: no hat, and bald
    // only where the forehead's skin runs up the midline to the photo's edge higher above the
    // brows than any hairline (that is scalp).
    // The crown the parse of the head sees decides bald (a greyscale photo is never bald: without
    // colour a scalp and grey or white hair look alike).
    const bool parsedCrown = !out->crownCut && !(out->topCut && out->headHeight < AppearanceFindings::kMinHeadHeight);
    const bool parsedBald = parsedCrown && !colourless(skin) && out->scalpReach >= AppearanceFindings::kScalpReach
        && out->headHeight >= AppearanceFindings::kMinHeadHeight;
    if (crown.empty() || 2 * seen < sampled) {
        if (parsedCrown) {
            out->appearance.bald = parsedBald;
            return;
        }
        const bool skinToTheEdge = !px.inside(int(hairline.x()), int(std::floor(hairline.y() - 0.05 * es0)));
        out->appearance.bald = skinToTheEdge && browY - hairline.y() >= kScalpAboveBrows * es0;
        return;
    }
    const auto scalp
        = std::count_if(crown.begin(), crown.end(), [&](QRgb c) { return skinLike(c, skin) || shineOnSkin(c, skin); });
    out->baldScore = double(scalp) / double(crown.size());
    // How far up toward the head's top the forehead's skin reaches (11.1, where the skin up the
    // midline ends, over the hair outline's top h.10, from the brows): on a bald or shaved head
    // all the way, whatever the outline strayed into above it.
    const double headTop = browY - face.point("h.10").y();
    // (Seen only where the hairline is in the photo, not beyond an edge that cuts the head off.)
    const bool hairlineSeen = px.inside(int(hairline.x()), int(hairline.y()) - 1);
    out->skinReach = headTop > 0.5 * es0 && hairlineSeen ? (browY - hairline.y()) / headTop : 0.0;
    const bool skinToTheTop
        = out->skinReach >= AppearanceFindings::kSkinReachThreshold && out->skinReach <= kMaxSkinReach;
    // Without colour, a scalp and grey or white hair look alike: a greyscale photo is never bald.
    out->appearance.bald = parsedCrown
        ? parsedBald
        : !colourless(skin) && (out->baldScore >= AppearanceFindings::kBaldThreshold || skinToTheTop);
    if (out->appearance.bald)
        return;
    // A hat by its colour: none that hair grows in (black, browns, blondes, reds, greys and white);
    // its score is how far its hue lies outside that range, weighted by its saturation.
    // A hat of any colour: the crown unlike both the skin and the hair that shows beside the
    // temples, over a straight edge across the forehead (a brim; a hairline curves or breaks).
    const QColor top = median(crown);
    const QColor temples = templeHair(px, face, es0, skin);
    out->templeHair = temples;
    out->crownToHair = temples.isValid() ? labDistance(top, temples) : 0.0;
    out->crownToSkin = labDistance(top, skin);
    out->brimSpread = foreheadEdgeSpread(px, face, es0, skin);
    if (std::min(out->crownToHair, out->crownToSkin) >= AppearanceFindings::kHatContrast && out->brimSpread >= 0
        && out->brimSpread <= AppearanceFindings::kBrimSpread) {
        out->appearance.hat = true;
        out->hat = top;
        return;
    }
    // By its colour alone: none that hair grows in.
    const double hue = top.hsvHueF() * 360.0, sat = top.hsvSaturationF();
    const bool hairHue = hue < 0 || hue <= kHairHues[1] || hue >= kHairHues[0];
    const double outside = hairHue ? 0.0 : std::min(hue - kHairHues[1], kHairHues[0] - hue);
    out->hatScore = top.valueF() < kDarkest || sat < kGreyest ? 0.0 : outside * sat;
    if (out->hatScore >= AppearanceFindings::kHatThreshold) {
        out->appearance.hat = true;
        out->hat = top;
    }
}

// The face's own parts (over the lip, under the eyes, around the lenses) are looked for in boxes
// square to its eyes' line. On a face tilted in the picture's plane the photo's boxes would cut
// across them (at 20 degrees, the lip's top corner rises past the nose's bottom), so the face is
// measured upright: the photo around it turned until the eyes are level, the points with it.
// Where the turned photo does not reach, it shows the skin (nothing there, as outside the photo).
struct Upright
{
    QImage photo;
    FaceModel face;
};

// Nothing for a face already upright (tilted less than kUprightRoll).
std::optional<Upright> upright(const QImage &photo, const FaceModel &face, const QColor &skin, double es0)
{
    QPointF l = face.point("3.6"), r = face.point("3.5");
    if (l.x() > r.x())
        std::swap(l, r);
    const QLineF eyes(l, r);
    const double roll = std::atan2(eyes.dy(), eyes.dx()) * 180.0 / std::numbers::pi; // y down: clockwise
    if (std::abs(roll) < kUprightRoll)
        return std::nullopt;
    const QPointF centre = eyes.center();
    QTransform level;
    level.translate(centre.x(), centre.y());
    level.rotate(-roll);
    level.translate(-centre.x(), -centre.y());
    QPolygonF points;
    for (const QPointF &p : face.points())
        points << level.map(p);
    const QRect area = points.boundingRect().adjusted(-es0, -es0, es0, es0).toAlignedRect();
    Upright out {QImage(area.size(), QImage::Format_RGB32), face};
    out.face.setImageSize(area.size());
    for (int i = 0; i < kPointCount; ++i)
        out.face.setPoint(i, points[i] - area.topLeft(), face.isHandPlaced(i));
    level *= QTransform::fromTranslate(-area.left(), -area.top());
    out.photo.fill(skin);
    {
        QPainter painter(&out.photo);
        painter.setRenderHint(QPainter::SmoothPixmapTransform);
        painter.setTransform(level);
        painter.drawImage(QPointF(0, 0), photo);
    }
    return out;
}

} // namespace

AppearanceFindings findAppearance(const QImage &photo, const FaceModel &face, const QColor &skin)
{
    AppearanceFindings out;
    if (photo.isNull() || !face.isValid() || !skin.isValid())
        return out;
    const double es0 = face.fapu().es0;
    const double skinLuma = std::max(1.0, lumaOf(skin.rgb()));
    const Pixels px(photo);
    if (const std::optional<Upright> level = upright(photo, face, skin, es0)) {
        const Pixels levelPx(level->photo);
        out.evidence = measureEvidence(level->photo, level->face);
        findGlasses(levelPx, level->face, es0, skinLuma, &out);
        findFacialHair(levelPx, level->face, es0, skinLuma, colourless(skin), &out);
    } else {
        out.evidence = measureEvidence(photo, face);
        findGlasses(px, face, es0, skinLuma, &out);
        findFacialHair(px, face, es0, skinLuma, colourless(skin), &out);
    }
    const HeadParse parse = parseHead(photo, face);
    if (parse.valid) {
        out.crownCut = parse.crownCut;
        out.topCut = parse.topCut;
        out.headHeight = parse.headHeight; // eye distances, as ES0
        out.scalpReach = parse.scalpReach;
        out.hairSeen = parse.hairSeen;
        out.hairFall = parse.hairFall;
    }
    findHead(px, face, es0, skin, &out);
    rateAppearance(face, &out);
    return out;
}

} // namespace toonface
