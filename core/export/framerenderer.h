#pragma once

#include "anim/timelineevaluator.h"
#include "render/svgface.h"

#include <QByteArray>
#include <QColor>
#include <QImage>
#include <QSize>

#include <atomic>
#include <functional>
#include <memory>

namespace toonface {

class MouthShapeSet;
class Timeline;

// The frames of a timeline as images, for video export and previews: frame i shows time
// i / frameRate(), drawn by SvgFace::svg() (extra layers included) and rasterized by
// QSvgRenderer (rasterizeSvg(): aspect kept, centred, `background` inside the drawing; a
// transparent background leaves alpha 0 around the face) over `backdrop` when one is given (a
// picture of `size`, such as backgroundPicture()). A frame is drawn in two passes
// (SvgFace::svgPasses()) whose under pass, the same for most frames, is rasterized once and
// reused: the pixels are those of rasterizeSvg(svgAt(t)).
// Immutable after construction but for that reuse, which copies share; render() may run on
// several threads at once.
class FrameRenderer
{
public:
    // requires: size not empty; backdrop null or of `size`
    FrameRenderer(const SvgFace &face, const Timeline &timeline, const MouthShapeSet &shapes, QSize size,
        QColor background = Qt::white, const QImage &backdrop = {});

    QSize size() const { return m_size; }
    double frameRate() const { return m_frameRate; }
    // Frames of the timeline's duration (at least one).
    int frameCount() const { return m_frameCount; }
    double frameTime(int frame) const { return frame / m_frameRate; }

    QByteArray svgAt(double t) const;
    QImage renderAt(double t) const;
    QImage render(int frame) const { return renderAt(frameTime(frame)); }

    const TimelineEvaluator &evaluator() const { return m_evaluator; }

private:
    class UnderPasses; // the last under passes rasterized, shared by the threads

    SvgFace m_face;
    TimelineEvaluator m_evaluator;
    QSize m_size;
    QColor m_background;
    QImage m_backdrop;
    double m_frameRate;
    int m_frameCount;
    std::shared_ptr<UnderPasses> m_under;
};

struct FrameRenderOptions
{
    int first = 0;
    int count = -1; // frames from `first`; -1: to the end
    // Frames rendered per batch; one batch renders while the previous one is delivered, so at
    // most two batches of images are held. 0: twice the number of cores.
    int batch = 0;
    // Called on the calling thread after each delivered frame.
    std::function<void(int delivered, int total)> progress;
    // When set and it becomes true, rendering stops (renderFrames returns false).
    const std::atomic_bool *cancel = nullptr;
};

// Renders frames in parallel (QtConcurrent) and hands them to `sink` in frame order on the
// calling thread. The sink returns false to stop. Returns true when every requested frame
// reached the sink, false when cancelled or stopped by the sink; all rendering has finished
// when it returns.
bool renderFrames(const FrameRenderer &renderer, const std::function<bool(int frame, const QImage &image)> &sink,
    const FrameRenderOptions &options = {});

} // namespace toonface
