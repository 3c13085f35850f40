#pragma once

#include "detect/landmarkmap.h"

#include <QTransform>

#include <array>
#include <cmath>
#include <numbers>

namespace toonface::testing {

// An upright synthetic face in iBUG 68-point order, laid out in a unit box (x from the jaw's
// left end to its right end, y from above the brows to the chin), then placed by `t`.
inline std::array<QPointF, kIbugPointCount> syntheticLandmarks(const QTransform &t)
{
    std::array<QPointF, kIbugPointCount> p {};
    for (int k = 0; k <= 16; ++k) {
        const double phi = std::numbers::pi - k * std::numbers::pi / 16;
        p[k] = QPointF(0.5 + 0.45 * std::cos(phi), 0.33 + 0.72 * std::sin(phi));
    }
    for (int k = 0; k < 5; ++k) {
        const double u = k / 4.0;
        const double arch = 0.05 * std::sin(std::numbers::pi * u);
        p[17 + k] = QPointF(0.16 + 0.28 * u, 0.24 - arch);
        p[26 - k] = QPointF(0.84 - 0.28 * u, 0.24 - arch);
    }
    const QPointF rest[] = {
        {0.5, 0.32}, {0.5, 0.40}, {0.5, 0.48}, {0.5, 0.56}, // 27..30
        {0.43, 0.60}, {0.465, 0.615}, {0.5, 0.63}, {0.535, 0.615}, {0.57, 0.60}, // 31..35
        {0.245, 0.34}, {0.28, 0.32}, {0.32, 0.32}, {0.355, 0.34}, {0.32, 0.36}, {0.28, 0.36}, // 36..41
        {0.645, 0.34}, {0.68, 0.32}, {0.72, 0.32}, {0.755, 0.34}, {0.72, 0.36}, {0.68, 0.36}, // 42..47
        {0.36, 0.75}, {0.41, 0.72}, {0.46, 0.705}, {0.5, 0.715}, {0.54, 0.705}, {0.59, 0.72}, // 48..53
        {0.64, 0.75}, {0.59, 0.80}, {0.545, 0.83}, {0.5, 0.835}, {0.455, 0.83}, {0.41, 0.80}, // 54..59
        {0.38, 0.75}, {0.45, 0.745}, {0.5, 0.748}, {0.55, 0.745}, // 60..63
        {0.62, 0.75}, {0.55, 0.755}, {0.5, 0.758}, {0.45, 0.755}, // 64..67
    };
    for (int k = 0; k < 41; ++k)
        p[27 + k] = rest[k];
    for (QPointF &q : p)
        q = t.map(q);
    return p;
}

} // namespace toonface::testing
