#include "detect/photopixels.h"

#include <array>
#include <cstdint>
#include <numeric>
#include <optional>

namespace toonface {

namespace {

constexpr double kBarDark = 0.8; // a frame's bar is darker than this share of the skin's luma
constexpr double kBarAbove = 0.3; // ES0: how far above the eyes' centres a frame's bar is looked for
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

} // namespace

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

} // namespace toonface
