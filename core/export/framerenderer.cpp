#include "export/framerenderer.h"

#include "anim/timeline.h"

#include <QFuture>
#include <QPainter>
#include <QThread>
#include <QtConcurrent/QtConcurrentMap>

#include <algorithm>
#include <numeric>

namespace toonface {

FrameRenderer::FrameRenderer(const SvgFace &face, const Timeline &timeline, const MouthShapeSet &shapes, QSize size,
    QColor background, const QImage &backdrop)
    : m_face(face)
    , m_evaluator(timeline, face.face(), shapes)
    , m_size(size)
    , m_background(background)
    , m_backdrop(backdrop)
    , m_frameRate(timeline.frameRate() > 0 ? timeline.frameRate() : 25.0)
    , m_frameCount(std::max(1, timeline.frameCount()))
{ }

QByteArray FrameRenderer::svgAt(double t) const
{
    return m_face.svg(m_evaluator.evaluate(t));
}

QImage FrameRenderer::renderAt(double t) const
{
    if (m_backdrop.isNull())
        return rasterizeSvg(svgAt(t), m_size, m_background);
    QImage image = m_backdrop.convertToFormat(QImage::Format_ARGB32_Premultiplied);
    QPainter painter(&image);
    painter.drawImage(0, 0, rasterizeSvg(svgAt(t), m_size, Qt::transparent));
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
