#include "face/facemodel.h"

#include "face/fapu.h"

#include <QRectF>

#include <algorithm>
#include <cmath>

namespace toonface {

void FaceModel::setPoint(int index, QPointF pos, bool handPlaced)
{
    m_points[index] = pos;
    m_handPlaced[index] = handPlaced;
}

int FaceModel::handPlacedCount() const
{
    int n = 0;
    for (bool b : m_handPlaced)
        n += b ? 1 : 0;
    return n;
}

void FaceModel::mergeDetection(const FaceModel &detected, bool keepHandPlaced)
{
    m_imageSize = detected.m_imageSize;
    for (int i = 0; i < kPointCount; ++i) {
        if (keepHandPlaced && m_handPlaced[i])
            continue;
        m_points[i] = detected.m_points[i];
        m_handPlaced[i] = false;
    }
}

namespace {

// The smallest rectangle holding the points (as QPolygonF::boundingRect, without linking Qt
// Gui for it: the light toonface-cli uses the face model without loading Qt Gui).
struct Bounds
{
    bool empty = true;
    qreal left = 0, top = 0, right = 0, bottom = 0;
    void add(const QPointF &p)
    {
        if (empty) {
            left = right = p.x();
            top = bottom = p.y();
            empty = false;
            return;
        }
        left = std::min(left, p.x());
        right = std::max(right, p.x());
        top = std::min(top, p.y());
        bottom = std::max(bottom, p.y());
    }
    QRectF rect() const { return empty ? QRectF() : QRectF(left, top, right - left, bottom - top); }
};

} // namespace

QRectF FaceModel::bounds() const
{
    Bounds b;
    for (const QPointF &p : m_points)
        b.add(p);
    return b.rect();
}

QRectF FaceModel::bounds(PointGroup group) const
{
    Bounds b;
    for (int i = 0; i < kPointCount; ++i) {
        if (pointTable()[i].group == group)
            b.add(m_points[i]);
    }
    return b.rect();
}

bool FaceModel::isValid() const
{
    for (const QPointF &p : m_points) {
        if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
            return false;
    }
    const Fapu f = fapu();
    return f.es0 > 0 && f.mw0 > 0 && f.mns0 > 0;
}

Fapu FaceModel::fapu() const
{
    return Fapu::measure(*this);
}

} // namespace toonface
