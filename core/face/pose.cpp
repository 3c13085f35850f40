#include "face/pose.h"

#include "face/facemodel.h"
#include "face/fapu.h"

#include <algorithm>

namespace toonface {

Pose &Pose::operator+=(const Pose &other)
{
    for (int i = 0; i < kPointCount; ++i)
        offset[i] += other.offset[i];
    leftEyeOpen *= other.leftEyeOpen;
    rightEyeOpen *= other.rightEyeOpen;
    head.rotationDeg += other.head.rotationDeg;
    head.translation += other.head.translation;
    head.scale *= other.head.scale;
    return *this;
}

Pose Pose::lerp(const Pose &a, const Pose &b, double t)
{
    Pose p;
    for (int i = 0; i < kPointCount; ++i)
        p.offset[i] = a.offset[i] + (b.offset[i] - a.offset[i]) * t;
    p.leftEyeOpen = a.leftEyeOpen + (b.leftEyeOpen - a.leftEyeOpen) * t;
    p.rightEyeOpen = a.rightEyeOpen + (b.rightEyeOpen - a.rightEyeOpen) * t;
    p.head.rotationDeg = a.head.rotationDeg + (b.head.rotationDeg - a.head.rotationDeg) * t;
    p.head.translation = a.head.translation + (b.head.translation - a.head.translation) * t;
    p.head.scale = a.head.scale + (b.head.scale - a.head.scale) * t;
    return p;
}

namespace {

// Moves a lid point toward the line between the eye corners, keeping `open` of its height.
QPointF closeLid(QPointF lid, QPointF cornerA, QPointF cornerB, double open)
{
    const double dx = cornerB.x() - cornerA.x();
    const double t = dx != 0 ? (lid.x() - cornerA.x()) / dx : 0.5;
    const double lineY = cornerA.y() + (cornerB.y() - cornerA.y()) * t;
    return {lid.x(), lineY + (lid.y() - lineY) * std::max(0.0, open)};
}

} // namespace

std::array<QPointF, kPointCount> posedPoints(const FaceModel &face, const Pose &pose)
{
    const auto &table = pointTable();
    std::array<QPointF, kPointCount> p = face.points();
    for (int i = 0; i < kPointCount; ++i) {
        if (table[i].control)
            p[i] += pose.offset[i];
    }
    auto at = [&](const char *id) -> QPointF & { return p[pt::idx(id)]; };
    auto moved = [&](const char *id) { return pose.offset[pt::idx(id)]; };

    // Mouth: 8.10 mirrors 8.9 about the mouth axis; 8.1 keeps its offset from 8.9;
    // the inner lips follow the outer ones and closed lips touch.
    const QPointF dUp = moved("8.9");
    const QPointF dDn = moved("8.2");
    const double dAxis = (moved("8.4").x() + moved("8.3").x()) / 2.0;
    at("8.10") += QPointF(2 * dAxis - dUp.x(), dUp.y());
    at("8.1") += dUp;
    at("2.2") += dUp;
    at("2.3") += dDn;
    if (at("2.2").y() > at("2.3").y()) {
        const double y = (at("2.2").y() + at("2.3").y()) / 2.0;
        at("2.2").setY(y);
        at("2.3").setY(y);
    }

    // Jaw: the chin keeps JawH below 8.2; the lower jaw points take half of its motion.
    at("2.1") += dDn;
    at("2.12") += dDn / 2.0;
    at("2.11") += dDn / 2.0;

    // Eyes: lids close toward the corner line for blinks; eyeballs stay between the corners.
    at("3.2") = closeLid(at("3.2"), at("3.12"), at("3.8"), pose.leftEyeOpen);
    at("3.4") = closeLid(at("3.4"), at("3.12"), at("3.8"), pose.leftEyeOpen);
    at("3.1") = closeLid(at("3.1"), at("3.11"), at("3.7"), pose.rightEyeOpen);
    at("3.3") = closeLid(at("3.3"), at("3.11"), at("3.7"), pose.rightEyeOpen);
    auto clampEyeball = [&](const char *ball, const char *c1, const char *c2) {
        QPointF &b = at(ball);
        const double lo = std::min(at(c1).x(), at(c2).x());
        const double hi = std::max(at(c1).x(), at(c2).x());
        if (lo < hi)
            b.setX(std::clamp(b.x(), lo, hi));
    };
    clampEyeball("3.6", "3.12", "3.8");
    clampEyeball("3.5", "3.11", "3.7");
    return p;
}

} // namespace toonface
