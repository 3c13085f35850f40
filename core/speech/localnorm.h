#pragma once

#include <vector>

namespace toonface {

// Normalisation of a recording's frame measures against the speech around each frame (a few
// seconds) rather than the whole recording: recordings joined from several sources, or a speaker who
// moves off the microphone or changes the room, hold speech whose level and spectrum differ
// from one stretch to the next.

// Per frame, what to add to a log level (ln units) to bring the speech around it to the
// recording's overall level (see localnorm.cpp).
std::vector<float> levelOffsets(const std::vector<float> &logEnergy);

// The weighted mean and standard deviation of each channel of `values` (frames × channels)
// over the frames within ±2.5 s, `weight` per frame (how surely it is speech). The window's
// moments are drawn toward the whole recording's as if it held `priorFrames` more frames
// of them: a window with little speech keeps the recording's.
class LocalMoments
{
public:
    LocalMoments(const float *values, int frames, int channels, const std::vector<float> &weight, double priorFrames);
    // (x - mean) / sd of channel c around frame t.
    float normalised(int t, int c, float x) const;

private:
    int m_frames, m_channels, m_blocks;
    std::vector<float> m_mean, m_inv; // per block × channel
};

} // namespace toonface
