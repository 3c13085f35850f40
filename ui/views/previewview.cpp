#include "views/previewview.h"

#include "render/svgface.h"

#include <QPaintEvent>
#include <QPainter>
#include <QTimer>

#include <algorithm>

namespace toonface {

namespace {

constexpr double kFrameMargin = 0.08; // of the face's size, on each side
constexpr int kCardMargin = 12; // widget pixels around the drawing

} // namespace

PreviewView::PreviewView(Document *document, QWidget *parent)
    : QWidget(parent)
    , m_document(document)
{
    setAttribute(Qt::WA_OpaquePaintEvent);
    setAutoFillBackground(false);
    connect(m_document, &Document::changed, this, &PreviewView::onDocumentChanged);
    m_pending = true;
    rebuildIfPending();
}

PreviewView::~PreviewView() = default;

QByteArray PreviewView::svg()
{
    rebuildIfPending();
    return m_svg;
}

QImage PreviewView::image()
{
    rebuildIfPending();
    if (!m_cacheValid)
        renderCache();
    return m_cache;
}

QSize PreviewView::sizeHint() const
{
    return QSize(480, 560);
}

QSize PreviewView::minimumSizeHint() const
{
    return QSize(160, 160);
}

void PreviewView::onDocumentChanged(ChangeFlags what)
{
    if (what & (Change::Face | Change::Photo))
        m_frameStale = true;
    if (what & (Change::Points | Change::Face | Change::Style | Change::Photo))
        scheduleRebuild();
}

void PreviewView::scheduleRebuild()
{
    if (m_pending)
        return;
    m_pending = true;
    QTimer::singleShot(0, this, &PreviewView::rebuildIfPending);
}

void PreviewView::rebuildIfPending()
{
    if (!m_pending)
        return;
    m_pending = false;
    ++m_rebuilds;
    if (!m_document->hasFace()) {
        m_svg.clear();
        m_renderer.load(QByteArray());
        m_frame = QRectF();
    } else {
        const FaceModel &face = m_document->face();
        m_svg = SvgFace(face, m_document->style()).svg();
        m_renderer.load(m_svg);
        // The frame follows the face only when the face is replaced, so that it holds still
        // while a point is dragged.
        if (m_frameStale || m_frame.isEmpty()) {
            const QRectF bounds = face.bounds();
            const double margin = kFrameMargin * std::max(bounds.width(), bounds.height());
            m_frame = bounds.adjusted(-margin, -margin, margin, margin);
            m_frameStale = false;
        }
    }
    m_cacheValid = false;
    update();
}

QRectF PreviewView::targetRect() const
{
    const QRectF area = QRectF(rect()).adjusted(kCardMargin, kCardMargin, -kCardMargin, -kCardMargin);
    if (m_frame.isEmpty() || area.isEmpty())
        return QRectF();
    QSizeF size = m_frame.size();
    size.scale(area.size(), Qt::KeepAspectRatio);
    QRectF target(QPointF(), size);
    target.moveCenter(area.center());
    return target;
}

void PreviewView::renderCache()
{
    const qreal dpr = devicePixelRatioF();
    m_cache = QImage((QSizeF(size()) * dpr).toSize(), QImage::Format_ARGB32_Premultiplied);
    m_cache.setDevicePixelRatio(dpr);
    m_cache.fill(palette().color(QPalette::Window).darker(108));
    m_cacheValid = true;

    QPainter painter(&m_cache);
    painter.setRenderHints(QPainter::Antialiasing | QPainter::SmoothPixmapTransform);
    const QRectF target = targetRect();
    if (m_svg.isEmpty() || !m_renderer.isValid() || target.isEmpty()) {
        painter.setPen(palette().color(QPalette::PlaceholderText));
        painter.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap,
            m_document->photo().isNull() ? tr("Open a photo to draw its cartoon.") : tr("No face points yet."));
        return;
    }
    painter.fillRect(target.translated(2, 3), QColor(0, 0, 0, 40));
    painter.fillRect(target, Qt::white);
    painter.setClipRect(target);
    m_renderer.setViewBox(m_frame);
    m_renderer.render(&painter, target);
}

void PreviewView::paintEvent(QPaintEvent *event)
{
    if (!m_cacheValid)
        renderCache();
    QPainter painter(this);
    painter.drawImage(event->rect(), m_cache,
        QRectF(QPointF(event->rect().topLeft()) * m_cache.devicePixelRatio(),
            QSizeF(event->rect().size()) * m_cache.devicePixelRatio()));
}

void PreviewView::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    m_cacheValid = false;
}

} // namespace toonface
