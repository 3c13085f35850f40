#include "views/previewrenderer.h"

#include "anim/timelineevaluator.h"
#include "playback/playhead.h"
#include "render/svgface.h"

#include <QPainter>
#include <QSvgRenderer>
#include <QThread>
#include <QTimer>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>

namespace toonface {

namespace {

constexpr double kDisplayRefreshMs = 1000.0 / 60.0;
constexpr double kCostSmoothing = 0.3; // weight of the newest frame in averageRenderMs()

} // namespace

PreviewRenderer::PreviewRenderer(Document *document, Playhead *playhead, QObject *parent)
    : QObject(parent)
    , m_document(document)
    , m_playhead(playhead)
{
    connect(m_document, &Document::changed, this, &PreviewRenderer::onDocumentChanged);
    if (m_playhead) {
        connect(m_playhead, &Playhead::timeChanged, this, &PreviewRenderer::onPlayheadMoved);
        connect(m_playhead, &Playhead::playingChanged, this, &PreviewRenderer::schedule);
    }
    connect(&m_watcher, &QFutureWatcher<Frame>::finished, this, &PreviewRenderer::onJobFinished);
    rebuildScene();
    m_pictureStale = true;
    schedule();
}

PreviewRenderer::~PreviewRenderer()
{
    m_watcher.disconnect(this);
    m_watcher.waitForFinished();
}

double PreviewRenderer::time() const
{
    return m_playhead ? m_playhead->time() : 0.0;
}

double PreviewRenderer::renderBudgetMs() const
{
    if (m_playhead && m_playhead->isPlaying()) {
        const double fps = std::max(1.0, m_document->timeline().frameRate());
        return 0.5 * 1000.0 / fps;
    }
    return kDisplayRefreshMs;
}

void PreviewRenderer::setImageSize(QSize pixels)
{
    pixels = pixels.expandedTo(QSize(1, 1));
    if (pixels == m_imageSize)
        return;
    m_imageSize = pixels;
    m_pictureStale = true;
    schedule();
}

void PreviewRenderer::setTransparent(bool transparent)
{
    if (transparent == m_transparent)
        return;
    m_transparent = transparent;
    m_pictureStale = true;
    schedule();
}

void PreviewRenderer::onDocumentChanged(ChangeFlags what)
{
    if (what & (Change::Face | Change::Photo))
        m_frameStale = true;
    if (what & (Change::Points | Change::Face | Change::Style | Change::Photo))
        m_faceStale = true;
    if (what & (Change::Animation | Change::Points | Change::Face | Change::MouthShapes | Change::Photo))
        m_evaluatorStale = true;
    if (m_faceStale || m_evaluatorStale) {
        m_pictureStale = true;
        schedule();
    }
}

void PreviewRenderer::onPlayheadMoved()
{
    m_pictureStale = true;
    schedule();
}

void PreviewRenderer::schedule()
{
    if (m_scheduled)
        return;
    m_scheduled = true;
    QTimer::singleShot(0, this, &PreviewRenderer::update);
}

void PreviewRenderer::rebuildScene()
{
    if (!m_faceStale && !m_evaluatorStale)
        return;
    ++m_rebuilds;
    ++m_sceneSerial;
    if (!m_document->hasFace()) {
        const bool had = m_face != nullptr;
        m_face.reset();
        m_evaluator.reset();
        m_frame = QRectF();
        m_faceStale = m_evaluatorStale = false;
        if (had)
            Q_EMIT sceneChanged();
        return;
    }
    const FaceModel &face = m_document->face();
    bool faceChanged = false;
    if (m_frameStale || m_frame.isEmpty()) {
        m_frame = headFrame(face, 0.0);
        m_frameStale = false;
        m_faceStale = true;
    }
    if (m_faceStale || !m_face) {
        auto svgFace = std::make_shared<SvgFace>(face, m_document->style());
        svgFace->setFrame(m_frame);
        m_face = std::move(svgFace);
        m_faceStale = false;
        faceChanged = true;
    }
    if (m_evaluatorStale || !m_evaluator) {
        m_evaluator
            = std::make_shared<const TimelineEvaluator>(m_document->timeline(), face, m_document->mouthShapes());
        m_evaluatorStale = false;
    }
    if (faceChanged)
        Q_EMIT sceneChanged();
}

QImage PreviewRenderer::renderPose(
    const SvgFace &face, const QRectF &frame, QSize size, const Pose &pose, QByteArray *svg, QColor background)
{
    const QByteArray drawn = face.svg(pose);
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.fill(background);
    QSvgRenderer renderer(drawn);
    if (renderer.isValid() && !frame.isEmpty()) {
        QSizeF fitted = frame.size();
        fitted.scale(QSizeF(size), Qt::KeepAspectRatio);
        QRectF target(QPointF(), fitted);
        target.moveCenter(QRectF(QPointF(), QSizeF(size)).center());
        QPainter painter(&image);
        painter.setRenderHints(QPainter::Antialiasing | QPainter::SmoothPixmapTransform);
        painter.setClipRect(target); // nothing beyond the frame (the shoulders reach below it)
        renderer.setViewBox(frame);
        renderer.render(&painter, target);
    }
    if (svg)
        *svg = drawn;
    return image;
}

PreviewRenderer::Frame PreviewRenderer::render(const std::shared_ptr<const SvgFace> &face,
    const std::shared_ptr<const TimelineEvaluator> &evaluator, const QRectF &frame, QSize size, double time,
    quint64 scene, int extraCostMs, bool transparent)
{
    Frame out;
    out.time = time;
    out.scene = scene;
    out.transparent = transparent;
    if (!face || size.isEmpty())
        return out;
    if (evaluator)
        out.pose = evaluator->evaluate(time);
    out.image
        = renderPose(*face, frame, size, out.pose, &out.svg, transparent ? QColor(Qt::transparent) : QColor(Qt::white));
    if (extraCostMs > 0)
        QThread::msleep(ulong(extraCostMs));
    return out;
}

void PreviewRenderer::update()
{
    m_scheduled = false;
    rebuildScene();
    if (!m_pictureStale)
        return;
    if (m_watcher.isRunning()) {
        // Drawn when the job ends, at the playhead's time then.
        ++m_requestsSinceJob;
        return;
    }
    if (m_face && m_averageMs > renderBudgetMs()) {
        startJob();
        return;
    }
    QElapsedTimer clock;
    clock.start();
    Frame frame
        = render(m_face, m_evaluator, m_frame, m_imageSize, time(), m_sceneSerial, m_extraCostMs, m_transparent);
    m_pictureStale = false;
    show(std::move(frame), clock.nsecsElapsed() / 1e6, false);
}

void PreviewRenderer::startJob()
{
    m_pictureStale = false;
    m_requestsSinceJob = 0;
    m_jobTime = time();
    m_jobScene = m_sceneSerial;
    m_jobSize = m_imageSize;
    m_jobClock.start();
    m_watcher.setFuture(QtConcurrent::run(&PreviewRenderer::render, m_face, m_evaluator, m_frame, m_imageSize,
        m_jobTime, m_jobScene, m_extraCostMs, m_transparent));
}

void PreviewRenderer::onJobFinished()
{
    const QFuture<Frame> future = m_watcher.future();
    if (!future.isValid() || future.resultCount() == 0)
        return;
    Frame frame = future.result();
    // Forget the finished future, so that a flush() that already took it does not take it again.
    m_watcher.setFuture(QFuture<Frame>());
    show(std::move(frame), m_jobClock.nsecsElapsed() / 1e6, true);
    if (m_pictureStale) {
        // Only the newest request is drawn; the frames the playhead passed meanwhile are dropped.
        m_dropped += std::max(0, m_requestsSinceJob - 1);
        m_requestsSinceJob = 0;
        schedule();
    }
}

void PreviewRenderer::show(Frame frame, double ms, bool background)
{
    m_averageMs = m_rendered == 0 ? ms : (1.0 - kCostSmoothing) * m_averageMs + kCostSmoothing * ms;
    m_current = std::move(frame);
    ++m_rendered;
    if (background)
        ++m_backgroundRendered;
    Q_EMIT frameReady();
}

void PreviewRenderer::flush()
{
    if (m_watcher.isRunning() || m_watcher.future().resultCount() > 0) {
        m_watcher.waitForFinished();
        onJobFinished();
    }
    rebuildScene();
    if (!m_pictureStale)
        return;
    QElapsedTimer clock;
    clock.start();
    Frame frame
        = render(m_face, m_evaluator, m_frame, m_imageSize, time(), m_sceneSerial, m_extraCostMs, m_transparent);
    m_pictureStale = false;
    show(std::move(frame), clock.nsecsElapsed() / 1e6, false);
}

} // namespace toonface
