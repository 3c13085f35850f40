#include "speech/localnorm.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace toonface {

namespace {

constexpr int kBlock = 25; // frames (0.25 s)
// Blocks either side: levels over ±1.5 s (about a phrase: a window across the boundary of a
// quiet and a loud stretch measures the quiet one's end against the loud one), the spectral
// moments, which need more frames to settle, over ±2.5 s.
constexpr int kReach = 6;
constexpr int kMomentReach = 10;

// A frame's value between those of the centres of the two nearest blocks, linearly.
struct BlockBlend
{
    int b0, b1;
    float f;
};
BlockBlend blockBlend(int t, int blocks)
{
    const double x = (t + 0.5) / kBlock - 0.5;
    const int b0 = std::clamp(int(std::floor(x)), 0, blocks - 1);
    return {b0, std::min(b0 + 1, blocks - 1), float(std::clamp(x - b0, 0.0, 1.0))};
}

} // namespace

// Per frame, how far (ln units) the level of the speech around it lies under the recording's
// loud frames: the 95th percentile of the log energy within ±1.5 s against that of the whole
// recording, less the 5 dB by which a speaker's level wanders anyway. A recording joined from several sources, or a
// speaker who moves off the microphone, holds speech at levels 20 dB apart; measured against the whole recording, the
// quiet part's vowels look like consonants and its consonants like pauses. Windows without
// speech (less than 12 dB between their quiet and loud frames, or loud frames more than 30 dB
// under the recording's) take the level of the nearest window with speech.
std::vector<float> levelOffsets(const std::vector<float> &logEnergy)
{
    constexpr float kContrast = 2.8f, kQuietest = 6.9f; // ln units: 12 dB, 30 dB
    constexpr float kNatural = 1.15f; // ln units: 5 dB
    const int frames = int(logEnergy.size());
    const int blocks = (frames + kBlock - 1) / kBlock;
    if (blocks == 0)
        return {};
    const float overall = [&] {
        std::vector<float> v = logEnergy;
        const size_t k = size_t(0.95 * double(v.size() - 1));
        std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
        return v[k];
    }();
    std::vector<float> level(size_t(blocks), 0.0f);
    std::vector<bool> valid(size_t(blocks), false);
    std::vector<float> window;
    for (int b = 0; b < blocks; ++b) {
        const int from = std::max(0, (b - kReach) * kBlock), to = std::min(frames, (b + kReach + 1) * kBlock);
        window.assign(logEnergy.begin() + from, logEnergy.begin() + to);
        const size_t hi = size_t(0.95 * double(window.size() - 1)), lo = size_t(0.05 * double(window.size() - 1));
        std::nth_element(window.begin(), window.begin() + std::ptrdiff_t(hi), window.end());
        const float loud = window[hi];
        std::nth_element(window.begin(), window.begin() + std::ptrdiff_t(lo), window.begin() + std::ptrdiff_t(hi));
        const float quiet = window[lo];
        level[size_t(b)] = loud;
        valid[size_t(b)] = loud - quiet >= kContrast && loud >= overall - kQuietest;
    }
    // Blocks without speech: the nearest block with speech's level (the whole recording's
    // when there is none).
    std::vector<int> before(size_t(blocks), -1), after(size_t(blocks), -1);
    for (int b = 0, last = -1; b < blocks; ++b)
        before[size_t(b)] = last = valid[size_t(b)] ? b : last;
    for (int b = blocks - 1, next = -1; b >= 0; --b)
        after[size_t(b)] = next = valid[size_t(b)] ? b : next;
    std::vector<float> filled(size_t(blocks), overall);
    for (int b = 0; b < blocks; ++b) {
        const int p = before[size_t(b)], q = after[size_t(b)];
        if (p >= 0 && (q < 0 || b - p <= q - b))
            filled[size_t(b)] = level[size_t(p)];
        else if (q >= 0)
            filled[size_t(b)] = level[size_t(q)];
    }
    std::vector<float> offsets(static_cast<size_t>(frames));
    for (int t = 0; t < frames; ++t) {
        const BlockBlend m = blockBlend(t, blocks);
        const float offset = overall - ((1 - m.f) * filled[size_t(m.b0)] + m.f * filled[size_t(m.b1)]);
        // A speaker's level wanders by a few dB from phrase to phrase, which the recording's
        // normalisation handles: only what lies beyond that is made up.
        offsets[size_t(t)] = offset > 0 ? std::max(offset - kNatural, 0.0f) : std::min(offset + kNatural, 0.0f);
    }
    return offsets;
}

