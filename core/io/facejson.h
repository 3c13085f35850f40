#pragma once

#include "detect/faceregions.h"
#include "face/facemodel.h"

#include <QJsonObject>
#include <QMap>
#include <QString>

#include <optional>

namespace toonface {

struct DetectionResult;

// The face JSON of architecture.md, format "toonface.face/1":
// {format, points: [{id, x, y, group, control, handPlaced}] in face-model.md order, fapu {...},
//  method, image {path, width, height}, timingMs {stage: ms, total}, faceCount, faceBox,
//  groupConfidence, regions, tracking}.
// regions: {face, hair, nose, mouth: box; faceOutline, hairOutline: [[x, y], ...];
//  ears, brows, eyes: [box, box] image-left first}, a box being {x, y, width, height}.
// tracking (only when the detection could measure it): {rect: box, m1, s1, t1, m2, s2, d,
//  eyeMid: [x, y], eyeballs: [{x, y, radius}, {...}], divEE, divEN, divNM, mouth: box,
//  skin, hair: {samples, r, g, b, spread}} (detect/faceregions.h).
// Without a detection, method is "none" and the detection fields (timingMs, faceCount, faceBox,
// groupConfidence, regions, tracking) are left out; image.width/height are left out when the face has no valid
// image size. fapu, method and the detection fields are informative: faceFromJson does not
// read them back.
inline constexpr const char *kFaceFormat = "toonface.face/1";

QJsonObject faceToJson(const FaceModel &face, const QString &imagePath, const DetectionResult *detection = nullptr);

// Reads a face JSON; on failure returns nullopt and sets *error to the path of the first bad
// field and what was expected (e.g. "points[12].x: expected a number").
std::optional<FaceModel> faceFromJson(const QJsonObject &json, QString *error, QString *imagePath = nullptr);

// Reads the regions and tracking keys of a face JSON. A missing key (a file written before
// they existed, or a face without detection) leaves its output default-constructed (for
// tracking: valid == false) and is not an error; a malformed one returns false with *error
// naming the field.
bool faceRegionsFromJson(const QJsonObject &json, FaceRegions *regions, TrackingSeed *tracking, QString *error);

} // namespace toonface
