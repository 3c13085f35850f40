#include "playback/playhead.h"

#include <cmath>

namespace toonface {

Playhead::Playhead(QObject *parent)
    : QObject(parent)
{ }

int Playhead::frame(double fps) const
{
    return int(std::floor(m_time * fps + 1e-9));
}

void Playhead::setTime(double seconds)
{
    const double t = std::isfinite(seconds) ? std::max(0.0, seconds) : 0.0;
    if (t == m_time)
        return;
    m_time = t;
    Q_EMIT timeChanged(m_time);
}

void Playhead::setPlaying(bool playing)
{
    if (playing == m_playing)
        return;
    m_playing = playing;
    Q_EMIT playingChanged(m_playing);
}

void Playhead::setScrubbing(bool scrubbing)
{
    if (scrubbing == m_scrubbing)
        return;
    m_scrubbing = scrubbing;
    Q_EMIT scrubbingChanged(m_scrubbing);
}

} // namespace toonface
