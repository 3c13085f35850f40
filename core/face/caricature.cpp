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

// The average face the person is measured against: the template (aligned to the person), with
// people's eyes. The template's eyes are a cartoon's (half the eye distance wide, open a third of
// their width), larger than anyone's as the landmarks find them, so measured against them every
// eye came out smaller and narrower than the person's: all one small almond. Each eye is scaled
// about its centre, along and across the eye line, to the medians of the 322 eyes of the 161
// faces of faces-attributes the detector finds (caricature.h; the medians of any four of five
// folds lie within 0.005 of them), so an eye is exaggerated by how it differs from people's.
// Only the eyes' points change, after the alignment, so every other point is measured as before.
void givePeoplesEyes(std::array<QPointF, kPointCount> &p)
{
    auto at = [&](const char *id) -> QPointF & { return p[pt::idx(id)]; };
    const QPointF line = at("3.5") - at("3.6");
    const double es0 = std::hypot(line.x(), line.y());
    if (es0 <= 0)
        return;
    const QPointF along = line / es0, across(-along.y(), along.x());
    auto dot = [](QPointF a, QPointF b) { return a.x() * b.x() + a.y() * b.y(); };
    for (const auto &eye :
        {std::array {"3.6", "3.12", "3.8", "3.2", "3.4"}, std::array {"3.5", "3.11", "3.7", "3.1", "3.3"}}) {
        const QPointF centre = at(eye[0]);
        const double width = std::abs(dot(at(eye[2]) - at(eye[1]), along));
        const double height = std::abs(dot(at(eye[4]) - at(eye[3]), across));
        if (width <= 0 || height <= 0)
            continue;
        const double sx = kPeoplesEyeWidth * es0 / width;
        const double sy = kPeoplesEyeOpening * kPeoplesEyeWidth * es0 / height;
        for (const char *id : eye) {
            const QPointF d = at(id) - centre;
            at(id) = centre + along * (dot(d, along) * sx) + across * (dot(d, across) * sy);
        }
    }
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
    auto average = alignSimilar(averageFaceUnitPoints(), face.points(), use);
    givePeoplesEyes(average);
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
