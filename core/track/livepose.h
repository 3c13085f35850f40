#pragma once

#include "face/mouthshape.h"
#include "face/pose.h"
#include "track/tracker.h"

#include <optional>

namespace toonface {

class FaceModel;

// What drives the live mouth: the camera's tracking, the microphone (AudioMouth), or both
// (the microphone while the camera has lost the face).
enum class LiveMouth { Camera, Microphone, Both };

// A mouth shape and how far toward it (MouthKey's shape and weight).
struct WeightedShape
{
    MouthShape shape = MouthShape::M;
    double weight = 1.0;
};

// The pose of one tracked frame on `face`, as live mode shows it: what addTrackToTimeline()'s
// keys of that frame play through TimelineEvaluator (the mouth and brow controls on the shut
// mouth, the gaze, the head), with the lids followed frame by frame (a recording turns them
// into blinks instead). With `soundMouth` the mouth controls hold that shape at that weight
// (as a mouth key does) instead of the tracked mouth.
Pose livePose(const TrackedFrame &frame, const FaceModel &face, const MouthShapeSet &shapes,
    const std::optional<WeightedShape> &soundMouth = std::nullopt);

// Which mouth to show: the sound's for Microphone, for Both when the face is lost; none (the
// tracked mouth) otherwise.
std::optional<WeightedShape> chooseMouth(LiveMouth mode, bool faceLost, const WeightedShape &sound);

} // namespace toonface
