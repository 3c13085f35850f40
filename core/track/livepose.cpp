#include "track/livepose.h"

#include "face/facemodel.h"
#include "face/fapu.h"

#include <algorithm>

namespace toonface {

namespace {

// The points addTrackToTimeline() keys: the mouth controls and the brows.
constexpr std::array<const char *, 4> kMouthIds = {"8.9", "8.2", "8.4", "8.3"};
constexpr std::array<const char *, 8> kBrowIds = {"4.6", "4.4a", "4.4", "4.2", "4.1", "4.3", "4.3a", "4.5"};

} // namespace

Pose livePose(const TrackedFrame &frame, const FaceModel &face, const MouthShapeSet &shapes,
    const std::optional<WeightedShape> &soundMouth)
{
    const double es0 = face.fapu().es0;
    const FaceMotion &m = frame.motion;
    Pose pose;
    if (soundMouth) {
        const std::array<QPointF, 4> d = shapes.displacements(soundMouth->shape, face);
        for (int k = 0; k < 4; ++k)
            pose.offset[pt::idx(kMouthIds[k])] = d[k] * soundMouth->weight;
    } else {
        const std::array<QPointF, 4> resting = shapes.displacements(MouthShape::M, face);
        for (int k = 0; k < 4; ++k) {
            const int i = pt::idx(kMouthIds[k]);
            pose.offset[i] = resting[k] + m.displacementEs0[i] * es0;
        }
    }
    for (const char *id : kBrowIds) {
        const int i = pt::idx(id);
        pose.offset[i] = m.displacementEs0[i] * es0;
    }
    const QPointF gaze = m.gazeEs0 * es0;
    pose.offset[pt::idx("3.6")] += gaze;
    pose.offset[pt::idx("3.5")] += gaze;
    pose.leftEyeOpen = std::max(0.0, m.leftEyeOpen);
    pose.rightEyeOpen = std::max(0.0, m.rightEyeOpen);
    pose.head.rotationDeg = m.rotationDeg;
    pose.head.translation = m.translationEs0 * es0;
    pose.head.scale = m.scale;
    return pose;
}

std::optional<WeightedShape> chooseMouth(LiveMouth mode, bool faceLost, const WeightedShape &sound)
{
    if (mode == LiveMouth::Microphone || (mode == LiveMouth::Both && faceLost))
        return sound;
    return std::nullopt;
}

} // namespace toonface
