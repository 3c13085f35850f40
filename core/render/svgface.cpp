#include "render/svgface.h"

#include "face/fapu.h"
#include "face/restingface.h"
#include "i18n/coretext.h"
#include "media/userfile.h"
#include "render/agestyle.h"
#include "render/svgbody.h"
#include "render/svgexpression.h"
#include "render/svgfacebuild.h"
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

namespace toonface {

namespace {

using namespace svgparts;
using namespace svgfacebuild;

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
