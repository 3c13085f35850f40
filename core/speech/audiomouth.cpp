#include "speech/audiomouth.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace toonface {

namespace {

constexpr double kSilentDb = -120.0;

// The weight of the newest value in a one-pole smoother of time constant `tauS` stepped by `stepS`.
double alpha(double stepS, double tauS)
{
    return tauS > 0 ? 1.0 - std::exp(-stepS / tauS) : 1.0;
}

enum class Colour { Dark, Mid, Bright };

MouthShape shapeFor(Colour colour, bool large)
{
    switch (colour) {
    case Colour::Dark: return large ? MouthShape::O : MouthShape::U;
    case Colour::Mid: return large ? MouthShape::A : MouthShape::E;
    case Colour::Bright: return large ? MouthShape::E : MouthShape::I;
    }
    return MouthShape::M;
}

bool isLarge(MouthShape shape)
{
    return shape == MouthShape::O || shape == MouthShape::A;
}

} // namespace

AudioMouth::AudioMouth(int sampleRate, AudioMouthOptions options)
    : m_rate(std::max(1, sampleRate))
    , m_options(options)
    , m_hop(std::max(1, int(std::lround(options.hopMs / 1000.0 * m_rate))))
{
    // A Butterworth high-pass (the audio EQ cookbook's biquad, Q = 1/sqrt(2)).
    if (options.highPassHz > 0 && options.highPassHz < m_rate / 2.0) {
        const double w = 2 * std::numbers::pi * options.highPassHz / m_rate;
        const double a = std::sin(w) / std::sqrt(2.0);
        const double c = std::cos(w);
        const double a0 = 1 + a;
        m_b0 = (1 + c) / 2 / a0;
        m_b1 = -(1 + c) / a0;
        m_b2 = (1 + c) / 2 / a0;
        m_a1 = -2 * c / a0;
        m_a2 = (1 - a) / a0;
    }
}

void AudioMouth::reset()
{
    *this = AudioMouth(m_rate, m_options);
}

QVector<AudioMouthFrame> AudioMouth::push(const float *samples, qsizetype count)
{
    QVector<AudioMouthFrame> out;
    for (qsizetype i = 0; i < count; ++i) {
        const double in = samples[i];
        const double x = m_b0 * in + m_b1 * m_x1 + m_b2 * m_x2 - m_a1 * m_y1 - m_a2 * m_y2;
        m_x2 = m_x1;
        m_x1 = in;
        m_y2 = m_y1;
        m_y1 = x;
        const double d = x - m_previous;
        m_previous = float(x);
        m_sumSquares += x * x;
        m_sumDiffSquares += d * d;
        if (++m_filled == m_hop) {
            out.append(analyse(m_sumSquares, m_sumDiffSquares, m_filled));
            m_sumSquares = m_sumDiffSquares = 0;
            m_filled = 0;
        }
    }
    return out;
}

