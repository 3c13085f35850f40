#include "dialogs/posepreview.h"

#include <QMouseEvent>
#include <QPaintEvent>
#include <QPainter>
#include <QPainterPath>

#include <cmath>

namespace toonface {

namespace {

constexpr int kMargin = 8; // widget pixels around the drawing
constexpr double kGrabRadius = 9; // widget pixels around a marker that pick it up

QRectF fitted(const QRectF &frame, const QRectF &area)
{
    if (frame.isEmpty() || area.isEmpty())
        return QRectF();
    QSizeF size = frame.size();
    size.scale(area.size(), Qt::KeepAspectRatio);
    QRectF target(QPointF(), size);
    target.moveCenter(area.center());
    return target;
}

} // namespace

QImage renderPose(const SvgFace &face, const Pose &pose, const QRectF &frame, QSize size)
{
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    const QRectF target = fitted(frame, QRectF(QPointF(), QSizeF(size)));
    if (target.isEmpty())
        return image;
    QSvgRenderer renderer(face.svg(pose));
    QPainter painter(&image);
    painter.setRenderHints(QPainter::Antialiasing | QPainter::SmoothPixmapTransform);
    painter.fillRect(target, Qt::white);
    painter.setClipRect(target);
    renderer.setViewBox(frame);
    renderer.render(&painter, target);
    return image;
}

PosePreview::PosePreview(QWidget *parent)
    : QWidget(parent)
{
    setAttribute(Qt::WA_OpaquePaintEvent);
}

void PosePreview::setFace(const SvgFace &face)
{
    m_face = face;
    m_pose = Pose();
    invalidate();
}

void PosePreview::setPose(const Pose &pose)
{
    if (pose == m_pose)
        return;
    m_pose = pose;
    invalidate();
}

void PosePreview::setFrame(const QRectF &frame)
{
    m_frame = frame;
    invalidate();
}

void PosePreview::setMarkers(const QVector<Marker> &markers)
{
    m_markers = markers;
    update();
}

QImage PosePreview::image()
{
    if (!m_cacheValid) {
        const qreal dpr = devicePixelRatioF();
        QImage drawing
            = m_face ? renderPose(*m_face, m_pose, m_frame, (QSizeF(targetRect().size()) * dpr).toSize()) : QImage();
        m_cache = QImage((QSizeF(size()) * dpr).toSize(), QImage::Format_ARGB32_Premultiplied);
        m_cache.setDevicePixelRatio(dpr);
        m_cache.fill(palette().color(QPalette::Window).darker(108));
        QPainter painter(&m_cache);
        const QRectF target = targetRect();
        if (!drawing.isNull() && !target.isEmpty()) {
            drawing.setDevicePixelRatio(dpr);
            painter.fillRect(target.translated(2, 3), QColor(0, 0, 0, 40));
            painter.drawImage(target.topLeft(), drawing);
        }
        m_cacheValid = true;
    }
    return m_cache;
}

QRectF PosePreview::targetRect() const
{
    return fitted(m_frame, QRectF(rect()).adjusted(kMargin, kMargin, -kMargin, -kMargin)).toAlignedRect();
}

void PosePreview::invalidate()
{
    m_cacheValid = false;
    update();
}

void PosePreview::paintEvent(QPaintEvent *)
{
    const QImage picture = image();
    QPainter painter(this);
    painter.drawImage(QPointF(0, 0), picture);
    const QRectF target = targetRect();
    if (m_markers.isEmpty() || target.isEmpty() || m_frame.isEmpty())
        return;
    painter.setRenderHint(QPainter::Antialiasing);
    const auto map = [this](QPointF p) { return toWidget(p); };
    const QColor accent = palette().color(QPalette::Highlight);
    for (const Marker &m : m_markers) {
        const QPointF a = map(m.from);
        const QPointF b = map(m.to);
        painter.setPen(QPen(accent, 1.5, Qt::DashLine));
        painter.setBrush(Qt::NoBrush);
        painter.drawEllipse(a, 4, 4);
        if (QLineF(a, b).length() > 6)
            painter.drawLine(a, b);
        painter.setPen(QPen(Qt::white, 1.5));
        painter.setBrush(accent);
        painter.drawEllipse(b, 5, 5);
        if (!m.label.isEmpty()) {
            painter.setPen(palette().color(QPalette::Text));
            painter.drawText(b + QPointF(8, -6), m.label);
        }
    }
}

QPointF PosePreview::toWidget(QPointF photo) const
{
    const QRectF target = targetRect();
    if (target.isEmpty() || m_frame.isEmpty())
        return QPointF();
    return target.topLeft() + (photo - m_frame.topLeft()) * (target.width() / m_frame.width());
}

QPointF PosePreview::toPhoto(QPointF widget) const
{
    const QRectF target = targetRect();
    if (target.isEmpty() || m_frame.isEmpty())
        return QPointF();
    return m_frame.topLeft() + (widget - target.topLeft()) * (m_frame.width() / target.width());
}

void PosePreview::mousePressEvent(QMouseEvent *event)
{
    m_dragged = -1;
    if (!m_draggable || event->button() != Qt::LeftButton)
        return QWidget::mousePressEvent(event);
    double best = kGrabRadius;
    for (int i = 0; i < m_markers.size(); ++i) {
        const double d = QLineF(toWidget(m_markers[i].to), event->position()).length();
        if (d <= best) {
            best = d;
            m_dragged = i;
        }
    }
    if (m_dragged >= 0)
        setCursor(Qt::ClosedHandCursor);
}

void PosePreview::mouseMoveEvent(QMouseEvent *event)
{
    if (m_dragged >= 0) {
        Q_EMIT markerDragged(m_dragged, toPhoto(event->position()), false);
        return;
    }
    if (m_draggable) {
        bool over = false;
        for (const Marker &m : std::as_const(m_markers))
            over |= QLineF(toWidget(m.to), event->position()).length() <= kGrabRadius;
        setCursor(over ? Qt::OpenHandCursor : Qt::ArrowCursor);
    }
}

void PosePreview::mouseReleaseEvent(QMouseEvent *event)
{
    if (m_dragged < 0 || event->button() != Qt::LeftButton)
        return QWidget::mouseReleaseEvent(event);
    const int index = m_dragged;
    m_dragged = -1;
    unsetCursor();
    Q_EMIT markerDragged(index, toPhoto(event->position()), true);
}

void PosePreview::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    invalidate();
}

} // namespace toonface
