#pragma once

#include "anim/timeline.h"

#include <QVector>

namespace toonface {

// POSE TRACK HOOK. The pose key-frame track (Timeline::poseKeys, the "track" branch) may not
// be on this branch yet; the timeline reaches it only through these three functions, which
// see an empty track until Timeline has poseKeys() and then use it with no other change.

template<class T = Timeline>
QVector<double> poseKeyTimes(const T &timeline)
{
    QVector<double> times;
    if constexpr (requires { timeline.poseKeys(); })
        for (const auto &key : timeline.poseKeys())
            times.append(key.time);
    return times;
}

// Gives the pose keys new times (one per key, in key order); the track is re-sorted.
template<class T = Timeline>
void setPoseKeyTimes(T &timeline, const QVector<double> &times)
{
    if constexpr (requires { timeline.poseKeys(); }) {
        auto keys = timeline.poseKeys();
        for (qsizetype i = 0; i < keys.size() && i < times.size(); ++i)
            keys[i].time = times[i];
        timeline.setPoseKeys(keys);
    } else {
        Q_UNUSED(timeline);
        Q_UNUSED(times);
    }
}

// Removes the pose keys at `indices` (ascending).
template<class T = Timeline>
void removePoseKeys(T &timeline, const QVector<int> &indices)
{
    if constexpr (requires { timeline.poseKeys(); }) {
        auto keys = timeline.poseKeys();
        for (qsizetype i = indices.size() - 1; i >= 0; --i)
            if (indices[i] >= 0 && indices[i] < keys.size())
                keys.removeAt(indices[i]);
        timeline.setPoseKeys(keys);
    } else {
        Q_UNUSED(timeline);
        Q_UNUSED(indices);
    }
}

} // namespace toonface
