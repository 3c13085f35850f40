#include "detect/photopixels.h"

namespace toonface {

QColor median(std::vector<QRgb> px)
{
    if (px.empty())
        return {};
    auto channel = [&](int (*f)(QRgb)) {
        std::vector<int> v;
        v.reserve(px.size());
        for (QRgb p : px)
            v.push_back(f(p));
        std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
        return v[v.size() / 2];
    };
    return QColor(channel(qRed), channel(qGreen), channel(qBlue));
}

QColor darkest(std::vector<QRgb> px, double share)
{
    std::sort(px.begin(), px.end(), [](QRgb a, QRgb b) { return lumaOf(a) < lumaOf(b); });
    px.resize(std::max<size_t>(1, size_t(px.size() * share)));
    return median(px);
}

QRectF around(QPointF c, double rx, double ry)
{
    return QRectF(c.x() - rx, c.y() - ry, 2 * rx, 2 * ry);
}

double percentile(std::vector<double> v, double q)
{
    if (v.empty())
        return 0;
    auto it = v.begin() + qsizetype(q * double(v.size() - 1));
    std::nth_element(v.begin(), it, v.end());
    return *it;
}

} // namespace toonface
