#include "face/headturn.h"

#include "face/facemodel.h"

#include <cmath>
#include <numbers>

namespace toonface {

HeadTurn headTurn(const FaceModel &face)
{
    HeadTurn turn;
    const QPointF left = face.point("3.6");
    const QPointF right = face.point("3.5");
    const QPointF eyes = right - left;
    const double es0 = std::hypot(eyes.x(), eyes.y());
    if (!(es0 > 0))
        return turn;
    constexpr double kDegrees = 180.0 / std::numbers::pi;
    turn.rollDeg = std::atan2(eyes.y(), eyes.x()) * kDegrees;
    const QPointF along = eyes / es0;
    const QPointF nose = face.point("9.15") - (left + right) / 2.0;
    const double offsetEs0 = (nose.x() * along.x() + nose.y() * along.y()) / es0;
    turn.yawDeg = std::atan(offsetEs0 / kNoseDepthEs0) * kDegrees;
    return turn;
}

bool turnedTooFar(const HeadTurn &turn)
{
    return std::abs(turn.yawDeg) > kDrawnWellDeg || std::abs(turn.rollDeg) > kDrawnWellDeg;
}

} // namespace toonface
