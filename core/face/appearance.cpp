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

} // namespace toonface
