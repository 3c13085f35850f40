#include "io/appearancejson.h"

#include "detect/appearance.h"
#include "render/style.h"

#include <algorithm>

namespace toonface {

QJsonObject appearanceToJson(const Style &style, const AppearanceFindings &findings)
{
    const Appearance &a = style.appearance;
    QJsonObject out;
    out.insert(QStringLiteral("skin"), style.components.value(QStringLiteral("face")).fill.name());
    const bool hairless = a.bald || findings.hairLength == HairLength::None;
    out.insert(QStringLiteral("hair"),
        hairless ? QJsonValue(QJsonValue::Null)
                 : QJsonValue(style.components.value(QStringLiteral("hair")).fill.name()));
    out.insert(QStringLiteral("hairLength"), hairLengthName(a.bald ? HairLength::None : findings.hairLength));
    out.insert(QStringLiteral("bald"), a.bald);
    out.insert(QStringLiteral("headwear"), a.hat);
    // What kind: "hat" (over the crown) or "wrap" (a headscarf or hood around the face); null without.
    out.insert(QStringLiteral("headwearKind"),
        a.hat ? QJsonValue(a.wrap ? QStringLiteral("wrap") : QStringLiteral("hat")) : QJsonValue());
    out.insert(QStringLiteral("moustache"), a.moustache);
    out.insert(QStringLiteral("beard"), a.beard);
    out.insert(QStringLiteral("goatee"), a.goatee);
    out.insert(QStringLiteral("glasses"), glassesShapeName(a.glasses));
    out.insert(QStringLiteral("ageGroup"), ageGroupName(a.age));
    const AppearanceConfidence &c = findings.confidence;
    auto unit = [](double v) { return std::clamp(v, 0.0, 1.0); };
    QJsonObject confidence;
    confidence.insert(QStringLiteral("hairLength"), unit(c.hairLength));
    confidence.insert(QStringLiteral("bald"), unit(c.bald));
    confidence.insert(QStringLiteral("headwear"), unit(c.headwear));
    confidence.insert(QStringLiteral("moustache"), unit(c.moustache));
    confidence.insert(QStringLiteral("beard"), unit(c.beard));
    confidence.insert(QStringLiteral("goatee"), unit(c.goatee));
    confidence.insert(QStringLiteral("glasses"), unit(c.glasses));
    // The age group's: the probability of the group drawn (1 - it when the user chose another).
    const double age = findings.age.group == a.age ? findings.age.confidence : 1.0 - findings.age.confidence;
    confidence.insert(QStringLiteral("ageGroup"), unit(age));
    out.insert(QStringLiteral("confidence"), confidence);
    return out;
}

} // namespace toonface
