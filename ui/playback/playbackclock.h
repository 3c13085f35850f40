#pragma once

#include <QtGlobal>

namespace toonface {

// The time base of playback: animation seconds as a function of a monotonic wall clock
// (nanoseconds, e.g. QElapsedTimer::nsecsElapsed()), optionally locked to the audio clock.
//
// Between observations the clock runs on the wall clock. Each observation of the sound's
// position (syncToAudio(), once per frame while the sound plays) pulls the clock toward the
// audio clock: an error larger than kResyncThreshold (a seek, a stall, the sound starting late)
// is taken at once; a smaller one is corrected by a fraction kSlewGain per observation, which
// averages out the coarse steps audio back ends report positions in, so the picture neither
// jitters nor drifts: a steady rate difference r between the two clocks leaves an error of
// about r * (observation interval) / kSlewGain (0.1 % at 30 fps: 0.3 ms), however long it plays.
//
// A plain value type with no Qt event machinery, so it is tested with simulated clocks.
class PlaybackClock
{
public:
    // Errors above this (seconds) re-anchor at once instead of slewing.
    static constexpr double kResyncThreshold = 0.030;
    // The fraction of a smaller error corrected per observation.
    static constexpr double kSlewGain = 0.1;

    // Runs from now: at wall time `wallNs` the animation is at `time` seconds.
    void start(double time, qint64 wallNs);
    // Animation seconds at wall time `wallNs` (>= the start's wall time).
    double time(qint64 wallNs) const;
    // Observes the audio clock: at wall time `wallNs` the sound plays animation time `audioTime`.
    // Returns true when the error was large enough to re-anchor (the picture jumps).
    bool syncToAudio(double audioTime, qint64 wallNs);

    // The last error seen by syncToAudio() (audio minus clock, seconds, before correcting).
    double lastError() const { return m_lastError; }

private:
    double m_anchorTime = 0;
    qint64 m_anchorWallNs = 0;
    double m_lastError = 0;
};

} // namespace toonface
