#include "track/facemeasure.h"

#include <QLineF>
#include <QPolygonF>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace toonface {

QPointF HeadMotion::unmap(QPointF p) const
{
    const double s2 = a * a + b * b;
    if (!(s2 > 0))
        return p;
    const QPointF q = p - t;
    return {(a * q.x() + b * q.y()) / s2, (-b * q.x() + a * q.y()) / s2};
}

double HeadMotion::rotationDeg() const
{
    return std::atan2(b, a) * 180.0 / std::numbers::pi;
}

HeadMotion fitHeadMotion(const std::array<QPointF, kPointCount> &neutral, const std::array<QPointF, kPointCount> &now,
    const QVector<int> &stable)
{
    HeadMotion h;
    if (stable.size() < 2)
        return h;
    QPointF cn, cm;
    for (int i : stable) {
        cn += neutral[i] / double(stable.size());
        cm += now[i] / double(stable.size());
    }
    double sxx = 0, sdot = 0, scross = 0;
    for (int i : stable) {
        const QPointF u = neutral[i] - cn, v = now[i] - cm;
        sxx += u.x() * u.x() + u.y() * u.y();
        sdot += u.x() * v.x() + u.y() * v.y();
        scross += u.x() * v.y() - u.y() * v.x();
    }
    if (!(sxx > 0))
        return h;
    h.a = sdot / sxx;
    h.b = scross / sxx;
    h.t = cm - QPointF(h.a * cn.x() - h.b * cn.y(), h.b * cn.x() + h.a * cn.y());
    return h;
}

namespace {

// The brows, each from its inner end to its outer end (face-model.md).
constexpr std::array<std::array<const char *, 4>, 2> kBrows
    = {{{"4.2", "4.4", "4.4a", "4.6"}, {"4.1", "4.3", "4.3a", "4.5"}}};

} // namespace

void fitBrowMotion(const std::array<QPointF, kPointCount> &neutral, std::array<QPointF, kPointCount> *displacement)
{
    for (const auto &brow : kBrows) {
        const QPointF inner = neutral[pt::idx(brow.front())];
        const QPointF axis = neutral[pt::idx(brow.back())] - inner;
        const double length2 = QPointF::dotProduct(axis, axis);
        if (!(length2 > 0))
            continue;
        // Least squares of d = a + b * u, u the position along the brow (0 inner, 1 outer).
        double su = 0, suu = 0;
        QPointF sd, sud;
        std::array<double, 4> u {};
        for (size_t k = 0; k < brow.size(); ++k) {
            const int i = pt::idx(brow[k]);
            u[k] = QPointF::dotProduct(neutral[i] - inner, axis) / length2;
            su += u[k];
            suu += u[k] * u[k];
            sd += (*displacement)[i];
            sud += u[k] * (*displacement)[i];
        }
        const double n = double(brow.size());
        const double det = n * suu - su * su;
        if (!(std::abs(det) > 1e-9))
            continue;
        const QPointF b = (n * sud - su * sd) / det;
        const QPointF a = (sd - b * su) / n;
        for (size_t k = 0; k < brow.size(); ++k)
            (*displacement)[pt::idx(brow[k])] = a + b * u[k];
    }
}

FaceMotion measureMotion(const FaceMeasurement &neutral, const FaceMeasurement &now)
{
    FaceMotion m;
    const auto &n = neutral.points;
    auto at = [](const std::array<QPointF, kPointCount> &p, const char *id) { return p[pt::idx(id)]; };
    const double es0 = QLineF(at(n, "3.6"), at(n, "3.5")).length();
    if (!(es0 > 0))
        return m;
    const HeadMotion head = fitHeadMotion(n, now.points, neutral.stable);
    std::array<QPointF, kPointCount> local {};
    for (int i = 0; i < kPointCount; ++i) {
        local[i] = head.unmap(now.points[i]);
        m.displacementEs0[i] = (local[i] - n[i]) / es0;
    }
    fitBrowMotion(n, &m.displacementEs0);
    m.rotationDeg = head.rotationDeg();
    m.scale = head.scale();
    const QPointF eyeMid = (at(n, "3.6") + at(n, "3.5")) / 2.0;
    m.translationEs0 = (head.map(eyeMid) - eyeMid) / es0;

    auto aperture = [&](const std::array<QPointF, kPointCount> &p, const char *upper, const char *lower) {
        return QLineF(at(p, upper), at(p, lower)).length();
    };
    const double left0 = aperture(n, "3.2", "3.4");
    const double right0 = aperture(n, "3.1", "3.3");
    m.leftEyeOpen = left0 > 0 ? aperture(local, "3.2", "3.4") / left0 : 1.0;
    m.rightEyeOpen = right0 > 0 ? aperture(local, "3.1", "3.3") / right0 : 1.0;
    m.mouthOpenEs0 = std::max(0.0, at(local, "2.3").y() - at(local, "2.2").y()) / es0;

    auto eyeOffset = [&](const std::array<QPointF, kPointCount> &p) {
        const QPointF left = at(p, "3.6") - (at(p, "3.12") + at(p, "3.8")) / 2.0;
        const QPointF right = at(p, "3.5") - (at(p, "3.11") + at(p, "3.7")) / 2.0;
        return (left + right) / 2.0;
    };
    m.gazeEs0 = (eyeOffset(local) - eyeOffset(n)) / es0;
    return m;
}

QPointF locatePupil(const QImage &gray, const QVector<QPointF> &outline)
{
    const QPolygonF polygon(outline);
    const QRect box = polygon.boundingRect().toAlignedRect().intersected(gray.rect());
    QPointF centre;
    for (const QPointF &p : outline)
        centre += p / double(std::max<qsizetype>(1, outline.size()));
    if (box.width() < 4 || box.height() < 2)
        return centre;
    struct Pixel
    {
        int value;
        int x, y;
    };
    std::vector<Pixel> inside;
    inside.reserve(size_t(box.width()) * box.height());
    for (int y = box.top(); y <= box.bottom(); ++y) {
        const uchar *row = gray.constScanLine(y);
        for (int x = box.left(); x <= box.right(); ++x) {
            if (polygon.containsPoint(QPointF(x + 0.5, y + 0.5), Qt::OddEvenFill))
                inside.push_back({row[x], x, y});
        }
    }
    if (inside.size() < 8)
        return centre;
    const size_t quarter = std::max<size_t>(3, inside.size() / 4);
    std::nth_element(inside.begin(), inside.begin() + quarter, inside.end(),
        [](const Pixel &a, const Pixel &b) { return a.value < b.value; });
    QPointF sum;
    for (size_t i = 0; i < quarter; ++i)
        sum += QPointF(inside[i].x + 0.5, inside[i].y + 0.5);
    return sum / double(quarter);
}

} // namespace toonface
