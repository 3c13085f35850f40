#include "render/svgfacebuild.h"

#include "face/caricature.h"
#include "face/facemodel.h"
#include "face/fapu.h"
#include "render/agestyle.h"
#include "render/curves.h"
#include "render/svgfeatures.h"
#include "render/svgparts.h"
#include <algorithm>
#include <cmath>
#include <numbers>

namespace toonface::svgfacebuild {

// ---- the style's rules (caricature, cute) ----

// What the cute rules add to the points, from the neutral face: the same in every pose.
std::array<QPointF, kPointCount> styleRuleOffsets(const FaceModel &original, const Style &style)
{
    // First the caricature (the person's own proportions, exaggerated), then the cute rules on it.
    std::array<QPointF, kPointCount> off = caricatureOffsets(original, style.caricature);
    const double k = childRules(style); // all of the cute rules, a child's share of them, or none
    if (k <= 0)
        return off;
    FaceModel face = original;
    for (int i = 0; i < kPointCount; ++i)
        face.setPoint(i, original.point(i) + off[i], original.isHandPlaced(i));
    const Pt P {face.points()};
    const Fapu f = face.fapu();
    // A shorter, rounder jaw: the chin comes up, and the lower jaw points move onto the quarter
    // ellipses from the jaw sides (2.14, 2.13) to the raised chin.
    const QPointF chin = P("2.1") + QPointF(0, -k * kCuteChinRaise * f.jawH);
    off[pt::idx("2.1")] += chin - P("2.1");
    const double c = std::cos(std::numbers::pi / 4);
    for (const auto &[lower, side] : {std::pair {"2.12", "2.14"}, std::pair {"2.11", "2.13"}}) {
        const QPointF s = P(side);
        const QPointF centre(chin.x(), s.y());
        const QPointF onEllipse = centre + QPointF((s.x() - chin.x()) * c, (chin.y() - s.y()) * c);
        off[pt::idx(lower)] += (onEllipse - P(lower)) * k;
    }
    // A smaller nose, shrunk about its tip.
    const QPointF tip = P("9.15");
    for (const char *id : {"9.6", "9.7", "9.14", "9.13", "9.2", "9.1", "9.4", "9.5"})
        off[pt::idx(id)] += (P(id) - tip) * (k * (kCuteNoseScale - 1.0));
    return off;
}

// Applies the style's rules to neutral or posed points: the offsets, then larger eyes, scaled
// about the middle of their corners (which never move, so blinks still close on the corner line).
void applyStyleRules(Points &p, const SvgFaceGeometry &g, const Style &style)
{
    for (int i = 0; i < kPointCount; ++i)
        p[i] += g.ruleOffset[i];
    const double k = childRules(style);
    if (k <= 0)
        return;
    const double eyeScale = 1.0 + k * (kCuteEyeScale - 1.0);
    for (const auto &ids :
        {std::array {"3.12", "3.8", "3.2", "3.4", "3.6"}, std::array {"3.11", "3.7", "3.1", "3.3", "3.5"}}) {
        const QPointF mid = (p[pt::idx(ids[0])] + p[pt::idx(ids[1])]) / 2.0;
        for (const char *id : ids)
            p[pt::idx(id)] = mid + (p[pt::idx(id)] - mid) * eyeScale;
    }
}

// ---- static parts ----

Part makeHair(const Pt &P, const SvgFaceGeometry &g, int depth)
{
    QVector<QPointF> outline;
    outline.reserve(19);
    for (int i = 0; i < 19; ++i)
        outline.append(P.p[pt::idx("h.1") + i]);
    // Closed behind the face: from h.19 back to h.1 along the inside of the face contour. Long
    // hair, whose ends lie below the cheeks, is closed along the jaw down to its ends' height,
    // so that it fills the side of the face rather than leave a wedge between its outer edge
    // and a line cut up to the cheek. The whole outline is cut, so its lower ends round off.
    const std::array<const char *, 4> right {"5.1", "2.13", "2.11", "2.1"};
    const std::array<const char *, 4> left {"5.2", "2.14", "2.12", "2.1"};
    auto down = [&](const std::array<const char *, 4> &side, double endY) {
        // The contour below the cheek to the height of the hair's end, inset like the rest.
        std::vector<QPointF> out;
        for (int k = 1; k < int(side.size()); ++k) {
            const QPointF a = P(side[k - 1]), b = P(side[k]);
            if (b.y() < endY) {
                out.push_back(b);
                continue;
            }
            if (endY > a.y())
                out.push_back(lerp(a, b, (endY - a.y()) / std::max(b.y() - a.y(), 1e-9)));
            break;
        }
        if (!out.empty() && out.back() == P("2.1"))
            out.pop_back(); // below the chin: the two sides' ends are not joined across it
        return out;
    };
    const std::vector<QPointF> rightJaw = down(right, P("h.19").y());
    for (auto it = rightJaw.rbegin(); it != rightJaw.rend(); ++it)
        outline.append(lerp(*it, g.centre, kHairInset));
    for (const char *id : {"5.1", "11.3", "11.1", "11.2", "5.2"})
        outline.append(lerp(P(id), g.centre, kHairInset));
    for (const QPointF &q : down(left, P("h.1").y()))
        outline.append(lerp(q, g.centre, kHairInset));
    const QVector<QPointF> shape = cornerCutPolyline(outline, depth, true);
    return {"hair", false, "polygon", {{"points", pointList(shape)}}, "hair"};
}

void makeEar(const Pt &P, const SvgFaceGeometry &g, bool left, std::vector<Part> *out)
{
    const QPointF top = P(left ? "10.2" : "10.1");
    const QPointF outer = P(left ? "10.4" : "10.3");
    const QPointF lobe = P(left ? "10.6" : "10.5");
    const QPointF junction = P(left ? "10.10" : "10.9");
    // The rim: from the top, round over to the outermost point, then down through the lobe's
    // bottom (the middle of the lower rim) and back to the cheek, where it disappears behind
    // the face.
    const QPointF earCentre = (top + outer + lobe + junction) / 4.0;
    QPointF bulge = perpendicular(outer - top) * 0.3;
    if (QPointF::dotProduct(bulge, (top + outer) / 2.0 - earCentre) < 0)
        bulge = -bulge;
    const QVector<CubicBezier> rim = fitBezierChain({top, outer, junction}, {(top + outer) / 2.0 + bulge, lobe});
    const QPointF inward = unit(junction - rim.last().q2);
    // Open path: both ends continue a little into the face along the rim's own direction, so
    // the fill closes out of sight behind the face and the stroke ends there too.
    const double reach = 0.08 * g.es0;
    PathData d;
    d.moveTo(top - unit(rim.first().q1 - top) * reach).lineTo(top).cubics(rim).lineTo(junction + inward * reach);
    out->push_back({left ? "ear-left" : "ear-right", false, "path", {{"d", d.data()}}, "ears"});

    // The inner fold: a "(" inside the rim.
    const QPointF chordMid = (top + junction) / 2.0;
    const QPointF outward = outer - chordMid;
    const QPointF a = lerp(top, junction, 0.22) + outward * 0.3;
    const QPointF b = lerp(top, junction, 0.68) + outward * 0.22;
    const CubicBezier fold = fitBezierThrough(a, (a + b) / 2.0 + outward * 0.3, b);
    PathData f;
    f.moveTo(a).cubic(fold);
    out->push_back({left ? "ear-left-inner" : "ear-right-inner", false, "path", {{"d", f.data()}}, "ears", StrokeOnly});
}

Part makeFace(const Pt &P, const SvgFaceGeometry &g, bool bald)
{
    if (bald) // the skull is the face's: no hair, no hairline
        return {"face", false, "path", {{"d", baldFaceOutline(P, g.es0, g.jawStartTangent, g.jawEndTangent)}}, "face"};
    // Open path: the fill closes it with the straight line 2.13 -> 2.14 (where the jaw takes
    // over), the stroke does not.
    const QVector<CubicBezier> chain = fitBezierChain({P("2.14"), P("11.2"), P("11.3"), P("2.13")},
        {P("5.2"), P("11.1"), P("5.1")}, {-g.jawStartTangent, -g.jawEndTangent});
    PathData d;
    d.moveTo(P("2.14")).cubics(chain);
    return {"face", false, "path", {{"d", d.data()}}, "face"};
}

void makeNose(const Pt &P, NoseVariant variant, double es0, std::vector<Part> *out)
{
    const QPointF tip = P("9.15");
    const QPointF wl = P("9.2"), wr = P("9.1"), nl = P("9.4"), nr = P("9.5");
    if (variant == NoseVariant::Tip) {
        // Only the bottom between the nostrils, through the tip: a button nose.
        PathData d;
        d.moveTo(nl).cubic(fitBezierThrough(nl, tip + QPointF(0, 0.01 * es0), nr, 1.4));
        out->push_back({"nose-tip", false, "path", {{"d", d.data()}}, "nose"});
        return;
    }
    if (variant == NoseVariant::Full) {
        // One side of the bridge, the image-left one, lit from the right: a soft line from the
        // top of the nose region toward the wing.
        const QPointF start = lerp(P("9.6"), P("9.14"), 0.7);
        const QPointF end = lerp(P("9.14"), wl, 0.5);
        const QPointF bow = (start + end) / 2.0 + (P("9.14") - (start + end) / 2.0) * 0.6;
        PathData d;
        d.moveTo(start).cubic(fitBezierThrough(start, bow, end));
        out->push_back({"nose-bridge", false, "path", {{"d", d.data()}}, "nose"});
    }
    // The wings "(" and ")" bulge out above the nostrils and join the bottom, which runs
    // through the tip: one smooth line.
    auto wing = [&](QPointF wingPoint, QPointF nostril, QPointF top) {
        const QPointF start = lerp(wingPoint, top, 0.3);
        QPointF outward = perpendicular(nostril - start) * 0.3;
        if (QPointF::dotProduct(outward, wingPoint - tip) < 0)
            outward = -outward;
        return std::pair {start, (start + nostril) / 2.0 + outward};
    };
    const auto [startL, bulgeL] = wing(wl, nl, P("9.14"));
    const auto [startR, bulgeR] = wing(wr, nr, P("9.13"));
    PathData d;
    d.moveTo(startL).cubics(fitBezierChain({startL, nl, nr, startR}, {bulgeL, tip, bulgeR}));
    out->push_back({"nose-bottom", false, "path", {{"d", d.data()}}, "nose"});
}

// ---- eyebrows (static layer, but they move with emotions) ----

void makeEyebrows(const Pt &P, const Style &style, double es0, std::vector<Part> *out)
{
    for (bool left : {true, false}) {
        const char *id = left ? "eyebrow-left" : "eyebrow-right";
        const QPointF outer = P(left ? "4.6" : "4.5");
        const QPointF a = P(left ? "4.4a" : "4.3a");
        const QPointF b = P(left ? "4.4" : "4.3");
        const QPointF inner = P(left ? "4.2" : "4.1");
        switch (style.eyebrows) {
        case EyebrowVariant::Polyline: {
            const QVector<QPointF> line = cornerCutPolyline({outer, a, b, inner}, style.cornerCutDepth, false);
            out->push_back({id, false, "polyline", {{"points", pointList(line)}}, "eyebrows", StrokeOnly});
            break;
        }
        case EyebrowVariant::Bezier: {
            PathData d;
            d.moveTo(outer).cubic(fitBezierThrough(outer, (a + b) / 2.0, inner, 1.0, kMovingFitTolerance));
            out->push_back({id, false, "path", {{"d", d.data()}}, "eyebrows", StrokeOnly});
            break;
        }
        case EyebrowVariant::Thick: {
            // A filled brow, pointed at the outer end, full at the inner end.
            QPointF up = unit(perpendicular(inner - outer));
            if (up.y() > 0)
                up = -up;
            const QPointF mid = (a + b) / 2.0;
            const double t = kThickBrow * es0;
            const QPointF innerTop = inner + up * (0.45 * t);
            const QPointF innerBottom = inner - up * (0.45 * t);
            PathData d;
            d.moveTo(outer)
                .cubic(fitBezierThrough(outer, mid + up * (0.5 * t), innerTop, 1.0, kMovingFitTolerance))
                .lineTo(innerBottom)
                .cubic(fitBezierThrough(innerBottom, mid - up * (0.5 * t), outer, 1.0, kMovingFitTolerance))
                .close();
            out->push_back({id, false, "path", {{"d", d.data()}}, "eyebrows", FillOnly});
            break;
        }
        }
    }
}

// ---- dynamic parts ----

Part makeJaw(const Pt &P, const SvgFaceGeometry &g)
{
    const QPointF left = P("2.14"), right = P("2.13");
    const QVector<CubicBezier> chain = fitBezierChain(
        {left, P("2.1"), right}, {P("2.12"), P("2.11")}, {g.jawStartTangent, g.jawEndTangent}, kMovingFitTolerance);
    // Starts and ends a little up the face's sides, along them, so the jaw's fill overlaps the
    // face's and no seam shows; the stroke there lies on the face's own.
    const double overlap = kJawOverlap * g.unit;
    PathData d;
    d.moveTo(left - g.jawStartTangent * overlap).lineTo(left).cubics(chain).lineTo(right + g.jawEndTangent * overlap);
    return {"jaw", true, "path", {{"d", d.data()}}, "jaw"};
}

void makeMouth(const Pt &P, std::vector<Part> *out)
{
    const QPointF l = P("8.4"), r = P("8.3");
    const CubicBezier innerTop = fitBezierThrough(l, P("2.2"), r, 1.0, kMovingFitTolerance);
    const CubicBezier innerBottom = fitBezierThrough(r, P("2.3"), l, kLowerLipSpread, kMovingFitTolerance);
    PathData inner;
    inner.moveTo(l).cubic(innerTop).cubic(innerBottom).close();
    out->push_back({"mouth-inner", true, "path", {{"d", inner.data()}}, "mouth-inner", FillOnly});

    // Tongue and upper teeth: each between one lip's inner edge and a blend of both edges.
    // Blending control points blends the curves point by point, so they always stay inside
    // the open mouth (no clipping needed) and vanish when it closes.
    const CubicBezier innerBottomForward = reversed(innerBottom);
    const CubicBezier tongueTop = blend(innerBottomForward, innerTop, kTongueShare);
    PathData tongue;
    tongue.moveTo(l).cubic(innerBottomForward).cubic(reversed(tongueTop)).close();
    out->push_back({"mouth-tongue", true, "path", {{"d", tongue.data()}}, "tongue", FillOnly});
    const CubicBezier teethEdge = blend(innerTop, innerBottomForward, kTeethShare);
    PathData teeth;
    teeth.moveTo(l).cubic(innerTop).cubic(reversed(teethEdge)).close();
    out->push_back({"mouth-teeth", true, "path", {{"d", teeth.data()}}, "teeth", FillOnly});

    PathData upper;
    upper.moveTo(l)
        .cubic(fitBezierThrough(l, P("8.9"), P("8.1"), 1.0, kMovingFitTolerance))
        .cubic(fitBezierThrough(P("8.1"), P("8.10"), r, 1.0, kMovingFitTolerance))
        .cubic(reversed(innerTop))
        .close();
    out->push_back({"mouth-upper-lip", true, "path", {{"d", upper.data()}}, "lips"});

    PathData lower;
    lower.moveTo(l)
        .cubic(reversed(innerBottom))
        .cubic(fitBezierThrough(r, P("8.2"), l, kLowerLipSpread, kMovingFitTolerance))
        .close();
    out->push_back({"mouth-lower-lip", true, "path", {{"d", lower.data()}}, "lips"});
}

void makeEye(const Pt &P, const SvgFaceGeometry &g, bool left, bool cover, std::vector<Part> *out)
{
    const QPointF a = P(left ? "3.12" : "3.11");
    const QPointF upperLid = P(left ? "3.2" : "3.1");
    const QPointF b = P(left ? "3.8" : "3.7");
    const QPointF lowerLid = P(left ? "3.4" : "3.3");
    const QPointF ball = P(left ? "3.6" : "3.5");
    const CubicBezier upper = fitBezierThrough(a, upperLid, b, 1.0, kMovingFitTolerance);
    const CubicBezier lower = fitBezierThrough(b, lowerLid, a, 1.0, kMovingFitTolerance);
    PathData outline;
    outline.moveTo(a).cubic(upper).cubic(lower).close();
    const QByteArray eye = outline.data();
    const char *clip = left ? "clip-eye-left" : "clip-eye-right";
    const double r = g.eyeballRadius;

    out->push_back({left ? "eye-left" : "eye-right", true, "path", {{"d", eye}}, "eyes", FillOnly});
    auto circle = [&](const char *id, QPointF c, double radius, const char *key) {
        out->push_back({id, true, "circle", {{"cx", number(c.x())}, {"cy", number(c.y())}, {"r", number(radius)}}, key,
            FillAndStroke, clip});
    };
    circle(left ? "eyeball-left" : "eyeball-right", ball, r, "eyeballs");
    circle(left ? "pupil-left" : "pupil-right", ball, r * kPupilRadius, "pupils");
    circle(left ? "highlight-left" : "highlight-right", ball + QPointF(0.32 * r, -0.36 * r), r * kHighlightRadius,
        "highlights");

    // The eyeballs are clipped by the eye outline (clip-path). Renderers without clipping
    // (QSvgRenderer before Qt 6.7) would show them outside the lids, so skin covers
    // everything around the opening that the eyeball could reach: a box holding the eye and
    // the eyeball, minus the eye outline (even-odd).
    if (cover) {
        QRectF box = bezierBounds(upper).united(bezierBounds(lower));
        box = box.united(QRectF(ball.x() - r, ball.y() - r, 2 * r, 2 * r));
        box.adjust(-g.unit, -g.unit, g.unit, g.unit);
        PathData skin;
        skin.moveTo(box.topLeft()).horizontalTo(box.right()).verticalTo(box.bottom()).horizontalTo(box.left()).close();
        out->push_back({left ? "eye-left-cover" : "eye-right-cover", true, "path",
            {{"d", skin.data() + eye}, {"fill-rule", QByteArrayLiteral("evenodd")}}, "face", FillOnly});
    }
    out->push_back({left ? "eye-left-line" : "eye-right-line", true, "path", {{"d", eye}}, "eyes", StrokeOnly});
}

} // namespace toonface::svgfacebuild
