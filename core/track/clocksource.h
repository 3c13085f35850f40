#pragma once

// Frames without a picture at a steady rate, in real time: the beat of live mode when the
// performer is only heard (the microphone drives the mouth and no camera looks), so that the
// cartoon is drawn and a take is recorded at a frame rate as with a camera.

#include "track/framesource.h"

#include <chrono>
#include <condition_variable>
#include <mutex>

namespace toonface {

class ClockSource : public FrameSource
{
public:
    explicit ClockSource(double fps = 30.0);

    // A frame with a null image every 1 / fps seconds from the first call; a late reader gets
    // the frame due now (the ones it missed are counted in the index, not delivered).
    std::optional<VideoFrame> next() override;
    double frameRate() const override { return m_fps; }
    QSize frameSize() const override { return {}; }
    void stop() override;

private:
    double m_fps;
    std::mutex m_lock;
    std::condition_variable m_wake;
    bool m_stopped = false;
    bool m_started = false;
    std::chrono::steady_clock::time_point m_start;
    int m_next = 0;
};

} // namespace toonface
