#include "views/previewview.h"

#include "anim/timelineevaluator.h"
#include "face/pose.h"
#include "playback/playhead.h"
#include "render/svgface.h"
#include "views/checkerboard.h"
#include "views/posekeydrag.h"
#include "views/themedicon.h"

#include <QAction>
#include <QKeySequence>
#include <QMouseEvent>
#include <QPaintEvent>
#include <QPainter>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>

namespace toonface {

namespace {

constexpr int kCardMargin = 12; // widget pixels around the drawing
constexpr double kHandleRadius = 5.0; // on screen
constexpr double kHandlePick = 9.0; // how near a press must be to take a handle

// SvgFace::headTransform() as a QTransform: "translate(x,y) rotate(a) scale(s) translate(-cx,-cy)".
QTransform headTransform(const SvgFace &face, const HeadPose &head)
{
    static const QRegularExpression number(QStringLiteral("[-+]?(?:\\d+\\.?\\d*|\\.\\d+)(?:[eE][-+]?\\d+)?"));
    QVector<double> v;
    for (auto it = number.globalMatch(face.headTransform(head)); it.hasNext();)
        v.append(it.next().captured().toDouble());
    if (v.size() != 6)
        return {};
    QTransform t;
    t.translate(v[0], v[1]);
    t.rotate(v[2]);
    t.scale(v[3], v[3]);
    t.translate(v[4], v[5]);
    return t;
}

} // namespace

PreviewView::PreviewView(Document *document, QWidget *parent)
    : PreviewView(document, nullptr, parent)
{ }

PreviewView::PreviewView(Document *document, Playhead *playhead, QWidget *parent)
    : QWidget(parent)
    , m_document(document)
    , m_playhead(playhead)
    , m_renderer(new PreviewRenderer(document, playhead, this))
{
    setAttribute(Qt::WA_OpaquePaintEvent);
    setAutoFillBackground(false);
    setMouseTracking(true);
    connect(m_renderer, &PreviewRenderer::frameReady, this, qOverload<>(&QWidget::update));
    connect(m_renderer, &PreviewRenderer::sceneChanged, this, &PreviewView::updateImageSize);

    m_editPoseAction = new QAction(themedIcon("transform-move", "pose-edit.svg"), tr("Edit &Pose"), this);
    m_editPoseAction->setObjectName(QStringLiteral("editPoseAction"));
    m_editPoseAction->setCheckable(true);
    m_editPoseAction->setToolTip(
        tr("Show the control points on the preview: drag one to set a pose key frame at the playhead"));
    connect(m_editPoseAction, &QAction::toggled, this, [this] {
        m_hovered = -1;
        unsetCursor();
        update();
    });
    m_transparentAction = new QAction(tr("&Transparent Background"), this);
    m_transparentAction->setObjectName(QStringLiteral("transparentPreviewAction"));
    m_transparentAction->setCheckable(true);
    m_transparentAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_B));
    m_transparentAction->setToolTip(
        tr("Show the cartoon without its background, over a checkerboard, as a transparent sticker exports it"));
    m_transparentAction->setStatusTip(m_transparentAction->toolTip());
    connect(m_transparentAction, &QAction::toggled, m_renderer, &PreviewRenderer::setTransparent);
    if (m_playhead) {
        connect(m_playhead, &Playhead::playingChanged, this, [this] {
            m_hovered = -1;
            update();
        });
    }
    updateImageSize();
}

PreviewView::~PreviewView() = default;

bool PreviewView::isEditingPose() const
{
    // The handles rest while the animation plays: a key is set on a still frame.
    return m_editPoseAction->isChecked() && m_renderer->hasScene() && !(m_playhead && m_playhead->isPlaying());
}

QByteArray PreviewView::svg()
{
    m_renderer->flush();
    return m_renderer->current().svg;
}

QImage PreviewView::image()
{
    m_renderer->flush();
    const qreal dpr = devicePixelRatioF();
    QImage image((QSizeF(size()) * dpr).toSize(), QImage::Format_ARGB32_Premultiplied);
    image.setDevicePixelRatio(dpr);
    QPainter painter(&image);
    paintCard(painter, rect());
    return image;
}

