#include "track/clipsilence.h"

#include <algorithm>
#include <cmath>

namespace toonface {

QVector<double> frameLevelsDb(
    const QVector<TrackedFrame> &frames, const QVector<float> &samples, int sampleRate, double period)
{
    QVector<double> levels;
    levels.reserve(frames.size());
    for (const TrackedFrame &f : frames) {
        const auto from = std::clamp<qsizetype>(qsizetype(f.time * sampleRate), 0, samples.size());
        const auto to = std::clamp<qsizetype>(qsizetype((f.time + period) * sampleRate), from, samples.size());
        double sum = 0;
        for (qsizetype i = from; i < to; ++i)
            sum += double(samples[i]) * samples[i];
        const double rms = to > from ? std::sqrt(sum / double(to - from)) : 0.0;
        levels.append(rms > 1e-6 ? 20.0 * std::log10(rms) : -120.0);
    }
    return levels;
}

QVector<bool> silentFrames(
    const QVector<TrackedFrame> &frames, const QVector<float> &samples, int sampleRate, double period, double share)
{
    const qsizetype n = frames.size();
    QVector<bool> silent(n, false);
    if (samples.isEmpty() || n == 0 || period <= 0)
        return silent;
    const QVector<double> levels = frameLevelsDb(frames, samples, sampleRate, period);
    QVector<double> sorted = levels;
    std::sort(sorted.begin(), sorted.end());
    const auto at
        = [&](double p) { return sorted[std::clamp<qsizetype>(qsizetype(std::ceil(p * double(n))) - 1, 0, n - 1)]; };
    const double loud = at(kLoudPercentile);
    const double room = at(kRoomPercentile);
    if (loud - room < kMinVoiceRangeDb && loud >= kSilenceGateDb)
        return silent;
    const double threshold = std::max(room + share * (loud - room), kSilenceGateDb);

    // The voice, widened by the lips' lead before it and their closing after it.
    const int lead = int(std::lround(kLipLeadS / period));
    const int close = int(std::lround(kLipCloseS / period));
    QVector<bool> moving(n, false);
    for (qsizetype i = 0; i < n; ++i) {
        if (levels[i] < threshold)
            continue;
        for (qsizetype j = std::max<qsizetype>(0, i - lead); j <= std::min<qsizetype>(n - 1, i + close); ++j)
            moving[j] = true;
    }
    // Runs of silence long enough to be a pause.
    const int shortest = std::max(1, int(std::lround(kMinSilenceS / period)));
    for (qsizetype i = 0; i < n;) {
        qsizetype end = i;
        while (end < n && !moving[end])
            ++end;
        if (end - i >= shortest)
            std::fill(silent.begin() + i, silent.begin() + end, true);
        i = std::max(end, i) + 1;
    }
    return silent;
}

} // namespace toonface
