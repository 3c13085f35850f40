#include "face/averageface.h"

#include <cmath>
#include <numbers>

namespace toonface {

const std::array<QPointF, kPointCount> &averageFaceUnitPoints()
{
    static const std::array<QPointF, kPointCount> pts = [] {
        std::array<QPointF, kPointCount> p {};
        // Hair: an arc around the skull from the image-left lower end over the crown.
        for (int i = 0; i < 19; ++i) {
            const double a = (190.0 - i * (200.0 / 18.0)) * std::numbers::pi / 180.0;
            p[i] = QPointF(0.5 + 0.58 * std::cos(a), 0.30 - 0.52 * std::sin(a));
        }
        const std::pair<const char *, QPointF> rest[] = {
            {"11.2", {0.08, 0.10}},
            {"11.1", {0.50, -0.05}},
            {"11.3", {0.92, 0.10}},
            {"5.2", {0.03, 0.38}},
            {"5.1", {0.97, 0.38}},
            {"2.14", {0.07, 0.74}},
            {"2.12", {0.22, 0.93}},
            {"2.1", {0.50, 1.02}},
            {"2.11", {0.78, 0.93}},
            {"2.13", {0.93, 0.74}},
            {"10.2", {0.02, 0.33}},
            {"10.4", {-0.06, 0.45}},
            {"10.6", {0.00, 0.62}},
            {"10.10", {0.05, 0.60}},
            {"10.1", {0.98, 0.33}},
            {"10.3", {1.06, 0.45}},
            {"10.5", {1.00, 0.62}},
            {"10.9", {0.95, 0.60}},
            {"4.6", {0.15, 0.27}},
            {"4.4a", {0.23, 0.235}},
            {"4.4", {0.32, 0.225}},
            {"4.2", {0.42, 0.25}},
            {"4.1", {0.58, 0.25}},
            {"4.3", {0.68, 0.225}},
            {"4.3a", {0.77, 0.235}},
            {"4.5", {0.85, 0.27}},
            {"3.12", {0.20, 0.365}},
            {"3.2", {0.30, 0.33}},
            {"3.8", {0.40, 0.365}},
            {"3.4", {0.30, 0.395}},
            {"3.6", {0.30, 0.362}},
            {"3.11", {0.60, 0.365}},
            {"3.1", {0.70, 0.33}},
            {"3.7", {0.80, 0.365}},
            {"3.3", {0.70, 0.395}},
            {"3.5", {0.70, 0.362}},
            {"9.6", {0.4667, 0.362}},
            {"9.7", {0.5333, 0.362}},
            {"9.14", {0.44, 0.45}},
            {"9.13", {0.56, 0.45}},
            {"9.2", {0.41, 0.60}},
            {"9.1", {0.59, 0.60}},
            {"9.4", {0.44, 0.64}},
            {"9.5", {0.56, 0.64}},
            {"9.15", {0.50, 0.645}},
            {"8.4", {0.37, 0.77}},
            {"8.9", {0.45, 0.728}},
            {"8.1", {0.50, 0.738}},
            {"8.10", {0.55, 0.728}},
            {"8.3", {0.63, 0.77}},
            {"8.2", {0.50, 0.82}},
            {"2.2", {0.50, 0.768}},
            {"2.3", {0.50, 0.772}},
        };
        for (const auto &[id, pos] : rest)
            p[pt::idx(id)] = pos;
        return p;
    }();
    return pts;
}

FaceModel averageFace(const QRectF &faceBox, QSize imageSize)
{
    FaceModel face(imageSize);
    const auto &unit = averageFaceUnitPoints();
    for (int i = 0; i < kPointCount; ++i) {
        face.setPoint(
            i, QPointF(faceBox.left() + unit[i].x() * faceBox.width(), faceBox.top() + unit[i].y() * faceBox.height()));
    }
    return face;
}

} // namespace toonface
