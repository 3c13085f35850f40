#pragma once

#include "track/framesource.h"

#include <QElapsedTimer>
#include <QImage>

#include <condition_variable>
#include <memory>
#include <mutex>

class QVideoFrame;
class QVideoSink;

namespace toonface {

// A camera as a FrameSource: a QVideoSink (or a test) feeds frames from its own thread, the
// tracker's thread reads them with next(). Latest frame wins: a frame not yet read when the
// next one arrives is replaced (counted in replacedFrames()), never queued, so the reader is
// at most one frame behind the camera.
//
// Thread safety: push()/feed() from one feeding thread, next() from one reading thread,
// stop() and the counters from any; one lock between them.
class CameraFrameSource : public FrameSource
{
public:
    explicit CameraFrameSource(double nominalRate = 30.0);
    ~CameraFrameSource() override;

    // Feeds every frame `sink` shows from now on (a direct connection: the sink's thread).
    // The source must outlive the connection: detach() or destroy the sink first.
    void attach(QVideoSink *sink);
    void detach();

    // One frame from the camera: mapped and converted to RGB32 (QVideoFrame::toImage(), Qt 6.0);
    // an invalid or unreadable frame is skipped (false).
    bool push(const QVideoFrame &frame);
    // One picture, `time` seconds from the first (negative: the arrival time).
    void push(QImage image, double time = -1);

    std::optional<VideoFrame> next() override;
    double frameRate() const override { return m_rate; }
    QSize frameSize() const override;
    QString error() const override;
    void stop() override;

    // The camera failed or went away: next() returns nullopt and error() says `message`.
    void fail(const QString &message);

    // Seconds since the source was made, on the clock push() stamps arrivals with.
    double now() const;
    // When the frame next() returned last arrived (now() seconds); -1 before any.
    double lastArrival() const;
    int pushedFrames() const;
    int replacedFrames() const;

private:
    double m_rate;
    QElapsedTimer m_clock;
    mutable std::mutex m_lock;
    std::condition_variable m_arrived;
    std::optional<VideoFrame> m_pending;
    double m_pendingArrival = -1;
    double m_lastArrival = -1;
    QSize m_size;
    QString m_error;
    bool m_stopped = false;
    int m_pushed = 0;
    int m_replaced = 0;
    struct Connection;
    std::unique_ptr<Connection> m_connection;
};

} // namespace toonface
