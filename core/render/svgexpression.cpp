#include "render/svgexpression.h"

namespace toonface::svgparts {

namespace {

// Displacements (ES0) at which a cue is fully drawn, and below which it is not drawn at all, so
// that the small corner and brow motions of speech draw no lines. Fully drawn where the emotion's
// preset (face/emotion.cpp) puts the points at full intensity, so that a cue keeps growing all
// the way there (half intensity draws 3/4 of the moves: emotionWeight).
constexpr double kFrownFull = 0.19; // inner brow ends lowered
constexpr double kWorryFull = 0.34; // inner ends raised relative to the outer ends
constexpr double kForeheadStart = 0.04; // whole brow raised
constexpr double kForeheadFull = 0.26;
constexpr double kSmileStart = 0.035; // mouth corners raised (speech's "i" lifts them 0.03)
constexpr double kSmileFull = 0.18;

// Sizes in ES0.
constexpr double kCreaseHalfWidth = 0.028; // a crease's half thickness at full strength
constexpr double kBlushRadius = 0.19;

double clamp01(double v)
{
    return std::clamp(v, 0.0, 1.0);
}

} // namespace

QByteArray lens(QPointF a, QPointF b, QPointF side, double bow, double halfWidth)
{
    const QPointF n = unit(side);
    constexpr double k = 4.0 / 3.0; // a cubic's handles offset by h reach 3/4 h at its middle
    const QPointF third = (b - a) / 3.0;
    PathData d;
    d.moveTo(a)
        .cubic({a, a + third + n * (k * (bow + halfWidth)), b - third + n * (k * (bow + halfWidth)), b})
        .cubic({b, b - third + n * (k * (bow - halfWidth)), a + third + n * (k * (bow - halfWidth)), a})
        .close();
    return d.data();
}

namespace {

void addCrease(std::vector<Part> *out, const char *id, QPointF a, QPointF b, QPointF side, double bow, double w)
{
    out->push_back({id, true, "path", {{"d", lens(a, b, side, bow, w)}}, "creases", FillOnly});
}

} // namespace

CueStrengths cueStrengths(const Pt &P, const Pt &N, const Pt &R, double es0)
{
    auto down = [&](const char *id) {
        const double y = P(id).y(), low = std::max(N(id).y(), R(id).y()), high = std::min(N(id).y(), R(id).y());
        return (y > low ? y - low : y < high ? y - high : 0.0) / es0;
    };
    auto pair = [&](const char *left, const char *right) { return (down(left) + down(right)) / 2.0; };
    CueStrengths s;
    const double inner = pair("4.2", "4.1");
    const double outer = pair("4.6", "4.5");
    const double middle = pair("4.4", "4.3");
    s.frown = clamp01(inner / kFrownFull);
    s.worry = clamp01((outer - inner) / kWorryFull);
    s.forehead = clamp01((-std::max({inner, outer, middle}) - kForeheadStart) / (kForeheadFull - kForeheadStart));
    s.smile = clamp01((-pair("8.4", "8.3") - kSmileStart) / (kSmileFull - kSmileStart));
    return s;
}

void makeExpressionCues(const Pt &P, const Pt &N, const Pt &R, double es0, std::vector<Part> *out)
{
    const CueStrengths s = cueStrengths(P, N, R, es0);
    const double w = kCreaseHalfWidth * es0;
    const QPointF up(0, -es0);
    for (bool left : {true, false}) {
        // Image-left is the person's right side; `out` points away from the face's middle.
        const QPointF outward(left ? -es0 : es0, 0);
        auto id = [&](const char *l, const char *r) { return left ? l : r; };

        // Smile: the cheeks rise into round blushes, with a line from the nose wing around the
        // raised mouth corner.
        const QPointF corner = P(id("8.4", "8.3"));
        const QPointF lid = P(id("3.4", "3.3"));
        const QPointF blush = lerp(lid, corner, 0.42) + outward * 0.16;
        out->push_back({id("blush-left", "blush-right"), true, "circle",
            {{"cx", number(blush.x())}, {"cy", number(blush.y())}, {"r", number(kBlushRadius * es0 * s.smile)}},
            "blush", FillOnly});
        const QPointF wing = P(id("9.2", "9.1"));
        addCrease(out, id("crease-cheek-left", "crease-cheek-right"), wing + outward * 0.08 + up * 0.06,
            corner + outward * 0.1 - up * 0.09, outward, 0.07 * es0, w * s.smile);

        // Angry: short frown lines rising from the lowered inner brow ends.
        const QPointF innerBrow = P(id("4.2", "4.1"));
        const QPointF mid = (P("4.2") + P("4.1")) / 2.0;
        const QPointF frownBottom = lerp(innerBrow, mid, 0.45) - up * 0.04;
        addCrease(out, id("crease-frown-left", "crease-frown-right"), frownBottom, frownBottom + up * 0.17, -outward,
            0.015 * es0, w * s.frown);

        // Angry: the nostrils flare, a dark fold outside each nose wing.
        const QPointF nostril = P(id("9.4", "9.5"));
        addCrease(out, id("crease-nostril-left", "crease-nostril-right"), wing + outward * 0.02 - up * 0.02,
            lerp(wing, nostril, 0.7) + outward * 0.02 - up * 0.04, outward, 0.035 * es0, 0.8 * w * s.frown);

        // Sad: worry lines over the raised inner brow ends, slanting as the brows do.
        const QPointF middleBrow = P(id("4.4", "4.3"));
        addCrease(out, id("crease-worry-left", "crease-worry-right"), middleBrow + up * 0.1, innerBrow + up * 0.12, up,
            0.025 * es0, w * s.worry);
    }
    // Surprise: two long lines across the forehead, over the raised brows (on a low forehead they
    // crowd under the hairline).
    const double top = std::min({P("4.4").y(), P("4.3").y(), P("4.2").y(), P("4.1").y()});
    const double left = P("4.4").x(), right = P("4.3").x();
    const char *ids[] = {"crease-forehead-1", "crease-forehead-2"};
    for (int i = 0; i < 2; ++i) {
        // Never over the hair: at most up to just under the hairline.
        const double y = std::max(top - (0.11 + 0.09 * i) * es0, P("11.1").y() + (0.1 + 0.06 * (1 - i)) * es0);
        const double inset = (0.05 + 0.08 * i) * (right - left) / 2.0;
        addCrease(
            out, ids[i], QPointF(left + inset, y), QPointF(right - inset, y), up, 0.03 * es0, 0.9 * w * s.forehead);
    }
}

} // namespace toonface::svgparts
