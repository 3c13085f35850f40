#include "face/restingface.h"

#include "face/facemodel.h"
#include "face/mouthshape.h"

#include <QLineF>

#include <algorithm>
#include <cmath>

namespace toonface {

namespace {

// The eye line's frame of `points`: along it (image-left to image-right) and up from it, unit.
struct EyeFrame
{
    QPointF along {1, 0}, up {0, -1};
    double es0 = 1;
};

EyeFrame eyeFrame(const std::array<QPointF, kPointCount> &p)
{
    EyeFrame f;
    const QPointF d = p[pt::idx("3.5")] - p[pt::idx("3.6")];
    const double len = std::hypot(d.x(), d.y());
    if (len <= 0)
        return f;
    f.es0 = len;
    f.along = d / len;
    f.up = QPointF(f.along.y(), -f.along.x());
    return f;
}

double dot(QPointF a, QPointF b)
{
    return a.x() * b.x() + a.y() * b.y();
}

struct BrowIds
{
    const char *outer, *a, *b, *inner, *outerCorner, *innerCorner;
};
constexpr BrowIds kBrows[2]
    = {{"4.6", "4.4a", "4.4", "4.2", "3.12", "3.8"}, {"4.5", "4.3a", "4.3", "4.1", "3.7", "3.11"}};

// Where the line the lips meet on lies when shut (restingMouth), and the corners' mean height.
double cornerLiftOf(const std::array<QPointF, kPointCount> &p, const EyeFrame &f, QPointF restUp, QPointF restDown)
{
    const QPointF lips = (p[pt::idx("2.2")] + restUp + p[pt::idx("2.3")] + restDown) / 2.0;
    const QPointF corners = (p[pt::idx("8.4")] + p[pt::idx("8.3")]) / 2.0;
    return dot(corners - lips, f.up) / f.es0;
}

} // namespace

Pose restingFacePose(const FaceModel &face)
{
    Pose pose;
    const auto &p = face.points();
    const EyeFrame f = eyeFrame(p);
    if (f.es0 <= 1)
        return pose;
    auto at = [&](const char *id) { return p[pt::idx(id)]; };
    for (const BrowIds &s : kBrows) {
        const double inner = dot(at(s.inner) - at(s.innerCorner), f.up) / f.es0;
        const double outer = dot(at(s.outer) - at(s.outerCorner), f.up) / f.es0;
        const double mean = std::clamp((inner + outer) / 2.0, kBrowRest.heightLow, kBrowRest.heightHigh);
        const double slant = std::clamp(inner - outer, kBrowRest.slantLow, kBrowRest.slantHigh);
        const double innerMove = (mean + slant / 2.0 - inner) * f.es0;
        const double outerMove = (mean - slant / 2.0 - outer) * f.es0;
        // The middle points by their place between the ends along the eye line.
        const double span = dot(at(s.inner) - at(s.outer), f.along);
        for (const char *id : {s.outer, s.a, s.b, s.inner}) {
            const double t
                = std::abs(span) > 1e-9 ? std::clamp(dot(at(id) - at(s.outer), f.along) / span, 0.0, 1.0) : 0.5;
            pose.offset[pt::idx(id)] += f.up * (outerMove + t * (innerMove - outerMove));
        }
    }
    // Inner ends drawn together by a frown go apart to the band's edge, each half the way.
    const double gap = dot(at("4.1") - at("4.2"), f.along) / f.es0;
    if (gap < kBrowRest.innerGapLow) {
        const QPointF half = f.along * ((kBrowRest.innerGapLow - gap) / 2.0 * f.es0);
        pose.offset[pt::idx("4.2")] -= half;
        pose.offset[pt::idx("4.1")] += half;
    }
    // The corners onto the lips' meeting line, or to kRestingCornerDrop below it.
    const std::array<QPointF, 4> rest = restingMouth(face);
    const double lift = cornerLiftOf(p, f, rest[Up], rest[Down]);
    const double target = std::clamp(lift, -kRestingCornerDrop, 0.0);
    for (const char *id : {"8.4", "8.3"})
        pose.offset[pt::idx(id)] += f.up * ((target - lift) * f.es0);
    // A mouth stretched wider than people's at rest comes in, each corner half the way.
    const double width = dot(at("8.3") - at("8.4"), f.along) / f.es0;
    if (width > kRestingMouthWidthHigh) {
        const QPointF half = f.along * ((width - kRestingMouthWidthHigh) / 2.0 * f.es0);
        pose.offset[pt::idx("8.4")] += half;
        pose.offset[pt::idx("8.3")] -= half;
    }
    return pose;
}

void keepBrowsUnderHairline(const FaceModel &face, Pose *pose)
{
    const auto &p = face.points();
    const EyeFrame f = eyeFrame(p);
    const double limitY = p[pt::idx("11.1")].y() + kBrowBelowHairline * f.es0;
    // How far the brows must come down for every point to stay under the limit (or no higher than
    // its own place, where the photo's brow already lies above it); both brows come down together,
    // keeping their shapes (a sad brow under a brim still slants) and each other's mirror image.
    double push = 0;
    for (const BrowIds &s : kBrows) {
        for (const char *id : {s.outer, s.a, s.b, s.inner}) {
            const int i = pt::idx(id);
            const double allowed = std::min(p[i].y(), limitY);
            push = std::max(push, allowed - (p[i].y() + pose->offset[i].y()));
        }
    }
    if (push <= 0)
        return;
    for (const BrowIds &s : kBrows)
        for (const char *id : {s.outer, s.a, s.b, s.inner})
            pose->offset[pt::idx(id)].ry() += push;
}

ExpressionShape expressionShape(const FaceModel &face, const Pose &pose)
{
    ExpressionShape e;
    const std::array<QPointF, kPointCount> p = posedPoints(face, pose);
    const EyeFrame f = eyeFrame(p);
    auto at = [&](const char *id) { return p[pt::idx(id)]; };
    for (int side = 0; side < 2; ++side) {
        const BrowIds &s = kBrows[side];
        e.innerHeight[side] = dot(at(s.inner) - at(s.innerCorner), f.up) / f.es0;
        e.outerHeight[side] = dot(at(s.outer) - at(s.outerCorner), f.up) / f.es0;
    }
    e.innerGap = dot(at("4.1") - at("4.2"), f.along) / f.es0;
    e.cornerLift = cornerLiftOf(p, f, {}, {});
    e.mouthOpen = dot(at("2.2") - at("2.3"), f.up) / f.es0;
    e.lipHeight = dot(at("8.1") - at("8.2"), f.up) / f.es0;
    return e;
}

} // namespace toonface
