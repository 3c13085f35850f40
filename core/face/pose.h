#pragma once

#include "face/pointtable.h"

#include <QPointF>

#include <array>

namespace toonface {

class FaceModel;

// Rigid head motion, applied to the whole drawing about the face's centre.
struct HeadPose
{
    double rotationDeg = 0; // positive turns clockwise on screen (y down)
    QPointF translation; // pixels
    double scale = 1.0;

    bool operator==(const HeadPose &) const = default;
};

// A face at one instant: displacements of the control points from the neutral face (pixels;
// entries of non-control points are ignored), the lid opening of each eye (1 = neutral,
// 0 = shut) and the head motion. Poses compose: speech + emotion + blink + head.
struct Pose
{
    std::array<QPointF, kPointCount> offset {};
    double leftEyeOpen = 1.0;
    double rightEyeOpen = 1.0;
    HeadPose head;

    // Adds displacements and head motion; multiplies lid openings.
    Pose &operator+=(const Pose &other);
    friend Pose operator+(Pose a, const Pose &b) { return a += b; }

    // Component-wise interpolation; t = 0 gives a, t = 1 gives b.
    static Pose lerp(const Pose &a, const Pose &b, double t);

    bool operator==(const Pose &) const = default;
};

// The 72 points of `face` in `pose`, with every derived point following its controls by the
// rules of face-model.md. Derived points move by their controls' displacement, so the neutral
// pose reproduces the neutral points exactly, hand-placed ones included. Head motion is not
// applied here (the renderer applies it as a transform).
std::array<QPointF, kPointCount> posedPoints(const FaceModel &face, const Pose &pose);

} // namespace toonface