QSize PreviewView::sizeHint() const
{
    return QSize(480, 560);
}

QSize PreviewView::minimumSizeHint() const
{
    return QSize(160, 160);
}

QRectF PreviewView::targetRect() const
{
    const QRectF area = QRectF(rect()).adjusted(kCardMargin, kCardMargin, -kCardMargin, -kCardMargin);
    const QRectF frame = m_renderer->frame();
    if (frame.isEmpty() || area.isEmpty())
        return QRectF();
    QSizeF size = frame.size();
    size.scale(area.size(), Qt::KeepAspectRatio);
    QRectF target(QPointF(), size);
    target.moveCenter(area.center());
    // Whole device pixels, so the picture is blitted without resampling.
    const qreal dpr = devicePixelRatioF();
    return QRectF(std::round(target.x() * dpr) / dpr, std::round(target.y() * dpr) / dpr,
        std::round(target.width() * dpr) / dpr, std::round(target.height() * dpr) / dpr);
}

void PreviewView::updateImageSize()
{
    const QRectF target = targetRect();
    if (!target.isEmpty())
        m_renderer->setImageSize((target.size() * devicePixelRatioF()).toSize());
    update();
}

QTransform PreviewView::photoToWidget() const
{
    const QRectF target = targetRect();
    const QRectF frame = m_renderer->frame();
    const auto face = m_renderer->svgFace();
    if (target.isEmpty() || frame.isEmpty() || !face)
        return {};
    QTransform view;
    view.translate(target.x(), target.y());
    view.scale(target.width() / frame.width(), target.height() / frame.height());
    view.translate(-frame.x(), -frame.y());
    return headTransform(*face, m_renderer->current().pose.head) * view;
}

void PreviewView::paintCard(QPainter &painter, const QRect &area) const
{
    painter.fillRect(area, palette().color(QPalette::Window).darker(108));
    const QRectF target = targetRect();
    const PreviewRenderer::Frame &frame = m_renderer->current();
    if (!m_renderer->hasScene() || target.isEmpty() || frame.image.isNull()) {
        painter.setPen(palette().color(QPalette::PlaceholderText));
        QString text;
        if (m_document->photo().isNull())
            text = tr("Open a photo to draw its cartoon.");
        else if (!m_document->hasFace())
            text = tr("No face points yet.");
        else
            text = tr("Drawing the cartoon…"); // its first picture is on the way
        painter.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap, text);
        return;
    }
    painter.fillRect(target.translated(2, 3), QColor(0, 0, 0, 40));
    if (frame.transparent)
        paintCheckerboard(&painter, target.toRect());
    // While a resize waits for its picture, the last one is stretched over the card.
    painter.setRenderHint(QPainter::SmoothPixmapTransform, frame.image.size() != m_renderer->imageSize());
    painter.drawImage(target, frame.image);
}

void PreviewView::paintHandles(QPainter &painter) const
{
    const auto face = m_renderer->svgFace();
    if (!face)
        return;
    const std::array<QPointF, kPointCount> points = posedPoints(face->face(), m_renderer->current().pose);
    const QTransform map = photoToWidget();
    const double t = m_renderer->current().time;
    bool onKey = false;
    for (const PoseKey &k : m_document->timeline().poseKeys())
        onKey = onKey || std::abs(k.time - t) <= Timeline::kPoseTimeTolerance;

    painter.setRenderHint(QPainter::Antialiasing);
    const QVector<PoseHandle> &handles = poseHandles();
    for (int i = 0; i < handles.size(); ++i) {
        const QPointF at = map.map(points[pt::idx(handles[i].shownAt)]);
        const bool active = i == m_hovered || (m_drag && m_drag->handle() == i);
        const double r = active ? kHandleRadius + 1.5 : kHandleRadius;
        // Filled on a pose key, hollow between keys (the pose there is interpolated).
        painter.setPen(QPen(QColor(255, 255, 255, 230), 3.0));
        painter.setBrush(Qt::NoBrush);
        painter.drawEllipse(at, r, r);
        const QColor accent = active ? QColor(255, 140, 0) : QColor(230, 60, 120);
        painter.setPen(QPen(accent, 1.6));
        painter.setBrush(onKey ? accent : QColor(255, 255, 255, 200));
        painter.drawEllipse(at, r, r);
    }
}

