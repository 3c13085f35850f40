#pragma once

#include "face/facemodel.h"
#include "io/jsonfield.h"

#include <QJsonArray>

namespace toonface {

// Coordinates beyond this many pixels are refused as corrupt (photos are capped far below).
inline constexpr double kMaxCoordinate = 1e7;

// The 72 points as [{id, x, y, handPlaced}] in pointTable() order; withGroups adds each point's
// `group` and `control` (the face JSON of architecture.md carries them for readers of the file).
QJsonArray pointsToJson(const FaceModel &face, bool withGroups);

// Reads what pointsToJson wrote into *face (points and hand-placed flags; the image size is
// left alone). Requires exactly 72 points with their ids in order and finite coordinates;
// `group` and `control` are optional but must match the table when present; `handPlaced` is
// optional (false). On failure returns false with *error naming the first bad field.
bool pointsFromJson(const JsonField &points, FaceModel *face, QString *error);

} // namespace toonface
