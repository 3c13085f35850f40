#include "detect/skintone.h"

#include <QPointF>

#include <cmath>

namespace toonface {

double lumaOf(QRgb c)
{
    return 0.299 * qRed(c) + 0.587 * qGreen(c) + 0.114 * qBlue(c);
}

bool skinLike(QRgb c, const QColor &skin)
{
    const double sum = std::max(1, qRed(c) + qGreen(c) + qBlue(c));
    const double skinSum = std::max(1, skin.red() + skin.green() + skin.blue());
    const double dr = qRed(c) / sum - skin.red() / skinSum, dg = qGreen(c) / sum - skin.green() / skinSum;
    const double shade = lumaOf(c) / std::max(1.0, lumaOf(skin.rgb()));
    return std::hypot(dr, dg) < kSkinChroma && shade > kSkinShade[0] && shade < kSkinShade[1];
}

bool shineOnSkin(QRgb c, const QColor &skin)
{
    const double sum = std::max(1, qRed(c) + qGreen(c) + qBlue(c));
    const double skinSum = std::max(1, skin.red() + skin.green() + skin.blue());
    const QPointF s(skin.red() / skinSum, skin.green() / skinSum);
    const QPointF v = QPointF(1.0 / 3.0, 1.0 / 3.0) - s;
    const double vv = QPointF::dotProduct(v, v);
    if (vv < kSkinChroma * kSkinChroma || lumaOf(c) <= lumaOf(skin.rgb()))
        return false;
    const QPointF d = QPointF(qRed(c) / sum, qGreen(c) / sum) - s;
    const double t = QPointF::dotProduct(d, v) / vv;
    const QPointF off = d - v * t;
    return t >= 0 && t <= kShineToNeutral && std::hypot(off.x(), off.y()) < kSkinChroma;
}

} // namespace toonface
