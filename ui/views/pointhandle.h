#pragma once

#include "face/pointtable.h"

#include <QGraphicsItem>

namespace toonface {

class PhotoView;

// The handle of one of the 72 points on the photo: a dot coloured by its point group, drawn
// at a constant size on screen whatever the zoom. Dragging it asks its PhotoView to move the
// point in the document; the handle itself only moves when the document says so (sync()).
class PointHandle : public QGraphicsItem
{
public:
    PointHandle(PhotoView *view, int index);

    int index() const { return m_index; }
    // Takes position and hand-placed state from the model.
    void sync(QPointF pos, bool handPlaced);
    void setShowId(bool show);
    bool isHovered() const { return m_hovered; }

    static QColor groupColour(PointGroup group);
    static constexpr double kRadius = 4.5; // on screen, in device-independent pixels

    QRectF boundingRect() const override;
    QPainterPath shape() const override;
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;

protected:
    void hoverEnterEvent(QGraphicsSceneHoverEvent *event) override;
    void hoverLeaveEvent(QGraphicsSceneHoverEvent *event) override;
    void mousePressEvent(QGraphicsSceneMouseEvent *event) override;
    void mouseMoveEvent(QGraphicsSceneMouseEvent *event) override;
    void mouseReleaseEvent(QGraphicsSceneMouseEvent *event) override;

private:
    void updateToolTip();

    PhotoView *m_view;
    int m_index;
    bool m_handPlaced = false;
    bool m_hovered = false;
    bool m_showId = false;
    bool m_dragging = false;
    bool m_moved = false;
    QPointF m_grabOffset; // from the point to where the mouse took it, in scene units
};

} // namespace toonface
