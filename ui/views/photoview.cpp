#include "views/photoview.h"

#include "views/pointhandle.h"

#include <QGraphicsPathItem>
#include <QGraphicsPixmapItem>
#include <QGraphicsRectItem>
#include <QGraphicsScene>
#include <QGraphicsSceneMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <functional>

namespace toonface {

namespace {

constexpr double kMinZoom = 0.02;
constexpr double kMaxZoom = 32.0;
constexpr double kZoomStep = 1.25;
constexpr double kFaceMargin = 0.06; // around the face's points when zooming to the face

// The feature outlines drawn under the handles, as chains of point IDs; `closed` joins the
// last point to the first. They show which point is which part of the face.
struct Outline
{
    std::initializer_list<const char *> ids;
    bool closed;
};

const Outline kOutlines[] = {
    {{"h.1", "h.2", "h.3", "h.4", "h.5", "h.6", "h.7", "h.8", "h.9", "h.10", "h.11", "h.12", "h.13", "h.14", "h.15",
         "h.16", "h.17", "h.18", "h.19"},
        false},
    {{"11.2", "11.1", "11.3", "5.1", "2.13", "2.11", "2.1", "2.12", "2.14", "5.2"}, true},
    {{"10.2", "10.4", "10.6", "10.10"}, false},
    {{"10.1", "10.3", "10.5", "10.9"}, false},
    {{"4.6", "4.4a", "4.4", "4.2"}, false},
    {{"4.1", "4.3", "4.3a", "4.5"}, false},
    {{"3.12", "3.2", "3.8", "3.4"}, true},
    {{"3.11", "3.1", "3.7", "3.3"}, true},
    {{"9.6", "9.14", "9.2", "9.4", "9.15", "9.5", "9.1", "9.13", "9.7"}, false},
    {{"8.4", "8.9", "8.1", "8.10", "8.3", "8.2"}, true},
    {{"8.4", "2.2", "8.3", "2.3"}, true},
};

// The box of another face in the photo: dashed, filled lightly under the cursor; a click
// inside it asks for that face.
class OtherFaceItem : public QGraphicsRectItem
{
public:
    OtherFaceItem(const QRectF &box, std::function<void(QPointF)> chosen)
        : QGraphicsRectItem(box)
        , m_chosen(std::move(chosen))
    {
        QPen pen(QColor(255, 220, 60), 2.0, Qt::DashLine);
        pen.setCosmetic(true);
        setPen(pen);
        setBrush(Qt::NoBrush);
        setAcceptHoverEvents(true);
        setAcceptedMouseButtons(Qt::LeftButton);
        setCursor(Qt::PointingHandCursor);
        setToolTip(PhotoView::tr("Another face in the photo: click to use it instead"));
        setZValue(0.8);
    }

protected:
    void hoverEnterEvent(QGraphicsSceneHoverEvent *) override { setBrush(QColor(255, 220, 60, 50)); }
    void hoverLeaveEvent(QGraphicsSceneHoverEvent *) override { setBrush(Qt::NoBrush); }
    void mousePressEvent(QGraphicsSceneMouseEvent *event) override { event->accept(); }
    void mouseReleaseEvent(QGraphicsSceneMouseEvent *event) override
    {
        if (rect().contains(event->pos()))
            m_chosen(event->pos());
    }

private:
    std::function<void(QPointF)> m_chosen;
};

} // namespace

PhotoView::PhotoView(Document *document, QWidget *parent)
    : QGraphicsView(parent)
    , m_document(document)
    , m_scene(new QGraphicsScene(this))
{
    setScene(m_scene);
    setRenderHints(QPainter::Antialiasing | QPainter::SmoothPixmapTransform);
    setTransformationAnchor(AnchorUnderMouse);
    setResizeAnchor(AnchorViewCenter);
    setDragMode(ScrollHandDrag);
    setBackgroundBrush(QColor(0x3a, 0x3a, 0x3e));
    setFrameShape(QFrame::NoFrame);
    setMouseTracking(true);

    m_canvasItem = m_scene->addRect(QRectF(), Qt::NoPen, QColor(0x55, 0x55, 0x5a));
    m_canvasItem->setZValue(-1);
    m_photoItem = m_scene->addPixmap(QPixmap());
    m_photoItem->setTransformationMode(Qt::SmoothTransformation);
    m_photoItem->setZValue(0);
    // Between the photo (0) and the outlines (1) and handles (2, 3); it takes no clicks, so
    // the handles and the hand-drag of the view work through it.
    m_overlayItem = m_scene->addPixmap(QPixmap());
    m_overlayItem->setTransformationMode(Qt::SmoothTransformation);
    m_overlayItem->setZValue(0.5);
    m_overlayItem->setAcceptedMouseButtons(Qt::NoButton);
    m_overlayItem->setAcceptHoverEvents(false);
    m_overlayItem->setOpacity(m_overlayOpacity);
    m_overlayItem->setVisible(false);

    QPen outlinePen(QColor(255, 255, 255, 150), 1.0);
    outlinePen.setCosmetic(true);
    m_outlineItem = m_scene->addPath(QPainterPath(), outlinePen);
    m_outlineItem->setZValue(1);

    m_handles.reserve(kPointCount);
    for (int i = 0; i < kPointCount; ++i) {
        auto *handle = new PointHandle(this, i);
        m_scene->addItem(handle);
        m_handles.append(handle);
    }

    updateScrollBars();
    connect(m_document, &Document::changed, this, &PhotoView::onDocumentChanged);
    syncPhoto();
    syncPoints();
}

PhotoView::~PhotoView() = default;

PointHandle *PhotoView::handle(int index) const
{
    return m_handles.value(index);
}

double PhotoView::zoom() const
{
    return transform().m11();
}

void PhotoView::setOverlay(const QImage &image)
{
    m_overlayItem->setPixmap(image.isNull() ? QPixmap() : QPixmap::fromImage(image));
    placeOverlay();
}

bool PhotoView::hasOverlay() const
{
    return m_overlayItem->isVisible();
}

void PhotoView::setOverlayOpacity(double opacity)
{
    m_overlayOpacity = std::clamp(opacity, 0.0, 1.0);
    m_overlayItem->setOpacity(m_overlayOpacity);
}

void PhotoView::placeOverlay()
{
    const QPixmap pixmap = m_overlayItem->pixmap();
    const QSizeF photo = m_photoItem->pixmap().size();
    const bool show = !pixmap.isNull() && !photo.isEmpty();
    m_overlayItem->setVisible(show);
    if (!show)
        return;
    // Exactly over the photo: pixel edges on pixel edges, whatever the overlay's resolution.
    m_overlayItem->setPos(m_photoItem->pos());
    m_overlayItem->setTransform(
        QTransform::fromScale(photo.width() / pixmap.width(), photo.height() / pixmap.height()));
}

void PhotoView::dragPoint(int index, QPointF pos, bool commit)
{
    if (m_document->hasFace())
        m_document->movePoint(index, pos, commit);
}

void PhotoView::pointHoverChanged(int index, bool hovered)
{
    Q_EMIT pointHovered(hovered ? index : -1);
}

void PhotoView::setShowPointIds(bool show)
{
    m_showIds = show;
    for (PointHandle *handle : std::as_const(m_handles))
        handle->setShowId(show);
}

void PhotoView::zoomIn()
{
    setZoom(zoom() * kZoomStep);
}

void PhotoView::zoomOut()
{
    setZoom(zoom() / kZoomStep);
}

void PhotoView::zoomToActualSize()
{
    setZoom(1.0);
}

void PhotoView::fitToWindow()
{
    m_fit = Fit::Photo;
    updateScrollBars();
    applyFit();
}

void PhotoView::zoomToFace()
{
    m_fit = Fit::Face;
    updateScrollBars();
    applyFit();
}

void PhotoView::updateScrollBars()
{
    // A fit mode frames its target in whatever room the viewport has. Scroll bars that come
    // and go with the zoom would change that room and the fit again, without end when the
    // target is about as large as the scene (a face whose hair points reach the photo's
    // edges); the hand drag still pans.
    const Qt::ScrollBarPolicy policy = m_fit == Fit::None ? Qt::ScrollBarAsNeeded : Qt::ScrollBarAlwaysOff;
    setHorizontalScrollBarPolicy(policy);
    setVerticalScrollBarPolicy(policy);
}

void PhotoView::applyFit()
{
    QRectF rect = sceneRect();
    if (m_fit == Fit::Face && m_document->hasFace()) {
        const QRectF face = m_document->face().bounds();
        const double margin = kFaceMargin * std::max(face.width(), face.height());
        rect = face.adjusted(-margin, -margin, margin, margin);
    }
    if (!rect.isEmpty())
        fitInView(rect, Qt::KeepAspectRatio);
    Q_EMIT zoomChanged(zoom());
}

void PhotoView::wheelEvent(QWheelEvent *event)
{
    const double steps = event->angleDelta().y() / 120.0;
    if (steps == 0) {
        QGraphicsView::wheelEvent(event);
        return;
    }
    setZoom(zoom() * std::pow(kZoomStep, steps));
    event->accept();
}

void PhotoView::resizeEvent(QResizeEvent *event)
{
    QGraphicsView::resizeEvent(event);
    if (m_fit != Fit::None)
        applyFit();
}

void PhotoView::setOtherFaces(const QList<QRect> &boxes)
{
    qDeleteAll(m_otherFaceItems);
    m_otherFaceItems.clear();
    for (const QRect &box : boxes) {
        auto *item = new OtherFaceItem(QRectF(box), [this](QPointF at) { Q_EMIT otherFaceChosen(at); });
        m_scene->addItem(item);
        m_otherFaceItems.append(item);
    }
}

QList<QRect> PhotoView::otherFaces() const
{
    QList<QRect> boxes;
    for (const QGraphicsRectItem *item : m_otherFaceItems)
        boxes.append(item->rect().toRect());
    return boxes;
}

void PhotoView::onDocumentChanged(ChangeFlags what)
{
    if (what & Change::Photo) {
        m_overlayItem->setPixmap(QPixmap()); // it belonged to the previous photo
        setOtherFaces({});
    }
    if (what & (Change::Photo | Change::Face))
        syncPhoto();
    if (what & (Change::Points | Change::Face))
        syncPoints();
}

void PhotoView::drawForeground(QPainter *painter, const QRectF &rect)
{
    QGraphicsView::drawForeground(painter, rect);
    if (!m_document->photo().isNull() || m_document->hasFace())
        return;
    painter->save();
    painter->resetTransform();
    QPen pen(palette().color(QPalette::Mid), 2, Qt::DashLine);
    painter->setPen(pen);
    const QRect area = viewport()->rect().adjusted(24, 24, -24, -24);
    painter->drawRoundedRect(area, 12, 12);
    painter->setPen(palette().color(QPalette::PlaceholderText));
    painter->drawText(area, Qt::AlignCenter | Qt::TextWordWrap,
        tr("Open a photo of a face (%1), or drop one here.")
            .arg(QKeySequence(QKeySequence::Open).toString(QKeySequence::NativeText)));
    painter->restore();
}

void PhotoView::syncPhoto()
{
    const QImage &photo = m_document->photo();
    m_photoItem->setPixmap(QPixmap::fromImage(photo));
    const QRectF canvas(QPointF(), QSizeF(m_document->canvasSize()));
    m_canvasItem->setRect(canvas);
    m_canvasItem->setVisible(photo.isNull() && !canvas.isEmpty());
    placeOverlay();
    viewport()->update(); // the hint of an empty view comes or goes

    // Room around the photo for points outside it (hair, ears), fixed until the next face,
    // so that the scene does not shift under a drag.
    QRectF content = canvas;
    if (m_document->hasFace())
        content |= m_document->face().bounds();
    const double margin = 0.03 * std::max(content.width(), content.height());
    m_scene->setSceneRect(content.adjusted(-margin, -margin, margin, margin));
    if (m_fit != Fit::None)
        applyFit();
}

void PhotoView::syncPoints()
{
    const bool visible = m_document->hasFace();
    const FaceModel &face = m_document->face();
    for (int i = 0; i < kPointCount; ++i) {
        m_handles[i]->setVisible(visible);
        if (visible)
            m_handles[i]->sync(face.point(i), face.isHandPlaced(i));
    }
    updateOutlines();
}

void PhotoView::updateOutlines()
{
    QPainterPath path;
    if (m_document->hasFace()) {
        const FaceModel &face = m_document->face();
        for (const Outline &outline : kOutlines) {
            bool first = true;
            for (const char *id : outline.ids) {
                const QPointF p = face.point(id);
                if (first)
                    path.moveTo(p);
                else
                    path.lineTo(p);
                first = false;
            }
            if (outline.closed)
                path.closeSubpath();
        }
    }
    m_outlineItem->setPath(path);
}

void PhotoView::setZoom(double zoom)
{
    zoom = std::clamp(zoom, kMinZoom, kMaxZoom);
    const double current = this->zoom();
    if (current <= 0 || zoom == current)
        return;
    m_fit = Fit::None;
    updateScrollBars();
    scale(zoom / current, zoom / current);
    Q_EMIT zoomChanged(this->zoom());
}

} // namespace toonface
