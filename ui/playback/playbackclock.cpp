#include "playback/playbackclock.h"

#include <cmath>

namespace toonface {

void PlaybackClock::start(double time, qint64 wallNs)
{
    m_anchorTime = time;
    m_anchorWallNs = wallNs;
    m_lastError = 0;
}

double PlaybackClock::time(qint64 wallNs) const
{
    return m_anchorTime + double(wallNs - m_anchorWallNs) * 1e-9;
}

bool PlaybackClock::syncToAudio(double audioTime, qint64 wallNs)
{
    const double now = time(wallNs);
    m_lastError = audioTime - now;
    if (std::abs(m_lastError) > kResyncThreshold) {
        start(audioTime, wallNs);
        m_lastError = audioTime - now;
        return true;
    }
    // Re-anchoring at `wallNs` keeps the correction exact however long since the last anchor.
    m_anchorTime = now + m_lastError * kSlewGain;
    m_anchorWallNs = wallNs;
    return false;
}

} // namespace toonface
