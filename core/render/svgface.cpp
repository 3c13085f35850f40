#include "render/svgface.h"

#include "face/caricature.h"
#include "face/fapu.h"
#include "face/restingface.h"
#include "i18n/coretext.h"
#include "media/userfile.h"
#include "render/agestyle.h"
#include "render/curves.h"
#include "render/svgbody.h"
#include "render/svgexpression.h"
#include "render/svgfeatures.h"
#include "render/svglayer.h"
#include "render/svgparts.h"

#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QPainter>
#include <QSvgRenderer>
#include <QXmlStreamReader>
#include <QXmlStreamWriter>

#include <algorithm>
#include <bitset>
#include <cmath>
#include <cstring>
#include <numbers>

namespace toonface {

namespace {

using namespace svgparts;

// The proportions of the drawing, in ES0 (eye distance) units unless said otherwise.
constexpr double kEyeballRadius = 0.105;
constexpr double kCuteEyeballScale = 1.45;
constexpr double kPupilRadius = 0.45; // of the eyeball radius
constexpr double kHighlightRadius = 0.24; // of the eyeball radius
constexpr double kCuteChinRaise = 0.22; // of JawH
constexpr double kCuteEyeScale = 1.3;
constexpr double kCheekRadius = 0.12;
constexpr double kCuteNoseScale = 0.6;
constexpr double kJawOverlap = 3.0; // thesis pixels (ES0/100) the jaw reaches up behind the face
constexpr double kThickBrow = 0.085;
constexpr double kLowerLipSpread = 1.5; // method B: the lower lip rounder than thirds
// The upper teeth and the tongue take fixed shares of the mouth opening (of the distance
// between the lips' inner edges). Fixed shares keep them linear in the pose like the rest of the
// mouth, so they ease exactly with it and an SMIL export interpolates them between key frames
// (a fixed height would need many more key frames).
constexpr double kTeethShare = 0.3;
constexpr double kTongueShare = 0.28;
constexpr double kHairInset = 0.15; // how far the hair's hidden closing runs inside the face

// Everything about a face that does not depend on the pose.
struct SvgFaceGeometry
{
    Points neutral; // the neutral points with the style's rules applied
    Points rest; // ... and those of the face at rest (restingFacePose), with them
    std::array<QPointF, kPointCount> ruleOffset {}; // what the style's rules add to every pose
    double unit = 1; // ES0 / 100: the thesis' pixel at its photo scale
    double es0 = 100;
    QPointF centre; // head rotation centre
    QPointF jawStartTangent; // the face contour's direction at 2.14 and 2.13, shared by face and jaw
    QPointF jawEndTangent;
    double eyeballRadius = 10;
    std::vector<Part> staticParts; // everything of the static layer but the eyebrows
    std::vector<Part> bodyParts; // neck and shoulders, or none
    QByteArray behind, front; // the style's visible layers, placed, that stay still
    QByteArray headBehind, headFront; // ... and those that follow the head (in its group)
    QMap<QString, ComponentStyle> components;
    // The style keys of components not drawn (componentStyle(...).visible false), so that
    // drawing a pose, done thousands of times by the SMIL export, looks no styles up.
    std::vector<QByteArray> hidden;
};

bool drawn(const SvgFaceGeometry &g, const char *key)
{
    return std::none_of(g.hidden.cbegin(), g.hidden.cend(), [&](const QByteArray &h) { return h == key; });
}

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

// ---- style attributes ----

ComponentStyle componentStyle(const QMap<QString, ComponentStyle> &components, const char *key)
{
    static const QMap<QString, ComponentStyle> defaults = Style::preset(QStringLiteral("normal")).components;
    const QString k = QLatin1StringView(key);
    auto it = components.constFind(k);
    if (it != components.constEnd())
        return *it;
    return defaults.value(k);
}

using Attributes = std::vector<std::pair<const char *, QByteArray>>;

void addColour(Attributes &out, const char *attribute, const char *opacityAttribute, const QColor &c)
{
    if (!c.isValid()) {
        out.emplace_back(attribute, QByteArrayLiteral("none"));
        return;
    }
    out.emplace_back(attribute, c.name(QColor::HexRgb).toLatin1());
    if (c.alpha() < 255)
        out.emplace_back(opacityAttribute, number(c.alphaF()));
}

// The presentation attributes of a part: the same in every pose.
Attributes paintAttributes(const ComponentStyle &s, Paint paint, double unit)
{
    Attributes out;
    addColour(out, "fill", "fill-opacity", paint == StrokeOnly ? QColor() : s.fill);
    const bool stroked = paint != FillOnly && s.stroke.isValid() && s.strokeWidth > 0;
    addColour(out, "stroke", "stroke-opacity", stroked ? s.stroke : QColor());
    if (stroked)
        out.emplace_back("stroke-width", number(s.strokeWidth * unit));
    return out;
}

QString latin1(const char *s)
{
    return QString::fromLatin1(s);
}

} // namespace

namespace {

// <g id="style-layer-N" transform=...> holding a style layer made inert, its viewBox's centre at
// the face's centre moved by the layer's offset and its width scaled to the layer's.
QByteArray placedLayer(const StyleLayer &layer, int number, const SvgFaceGeometry &g)
{
    const QByteArray id = "style-layer-" + QByteArray::number(number);
    LayerDrawing drawing;
    QString error;
    if (!readLayerSvg(layer.svg, QString::fromLatin1(id + '-'), &drawing, &error))
        return {}; // not drawn: the editor and the project reader refuse such layers by name
    const double scale = std::clamp(layer.width, 0.01, 100.0) * g.es0 / drawing.viewBox.width();
    QByteArray t = "translate(";
    appendPoint(t, g.centre + layer.offset * g.es0);
    t += ") scale(";
    t += QByteArray::number(scale, 'g', 6);
    t += ") translate(";
    appendPoint(t, -drawing.viewBox.center());
    t += ')';
    return "<g id=\"" + id + "\" transform=\"" + t + "\">" + drawing.fragment + "</g>\n";
}

SvgFaceGeometry buildGeometry(const FaceModel &face, const Style &style)
{
    SvgFaceGeometry g;
    const Fapu f = face.fapu();
    g.es0 = f.es0 > 0 && std::isfinite(f.es0) ? f.es0 : 100.0;
    g.unit = g.es0 / 100.0;
    g.components = style.components;
    {
        const QMap<QString, ComponentStyle> defaults = Style::preset(QStringLiteral("normal")).components;
        QStringList keys = style.components.keys() + defaults.keys();
        keys.removeDuplicates();
        for (const QString &key : keys) {
            if (!componentStyle(style.components, key.toLatin1().constData()).visible)
                g.hidden.push_back(key.toLatin1());
        }
    }
    g.ruleOffset = styleRuleOffsets(face, style);
    g.neutral = face.points();
    applyStyleRules(g.neutral, g, style);
    g.rest = posedPoints(face, restingFacePose(face));
    applyStyleRules(g.rest, g, style);
    const Pt P {g.neutral};
    g.centre = face.bounds(PointGroup::Contour).center();
    // The contour's direction where face and jaw meet, from the whole neutral outline, so the
    // static face and the moving jaw always join smoothly.
    g.jawStartTangent = unit(P("2.12") - P("5.2"));
    g.jawEndTangent = unit(P("5.1") - P("2.11"));
    g.eyeballRadius = kEyeballRadius * g.es0 * (1.0 + childRules(style) * (kCuteEyeballScale - 1.0));

    auto visible = [&](const char *key) { return componentStyle(style.components, key).visible; };
    const Appearance &look = style.appearance;
    // A wrap hides the hair; it lies behind the face, its crown and brim (the hat) in front.
    const bool wrapped = look.hat && look.wrap && visible("hat");
    if (wrapped)
        g.staticParts.push_back(makeWrap(P, g.centre, g.es0, style.cornerCutDepth));
    else if (visible("hair") && !look.bald)
        g.staticParts.push_back(makeHair(P, g, style.cornerCutDepth));
    if (visible("ears")) {
        makeEar(P, g, true, &g.staticParts);
        makeEar(P, g, false, &g.staticParts);
    }
    if (visible("face"))
        g.staticParts.push_back(makeFace(P, g, look.bald));
    if (visible("cheeks")) {
        // Blush on the cheeks, between the lower lid, the face side, the nose wing and the mouth.
        const double r = kCheekRadius * g.es0;
        for (bool left : {true, false}) {
            const QPointF c = left ? (P("3.4") + P("5.2") + P("9.2") + P("8.4")) / 4.0
                                   : (P("3.3") + P("5.1") + P("9.1") + P("8.3")) / 4.0;
            g.staticParts.push_back({left ? "cheek-left" : "cheek-right", false, "circle",
                {{"cx", number(c.x())}, {"cy", number(c.y())}, {"r", number(r)}}, "cheeks"});
        }
    }
    if (visible("nose"))
        makeNose(P, style.nose, g.es0, &g.staticParts);
    if (look.hat && visible("hat"))
        g.staticParts.push_back(makeHat(P, g.es0, style.cornerCutDepth));
    if (visible("body")) {
        g.bodyParts = makeBody(P, g.es0);
        std::erase_if(g.bodyParts, [&](const Part &p) { return !visible(p.styleKey); });
    }
    for (qsizetype i = 0; i < style.layers.size(); ++i) {
        const StyleLayer &layer = style.layers[i];
        if (layer.visible)
            (layer.followsHead ? (layer.front ? g.headFront : g.headBehind) : (layer.front ? g.front : g.behind))
                += placedLayer(layer, int(i + 1), g);
    }
    return g;
}

// What makes the parts that depend on the pose, in drawing order: each builder makes one or
// more parts (the mouth five, an eye up to six). A set of them builds only some parts.
enum class Builder { Eyebrows, Jaw, Beard, Cues, AgeLines, Mouth, Moustache, LeftEye, RightEye, Glasses, Count };
using Builders = std::bitset<size_t(Builder::Count)>;

// The parts in drawing order; only those that depend on the pose unless `withStatic`, and of
// those only the ones `only` builds when it is given. `builders`, when given, receives each
// part's builder (-1 for the still parts).
std::vector<Part> buildParts(const SvgFaceGeometry &g, const FaceModel &face, const Style &style, const Pose &pose,
    bool eyeCovers, bool withStatic = true, const Builders *only = nullptr, std::vector<int> *builders = nullptr)
{
    Points posed = posedPoints(face, pose);
    applyStyleRules(posed, g, style);
    const Appearance &look = style.appearance;
    if (look.hat && drawn(g, "hat"))
        keepBrowsUnderBrim(posed, g.neutral, g.es0);
    if (look.glasses != GlassesShape::None)
        keepBrowsAboveGlasses(posed, g.neutral, glassesLenses(Pt {posed}, look.glasses, look.lens, g.es0), g.es0);
    const Pt P {posed};
    std::vector<Part> parts;
    parts.reserve(g.staticParts.size() + 24);
    if (withStatic)
        parts = g.staticParts;
    std::vector<int> made(parts.size(), -1);
    auto build = [&](Builder b, const auto &make) {
        if (only && !only->test(size_t(b)))
            return;
        make();
        made.resize(parts.size(), int(b));
    };
    build(Builder::Eyebrows, [&] {
        if (drawn(g, "eyebrows"))
            makeEyebrows(P, style, g.es0, &parts);
    });
    build(Builder::Jaw, [&] {
        if (drawn(g, "jaw"))
            parts.push_back(makeJaw(P, g));
    });
    build(Builder::Beard, [&] {
        if (look.beard)
            parts.push_back(makeBeard(P, g.es0));
        else if (look.goatee)
            parts.push_back(makeGoatee(P, g.es0));
    });
    build(Builder::Cues, [&] { makeExpressionCues(P, Pt {g.neutral}, Pt {g.rest}, g.es0, &parts); });
    build(Builder::AgeLines, [&] {
        if (look.age == AgeGroup::Elderly)
            makeAgeLines(P, g.es0, &parts);
    });
    build(Builder::Mouth, [&] { makeMouth(P, &parts); });
    build(Builder::Moustache, [&] {
        if (look.moustache)
            parts.push_back(makeMoustache(P, g.es0));
    });
    build(Builder::LeftEye, [&] { makeEye(P, g, true, eyeCovers, &parts); });
    build(Builder::RightEye, [&] { makeEye(P, g, false, eyeCovers, &parts); });
    build(Builder::Glasses, [&] {
        if (look.glasses != GlassesShape::None)
            parts.push_back(makeGlasses(P, look.glasses, look.lens, g.es0));
    });
    size_t kept = 0;
    for (size_t i = 0; i < parts.size(); ++i) {
        if (!drawn(g, parts[i].styleKey))
            continue;
        if (kept != i) {
            parts[kept] = std::move(parts[i]);
            made[kept] = made[i];
        }
        ++kept;
    }
    parts.resize(kept);
    made.resize(kept);
    if (builders)
        *builders = std::move(made);
    return parts;
}

FacePart facePart(const Part &p, const SvgFaceGeometry &g)
{
    FacePart f;
    f.id = latin1(p.id);
    f.layer = p.dynamic ? QStringLiteral("dynamic") : QStringLiteral("static");
    f.element = latin1(p.element);
    for (const auto &[name, value] : p.geometry)
        f.geometry.insert(latin1(name), QString::fromLatin1(value));
    f.styleKey = latin1(p.styleKey);
    for (const auto &[name, value] : paintAttributes(componentStyle(g.components, p.styleKey), p.paint, g.unit))
        f.paint.insert(latin1(name), QString::fromLatin1(value));
    if (p.clipPath)
        f.clipPath = latin1(p.clipPath);
    return f;
}

QByteArray headTransformText(const SvgFaceGeometry &g, const HeadPose &head)
{
    // translate(t) rotate(a, c) then scale about c; identity when neutral, always present.
    QByteArray t = "translate(";
    appendPoint(t, head.translation + g.centre);
    t += ") rotate(";
    appendNumber(t, head.rotationDeg);
    t += ") scale(";
    appendNumber(t, head.scale);
    t += ") translate(";
    appendPoint(t, -g.centre);
    t += ')';
    return t;
}

// Writes one part as <element id=... geometry... clip-path=... paint.../>.
void writePart(QByteArray &out, const Part &p, const SvgFaceGeometry &g)
{
    out += '<';
    out += p.element;
    out += " id=\"";
    out += p.id;
    out += '"';
    auto attribute = [&out](const char *name, const QByteArray &value) {
        out += ' ';
        out += name;
        out += "=\"";
        out += value;
        out += '"';
    };
    for (const auto &[name, value] : p.geometry)
        attribute(name, value);
    if (p.clipPath)
        attribute("clip-path", QByteArray("url(#") + p.clipPath + ')');
    for (const auto &[name, value] : paintAttributes(componentStyle(g.components, p.styleKey), p.paint, g.unit))
        attribute(name, value);
    out += "/>\n";
}

} // namespace

struct SvgFace::Geometry
{
    SvgFaceGeometry g;
    QVector<FacePart> staticParts; // g.staticParts that are visible, for parts()
    Style drawn; // the style as drawn for the face's age (agestyle.h); style() stays the one given
    // The builder of each posed part's id, with and without the eye covers, for posedGeometry().
    QHash<QByteArray, int> builderOf;
};

SvgFace::SvgFace(const FaceModel &face, const Style &style)
    : m_face(face)
    , m_style(style)
{
    auto geometry = std::make_shared<Geometry>();
    geometry->drawn = agedStyle(style);
    geometry->g = buildGeometry(face, geometry->drawn);
    for (const Part &p : geometry->g.staticParts) {
        if (componentStyle(geometry->drawn.components, p.styleKey).visible)
            geometry->staticParts.append(facePart(p, geometry->g));
    }
    for (const bool covers : {true, false}) {
        std::vector<int> builders;
        const std::vector<Part> posed
            = buildParts(geometry->g, m_face, geometry->drawn, Pose {}, covers, false, nullptr, &builders);
        for (size_t i = 0; i < posed.size(); ++i)
            geometry->builderOf.insert(QByteArray(posed[i].id), builders[i]);
    }
    m_geometry = std::move(geometry);
}

bool SvgFace::addLayerFile(const QString &svgPath, QString *error)
{
    QString why;
    const std::optional<QByteArray> content = readUserFile(svgPath, kMaxLayerFileBytes, &why);
    if (!content) {
        if (error)
            *error = ImageText::tr("cannot read layer file %1: %2").arg(svgPath, why);
        return false;
    }
    LayerDrawing drawing;
    if (!readLayerSvg(*content, QStringLiteral("layer-%1-").arg(m_layers.size() + 1), &drawing, &why)) {
        if (error)
            *error = ImageText::tr("layer file %1 is not a valid SVG file: %2").arg(svgPath, why);
        return false;
    }
    m_layers.append(drawing.fragment);
    return true;
}

void SvgFace::addLayer(const QByteArray &svgContent)
{
    LayerDrawing drawing;
    QString why;
    if (!readLayerSvg(svgContent, QStringLiteral("layer-%1-").arg(m_layers.size() + 1), &drawing, &why))
        drawing.fragment.clear(); // still numbered, so later layers keep their ids
    m_layers.append(drawing.fragment);
}

QVector<FacePart> SvgFace::parts(const Pose &pose) const
{
    const SvgFaceGeometry &g = m_geometry->g;
    const std::vector<Part> posed = buildParts(g, m_face, m_geometry->drawn, pose, m_eyeCovers, false);
    QVector<FacePart> out = m_geometry->staticParts;
    out.reserve(out.size() + qsizetype(posed.size()));
    for (const Part &p : posed)
        out.append(facePart(p, g));
    return out;
}

std::vector<SvgFace::PartGeometry> SvgFace::posedGeometry(const Pose &pose, const QVector<QByteArray> &ids) const
{
    // Only the builders of the parts asked for; every one when a part is not known.
    Builders only;
    for (const QByteArray &id : ids) {
        const auto it = m_geometry->builderOf.constFind(id);
        if (it == m_geometry->builderOf.constEnd()) {
            only.set();
            break;
        }
        only.set(size_t(*it));
    }
    std::vector<Part> posed = buildParts(
        m_geometry->g, m_face, m_geometry->drawn, pose, m_eyeCovers, false, ids.isEmpty() ? nullptr : &only);
    std::vector<PartGeometry> out;
    out.reserve(posed.size());
    for (Part &p : posed)
        out.push_back({p.id, std::move(p.geometry)});
    return out;
}

qsizetype SvgFace::stillPartCount() const
{
    return m_geometry->staticParts.size();
}

QRectF SvgFace::frame() const
{
    if (m_frame.isValid() && !m_frame.isEmpty())
        return m_frame;
    // Without a photo (a face placed by hand), the frame holds the points with equal margins.
    QSize size = m_face.imageSize();
    if (!size.isValid() || size.isEmpty()) {
        const QRectF b = m_face.bounds();
        const double w = b.right() + std::max(0.0, b.left());
        const double h = b.bottom() + std::max(0.0, b.top());
        size = std::isfinite(w) && std::isfinite(h) && w >= 1 && h >= 1 && w < 1e5 && h < 1e5
            ? QSize(int(std::ceil(w)), int(std::ceil(h)))
            : QSize(512, 512);
    }
    return QRectF(QPointF(0, 0), QSizeF(size));
}

QRectF headFrame(const FaceModel &face, double aspect)
{
    const QRectF head = face.bounds();
    if (!head.isValid() || head.isEmpty())
        return {};
    // A shake turns the head by up to ~10 degrees about its centre and a nod moves it by a few
    // percent; the jaw drops by up to a mouth's height when it opens wide: a tenth of the head's
    // size on the sides and top, a fifth below (the chin and the neck's start).
    const double unit = std::max(head.width(), head.height());
    QRectF r = head.adjusted(-0.1 * unit, -0.1 * unit, 0.1 * unit, 0.2 * unit);
    if (!(aspect > 0))
        return r;
    if (r.width() / r.height() < aspect) {
        const double w = r.height() * aspect;
        r.adjust(-(w - r.width()) / 2, 0, (w - r.width()) / 2, 0);
    } else {
        const double h = r.width() / aspect;
        r.adjust(0, -(h - r.height()) / 2, 0, (h - r.height()) / 2);
    }
    // Whole pixels, so raster sizes and the drawing agree.
    return QRectF(std::floor(r.x()), std::floor(r.y()), std::ceil(r.width()), std::ceil(r.height()));
}

QString SvgFace::headTransform(const HeadPose &head) const
{
    return QString::fromLatin1(headTransformText(m_geometry->g, head));
}

QByteArray SvgFace::svg(const Pose &pose) const
{
    const std::vector<Part> parts = buildParts(m_geometry->g, m_face, m_geometry->drawn, pose, m_eyeCovers);
    return document(parts, pose, Pass::Whole);
}

SvgFace::Passes SvgFace::svgPasses(const Pose &pose) const
{
    const std::vector<Part> parts = buildParts(m_geometry->g, m_face, m_geometry->drawn, pose, m_eyeCovers);
    return {document(parts, pose, Pass::Under), document(parts, pose, Pass::Over)};
}

QByteArray SvgFace::document(const std::vector<Part> &parts, const Pose &pose, Pass pass) const
{
    const SvgFaceGeometry &g = m_geometry->g;
    const QRectF box = frame();
    QByteArray out;
    out.reserve(12000);
    out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
           "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" version=\"1.1\"";
    out += " width=\"";
    appendNumber(out, box.width());
    out += "\" height=\"";
    appendNumber(out, box.height());
    out += "\" viewBox=\"";
    appendNumber(out, box.x());
    out += ' ';
    appendNumber(out, box.y());
    out += ' ';
    appendNumber(out, box.width());
    out += ' ';
    appendNumber(out, box.height());
    out += "\">\n";

    // Clip paths reuse the outline they clip by, so animating the outline animates the clip.
    // The eyes are in the dynamic layer: the under pass has nothing to clip.
    if (pass != Pass::Under) {
        out += "<defs>";
        for (const Part &p : parts) {
            if (p.clipPath && std::strcmp(p.id, "eyeball-left") == 0)
                out += QByteArray("<clipPath id=\"") + p.clipPath + "\"><use xlink:href=\"#eye-left\"/></clipPath>";
            else if (p.clipPath && std::strcmp(p.id, "eyeball-right") == 0)
                out += QByteArray("<clipPath id=\"") + p.clipPath + "\"><use xlink:href=\"#eye-right\"/></clipPath>";
        }
        out += "</defs>\n";
    }

    if (pass != Pass::Over) {
        if (!g.bodyParts.empty()) {
            out += "<g id=\"body\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
            for (const Part &p : g.bodyParts)
                writePart(out, p, g);
            out += "</g>\n";
        }
        out += g.behind;
    }
    out += "<g id=\"head\" transform=\"" + headTransformText(g, pose.head)
        + "\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
    if (pass != Pass::Over)
        out += g.headBehind;
    for (bool dynamic : {false, true}) {
        if (dynamic ? pass == Pass::Under : pass == Pass::Over)
            continue;
        out += dynamic ? "<g id=\"dynamic-layer\">\n" : "<g id=\"static-layer\">\n";
        for (const Part &p : parts) {
            if (p.dynamic == dynamic)
                writePart(out, p, g);
        }
        out += "</g>\n";
    }
    if (pass != Pass::Under)
        out += g.headFront;
    out += "</g>\n";
    if (pass != Pass::Under) {
        out += g.front;
        for (qsizetype i = 0; i < m_layers.size(); ++i) {
            out += "<g id=\"layer-" + QByteArray::number(i + 1) + "\">";
            out += m_layers[i];
            out += "</g>\n";
        }
    }
    out += "</svg>\n";
    return out;
}

namespace {

// Where rasterizeSvg() places a drawing of `renderer` on an image of `size`.
QRectF placement(const QSvgRenderer &renderer, QSize size)
{
    QSizeF source = renderer.viewBoxF().size();
    if (source.isEmpty())
        source = renderer.defaultSize();
    if (source.isEmpty())
        source = size;
    const QSizeF fitted = source.scaled(QSizeF(size), Qt::KeepAspectRatio);
    return QRectF(QPointF((size.width() - fitted.width()) / 2.0, (size.height() - fitted.height()) / 2.0), fitted);
}

void draw(QSvgRenderer &renderer, QImage *image, const QRectF &target, const QColor *background)
{
    QPainter painter(image);
    painter.setRenderHint(QPainter::Antialiasing);
    if (background)
        painter.fillRect(target, *background);
    // As a browser does: nothing outside the viewBox (the shoulders and the user's layers may
    // reach beyond it), which QSvgRenderer would draw.
    painter.setClipRect(target);
    renderer.render(&painter, target);
    painter.end();
}

} // namespace

QImage rasterizeSvg(const QByteArray &svg, QSize size, QColor background)
{
    if (size.isEmpty())
        return {};
    QSvgRenderer renderer(svg);
    if (!renderer.isValid())
        return {};
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    draw(renderer, &image, placement(renderer, size), &background);
    return image;
}

bool drawSvg(const QByteArray &svg, QImage *image)
{
    if (image->isNull())
        return false;
    QSvgRenderer renderer(svg);
    if (!renderer.isValid())
        return false;
    draw(renderer, image, placement(renderer, image->size()), nullptr);
    return true;
}

} // namespace toonface
