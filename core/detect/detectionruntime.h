#pragma once

// What detection keeps for the whole process: the landmark model every detection shares, and
// the warm-up that does detection's one-time work in the background at launch (detector.h's
// warmUpDetection()). Private to core/detect.

#include "detect/landmarkpredictor.h"
#include "detect/modelcache.h"

#include <QString>

#include <memory>

namespace toonface {

// The model for landmarkModelPath(), loaded at most once per path (a test or the user may
// point TOONFACE_LANDMARK_MODEL elsewhere), through its cache in detectionCacheDir(). A load
// under way on another thread (the warm-up's) is waited for, not repeated. Failures are not
// kept, so that a file that appears later is found. The shared pointer keeps a model alive
// for detections still using it. *load, when given, is the report of the load that made the
// model (its time is 0 when this call did not load it).
std::shared_ptr<const LandmarkPredictor> sharedLandmarkModel(QString *error, LandmarkModelLoad *load = nullptr);

// Runs the stages after the landmarks (hair, regions) once on a made-up portrait with the
// average face, so that their one-time work (tables, first allocations) is done; needs no
// model (detector.cpp).
void warmUpFaceRefinement();

// Waits until the warm-up's run of those stages has ended, when one is under way (at once
// otherwise): a detection reaching them meanwhile would do their one-time work a second time
// beside the warm-up, on a machine whose cores the start-up keeps busy.
void awaitFaceRefinementWarmUp();

} // namespace toonface
