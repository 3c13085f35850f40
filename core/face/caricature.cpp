#include "face/caricature.h"

#include "face/averageface.h"
#include "face/facemodel.h"
#include "face/fapu.h"

#include <cmath>

namespace toonface {

namespace {

bool isFeature(PointGroup g)
{
    return g != PointGroup::Hair && g != PointGroup::Ears;
}

// The similarity transform (scale, rotation, translation) taking `from` onto `to` in the
// least-squares sense, over the points where `use` is true; applied to every point of `from`.
std::array<QPointF, kPointCount> alignSimilar(const std::array<QPointF, kPointCount> &from,
    const std::array<QPointF, kPointCount> &to, const std::array<bool, kPointCount> &use)
{
    QPointF mf, mt;
    int n = 0;
    for (int i = 0; i < kPointCount; ++i) {
        if (use[i]) {
            mf += from[i];
            mt += to[i];
            ++n;
        }
    }
    mf /= n;
    mt /= n;
    // As complex numbers: to - mt = s (from - mf), s = sum(conj(f) t) / sum(|f|^2).
    double re = 0, im = 0, norm = 0;
    for (int i = 0; i < kPointCount; ++i) {
        if (!use[i])
            continue;
        const QPointF f = from[i] - mf, t = to[i] - mt;
        re += f.x() * t.x() + f.y() * t.y();
        im += f.x() * t.y() - f.y() * t.x();
        norm += f.x() * f.x() + f.y() * f.y();
    }
    std::array<QPointF, kPointCount> out {};
    if (norm <= 0)
        return out;
    re /= norm;
    im /= norm;
    for (int i = 0; i < kPointCount; ++i) {
        const QPointF f = from[i] - mf;
        out[i] = mt + QPointF(re * f.x() - im * f.y(), im * f.x() + re * f.y());
    }
    return out;
}

} // namespace

std::array<QPointF, kPointCount> caricatureOffsets(const FaceModel &face, double factor)
{
    std::array<QPointF, kPointCount> off {};
    if (!(factor > 0) || !face.isValid())
        return off;
    const double es0 = face.fapu().es0;
    const auto &table = pointTable();
    std::array<bool, kPointCount> use {};
    for (int i = 0; i < kPointCount; ++i)
        use[i] = isFeature(table[i].group);
    const auto average = alignSimilar(averageFaceUnitPoints(), face.points(), use);
    const double limit = kMaxCaricatureShift * es0 * factor;
    for (int i = 0; i < kPointCount; ++i) {
        if (!use[i])
            continue;
        QPointF d = (face.point(i) - average[i]) * factor;
        const double len = std::hypot(d.x(), d.y());
        if (len > limit)
            d *= limit / len;
        off[i] = d;
    }
    // How far the lips are parted is the moment's, not the person's: the inner lips move as one,
    // so lips the rest (or a closed mouth shape) brings together still meet.
    const QPointF lips = (off[pt::idx("2.2")] + off[pt::idx("2.3")]) / 2.0;
    off[pt::idx("2.2")] = off[pt::idx("2.3")] = lips;
    // The hair outline moves with the contour: each point by the contour's displacement,
    // weighted by closeness, so it keeps its distance from the face.
    const char *const contour[] = {"11.2", "11.1", "11.3", "5.2", "5.1", "2.14", "2.13"};
    for (int i = pt::idx("h.1"); i <= pt::idx("h.19"); ++i) {
        QPointF sum;
        double weights = 0;
        for (const char *id : contour) {
            const QPointF v = face.point(i) - face.point(id);
            const double w = 1.0 / (1e-6 + v.x() * v.x() + v.y() * v.y());
            sum += off[pt::idx(id)] * w;
            weights += w;
        }
        off[i] = sum / weights;
    }
    for (const char *id : {"10.2", "10.4", "10.6", "10.10"})
        off[pt::idx(id)] = off[pt::idx("5.2")];
    for (const char *id : {"10.1", "10.3", "10.5", "10.9"})
        off[pt::idx(id)] = off[pt::idx("5.1")];
    return off;
}

} // namespace toonface
