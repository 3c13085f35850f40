#pragma once

#include "speech/audio.h"

#include <QString>
#include <QVector>

#include <atomic>

namespace toonface {

// The sound's envelope for drawing a waveform at any zoom: the minimum and maximum sample of
// consecutive bins, at several bin widths (levels). Level 0 has kBaseBin samples a bin; each
// next level merges kLevelFactor bins of the one before, down to a few hundred bins for the
// whole sound. A plain value type; computed once per sound, then only read.
class WaveformPeaks
{
public:
    static constexpr int kBaseBin = 16; // samples per bin at level 0 (1 ms at 16 kHz)
    static constexpr int kLevelFactor = 4;

    struct Level
    {
        int samplesPerBin = 0;
        QVector<float> min;
        QVector<float> max;
        bool operator==(const Level &) const = default;
    };

    WaveformPeaks() = default;

    // The peaks of `audio`. Stops early and returns empty peaks when *cancel becomes true.
    static WaveformPeaks compute(const Audio &audio, const std::atomic_bool *cancel = nullptr);

    bool isEmpty() const { return m_levels.isEmpty(); }
    int sampleRate() const { return m_sampleRate; }
    qint64 sampleCount() const { return m_sampleCount; }
    double duration() const { return m_sampleRate > 0 ? double(m_sampleCount) / m_sampleRate : 0.0; }
    const QVector<Level> &levels() const { return m_levels; }

    // The coarsest level whose bins are no wider than `samplesPerPixel` (level 0 when all are).
    int levelFor(double samplesPerPixel) const;

    // The lowest and highest sample in [t0, t1) seconds of the sound, read from the coarsest
    // level that resolves a span that wide; {0, 0} outside the sound or when empty.
    // requires: t0 <= t1
    std::pair<float, float> range(double t0, double t1) const;

    bool operator==(const WaveformPeaks &) const = default;

private:
    int m_sampleRate = 0;
    qint64 m_sampleCount = 0;
    QVector<Level> m_levels;
};

struct WaveformPeaksResult
{
    AudioStatus status = AudioStatus::Unreadable;
    QString error; // names the file and the problem when status != Ok
    WaveformPeaks peaks;
    bool ok() const { return status == AudioStatus::Ok; }
};

// Decodes `path` (see loadAudio) and computes its peaks. Long work: progress 0..1 while
// decoding, cancel polled throughout. Thread-safe.
WaveformPeaksResult loadWaveformPeaks(
    const QString &path, const SpeechProgressFn &progress = {}, const std::atomic_bool *cancel = nullptr);

} // namespace toonface
