#pragma once

#include <algorithm>

namespace toonface {

// The one ease of the timeline: cubic ease-in-out (smoothstep), 3u^2 - 2u^3 for u in [0, 1].
// Zero slope at both ends, so motion starts and stops softly at every key frame, and
// ease(1/2) = 1/2. It is exactly the SMIL timing function calcMode="spline"
// keySplines="1/3 0 2/3 1" (a cubic Bezier whose x control points sit at thirds, so x = u),
// which lets an SVG export reproduce it without sampling frames.
inline double ease(double u)
{
    u = std::clamp(u, 0.0, 1.0);
    return u * u * (3.0 - 2.0 * u);
}

// d ease / du.
inline double easeSlope(double u)
{
    if (u <= 0.0 || u >= 1.0)
        return 0.0;
    return 6.0 * u * (1.0 - u);
}

// The keySplines value of ease() for one SMIL interval.
inline constexpr const char *kEaseKeySpline = "0.333333 0 0.666667 1";

} // namespace toonface
