#include "views/pointhandle.h"

#include "views/displaynames.h"
#include "views/photoview.h"

#include <QCoreApplication>
#include <QCursor>
#include <QFontMetricsF>
#include <QGraphicsSceneMouseEvent>
#include <QPainter>

namespace toonface {

namespace {

// The label beside a point: its ID when every point is labelled (View ▸ Show Point IDs, compact),
// its plain name ("Mouth, left corner") beside the one point hovered.
QString labelText(int index, bool name)
{
    return name ? pointTitle(index) : pointId(index);
}

QFont labelFont()
{
    QFont font;
    font.setPointSizeF(8);
    return font;
}

// Where the label sits relative to the point, and its size.
QRectF labelRect(int index, bool name)
{
    const QFontMetricsF metrics(labelFont());
    const QRectF text = metrics.boundingRect(labelText(index, name));
    return QRectF(QPointF(PointHandle::kRadius + 2, -text.height() / 2), text.size()).adjusted(-1, 0, 1, 0);
}

constexpr double kHoveredZ = 4;

double restingZ(int index)
{
    return pointTable()[index].control ? 3 : 2;
}

} // namespace

PointHandle::PointHandle(PhotoView *view, int index)
    : m_view(view)
    , m_index(index)
{
    setFlag(ItemIgnoresTransformations);
    setAcceptHoverEvents(true);
    setAcceptedMouseButtons(Qt::LeftButton);
    setCursor(Qt::OpenHandCursor);
    setZValue(restingZ(index));
    updateToolTip();
}

QColor PointHandle::groupColour(PointGroup group)
{
    switch (group) {
    case PointGroup::Hair: return QColor(0xc0, 0x7a, 0x30);
    case PointGroup::Contour: return QColor(0xff, 0xa0, 0x20);
    case PointGroup::Ears: return QColor(0xc0, 0x60, 0xf0);
    case PointGroup::Eyebrows: return QColor(0xff, 0xe0, 0x30);
    case PointGroup::Eyes: return QColor(0x30, 0xd0, 0xff);
    case PointGroup::Nose: return QColor(0x40, 0xe0, 0x60);
    case PointGroup::Mouth: return QColor(0xff, 0x40, 0x70);
    }
    return Qt::white;
}

void PointHandle::sync(QPointF pos, bool handPlaced)
{
    if (pos != this->pos())
        setPos(pos);
    if (handPlaced != m_handPlaced) {
        m_handPlaced = handPlaced;
        updateToolTip();
        update();
    }
}

void PointHandle::setShowId(bool show)
{
    if (show == m_showId)
        return;
    prepareGeometryChange();
    m_showId = show;
}

QRectF PointHandle::boundingRect() const
{
    const double r = kRadius + 3;
    QRectF rect(-r, -r, 2 * r, 2 * r);
    if (m_showId || m_hovered)
        rect |= labelRect(m_index, !m_showId).adjusted(-1, -1, 1, 1);
    return rect;
}

QPainterPath PointHandle::shape() const
{
    // A grab area a little larger than the dot, so small handles stay easy to take.
    QPainterPath path;
    const double r = kRadius + 2;
    path.addEllipse(QPointF(), r, r);
    return path;
}

void PointHandle::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    const PointInfo &info = pointTable()[m_index];
    const double r = m_hovered || m_dragging ? kRadius + 1.5 : kRadius;
    painter->setRenderHint(QPainter::Antialiasing);
    painter->setBrush(groupColour(info.group));
    // Hand-placed points wear a white ring, detected ones a dark one.
    painter->setPen(QPen(m_handPlaced ? QColor(Qt::white) : QColor(20, 20, 20), m_handPlaced ? 2.0 : 1.2));
    if (info.control)
        painter->drawRect(QRectF(-r, -r, 2 * r, 2 * r).adjusted(0.5, 0.5, -0.5, -0.5));
    else
        painter->drawEllipse(QPointF(), r, r);

    if (m_showId || m_hovered) {
        const QRectF label = labelRect(m_index, !m_showId);
        painter->setPen(Qt::NoPen);
        painter->setBrush(QColor(0, 0, 0, 160));
        painter->drawRoundedRect(label, 2, 2);
        painter->setPen(Qt::white);
        painter->setFont(labelFont());
        painter->drawText(label, Qt::AlignCenter, labelText(m_index, !m_showId));
    }
}

void PointHandle::hoverEnterEvent(QGraphicsSceneHoverEvent *)
{
    prepareGeometryChange();
    m_hovered = true;
    setZValue(kHoveredZ); // its name reads over the neighbouring points
    m_view->pointHoverChanged(m_index, true);
}

void PointHandle::hoverLeaveEvent(QGraphicsSceneHoverEvent *)
{
    prepareGeometryChange();
    m_hovered = false;
    setZValue(restingZ(m_index));
    m_view->pointHoverChanged(m_index, false);
}

void PointHandle::mousePressEvent(QGraphicsSceneMouseEvent *event)
{
    if (event->button() != Qt::LeftButton) {
        event->ignore();
        return;
    }
    m_dragging = true;
    m_moved = false;
    m_grabOffset = event->scenePos() - pos();
    setCursor(Qt::ClosedHandCursor);
    update();
    event->accept();
}

void PointHandle::mouseMoveEvent(QGraphicsSceneMouseEvent *event)
{
    if (!m_dragging)
        return;
    m_moved = true;
    m_view->dragPoint(m_index, event->scenePos() - m_grabOffset, false);
}

void PointHandle::mouseReleaseEvent(QGraphicsSceneMouseEvent *event)
{
    if (!m_dragging)
        return;
    m_dragging = false;
    setCursor(Qt::OpenHandCursor);
    if (m_moved)
        m_view->dragPoint(m_index, event->scenePos() - m_grabOffset, true);
    update();
}

void PointHandle::updateToolTip()
{
    const PointInfo &info = pointTable()[m_index];
    QString tip = pointTitle(m_index);
    if (info.control)
        tip += QLatin1Char('\n') + QCoreApplication::translate("PointHandle", "Control point: animation moves it");
    if (m_handPlaced)
        tip += QLatin1Char('\n') + QCoreApplication::translate("PointHandle", "Placed by hand: re-detection keeps it");
    setToolTip(tip);
}

} // namespace toonface
