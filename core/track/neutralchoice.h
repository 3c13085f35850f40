#pragma once

#include "track/tracker.h"

#include <QString>

#include <atomic>

namespace toonface {

// The frame of a clip to take as its neutral face, found for the user: the face at rest, the
// lips closed, the eyes open, looking ahead, where nobody speaks. Frame 0 often catches the
// speaker mid-breath or the lips apart (GRID speakers part them before the sentence), and every
// other frame's motion is measured from the neutral.
//
// Among the first kNeutralSearchS of the clip, tracked from the first frame the face is found
// on: the frames found with a confidence of at least kSureShare of the window's best, both eyes
// at least kEyesOpenShare as open as the window's widest, the head within kFrontalDeg of
// upright, and in the sound's silence (track/clipsilence.h) when the clip has sound and the
// window has any; of those, the one whose outer lips part the least (the earliest of those
// within kClosedToleranceEs0 of it).
inline constexpr double kNeutralSearchS = 3.0;
inline constexpr double kSureShare = 0.9;
inline constexpr double kEyesOpenShare = 0.85;
inline constexpr double kFrontalDeg = 8.0;
inline constexpr double kClosedToleranceEs0 = 0.005;

struct NeutralChoice
{
    bool found = false; // a face was found in the window
    int frame = 0;
    bool silent = false; // the frame is in the sound's silence
    QString error; // "<path>: <problem>" when no frame could be read
};

// Reads the first kNeutralSearchS of the clip at `path`; `cancel` is polled every frame.
// Meant for a worker thread.
NeutralChoice chooseNeutralFrame(const QString &path, const std::atomic_bool *cancel = nullptr);

} // namespace toonface
