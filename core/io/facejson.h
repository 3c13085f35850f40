#pragma once

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
//  groupConfidence}.
// Without a detection, method is "none" and the detection fields (timingMs, faceCount, faceBox,
// groupConfidence) are left out; image.width/height are left out when the face has no valid
// image size. fapu, method and the detection fields are informative: faceFromJson does not
// read them back.
inline constexpr const char *kFaceFormat = "toonface.face/1";

QJsonObject faceToJson(const FaceModel &face, const QString &imagePath, const DetectionResult *detection = nullptr);

// Reads a face JSON; on failure returns nullopt and sets *error to the path of the first bad
// field and what was expected (e.g. "points[12].x: expected a number").
std::optional<FaceModel> faceFromJson(const QJsonObject &json, QString *error, QString *imagePath = nullptr);

} // namespace toonface
