#pragma once

namespace toonface {

class FaceModel;

// How far the photographed head is turned from facing the camera, from its points: the roll
// (tilt) is the angle of the line between the eyeball centres (3.6, 3.5); the yaw (turn to the
// side) comes from how far the nose tip (9.15) sits off the eyes' midpoint along that line,
// the nose tip standing kNoseDepthEs0 in front of the eyes (an adult's average proportion:
// about 0.6 of the distance between the pupils), so offset = depth · tan(yaw) in ES0 units.
// Positive yaw: the nose points to the photo's right; positive roll: the photo's right eye is
// lower.
struct HeadTurn
{
    double yawDeg = 0;
    double rollDeg = 0;
};

inline constexpr double kNoseDepthEs0 = 0.6;
// The cartoon is drawn from the front (its mouth shapes open straight down, its features
// mirror each other): beyond this much turn or tilt it looks twisted. On the 66 shared portraits
// measured (faces/ and the first 60 of faces-attributes/) four are beyond it: two faces turned
// clearly aside, one moderately, and Einstein at the lectern (turned and tilted).
inline constexpr double kDrawnWellDeg = 15.0;

HeadTurn headTurn(const FaceModel &face);
// Whether the cartoon of this face will look twisted (turn or tilt beyond kDrawnWellDeg).
bool turnedTooFar(const HeadTurn &turn);

} // namespace toonface