AudioMouthFrame AudioMouth::analyse(double sumSquares, double sumDiffSquares, int count)
{
    const AudioMouthOptions &o = m_options;
    const double step = double(count) / m_rate;
    AudioMouthFrame f;
    ++m_hops;
    f.time = double(m_hops) * m_hop / m_rate;
    const double meanSquare = sumSquares / std::max(1, count);
    f.levelDb = meanSquare > 1e-12 ? 10.0 * std::log10(meanSquare) : kSilentDb;
    // A sine of frequency F has E[diff²] / E[x²] = 4 sin²(πF / rate): the ratio gives the
    // spectrum's RMS frequency.
    if (sumSquares > 1e-12) {
        const double s = std::min(1.0, std::sqrt(sumDiffSquares / sumSquares) / 2.0);
        f.brightnessHz = m_rate / std::numbers::pi * std::asin(s);
    }

    // The floor: the quietest averaged level of the window.
    m_recentPower.append(meanSquare);
    const int averaged = std::max(1, int(std::lround(o.levelAverageMs / 1000.0 / step)));
    while (m_recentPower.size() > averaged)
        m_recentPower.removeFirst();
    double power = 0;
    for (double p : std::as_const(m_recentPower))
        power += p;
    power /= double(m_recentPower.size());
    // Until a whole average is in, the hop's level stands in (and leaves when the first comes).
    const bool whole = m_recentPower.size() == averaged;
    if (whole && !m_haveAverage) {
        m_averages.clear();
        m_haveAverage = true;
    }
    m_averages.append(whole ? (power > 1e-12 ? 10.0 * std::log10(power) : kSilentDb) : f.levelDb);
    const int window = std::max(1, int(std::lround(o.floorWindowS / step)));
    while (m_averages.size() > window)
        m_averages.removeFirst();
    const double quietest = *std::min_element(m_averages.cbegin(), m_averages.cend());
    if (!m_started || quietest < m_floorDb)
        m_floorDb = quietest;
    else
        m_floorDb = std::min(quietest, m_floorDb + o.floorRiseDbPerS * step);
    if (!m_started) {
        m_started = true;
        m_peakDb = std::max(f.levelDb, o.initialPeakDb);
    }
    // The peak rises at once and decays toward the floor.
    if (f.levelDb > m_peakDb)
        m_peakDb = f.levelDb;
    else
        m_peakDb = std::max(m_floorDb, m_peakDb - o.peakDecayDbPerS * step);
    f.floorDb = m_floorDb;

    // Openness is the hop's amplitude between the opening level's and the peak's: a voice
    // opens the mouth in proportion to its loudness (the speech envelope), not to its decibels.
    const double opensAt = m_floorDb + o.openAboveFloorDb;
    const double top = std::max(m_peakDb, opensAt + o.minimumRangeDb);
    double raw = 0;
    if (f.levelDb >= o.absoluteGateDb && f.levelDb > opensAt) {
        const double a = std::pow(10.0, f.levelDb / 20.0);
        const double a0 = std::pow(10.0, opensAt / 20.0);
        const double a1 = std::pow(10.0, top / 20.0);
        raw = std::clamp((a - a0) / (a1 - a0), 0.0, 1.0);
    }
    m_openness += (raw - m_openness) * alpha(step, raw > m_openness ? o.attackMs / 1000.0 : o.releaseMs / 1000.0);
    f.openness = m_openness;

    if (raw >= o.vowelFrom && f.brightnessHz > 0 && f.brightnessHz < o.vowelBrightnessBelowHz) {
        const double logB = std::log(f.brightnessHz);
        if (m_averageBrightness <= 0)
            m_averageBrightness = f.brightnessHz;
        else
            m_averageBrightness = std::exp(std::log(m_averageBrightness)
                + (logB - std::log(m_averageBrightness)) * alpha(step, o.brightnessAverageS));
    }

    MouthShape wanted = MouthShape::M;
    if (m_openness >= o.closedBelow) {
        Colour colour = Colour::Mid;
        if (m_averageBrightness > 0 && f.brightnessHz > 0) {
            if (f.brightnessHz < o.darkBelow * m_averageBrightness)
                colour = Colour::Dark;
            else if (f.brightnessHz > o.brightAbove * m_averageBrightness)
                colour = Colour::Bright;
        }
        wanted = shapeFor(colour, m_openness >= o.largeFrom);
    }
    // Shutting and opening follow at once (the smoothing already eased them); a change between
    // two open shapes waits until the new one has won holdHops hops.
    MouthShape shape = m_current.shape;
    if (wanted == MouthShape::M || shape == MouthShape::M) {
        shape = wanted;
        m_candidateHops = 0;
    } else if (wanted != shape) {
        m_candidateHops = wanted == m_candidate ? m_candidateHops + 1 : 1;
        m_candidate = wanted;
        if (m_candidateHops >= o.holdHops) {
            shape = wanted;
            m_candidateHops = 0;
        }
    } else {
        m_candidateHops = 0;
    }
    f.shape = shape;
    if (shape == MouthShape::M)
        f.weight = 1.0;
    else
        f.weight = std::clamp(m_openness / (isLarge(shape) ? 1.0 : o.largeFrom), 0.0, 1.0);
    m_current = f;
    return f;
}

QVector<AudioMouthFrame> audioMouthTrack(const Audio &audio, const AudioMouthOptions &options)
{
    AudioMouth mouth(audio.sampleRate, options);
    return mouth.push(audio.samples);
}

QVector<MouthKey> audioMouthKeys(const QVector<AudioMouthFrame> &frames, double offset)
{
    QVector<MouthKey> keys;
    double previousEnd = 0;
    for (const AudioMouthFrame &f : frames) {
        const double start = previousEnd;
        previousEnd = f.time;
        if (keys.isEmpty() || keys.last().shape != f.shape) {
            keys.append({offset + start, f.shape, f.shape == MouthShape::M ? 1.0 : f.weight, 0.0});
        } else if (f.shape != MouthShape::M) {
            keys.last().weight = std::max(keys.last().weight, f.weight);
        }
        keys.last().duration = offset + f.time - keys.last().time;
    }
    return keys;
}

} // namespace toonface
