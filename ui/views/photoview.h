#pragma once

#include "document/document.h"

#include <QGraphicsView>
#include <QList>
#include <QRect>
#include <QVector>

class QGraphicsPathItem;
class QGraphicsPixmapItem;
class QGraphicsRectItem;

namespace toonface {

class PointHandle;

// The photo with the 72 points as draggable handles, coloured by group, over thin outlines
// of the features. Dragging a handle moves the point in the document (one undo step per drag);
// the handles follow the document, never the other way round. The wheel zooms about the
// cursor. Two fit modes keep their target framed as the view resizes and the face changes:
// fitToWindow() (the whole photo) and zoomToFace() (the initial mode: the face, where the
// points are edited; the whole photo while there is no face).
//
// An overlay picture (a step of the detection) can be laid over the photo, under the outlines
// and handles, stretched to the photo's frame and drawn with an opacity; it is dropped when
// the photo changes.
class PhotoView : public QGraphicsView
{
    Q_OBJECT

public:
    explicit PhotoView(Document *document, QWidget *parent = nullptr);
    ~PhotoView() override;

    bool showPointIds() const { return m_showIds; }
    // The handle of point `index` (for tests and tools).
    PointHandle *handle(int index) const;
    // Current zoom: view pixels per photo pixel.
    double zoom() const;
    enum class Fit { None, Photo, Face };
    Fit fitMode() const { return m_fit; }

    // Lays `image` over the photo, stretched to the photo's rectangle (it shows the photo's
    // frame, maybe at a lower resolution); a null image removes the overlay.
    void setOverlay(const QImage &image);
    void clearOverlay() { setOverlay({}); }
    bool hasOverlay() const;
    // 0 (invisible) .. 1 (hides the photo where the overlay is opaque).
    void setOverlayOpacity(double opacity);
    double overlayOpacity() const { return m_overlayOpacity; }
    // The item drawing the overlay (for tests).
    QGraphicsPixmapItem *overlayItem() const { return m_overlayItem; }

    // The boxes of the other faces the detection saw (photo pixels), drawn dashed; a click in
    // one emits otherFaceChosen. They belong to the photo: a new photo clears them.
    void setOtherFaces(const QList<QRect> &boxes);
    QList<QRect> otherFaces() const;

    // Called by the handles.
    void dragPoint(int index, QPointF pos, bool commit);
    void pointHoverChanged(int index, bool hovered);

public Q_SLOTS:
    void setShowPointIds(bool show);
    void zoomIn();
    void zoomOut();
    void zoomToActualSize();
    void fitToWindow();
    void zoomToFace();

Q_SIGNALS:
    // A point came under the cursor (index), or none did any more (-1).
    void pointHovered(int index);
    void zoomChanged(double zoom);
    // The user clicked the box of another face (at `at`, photo pixels, inside the box).
    void otherFaceChosen(QPointF at);

protected:
    void wheelEvent(QWheelEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;
    // With no photo and no face: how to get one ("Open or drop a photo").
    void drawForeground(QPainter *painter, const QRectF &rect) override;

private:
    void onDocumentChanged(ChangeFlags what);
    void syncPhoto();
    void syncPoints();
    void updateOutlines();
    void setZoom(double zoom);
    void applyFit();
    void updateScrollBars();
    void placeOverlay();

    Document *m_document;
    QGraphicsScene *m_scene;
    QGraphicsPixmapItem *m_photoItem;
    QGraphicsPixmapItem *m_overlayItem;
    double m_overlayOpacity = 0.6;
    QGraphicsRectItem *m_canvasItem;
    QGraphicsPathItem *m_outlineItem;
    QVector<PointHandle *> m_handles;
    QList<QGraphicsRectItem *> m_otherFaceItems;
    bool m_showIds = false;
    Fit m_fit = Fit::Face;
};

} // namespace toonface
