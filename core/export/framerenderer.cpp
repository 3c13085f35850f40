#include "export/framerenderer.h"

#include "anim/timeline.h"

#include <QFuture>
#include <QMutex>
#include <QMutexLocker>
#include <QPainter>
#include <QThread>
#include <QtConcurrent/QtConcurrentMap>

#include <algorithm>
#include <numeric>

namespace toonface {

// Rasters of the under pass by its text. Threads render neighbouring frames, which mostly share
// it; a few kept cover a batch's threads and a head that turns back and forth. Each is a frame
// of pixels (1 MB at 512x512).
class FrameRenderer::UnderPasses
{
public:
    QImage raster(const QByteArray &svg, QSize size, const QColor &background)
    {
        {
            const QMutexLocker lock(&m_mutex);
            for (const Entry &e : m_entries) {
                if (e.svg == svg)
                    return e.image;
            }
        }
        // Rasterized outside the lock, so threads missing at once each draw their own.
        QImage image = rasterizeSvg(svg, size, background);
        const QMutexLocker lock(&m_mutex);
        if (m_entries.size() == kKept)
            m_entries.removeFirst();
        m_entries.append({svg, image});
        return image;
    }

private:
    static constexpr qsizetype kKept = 4;
    struct Entry
    {
        QByteArray svg;
        QImage image;
    };
    QMutex m_mutex;
    QVector<Entry> m_entries;
};

FrameRenderer::FrameRenderer(const SvgFace &face, const Timeline &timeline, const MouthShapeSet &shapes, QSize size,
    QColor background, const QImage &backdrop)
    : m_face(face)
    , m_evaluator(timeline, face.face(), shapes)
    , m_size(size)
    , m_background(background)
    , m_backdrop(backdrop)
    , m_frameRate(timeline.frameRate() > 0 ? timeline.frameRate() : 25.0)
    , m_frameCount(std::max(1, timeline.frameCount()))
    , m_under(std::make_shared<UnderPasses>())
{ }

QByteArray FrameRenderer::svgAt(double t) const
{
    return m_face.svg(m_evaluator.evaluate(t));
}

QImage FrameRenderer::renderAt(double t) const
{
    // Over a backdrop the drawing is rasterized on transparency, then laid on it.
    const QColor background = m_backdrop.isNull() ? m_background : QColor(Qt::transparent);
    const SvgFace::Passes passes = m_face.svgPasses(m_evaluator.evaluate(t));
    QImage drawing = m_under->raster(passes.under, m_size, background);
    if (drawing.isNull() || !drawSvg(passes.over, &drawing))
        return rasterizeSvg(svgAt(t), m_size, background); // as it was, whatever that gives
    if (m_backdrop.isNull())
        return drawing;
    QImage image = m_backdrop.convertToFormat(QImage::Format_ARGB32_Premultiplied);
    QPainter painter(&image);
    painter.drawImage(0, 0, drawing);
    painter.end();
    return image;
}

bool renderFrames(const FrameRenderer &renderer, const std::function<bool(int, const QImage &)> &sink,
    const FrameRenderOptions &options)
{
    const int first = std::clamp(options.first, 0, renderer.frameCount());
    const int available = renderer.frameCount() - first;
    const int total = options.count < 0 ? available : std::min(options.count, available);
    const int batch = options.batch > 0 ? options.batch : 2 * std::max(1, QThread::idealThreadCount());
    const int end = first + total;

    auto start = [&](int from) {
        QVector<int> frames(std::min(batch, end - from));
        std::iota(frames.begin(), frames.end(), from);
        return QtConcurrent::mapped(std::move(frames), [&renderer](int frame) { return renderer.render(frame); });
    };
    QFuture<QImage> current;
    QFuture<QImage> next;
    auto stop = [&] {
        current.cancel();
        next.cancel();
        current.waitForFinished();
        next.waitForFinished();
        return false;
    };
    if (total > 0)
        current = start(first);
    int delivered = 0;
    for (int from = first; from < end; from += batch) {
        const int count = std::min(batch, end - from);
        if (from + count < end)
            next = start(from + count);
        for (int i = 0; i < count; ++i) {
            if (options.cancel && options.cancel->load())
                return stop();
            if (!sink(from + i, current.resultAt(i)))
                return stop();
            ++delivered;
            if (options.progress)
                options.progress(delivered, total);
        }
        current = next;
        next = {};
    }
    return true;
}

} // namespace toonface
