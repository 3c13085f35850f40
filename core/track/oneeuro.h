#pragma once

#include <cmath>
#include <numbers>

namespace toonface {

// The one-euro filter (Casiez, Roussel and Vogel, CHI 2012): a low-pass filter whose cut-off
// rises with the signal's speed, so that a still signal is smoothed hard (no jitter) and a fast
// one passes with little lag. cutoff = minCutoff + beta * |speed| (Hz; speed in the signal's
// units per second, itself low-passed at derivativeCutoff).
struct OneEuroParams
{
    double minCutoff = 1.0;
    double beta = 0.0;
    double derivativeCutoff = 1.0;
};

class OneEuroFilter
{
public:
    OneEuroFilter() = default;
    explicit OneEuroFilter(OneEuroParams params)
        : m_params(params)
    { }

    // The filtered value of `x` sampled `dt` seconds after the previous sample (the first
    // sample passes unchanged).
    double filter(double x, double dt)
    {
        if (!m_started || !(dt > 0)) {
            m_started = true;
            m_x = x;
            m_dx = 0;
            return x;
        }
        const double dx = (x - m_x) / dt;
        m_dx += alpha(m_params.derivativeCutoff, dt) * (dx - m_dx);
        const double cutoff = m_params.minCutoff + m_params.beta * std::abs(m_dx);
        m_x += alpha(cutoff, dt) * (x - m_x);
        return m_x;
    }
    void reset() { m_started = false; }

private:
    static double alpha(double cutoff, double dt)
    {
        const double tau = 1.0 / (2.0 * std::numbers::pi * cutoff);
        return 1.0 / (1.0 + tau / dt);
    }

    OneEuroParams m_params;
    bool m_started = false;
    double m_x = 0;
    double m_dx = 0;
};

} // namespace toonface
