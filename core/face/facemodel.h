#pragma once

#include "face/pointtable.h"

#include <QPointF>
#include <QRectF>
#include <QSize>

#include <array>

namespace toonface {

struct Fapu;

// One person's neutral face: the 72 feature points in image pixels of the neutral photo
// (x right, y down), each with a flag saying whether the user placed it by hand.
//
// A plain value type: copyable, no sharing, not synchronised (copy it to use it on another
// thread). Indices are those of pointTable().
class FaceModel
{
public:
    FaceModel() = default;
    explicit FaceModel(QSize imageSize)
        : m_imageSize(imageSize)
    { }

    QSize imageSize() const { return m_imageSize; }
    void setImageSize(QSize size) { m_imageSize = size; }

    // requires: 0 <= index < kPointCount
    QPointF point(int index) const { return m_points[index]; }
    // requires: id names one of the 72 points
    QPointF point(const char *id) const { return m_points[pt::idx(id)]; }
    const std::array<QPointF, kPointCount> &points() const { return m_points; }

    // Places a point; handPlaced marks it as the user's, so re-detection keeps it.
    void setPoint(int index, QPointF pos, bool handPlaced = false);
    bool isHandPlaced(int index) const { return m_handPlaced[index]; }
    void setHandPlaced(int index, bool handPlaced) { m_handPlaced[index] = handPlaced; }
    int handPlacedCount() const;

    // Replaces every point that is not hand-placed by the one of `detected`
    // (all points when keepHandPlaced is false, which also clears the flags).
    void mergeDetection(const FaceModel &detected, bool keepHandPlaced);

    // Bounding box of the points of one group, or of all points.
    QRectF bounds() const;
    QRectF bounds(PointGroup group) const;

    // True when every coordinate is finite and the FAPUs are positive.
    bool isValid() const;

    Fapu fapu() const;

    bool operator==(const FaceModel &other) const = default;

private:
    QSize m_imageSize;
    std::array<QPointF, kPointCount> m_points {};
    std::array<bool, kPointCount> m_handPlaced {};
};

} // namespace toonface
