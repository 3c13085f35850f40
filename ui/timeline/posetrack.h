#pragma once

#include "anim/timeline.h"

#include <QVector>

namespace toonface {

// The pose key-frame track as the timeline's edits see it: key times only (the offsets are set
// on the preview, not here).

inline QVector<double> poseKeyTimes(const Timeline &timeline)
{
    QVector<double> times;
    times.reserve(timeline.poseKeys().size());
    for (const PoseKey &key : timeline.poseKeys())
        times.append(key.time);
    return times;
}

// Gives the pose keys new times (one per key, in key order); the track is re-sorted.
inline void setPoseKeyTimes(Timeline &timeline, const QVector<double> &times)
{
    QVector<PoseKey> keys = timeline.poseKeys();
    for (qsizetype i = 0; i < keys.size() && i < times.size(); ++i)
        keys[i].time = times[i];
    timeline.setPoseKeys(keys);
}

// Removes the pose keys at `indices` (ascending).
inline void removePoseKeys(Timeline &timeline, const QVector<int> &indices)
{
    QVector<PoseKey> keys = timeline.poseKeys();
    for (qsizetype i = indices.size() - 1; i >= 0; --i)
        if (indices[i] >= 0 && indices[i] < keys.size())
            keys.removeAt(indices[i]);
    timeline.setPoseKeys(keys);
}

} // namespace toonface
