#include "render/agestyle.h"

#include "render/svgexpression.h"

namespace toonface {

namespace {

// A child's brow: at most this line weight (ES0/100; the base brow is 4.5) ...
constexpr double kChildBrowWidth = 2.2;
// ... and this share of the way from its colour to the skin's.
constexpr double kChildBrowToSkin = 0.3;

QColor mix(const QColor &a, const QColor &b, double t)
{
    return QColor::fromRgbF(float(a.redF() + (b.redF() - a.redF()) * t),
        float(a.greenF() + (b.greenF() - a.greenF()) * t), float(a.blueF() + (b.blueF() - a.blueF()) * t));
}

QColor skinOf(const Style &style)
{
    const QColor skin = style.components.value(QStringLiteral("face")).fill;
    return skin.isValid() ? skin : Style::baseComponents().value(QStringLiteral("face")).fill;
}

} // namespace

QColor childLips(const QColor &skin)
{
    // Deeper by a fifth and turned a few degrees toward red: read as lips, not as lipstick, on
    // every skin tone (the hue stays the skin's own family).
    const QColor deeper = skin.darker(122);
    const float hue = std::max(0.0f, deeper.hsvHueF() - 6.0f / 360.0f);
    return QColor::fromHsvF(hue, std::min(1.0f, deeper.hsvSaturationF() * 1.15f), deeper.valueF());
}

Style agedStyle(const Style &style)
{
    if (style.appearance.age != AgeGroup::Child)
        return style;
    Style s = style;
    if (s.components.isEmpty())
        s.components = Style::baseComponents();
    const QColor skin = skinOf(s);
    ComponentStyle brows
        = s.components.value(QStringLiteral("eyebrows"), Style::baseComponents().value(QStringLiteral("eyebrows")));
    brows.strokeWidth = std::min(brows.strokeWidth, kChildBrowWidth);
    if (brows.stroke.isValid())
        brows.stroke = mix(brows.stroke, skin, kChildBrowToSkin);
    if (brows.fill.isValid())
        brows.fill = mix(brows.fill, skin, kChildBrowToSkin);
    s.components.insert(QStringLiteral("eyebrows"), brows);
    if (s.eyebrows == EyebrowVariant::Thick)
        s.eyebrows = EyebrowVariant::Bezier;
    ComponentStyle lips
        = s.components.value(QStringLiteral("lips"), Style::baseComponents().value(QStringLiteral("lips")));
    lips.fill = childLips(skin);
    lips.stroke = lips.fill.darker(135);
    s.components.insert(QStringLiteral("lips"), lips);
    return s;
}

double childRules(const Style &style)
{
    return style.cute ? 1.0 : style.appearance.age == AgeGroup::Child ? kChildRules : 0.0;
}

} // namespace toonface

namespace toonface::svgparts {

namespace {

// Half thickness of an age line (ES0): a third of an expression crease's, so they read as fine
// lines in the muted crease colour and never as an expression.
constexpr double kAgeLineHalfWidth = 0.01;

} // namespace

void makeAgeLines(const Pt &P, double es0, std::vector<Part> *out)
{
    const double w = kAgeLineHalfWidth * es0;
    auto add = [&](const char *id, QPointF a, QPointF b, QPointF side, double bow) {
        out->push_back({id, true, "path", {{"d", lens(a, b, side, bow * es0, w)}}, "creases", FillOnly});
    };
    const QPointF eyeLine = P("3.5") - P("3.6");
    const QPointF across = unit(eyeLine); // toward the face's right side (its 3.5)
    const QPointF down = QPointF(-across.y(), across.x());
    // Nasolabial folds: from above each nose wing, outward, to beside and below the mouth's corner.
    for (bool left : {true, false}) {
        const QPointF wing = P(left ? "9.2" : "9.1");
        const QPointF corner = P(left ? "8.4" : "8.3");
        const QPointF out = left ? -across : across;
        const QPointF a = wing + out * (0.12 * es0) - down * (0.05 * es0);
        const QPointF b = corner + out * (0.1 * es0) + down * (0.12 * es0);
        add(left ? "age-nasolabial-left" : "age-nasolabial-right", a, b, out, 0.05);
    }
    // Two forehead lines over the brows' middle, bowed up.
    const QPointF browMid = (P("4.4") + P("4.3")) / 2.0;
    const double half = 0.45 * length(P("4.3") - P("4.4"));
    for (int i = 0; i < 2; ++i) {
        const QPointF c = browMid - down * ((0.3 + 0.13 * i) * es0);
        add(i == 0 ? "age-forehead-1" : "age-forehead-2", c - across * half, c + across * half, -down, 0.04);
    }
    // Crow's feet: a short line fanning out from each eye's outer corner.
    for (bool left : {true, false}) {
        const QPointF corner = P(left ? "3.12" : "3.7");
        const QPointF out = left ? -across : across;
        const QPointF a = corner + out * (0.08 * es0);
        const QPointF b = a + out * (0.14 * es0) + down * (0.05 * es0);
        add(left ? "age-crow-left" : "age-crow-right", a, b, down, 0.0);
    }
}

} // namespace toonface::svgparts