std::optional<QPointF> PreviewView::handlePosition(const QString &id) const
{
    const auto face = m_renderer->svgFace();
    if (!isEditingPose() || !face)
        return std::nullopt;
    const QVector<PoseHandle> &handles = poseHandles();
    const bool isHandle = std::any_of(
        handles.begin(), handles.end(), [&](const PoseHandle &h) { return id == QLatin1StringView(h.shownAt); });
    const int index = pointIndex(id);
    if (!isHandle || index < 0)
        return std::nullopt;
    const std::array<QPointF, kPointCount> points = posedPoints(face->face(), m_renderer->current().pose);
    return photoToWidget().map(points[index]);
}

int PreviewView::handleAt(QPointF pos) const
{
    if (!isEditingPose())
        return -1;
    const auto face = m_renderer->svgFace();
    const std::array<QPointF, kPointCount> points = posedPoints(face->face(), m_renderer->current().pose);
    const QTransform map = photoToWidget();
    int best = -1;
    double bestDistance = kHandlePick;
    const QVector<PoseHandle> &handles = poseHandles();
    for (int i = 0; i < handles.size(); ++i) {
        const double d = QLineF(map.map(points[pt::idx(handles[i].shownAt)]), pos).length();
        if (d <= bestDistance) {
            best = i;
            bestDistance = d;
        }
    }
    return best;
}

void PreviewView::paintEvent(QPaintEvent *)
{
    QPainter painter(this);
    paintCard(painter, rect());
    if (isEditingPose())
        paintHandles(painter);
}

void PreviewView::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    updateImageSize();
}

void PreviewView::mousePressEvent(QMouseEvent *event)
{
    const int handle = event->button() == Qt::LeftButton ? handleAt(event->position()) : -1;
    if (handle < 0) {
        QWidget::mousePressEvent(event);
        return;
    }
    // The drag keys the pose the user sees: the picture of the playhead's time, up to date.
    m_renderer->flush();
    const double time = m_renderer->current().time;
    m_drag = std::make_unique<PoseKeyDrag>(m_document, m_renderer->evaluator(), handle, time);
    m_dragStart = photoToWidget().inverted().map(event->position());
    m_dragHead = photoToWidget();
    setCursor(Qt::ClosedHandCursor);
    event->accept();
    update();
}

void PreviewView::mouseMoveEvent(QMouseEvent *event)
{
    if (m_drag) {
        // Measured in the frame of the press: the head motion at the key's time stays put.
        m_drag->moveBy(m_dragHead.inverted().map(event->position()) - m_dragStart);
        event->accept();
        return;
    }
    const int hovered = handleAt(event->position());
    if (hovered != m_hovered) {
        m_hovered = hovered;
        if (hovered >= 0) {
            setCursor(Qt::OpenHandCursor);
            setToolTip(QCoreApplication::translate("PoseKeyDrag", poseHandles().at(hovered).label) + QLatin1Char(' ')
                + QString::fromLatin1(poseHandles().at(hovered).control));
        } else {
            unsetCursor();
            setToolTip(QString());
        }
        update();
    }
    QWidget::mouseMoveEvent(event);
}

void PreviewView::mouseReleaseEvent(QMouseEvent *event)
{
    if (!m_drag || event->button() != Qt::LeftButton) {
        QWidget::mouseReleaseEvent(event);
        return;
    }
    m_drag->moveBy(m_dragHead.inverted().map(event->position()) - m_dragStart);
    m_drag->finish();
    m_drag.reset();
    setCursor(m_hovered >= 0 ? Qt::OpenHandCursor : Qt::ArrowCursor);
    event->accept();
    update();
}

void PreviewView::leaveEvent(QEvent *event)
{
    if (!m_drag && m_hovered >= 0) {
        m_hovered = -1;
        update();
    }
    QWidget::leaveEvent(event);
}

} // namespace toonface
