#include "face/facemodel.h"

#include "face/fapu.h"

#include <QPolygonF>

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

QRectF FaceModel::bounds() const
{
    QPolygonF poly;
    for (const QPointF &p : m_points)
        poly << p;
    return poly.boundingRect();
}

QRectF FaceModel::bounds(PointGroup group) const
{
    QPolygonF poly;
    for (int i = 0; i < kPointCount; ++i) {
        if (pointTable()[i].group == group)
            poly << m_points[i];
    }
    return poly.boundingRect();
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
