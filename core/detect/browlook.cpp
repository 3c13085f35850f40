#include "detect/browlook.h"

#include "detect/labcolour.h"
#include "detect/levelface.h"
#include "face/facemodel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace toonface {

namespace {

// The profile runs from this far above a brow's middle (ES0) ...
constexpr double kAbove = 0.3;
// ... to this far below it, short of the upper lid's crease.
constexpr double kBelow = 0.2;

double median(std::vector<float> v)
{
    if (v.empty())
        return std::nan("");
    auto mid = v.begin() + qsizetype(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

// One brow's thickness (ES0) and contrast (L*) about its middle `m` (level face, ES0), `half`
// its middle third's half width.
std::pair<double, double> browDip(const LevelFace &f, QPointF m, double half)
{
    const double step = 1.0 / kLevelEs0; // one row of the level face
    std::vector<double> profile;
    for (double y = m.y() - kAbove; y <= m.y() + kBelow; y += step)
        profile.push_back(median(f.box(f.l, m.x(), y, half, 0.5 * step)));
    if (profile.size() < 5 || std::any_of(profile.begin(), profile.end(), [](double v) { return !std::isfinite(v); }))
        return {0, 0};
    // The darkest row near the points' middle (within a third of the span from it), and the skin
    // on either side: the lighter of the two sides' 75th percentiles (a lid's shadow below or a
    // fringe above does not lower it).
    const size_t centre = size_t(kAbove / step);
    const size_t reach = profile.size() / 3;
    const size_t from = centre > reach ? centre - reach : 0, to = std::min(profile.size(), centre + reach);
    const size_t darkest = size_t(
        std::min_element(profile.begin() + qsizetype(from), profile.begin() + qsizetype(to)) - profile.begin());
    auto sideLevel = [&](size_t a, size_t b) {
        std::vector<double> s(profile.begin() + qsizetype(a), profile.begin() + qsizetype(b));
        if (s.empty())
            return profile[darkest];
        auto q = s.begin() + qsizetype(0.75 * double(s.size() - 1));
        std::nth_element(s.begin(), q, s.end());
        return *q;
    };
    const double skin = std::max(sideLevel(0, darkest), sideLevel(darkest + 1, profile.size()));
    const double contrast = skin - profile[darkest];
    if (contrast <= 0)
        return {0, 0};
    const double halfDepth = skin - 0.5 * contrast;
    size_t top = darkest, bottom = darkest;
    while (top > 0 && profile[top - 1] < halfDepth)
        --top;
    while (bottom + 1 < profile.size() && profile[bottom + 1] < halfDepth)
        ++bottom;
    return {double(bottom - top + 1) * step, contrast};
}

// `c` at the lightness `targetL`, in CIE L*a*b*: it keeps its colourfulness (a*, b*) and only its
// lightness moves. (Scaled in RGB it would keep its HSV saturation: a near-black brown raised to
// a mid lightness turns a vivid orange.)
QColor withLightness(const QColor &c, double targetL)
{
    const LabColour lab = labOf(c);
    return colourOfLab(LabColour {targetL, lab.a, lab.b});
}

} // namespace

BrowLook measureBrows(const QImage &photo, const FaceModel &face)
{
    BrowLook look;
    const LevelFace f = levelFace(photo, face);
    if (f.isNull())
        return look;
    double thickness = 0, contrast = 0;
    int seen = 0;
    for (const auto &ids : {std::array {"4.6", "4.4a", "4.4", "4.2"}, std::array {"4.1", "4.3", "4.3a", "4.5"}}) {
        const QPointF outer = f.map(face.point(ids[0])), inner = f.map(face.point(ids[3]));
        const QPointF m = (f.map(face.point(ids[1])) + f.map(face.point(ids[2]))) / 2.0;
        const double half = std::abs(inner.x() - outer.x()) / 6.0;
        const auto [t, c] = browDip(f, m, std::max(half, 2.0 / kLevelEs0));
        thickness += t / 2.0;
        contrast += c / 2.0;
        seen += c >= kBrowSeenContrast;
    }
    look.thickness = thickness;
    look.contrast = contrast;
    look.seen = seen == 2;
    return look;
}

void applyBrowLook(const BrowLook &look, const QColor &skinDrawn, ComponentStyle *brows)
{
    if (!look.seen || !skinDrawn.isValid())
        return;
    brows->strokeWidth = std::clamp(kBrowWidth * look.thickness / kMedianBrowThickness, kBrowWidths[0], kBrowWidths[1]);
    const double target = std::max(5.0, labOf(skinDrawn).l - std::max(look.contrast, kMinBrowContrast));
    const QColor base = brows->stroke.isValid() ? brows->stroke : brows->fill;
    if (!base.isValid())
        return;
    const QColor drawn = withLightness(base, target);
    brows->stroke = drawn;
    if (brows->fill.isValid())
        brows->fill = drawn;
}

} // namespace toonface
