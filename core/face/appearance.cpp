#include "face/appearance.h"

namespace toonface {

QString glassesShapeName(GlassesShape v)
{
    switch (v) {
    case GlassesShape::None: return QStringLiteral("none");
    case GlassesShape::Round: return QStringLiteral("round");
    case GlassesShape::Rectangular: return QStringLiteral("rectangular");
    case GlassesShape::Rimless: return QStringLiteral("rimless");
    }
    return {};
}

bool glassesShapeFromName(const QString &name, GlassesShape *v)
{
    for (GlassesShape g : {GlassesShape::None, GlassesShape::Round, GlassesShape::Rectangular, GlassesShape::Rimless}) {
        if (glassesShapeName(g) == name) {
            *v = g;
            return true;
        }
    }
    return false;
}

QString ageGroupName(AgeGroup v)
{
    switch (v) {
    case AgeGroup::Adult: return QStringLiteral("adult");
    case AgeGroup::Child: return QStringLiteral("child");
    case AgeGroup::Elderly: return QStringLiteral("elderly");
    }
    return {};
}

bool ageGroupFromName(const QString &name, AgeGroup *v)
{
    for (AgeGroup g : {AgeGroup::Adult, AgeGroup::Child, AgeGroup::Elderly}) {
        if (ageGroupName(g) == name) {
            *v = g;
            return true;
        }
    }
    return false;
}

} // namespace toonface
