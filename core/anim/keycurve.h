#pragma once

#include "anim/easing.h"

#include <QVector>

#include <algorithm>

namespace toonface {

// Index of the last time <= t in sorted `times`, or -1 before the first.
inline qsizetype segmentAt(const QVector<double> &times, double t)
{
    return qsizetype(std::upper_bound(times.cbegin(), times.cend(), t) - times.cbegin()) - 1;
}

// A value eased between key frames: values[i] at times[i] (sorted), the ease between
// neighbours, the first value before the first key and the last after the last.
// `lerp(a, b, s)` mixes two values linearly.
// requires: times and values of equal, non-zero size
template<class V, class Lerp>
V easedAt(const QVector<double> &times, const QVector<V> &values, double t, Lerp lerp)
{
    const qsizetype i = segmentAt(times, t);
    if (i < 0)
        return values.first();
    if (i + 1 >= times.size())
        return values.last();
    const double span = times[i + 1] - times[i];
    return lerp(values[i], values[i + 1], ease((t - times[i]) / span));
}

} // namespace toonface
