#pragma once

#include <vector>

namespace toonface {

// Tsai's moment-preserving bi-level threshold (W.-H. Tsai, "Moment-preserving thresholding:
// a new approach", CVGIP 29, 1985): the two levels z0 < z1 and the fraction p0 of pixels
// at z0 that keep the first three moments of the histogram.
struct TsaiThreshold
{
    bool valid = false; // false when the histogram is empty or holds a single level
    double m1 = 0, m2 = 0, m3 = 0; // moments of the normalised histogram
    double z0 = 0, z1 = 0; // the two representative levels
    double p0 = 0; // the share of pixels that go to z0
    int threshold = 0; // pixels <= threshold belong to z0: the p0-tile (the occupied level whose
                       // cumulative share is nearest p0)
};

// requires: histogram[j] >= 0 is the count of level j (any number of levels).
TsaiThreshold tsaiThreshold(const std::vector<double> &histogram);

} // namespace toonface