LocalMoments::LocalMoments(
    const float *values, int frames, int channels, const std::vector<float> &weight, double priorFrames)
    : m_frames(frames)
    , m_channels(channels)
    , m_blocks((frames + kBlock - 1) / kBlock)
{
    if (frames <= 0 || channels <= 0)
        return;
    const size_t C = size_t(channels);
    // Sums per block: weight, weighted values and squares.
    std::vector<double> w0(size_t(m_blocks), 0.0), w1(size_t(m_blocks) * C, 0.0), w2(size_t(m_blocks) * C, 0.0);
    for (int t = 0; t < frames; ++t) {
        const size_t b = size_t(t / kBlock);
        const double w = weight[size_t(t)];
        w0[b] += w;
        for (size_t c = 0; c < C; ++c) {
            const double x = values[size_t(t) * C + c];
            w1[b * C + c] += w * x;
            w2[b * C + c] += w * x * x;
        }
    }
    // The whole recording's moments, which the windows are drawn toward.
    double g0 = 0;
    std::vector<double> g1(C, 0.0), g2(C, 0.0);
    for (int b = 0; b < m_blocks; ++b) {
        g0 += w0[size_t(b)];
        for (size_t c = 0; c < C; ++c) {
            g1[c] += w1[size_t(b) * C + c];
            g2[c] += w2[size_t(b) * C + c];
        }
    }
    m_mean.assign(size_t(m_blocks) * C, 0.0f);
    m_inv.assign(size_t(m_blocks) * C, 1.0f);
    if (g0 < 1e-9)
        return;
    std::vector<double> s1(C), s2(C);
    for (int b = 0; b < m_blocks; ++b) {
        double s0 = 0;
        std::fill(s1.begin(), s1.end(), 0.0);
        std::fill(s2.begin(), s2.end(), 0.0);
        for (int u = std::max(0, b - kMomentReach); u <= std::min(m_blocks - 1, b + kMomentReach); ++u) {
            s0 += w0[size_t(u)];
            for (size_t c = 0; c < C; ++c) {
                s1[c] += w1[size_t(u) * C + c];
                s2[c] += w2[size_t(u) * C + c];
            }
        }
        const double k = priorFrames / g0;
        for (size_t c = 0; c < C; ++c) {
            const double n = s0 + priorFrames;
            const double mean = (s1[c] + k * g1[c]) / n;
            const double square = (s2[c] + k * g2[c]) / n;
            m_mean[size_t(b) * C + c] = float(mean);
            m_inv[size_t(b) * C + c] = float(1.0 / std::sqrt(std::max(square - mean * mean, 0.0) + 1e-6));
        }
    }
}

float LocalMoments::normalised(int t, int c, float x) const
{
    if (m_blocks == 0)
        return x;
    const BlockBlend m = blockBlend(std::clamp(t, 0, m_frames - 1), m_blocks);
    const size_t i0 = size_t(m.b0) * size_t(m_channels) + size_t(c), i1 = size_t(m.b1) * size_t(m_channels) + size_t(c);
    const float mean = (1 - m.f) * m_mean[i0] + m.f * m_mean[i1];
    const float inv = (1 - m.f) * m_inv[i0] + m.f * m_inv[i1];
    return (x - mean) * inv;
}

} // namespace toonface
