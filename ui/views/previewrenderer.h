#pragma once

#include "document/document.h"
#include "face/pose.h"

#include <QByteArray>
#include <QColor>
#include <QElapsedTimer>
#include <QFutureWatcher>
#include <QImage>
#include <QObject>
#include <QPointer>
#include <QRectF>

#include <memory>

namespace toonface {

class Playhead;
class SvgFace;
class TimelineEvaluator;

// The animated preview's pictures, without a widget: the pose of the document's timeline at the
// playhead's time, TimelineEvaluator(timeline, face, mouth shapes).evaluate(t) ->
// SvgFace(face, style).svg(pose) -> QSvgRenderer, rasterised at imageSize() showing frame().
//
// What the pictures are drawn from (the scene: the SvgFace and the evaluator) is rebuilt only
// when the document changes what it depends on (the face and style for the SvgFace; the
// animation, points, face or mouth shapes for the evaluator). Changes and playhead moves are
// coalesced: however many arrive in one event-loop turn, one frame is drawn after it.
//
// A frame is drawn on the GUI thread while drawing one fits renderBudgetMs(); when it does not
// (a large preview, a slow machine), frames are drawn by a worker (QtConcurrent) with one job in
// flight: a playhead move while a job runs only marks the picture stale, and when the job ends
// the next one draws the playhead's time then. Frames the playhead passed meanwhile are dropped,
// never queued, so the picture is never more than one frame's work behind.
//
// Lives on the GUI thread. The scene is immutable and shared with the worker.
class PreviewRenderer : public QObject
{
    Q_OBJECT

public:
    // `playhead` may be null: the preview then shows time 0.
    PreviewRenderer(Document *document, Playhead *playhead, QObject *parent = nullptr);
    ~PreviewRenderer() override; // waits for a job in flight

    // One drawn picture.
    struct Frame
    {
        // imageSize(), the drawing fitted (aspect kept) on white, or on nothing (alpha 0) when
        // transparent; null without a face
        QImage image;
        bool transparent = false;
        QByteArray svg;
        Pose pose;
        double time = 0;
        quint64 scene = 0; // the scene it was drawn from (sceneSerial())
    };

    // Whether the pictures leave out the background (alpha 0 around the face), as a transparent
    // sticker exports it; changing it draws the picture again.
    void setTransparent(bool transparent);
    bool isTransparent() const { return m_transparent; }

    // The device-pixel size of the pictures (the widget's drawing area).
    void setImageSize(QSize pixels);
    QSize imageSize() const { return m_imageSize; }
    // The part of the drawing shown, in photo pixels: the head with room for its motions. It
    // follows the face only when the face is replaced, so that it holds still during a drag.
    QRectF frame() const { return m_frame; }
    // The time the preview follows: the playhead's, or 0 without one.
    double time() const;

    // The picture shown now (the last one drawn). May lag the playhead by one job while drawing
    // in the background; flush() brings it up to date.
    const Frame &current() const { return m_current; }
    // Rebuilds and draws now if anything is pending, waiting for a job in flight.
    void flush();

    bool hasScene() const { return m_face != nullptr; }
    // The scene (null without a face); shared, immutable.
    std::shared_ptr<const SvgFace> svgFace() const { return m_face; }
    std::shared_ptr<const TimelineEvaluator> evaluator() const { return m_evaluator; }
    quint64 sceneSerial() const { return m_sceneSerial; }

    // Figures, for tests, benchmarks and a status display.
    int rebuildCount() const { return m_rebuilds; } // scene rebuilds
    int renderedFrames() const { return m_rendered; } // pictures drawn and shown
    int backgroundFrames() const { return m_backgroundRendered; } // of those, drawn by the worker
    int droppedFrames() const { return m_dropped; } // requests passed over while a job ran
    double averageRenderMs() const { return m_averageMs; } // evaluate + SVG + rasterise, smoothed
    bool isBusy() const { return m_watcher.isRunning(); }
    // The most a frame may cost on the GUI thread: half a frame of the timeline's rate while
    // playing, one 60 Hz display refresh otherwise.
    double renderBudgetMs() const;

    // Simulates a slower machine: every frame's work takes this many milliseconds more
    // (for tests and benchmarks of the dropping path).
    void setExtraRenderCost(int ms) { m_extraCostMs = ms; }

    // Draws `pose` of `face` showing `frame` (photo pixels) fitted (aspect kept) on `background`
    // (transparent: nothing) in an image of `size`; *svg receives the SVG drawn when not null.
    // Runs on any thread.
    static QImage renderPose(const SvgFace &face, const QRectF &frame, QSize size, const Pose &pose,
        QByteArray *svg = nullptr, QColor background = Qt::white);

    // Draws one picture from a scene; runs on any thread.
    static Frame render(const std::shared_ptr<const SvgFace> &face,
        const std::shared_ptr<const TimelineEvaluator> &evaluator, const QRectF &frame, QSize size, double time,
        quint64 scene, int extraCostMs = 0, bool transparent = false);

Q_SIGNALS:
    // current() changed.
    void frameReady();
    // frame() or the scene's face changed (so overlays move).
    void sceneChanged();

private:
    void onDocumentChanged(ChangeFlags what);
    void onPlayheadMoved();
    void schedule();
    void update();
    void rebuildScene();
    void show(Frame frame, double ms, bool background);
    void startJob();
    void onJobFinished();

    Document *m_document;
    QPointer<Playhead> m_playhead;
    QSize m_imageSize {512, 512};
    bool m_transparent = false;

    std::shared_ptr<const SvgFace> m_face;
    std::shared_ptr<const TimelineEvaluator> m_evaluator;
    QRectF m_frame;
    quint64 m_sceneSerial = 0;
    bool m_faceStale = true;
    bool m_evaluatorStale = true;
    bool m_frameStale = true;

    Frame m_current;
    bool m_pictureStale = true; // current() does not show the time, scene and size now asked for
    bool m_scheduled = false;

    QFutureWatcher<Frame> m_watcher;
    QElapsedTimer m_jobClock;
    double m_jobTime = 0;
    quint64 m_jobScene = 0;
    QSize m_jobSize;
    int m_requestsSinceJob = 0;

    int m_rebuilds = 0;
    int m_rendered = 0;
    int m_backgroundRendered = 0;
    int m_dropped = 0;
    double m_averageMs = 0;
    int m_extraCostMs = 0;
};

} // namespace toonface
