#pragma once

#include "detect/detector.h"

#include <QString>

namespace toonface {

class Document;

// How a detection's face goes into the document.
enum class DetectionUse {
    NewFace, // the photo's first face, or another person in it: points and colours, one step
    Replace, // re-detection: every point replaced
    KeepHandPlaced, // re-detection keeping the points the user placed by hand
};

// Puts the detected face into `document` as one undo step. `choseFace`: the user clicked
// another person's box (the step is named for it).
void applyDetection(Document *document, const DetectionResult &result, DetectionUse use, bool choseFace);

// What the status bar says of a detection: the method and its time, how many faces were found
// and which is used, and why auto fell back to the thesis' pipeline.
QString detectionSummary(const DetectionResult &result, bool choseFace);
// Says that the face is turned or tilted beyond what the cartoon draws well (face/headturn.h),
// or nothing; detectionSummary() adds it.
QString turnedFaceWarning(const FaceModel &face);

} // namespace toonface
