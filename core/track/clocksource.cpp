#include "track/clocksource.h"

#include <algorithm>
#include <cmath>

namespace toonface {

ClockSource::ClockSource(double fps)
    : m_fps(fps > 0 ? fps : 30.0)
{ }

std::optional<VideoFrame> ClockSource::next()
{
    using namespace std::chrono;
    std::unique_lock lock(m_lock);
    if (m_stopped)
        return std::nullopt;
    const auto now = steady_clock::now();
    if (!m_started) {
        m_started = true;
        m_start = now;
    }
    // A reader that fell behind skips to the frame due now.
    const double elapsed = duration<double>(now - m_start).count();
    m_next = std::max(m_next, int(std::floor(elapsed * m_fps)));
    const auto due = m_start + duration_cast<steady_clock::duration>(duration<double>(m_next / m_fps));
    if (m_wake.wait_until(lock, due, [this] { return m_stopped; }))
        return std::nullopt;
    VideoFrame frame;
    frame.time = m_next / m_fps;
    frame.index = m_next++;
    return frame;
}

void ClockSource::stop()
{
    {
        std::lock_guard lock(m_lock);
        m_stopped = true;
    }
    m_wake.notify_all();
}

} // namespace toonface
