#pragma once

#include "face/pose.h"
#include "render/svgface.h"

#include <QImage>
#include <QPointF>
#include <QRectF>
#include <QSize>
#include <QSvgRenderer>
#include <QVector>
#include <QWidget>

#include <optional>

namespace toonface {

// Renders `face` in `pose` (SvgFace -> QSvgRenderer) showing only `frame` (photo pixels),
// scaled to `size` with its aspect ratio kept, on white. For thumbnails and previews.
QImage renderPose(const SvgFace &face, const Pose &pose, const QRectF &frame, QSize size);

// A picture of one posed face in a dialog: the drawing of the character in a pose, framed on
// a part of the face, with optional markers that show where points moved from and to.
// Rendered once per change into a cached image; painting only blits.
class PosePreview : public QWidget
{
    Q_OBJECT

public:
    explicit PosePreview(QWidget *parent = nullptr);

    // The face to draw; clears the pose.
    void setFace(const SvgFace &face);
    void setPose(const Pose &pose);
    // The part of the drawing shown, in photo pixels.
    void setFrame(const QRectF &frame);
    // Arrows from each point's rest position to its posed one (photo pixels).
    struct Marker
    {
        QPointF from;
        QPointF to;
        QString label;
    };
    void setMarkers(const QVector<Marker> &markers);
    // Lets the user drag a marker's posed end: markerDragged() reports where to, in photo
    // pixels, for each move (finished = false) and on release (finished = true).
    void setMarkersDraggable(bool draggable) { m_draggable = draggable; }

    // Widget <-> photo pixels, as drawn now.
    QPointF toWidget(QPointF photo) const;
    QPointF toPhoto(QPointF widget) const;

    // The drawing as shown (without the markers), at the widget's size.
    QImage image();

    QSize sizeHint() const override { return QSize(320, 240); }
    QSize minimumSizeHint() const override { return QSize(120, 90); }

Q_SIGNALS:
    void markerDragged(int index, QPointF photoPos, bool finished);

protected:
    void paintEvent(QPaintEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;

private:
    QRectF targetRect() const;
    void invalidate();

    std::optional<SvgFace> m_face;
    Pose m_pose;
    QRectF m_frame;
    QVector<Marker> m_markers;
    bool m_draggable = false;
    int m_dragged = -1;
    QImage m_cache;
    bool m_cacheValid = false;
};

} // namespace toonface
