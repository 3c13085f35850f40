#include "render/style.h"

namespace toonface {

namespace {

ComponentStyle paint(const char *fill, const char *stroke, double width)
{
    ComponentStyle s;
    if (fill)
        s.fill = QColor(QLatin1StringView(fill));
    if (stroke)
        s.stroke = QColor(QLatin1StringView(stroke));
    s.strokeWidth = width;
    return s;
}

} // namespace

QMap<QString, ComponentStyle> Style::baseComponents()
{
    const char *skin = "#f3cfb3";
    const char *outline = "#6b4430";
    QMap<QString, ComponentStyle> c;
    c.insert(QStringLiteral("hair"), paint("#3d2b1f", "#22170f", 2.0));
    c.insert(QStringLiteral("ears"), paint(skin, outline, 2.2));
    c.insert(QStringLiteral("face"), paint(skin, outline, 2.6));
    c.insert(QStringLiteral("jaw"), paint(skin, outline, 2.6));
    c.insert(QStringLiteral("nose"), paint(nullptr, "#a0664f", 2.2));
    c.insert(QStringLiteral("eyebrows"), paint("#2f2119", "#2f2119", 4.5));
    c.insert(QStringLiteral("eyes"), paint("#ffffff", "#2b1d16", 2.2));
    c.insert(QStringLiteral("eyeballs"), paint("#6b4a2b", "#2b1d16", 0.8));
    c.insert(QStringLiteral("pupils"), paint("#150e0b", nullptr, 0));
    c.insert(QStringLiteral("highlights"), paint("#ffffff", nullptr, 0));
    c.insert(QStringLiteral("lips"), paint("#d67c74", "#94443d", 1.6));
    c.insert(QStringLiteral("mouth-inner"), paint("#5c2323", nullptr, 0));
    c.insert(QStringLiteral("teeth"), paint("#fbf8f1", nullptr, 0));
    c.insert(QStringLiteral("tongue"), paint("#c0585a", nullptr, 0));
    ComponentStyle cheeks = paint("#f07f7f", nullptr, 0);
    cheeks.fill.setAlpha(77); // 30 %, in the 8 bits a project file keeps
    cheeks.visible = false;
    c.insert(QStringLiteral("cheeks"), cheeks);
    // The cues of expressions (render/svgexpression.h): creases and a smile's blush.
    ComponentStyle creases = paint(outline, nullptr, 0);
    creases.fill.setAlpha(204); // 80 %
    c.insert(QStringLiteral("creases"), creases);
    ComponentStyle blush = paint("#f06a6a", nullptr, 0);
    blush.fill.setAlpha(115); // 45 %
    c.insert(QStringLiteral("blush"), blush);
    // The clothes on the shoulders (the neck takes the face's colours); a photo gives their colour.
    c.insert(QStringLiteral("body"), paint("#4f6d8f", "#2e3f52", 2.2));
    // Drawn only when the appearance has them; these are the colours until a photo gives its own.
    c.insert(QStringLiteral("glasses"), paint(nullptr, "#2a2a2e", 2.6));
    c.insert(QStringLiteral("moustache"), paint("#3d2b1f", "#22170f", 1.2));
    c.insert(QStringLiteral("beard"), paint("#3d2b1f", "#22170f", 1.2));
    c.insert(QStringLiteral("hat"), paint("#2b3a55", "#151c2a", 2.2));
    return c;
}

QStringList Style::presetNames()
{
    return {QStringLiteral("normal"), QStringLiteral("soft"), QStringLiteral("bold"), QStringLiteral("cute")};
}

Style Style::preset(const QString &name, bool *ok)
{
    const bool known = presetNames().contains(name);
    if (ok)
        *ok = known;
    if (!known)
        return Style();
    // "normal" (thesis Fig. 7.8(a)): polyline eyebrows by corner cutting, the full nose.
    Style s;
    s.name = name;
    s.components = baseComponents();
    if (name == QLatin1StringView("soft")) {
        // Thesis Fig. 7.8(b): Bezier eyebrows and a simpler nose.
        s.eyebrows = EyebrowVariant::Bezier;
        s.nose = NoseVariant::Simple;
    } else if (name == QLatin1StringView("bold")) {
        s.eyebrows = EyebrowVariant::Thick;
        s.nose = NoseVariant::Simple;
        for (const char *key : {"face", "jaw", "ears", "eyes"})
            s.components[QLatin1StringView(key)].strokeWidth *= 1.5;
        s.components[QStringLiteral("hair")].strokeWidth = 3.0;
        s.components[QStringLiteral("nose")].strokeWidth = 3.0;
        s.components[QStringLiteral("lips")].strokeWidth = 2.4;
    } else if (name == QLatin1StringView("cute")) {
        // Thesis Fig. 7.8(c): rounder, shorter jaw, larger eyes and eyeballs, smaller nose (by
        // rule, in SvgFace), softer brows and blushing cheeks.
        s.cute = true;
        s.eyebrows = EyebrowVariant::Bezier;
        s.nose = NoseVariant::Simple;
        s.components[QStringLiteral("cheeks")].visible = true;
    }
    return s;
}

QString eyebrowVariantName(EyebrowVariant v)
{
    switch (v) {
    case EyebrowVariant::Polyline: return QStringLiteral("polyline");
    case EyebrowVariant::Bezier: return QStringLiteral("bezier");
    case EyebrowVariant::Thick: return QStringLiteral("thick");
    }
    return {};
}

bool eyebrowVariantFromName(const QString &name, EyebrowVariant *v)
{
    for (EyebrowVariant e : {EyebrowVariant::Polyline, EyebrowVariant::Bezier, EyebrowVariant::Thick}) {
        if (eyebrowVariantName(e) == name) {
            *v = e;
            return true;
        }
    }
    return false;
}

QString noseVariantName(NoseVariant v)
{
    switch (v) {
    case NoseVariant::Full: return QStringLiteral("full");
    case NoseVariant::Simple: return QStringLiteral("simple");
    case NoseVariant::Tip: return QStringLiteral("tip");
    }
    return {};
}

bool noseVariantFromName(const QString &name, NoseVariant *v)
{
    for (NoseVariant n : {NoseVariant::Full, NoseVariant::Simple, NoseVariant::Tip}) {
        if (noseVariantName(n) == name) {
            *v = n;
            return true;
        }
    }
    return false;
}

} // namespace toonface
