#include "detect/tsai.h"

#include <cmath>

namespace toonface {

TsaiThreshold tsaiThreshold(const std::vector<double> &histogram)
{
    TsaiThreshold t;
    double n = 0;
    for (double c : histogram)
        n += c;
    if (n <= 0)
        return t;
    for (size_t j = 0; j < histogram.size(); ++j) {
        const double p = histogram[j] / n, z = double(j);
        t.m1 += p * z;
        t.m2 += p * z * z;
        t.m3 += p * z * z * z;
    }
    const double cd = t.m2 - t.m1 * t.m1; // the variance: zero for a single level
    const int meanLevel = int(std::lround(t.m1));
    t.threshold = meanLevel;
    t.z0 = t.z1 = t.m1;
    if (cd <= 1e-12 * std::max(1.0, t.m2))
        return t;
    const double c0 = (t.m1 * t.m3 - t.m2 * t.m2) / cd;
    const double c1 = (t.m1 * t.m2 - t.m3) / cd;
    // c1^2 - 4 c0 is ((z1 - z0))^2 of the solution, positive whenever cd > 0; clamp rounding.
    const double root = std::sqrt(std::max(0.0, c1 * c1 - 4.0 * c0));
    t.z0 = (-c1 - root) / 2.0;
    t.z1 = (-c1 + root) / 2.0;
    if (t.z1 - t.z0 <= 0)
        return t;
    t.p0 = (t.z1 - t.m1) / (t.z1 - t.z0);
    // The p0-tile of a discrete histogram: the level whose cumulative share is nearest p0
    // (the first such level on a tie), so a bin that straddles p0 goes to the side that
    // holds most of it.
    double cumulative = 0, bestGap = 2;
    for (size_t j = 0; j < histogram.size(); ++j) {
        cumulative += histogram[j] / n;
        if (histogram[j] > 0 && std::abs(cumulative - t.p0) < bestGap - 1e-12) {
            bestGap = std::abs(cumulative - t.p0);
            t.threshold = int(j);
        }
    }
    t.valid = true;
    return t;
}

} // namespace toonface
