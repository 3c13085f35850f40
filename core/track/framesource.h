#pragma once

#include <QImage>
#include <QSize>
#include <QString>

#include <optional>

namespace toonface {

// One frame of a video or a camera: the picture (RGB32) and when it shows, in seconds from the
// source's first frame.
struct VideoFrame
{
    QImage image;
    double time = 0;
    int index = 0; // in the source's order, counting frames a paced source dropped
};

// Where frames come from: a video file (VideoFileSource), a camera (the editor's, fed by a
// QVideoSink), a test's drawings. The tracker and live mode read every source the same way.
//
// Thread safety: a source is used by one thread at a time (the thread that calls next()); a
// source fed from another thread (a camera) keeps its own lock between its feeder and next().
class FrameSource
{
public:
    virtual ~FrameSource() = default;

    // The next frame, waiting for it when the source is paced or live; nullopt at the end, on
    // an error (error() says which) or once stop() was called.
    virtual std::optional<VideoFrame> next() = 0;
    // Frames per second (nominal; 0 when unknown) and frame size.
    virtual double frameRate() const = 0;
    virtual QSize frameSize() const = 0;
    // The number of frames when known in advance, else -1.
    virtual int frameCount() const { return -1; }
    // Why next() returned nullopt before the end, or empty.
    virtual QString error() const { return {}; }
    // Makes a waiting or later next() return nullopt; may be called from any thread.
    virtual void stop() { }
};

} // namespace toonface
