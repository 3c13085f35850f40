#include "timeline/mouthicons.h"

#include "face/pose.h"
#include "render/svgface.h"

#include <algorithm>

namespace toonface {

namespace {

// The mouth's box over all nine shapes, with room around it, widened to `aspect`.
QRectF mouthFrame(const FaceModel &face, const MouthShapeSet &shapes, double aspect)
{
    double left = 1e9, top = 1e9, right = -1e9, bottom = -1e9;
    for (MouthShape shape : kAllMouthShapes) {
        const auto points = posedPoints(face, mouthPose(face, shapes, shape));
        for (int i = 0; i < kPointCount; ++i)
            if (pointTable()[i].group == PointGroup::Mouth) {
                left = std::min(left, points[i].x());
                right = std::max(right, points[i].x());
                top = std::min(top, points[i].y());
                bottom = std::max(bottom, points[i].y());
            }
    }
    if (right <= left || bottom <= top)
        return {};
    QRectF box(QPointF(left, top), QPointF(right, bottom));
    box.adjust(-box.width() * 0.12, -box.height() * 0.2, box.width() * 0.12, box.height() * 0.2);
    QSizeF size = box.size();
    if (size.width() < size.height() * aspect)
        size.setWidth(size.height() * aspect);
    else
        size.setHeight(size.width() / aspect);
    QRectF frame(QPointF(0, 0), size);
    frame.moveCenter(box.center());
    return frame;
}

} // namespace

MouthIcons::MouthIcons(QSize size, qreal devicePixelRatio)
    : m_size(size)
    , m_ratio(devicePixelRatio)
{ }

bool MouthIcons::update(const FaceModel &face, const Style &style, const MouthShapeSet &shapes, bool hasFace)
{
    if (m_built && hasFace == m_hasFace && (!hasFace || (face == m_face && style == m_style && shapes == m_shapes)))
        return false;
    m_built = true;
    m_hasFace = hasFace;
    m_face = face;
    m_style = style;
    m_shapes = shapes;
    ++m_builds;
    for (QImage &image : m_icons)
        image = QImage();
    if (!hasFace)
        return true;
    SvgFace svgFace(face, style);
    const QRectF frame = mouthFrame(face, shapes, double(m_size.width()) / m_size.height());
    if (frame.isEmpty())
        return true;
    svgFace.setFrame(frame);
    const QSize pixels(qRound(m_size.width() * m_ratio), qRound(m_size.height() * m_ratio));
    for (MouthShape shape : kAllMouthShapes) {
        QImage image = rasterizeSvg(svgFace.svg(mouthPose(face, shapes, shape)), pixels, Qt::transparent);
        image.setDevicePixelRatio(m_ratio);
        m_icons[int(shape)] = image;
    }
    return true;
}

} // namespace toonface
