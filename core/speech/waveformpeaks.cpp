#include "speech/waveformpeaks.h"

#include "i18n/coretext.h"

#include <algorithm>
#include <cmath>

namespace toonface {

namespace {

// Levels stop once the whole sound fits in about this many bins.
constexpr qsizetype kCoarsestBins = 256;

WaveformPeaks::Level baseLevel(const QVector<float> &samples, const std::atomic_bool *cancel)
{
    WaveformPeaks::Level level;
    level.samplesPerBin = WaveformPeaks::kBaseBin;
    const qsizetype n = samples.size();
    const qsizetype bins = (n + WaveformPeaks::kBaseBin - 1) / WaveformPeaks::kBaseBin;
    level.min.resize(bins);
    level.max.resize(bins);
    const float *s = samples.constData();
    for (qsizetype b = 0; b < bins; ++b) {
        if ((b & 0xffff) == 0 && isCancelled(cancel))
            return {};
        const qsizetype from = b * WaveformPeaks::kBaseBin;
        const qsizetype to = std::min(n, from + WaveformPeaks::kBaseBin);
        float lo = s[from], hi = s[from];
        for (qsizetype i = from + 1; i < to; ++i) {
            lo = std::min(lo, s[i]);
            hi = std::max(hi, s[i]);
        }
        level.min[b] = lo;
        level.max[b] = hi;
    }
    return level;
}

WaveformPeaks::Level mergedLevel(const WaveformPeaks::Level &finer)
{
    WaveformPeaks::Level level;
    level.samplesPerBin = finer.samplesPerBin * WaveformPeaks::kLevelFactor;
    const qsizetype n = finer.min.size();
    const qsizetype bins = (n + WaveformPeaks::kLevelFactor - 1) / WaveformPeaks::kLevelFactor;
    level.min.resize(bins);
    level.max.resize(bins);
    for (qsizetype b = 0; b < bins; ++b) {
        const qsizetype from = b * WaveformPeaks::kLevelFactor;
        const qsizetype to = std::min(n, from + WaveformPeaks::kLevelFactor);
        level.min[b] = *std::min_element(finer.min.constData() + from, finer.min.constData() + to);
        level.max[b] = *std::max_element(finer.max.constData() + from, finer.max.constData() + to);
    }
    return level;
}

} // namespace

WaveformPeaks WaveformPeaks::compute(const Audio &audio, const std::atomic_bool *cancel)
{
    WaveformPeaks peaks;
    if (audio.isEmpty() || audio.sampleRate <= 0)
        return peaks;
    Level level = baseLevel(audio.samples, cancel);
    if (level.min.isEmpty())
        return peaks;
    peaks.m_sampleRate = audio.sampleRate;
    peaks.m_sampleCount = audio.samples.size();
    peaks.m_levels.append(std::move(level));
    while (peaks.m_levels.last().min.size() > kCoarsestBins) {
        if (isCancelled(cancel))
            return {};
        peaks.m_levels.append(mergedLevel(peaks.m_levels.last()));
    }
    return peaks;
}

int WaveformPeaks::levelFor(double samplesPerPixel) const
{
    int best = 0;
    for (int i = 0; i < m_levels.size(); ++i)
        if (m_levels[i].samplesPerBin <= samplesPerPixel)
            best = i;
    return best;
}

std::pair<float, float> WaveformPeaks::range(double t0, double t1) const
{
    if (m_levels.isEmpty() || t1 < 0)
        return {0.f, 0.f};
    const double s0 = std::max(0.0, t0 * m_sampleRate);
    const double s1 = std::min(double(m_sampleCount), t1 * m_sampleRate);
    if (s0 >= double(m_sampleCount) || s1 < s0)
        return {0.f, 0.f};
    const Level &level = m_levels[levelFor(s1 - s0)];
    const qsizetype last = level.min.size() - 1;
    const qsizetype from = std::min(last, qsizetype(s0) / level.samplesPerBin);
    // A span inside one bin still reads that bin: [from, to] inclusive.
    const qsizetype to = std::clamp(qsizetype(std::ceil(s1)) / level.samplesPerBin, from, last);
    float lo = level.min[from], hi = level.max[from];
    for (qsizetype b = from + 1; b <= to; ++b) {
        lo = std::min(lo, level.min[b]);
        hi = std::max(hi, level.max[b]);
    }
    return {lo, hi};
}

WaveformPeaksResult loadWaveformPeaks(
    const QString &path, const SpeechProgressFn &progress, const std::atomic_bool *cancel)
{
    WaveformPeaksResult result;
    AudioResult decoded = loadAudio(path, progress, cancel);
    result.status = decoded.status;
    result.error = decoded.error;
    if (!decoded.ok())
        return result;
    result.peaks = WaveformPeaks::compute(decoded.audio, cancel);
    if (result.peaks.isEmpty() && isCancelled(cancel)) {
        result.status = AudioStatus::Cancelled;
        result.error = withProblem(path, SoundText::tr("cancelled"));
        return result;
    }
    return result;
}

} // namespace toonface
