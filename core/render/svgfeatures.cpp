#include "render/svgfeatures.h"

#include "face/restingface.h"

#include <numbers>

namespace toonface::svgparts {

namespace {

// Proportions in ES0 (eye distance) units.
constexpr double kLensHalfWidth = 0.37;
constexpr double kRoundLensHalfHeight = 0.31;
constexpr double kRectLensHalfHeight = 0.24;
constexpr double kLensCornerRound = 0.45; // share of the half height rounded at a rectangle's corners
constexpr double kLensDrop = 0.03; // lenses sit a little below the eye line
constexpr double kBeardFullness = 0.05; // the beard stands out beyond the jaw
constexpr double kBeardBelowLip = 0.10;
constexpr double kGoateeReach = 0.3; // how far from a mouth corner toward the jaw a goatee's side starts
constexpr double kMoustacheGap = 0.12; // share of nose-to-lip left bare under the nose
constexpr double kMoustacheOverLip = 0.025;
constexpr double kHatBrimReach = 0.06;
// A wrap lies kWrapOutset ES0 outside the hair outline and the cheeks, and reaches kWrapBelowChin
// ES0 under the chin (a scarf's fold under it, past where the jaw opens).
constexpr double kWrapOutset = 0.08, kWrapBelowChin = 0.45;
// A skull's top above the eyes' level, in ES0 (eye distances): adult heads measure about 1.5
// (9-10 cm over a 6.3 cm eye distance); the drawing keeps within these.
constexpr double kSkullHeight[2] = {1.2, 1.9};
constexpr double kSkullShoulder = 0.78; // a skull is rounder-shouldered than an ellipse (0.71)

// An ellipse (closed, four cubics) about c with half axes a, b.
void ellipse(PathData &d, QPointF c, double a, double b)
{
    constexpr double k = 0.5522847498; // 4/3 (sqrt 2 - 1): the quarter circle's handle
    d.moveTo(c + QPointF(a, 0));
    d.cubic({c + QPointF(a, 0), c + QPointF(a, k * b), c + QPointF(k * a, b), c + QPointF(0, b)});
    d.cubic({c + QPointF(0, b), c + QPointF(-k * a, b), c + QPointF(-a, k * b), c + QPointF(-a, 0)});
    d.cubic({c + QPointF(-a, 0), c + QPointF(-a, -k * b), c + QPointF(-k * a, -b), c + QPointF(0, -b)});
    d.cubic({c + QPointF(0, -b), c + QPointF(k * a, -b), c + QPointF(a, -k * b), c + QPointF(a, 0)});
    d.close();
}

// A rectangle about c with half sides a, b and corners rounded by r.
void roundedRect(PathData &d, QPointF c, double a, double b, double r)
{
    constexpr double k = 0.5522847498;
    const double l = c.x() - a, rt = c.x() + a, t = c.y() - b, bt = c.y() + b;
    d.moveTo({l + r, t}).lineTo({rt - r, t});
    d.cubic({{rt - r, t}, {rt - r + k * r, t}, {rt, t + r - k * r}, {rt, t + r}}).lineTo({rt, bt - r});
    d.cubic({{rt, bt - r}, {rt, bt - r + k * r}, {rt - r + k * r, bt}, {rt - r, bt}}).lineTo({l + r, bt});
    d.cubic({{l + r, bt}, {l + r - k * r, bt}, {l, bt - r + k * r}, {l, bt - r}}).lineTo({l, t + r});
    d.cubic({{l, t + r}, {l, t + r - k * r}, {l + r - k * r, t}, {l + r, t}}).close();
}

} // namespace

LensPlace glassesLenses(const Pt &P, GlassesShape shape, const GlassesFit &fit, double es0)
{
    // Each lens about its eye (as measured on the photo, else a little wider on the outer side).
    const QPointF leftMid = (P("3.12") + P("3.8")) / 2.0;
    const QPointF rightMid = (P("3.11") + P("3.7")) / 2.0;
    const QPointF across = unit(rightMid - leftMid);
    const QPointF down = QPointF(-across.y(), across.x());
    const bool fitted = fit.isSet();
    LensPlace l;
    l.halfWidth = (fitted ? fit.halfWidth : kLensHalfWidth) * es0;
    l.halfHeight = (fitted                                ? fit.halfHeight
                           : shape == GlassesShape::Round ? kRoundLensHalfHeight
                                                          : kRectLensHalfHeight)
        * es0;
    const double out = (fitted ? fit.outward : 0.02) * es0, drop = (fitted ? fit.down : kLensDrop) * es0;
    l.centre[0] = leftMid - across * out + down * drop;
    l.centre[1] = rightMid + across * out + down * drop;
    return l;
}

namespace {

constexpr const char *kBrowIds[] = {"4.6", "4.4a", "4.4", "4.2", "4.1", "4.3", "4.3a", "4.5"};

} // namespace

void keepBrowsUnderBrim(Points &posed, const Points &neutral, double es0)
{
    const double limit = posed[pt::idx("11.1")].y() + kBrowBelowHairline * es0;
    double push = 0;
    for (const char *id : kBrowIds) {
        const int i = pt::idx(id);
        push = std::max(push, std::min(limit, neutral[i].y()) - posed[i].y());
    }
    for (const char *id : kBrowIds)
        posed[pt::idx(id)].ry() += push;
}

void keepBrowsAboveGlasses(Points &posed, const Points &neutral, const LensPlace &lenses, double es0)
{
    const double limit = lenses.top() - kBrowAboveRim * es0;
    for (const char *id : kBrowIds) {
        const int i = pt::idx(id);
        const double lowest = std::max(limit, neutral[i].y());
        posed[i].ry() = std::min(posed[i].y(), lowest);
    }
}

Part makeGlasses(const Pt &P, GlassesShape shape, const GlassesFit &fit, double es0)
{
    // The lenses (glassesLenses); the bridge over the nose between the lenses' inner edges, the
    // arms from their outer edges to the face's sides.
    const LensPlace lenses = glassesLenses(P, shape, fit, es0);
    const QPointF leftLens = lenses.centre[0], rightLens = lenses.centre[1];
    const double a = lenses.halfWidth, b = lenses.halfHeight;
    PathData d;
    for (const QPointF &c : {leftLens, rightLens}) {
        if (shape == GlassesShape::Round)
            ellipse(d, c, a, b);
        else
            roundedRect(d, c, a, b, kLensCornerRound * b);
    }
    // Bridge: an arch between the lenses' inner edges, a third of the way up.
    const QPointF bridgeL = leftLens + QPointF(a, -0.3 * b);
    const QPointF bridgeR = rightLens + QPointF(-a, -0.3 * b);
    d.moveTo(bridgeL).cubic(fitBezierThrough(bridgeL, (bridgeL + bridgeR) / 2.0 - QPointF(0, 0.06 * es0), bridgeR));
    // Arms: from the outer edges back toward the ears' tops.
    const QPointF armL = leftLens - QPointF(a, 0.3 * b);
    const QPointF armR = rightLens + QPointF(a, -0.3 * b);
    d.moveTo(armL).lineTo(lerp(armL, P("10.2"), 0.85));
    d.moveTo(armR).lineTo(lerp(armR, P("10.1"), 0.85));
    return {"glasses", true, "path", {{"d", d.data()}}, "glasses"};
}

Part makeMoustache(const Pt &P, double es0)
{
    // Under the nose, down to the upper lip and out past its corners, drooping a little at the
    // ends; its lower edge follows the upper lip's outline (through its peaks, as the lip's own
    // outline does), so it moves with it. Laid out square to the eyes' line, so that it tilts with
    // the face: (x, y) below are along that line and down from it.
    const QPointF across = unit((P("3.11") + P("3.7")) / 2.0 - (P("3.12") + P("3.8")) / 2.0);
    const QPointF down = perpendicular(across);
    auto face
        = [&](const char *id) { return QPointF(QPointF::dotProduct(P(id), across), QPointF::dotProduct(P(id), down)); };
    auto image = [&](QPointF f) { return across * f.x() + down * f.y(); };
    const QPointF l = face("8.4"), r = face("8.3");
    const double noseBottom = std::max({face("9.15").y(), face("9.4").y(), face("9.5").y()});
    const double lipTop = std::min({face("8.9").y(), face("8.1").y(), face("8.10").y()});
    const double top = noseBottom + std::max(0.0, lipTop - noseBottom) * kMoustacheGap;
    const QPointF endL = l + QPointF(-0.05 * es0, 0.03 * es0);
    const QPointF endR = r + QPointF(0.05 * es0, 0.03 * es0);
    const QPointF topL(lerp(face("9.2"), face("9.4"), 0.5).x(), top);
    const QPointF topR(lerp(face("9.1"), face("9.5"), 0.5).x(), top);
    const QPointF topMid(face("9.15").x(), top + 0.02 * es0);
    const QPointF lift(0, -kMoustacheOverLip * es0);
    const QPointF peak(0, 0.01 * es0);
    PathData d;
    d.moveTo(image(endL))
        .cubics(fitBezierChain({image(endL), image(topL), image(topR), image(endR)},
            {image(lerp(endL, topL, 0.5) - QPointF(0.02 * es0, 0.02 * es0)), image(topMid),
                image(lerp(topR, endR, 0.5) + QPointF(0.02 * es0, -0.02 * es0))},
            {}, kMovingFitTolerance))
        .cubics(fitBezierChain({image(endR), image(r + lift), image(face("8.1") + lift), image(l + lift), image(endL)},
            {image(lerp(endR, r + lift, 0.5)), image(face("8.10") + lift + peak), image(face("8.9") + lift + peak),
                image(lerp(l + lift, endL, 0.5))},
            {}, kMovingFitTolerance))
        .close();
    return {"moustache", true, "path", {{"d", d.data()}}, "moustache"};
}

namespace {

// A beard's outer edge over a point of the jaw: stood off from the face's middle by its fullness.
QPointF beardEdge(const Pt &P, double es0, QPointF p)
{
    const QPointF centre = (P("5.2") + P("5.1") + P("8.2")) / 3.0;
    return p + unit(p - centre) * (kBeardFullness * es0);
}

} // namespace

Part makeBeard(const Pt &P, double es0)
{
    // Outer edge: the jaw from the cheeks down round the chin, stood off by the beard's fullness;
    // inner edge: up from the jaw's sides to beside the mouth corners and under the lower lip.
    auto out = [&](QPointF p) { return beardEdge(P, es0, p); };
    const QPointF startL = lerp(P("5.2"), P("2.14"), 0.45);
    const QPointF startR = lerp(P("5.1"), P("2.13"), 0.45);
    const QPointF belowLip = P("8.2") + QPointF(0, kBeardBelowLip * es0);
    const QPointF cornerL = P("8.4") + QPointF(-0.04 * es0, 0.08 * es0);
    const QPointF cornerR = P("8.3") + QPointF(0.04 * es0, 0.08 * es0);
    PathData d;
    d.moveTo(startL)
        .cubics(fitBezierChain({startL, out(P("2.14")), out(P("2.1")), out(P("2.13")), startR},
            {lerp(startL, out(P("2.14")), 0.5), out(P("2.12")), out(P("2.11")), lerp(out(P("2.13")), startR, 0.5)}, {},
            kMovingFitTolerance))
        .cubics(fitBezierChain({startR, cornerR, belowLip, cornerL, startL},
            {lerp(startR, cornerR, 0.5) + QPointF(0, 0.04 * es0), lerp(cornerR, belowLip, 0.5) + QPointF(0, 0.02 * es0),
                lerp(belowLip, cornerL, 0.5) + QPointF(0, 0.02 * es0),
                lerp(cornerL, startL, 0.5) + QPointF(0, 0.04 * es0)},
            {}, kMovingFitTolerance))
        .close();
    return {"beard", true, "path", {{"d", d.data()}}, "beard"};
}

Part makeGoatee(const Pt &P, double es0)
{
    // Outer edge: round the chin from under each mouth corner, stood off as a beard is; inner
    // edge: up under the lower lip.
    auto out = [&](QPointF p) { return beardEdge(P, es0, p); };
    const QPointF startL = lerp(P("8.4"), P("2.12"), kGoateeReach);
    const QPointF startR = lerp(P("8.3"), P("2.11"), kGoateeReach);
    const QPointF belowLip = P("8.2") + QPointF(0, kBeardBelowLip * es0);
    PathData d;
    d.moveTo(startL)
        .cubics(fitBezierChain({startL, out(P("2.1")), startR},
            {out(lerp(startL, P("2.1"), 0.5)), out(lerp(startR, P("2.1"), 0.5))}, {}, kMovingFitTolerance))
        .cubics(fitBezierChain({startR, belowLip, startL},
            {lerp(startR, belowLip, 0.5) + QPointF(0, 0.02 * es0),
                lerp(belowLip, startL, 0.5) + QPointF(0, 0.02 * es0)},
            {}, kMovingFitTolerance))
        .close();
    return {"beard", true, "path", {{"d", d.data()}}, "beard"};
}

Part makeHat(const Pt &P, double es0, int depth)
{
    // The crown: the hair outline above the brim; the brim: across the forehead where the hair
    // would start (the hairline 11.1), reaching a little past the hair on both sides.
    const double brim = P("11.1").y();
    QVector<QPointF> crown;
    for (int i = 0; i < 19; ++i) {
        const QPointF h = P.p[pt::idx("h.1") + i];
        if (h.y() < brim)
            crown.append(h);
    }
    const double left = std::min(P("11.2").x(), crown.isEmpty() ? P("11.2").x() : crown.first().x());
    const double right = std::max(P("11.3").x(), crown.isEmpty() ? P("11.3").x() : crown.last().x());
    const double reach = kHatBrimReach * es0;
    QVector<QPointF> outline;
    outline.append({left - reach, brim + 0.02 * es0});
    outline.append(crown);
    outline.append({right + reach, brim + 0.02 * es0});
    outline.append({(left + right) / 2.0, brim + 0.1 * es0});
    const QVector<QPointF> shape = cornerCutPolyline(outline, depth, true);
    return {"hat", false, "polygon", {{"points", pointList(shape)}}, "hat"};
}

Part makeWrap(const Pt &P, QPointF centre, double es0, int depth)
{
    QVector<QPointF> outline;
    // Over the head: the hair outline pushed out from the face's centre.
    for (int i = 0; i < 19; ++i) {
        const QPointF h = P.p[pt::idx("h.1") + i];
        const QPointF out = h - centre;
        const double len = std::max(1e-9, std::hypot(out.x(), out.y()));
        outline.append(h + out / len * (kWrapOutset * es0));
    }
    // Down the sides, wider than the cheeks, and round under the chin.
    const QPointF chin = P("2.1");
    const double right = std::max(P("5.1").x(), outline.last().x()) + kWrapOutset * es0;
    const double left = std::min(P("5.2").x(), outline.first().x()) - kWrapOutset * es0;
    const double bottom = chin.y() + kWrapBelowChin * es0;
    outline.append({right, std::max(outline.last().y(), P("2.13").y())});
    outline.append({right - 0.1 * es0, bottom - 0.1 * es0});
    outline.append({chin.x(), bottom});
    outline.append({left + 0.1 * es0, bottom - 0.1 * es0});
    outline.append({left, std::max(outline.first().y(), P("2.14").y())});
    const QVector<QPointF> shape = cornerCutPolyline(outline, depth, true);
    return {"hat-wrap", false, "polygon", {{"points", pointList(shape)}}, "hat"};
}

QByteArray baldFaceOutline(const Pt &P, double es0, QPointF startTangent, QPointF endTangent)
{
    // The skull over the cheeks at eye level (5.2, 5.1): its top where the outline's crown h.10
    // is, within what skulls are (an outline that strayed into the room above or beside a shaved
    // head no longer draws a tall, boxy skull), and its shoulders on a rounded arch between.
    const QPointF l = P("5.2"), r = P("5.1");
    const QPointF c = (l + r) / 2.0;
    const double a = std::abs(r.x() - l.x()) / 2.0;
    const double b = std::clamp(c.y() - P("h.10").y(), kSkullHeight[0] * es0, kSkullHeight[1] * es0);
    const QPointF top(P("h.10").x(), c.y() - b);
    const QPointF shoulderL = c + QPointF(-kSkullShoulder * a, -kSkullShoulder * b);
    const QPointF shoulderR = c + QPointF(kSkullShoulder * a, -kSkullShoulder * b);
    const QVector<CubicBezier> chain = fitBezierChain({P("2.14"), l, top, r, P("2.13")},
        {lerp(P("2.14"), l, 0.5), shoulderL, shoulderR, lerp(r, P("2.13"), 0.5)}, {-startTangent, -endTangent});
    PathData d;
    d.moveTo(P("2.14")).cubics(chain);
    return d.data();
}

} // namespace toonface::svgparts
