#pragma once

#include "speech/audio.h"

#include <vector>

namespace toonface {

// Frame-level acoustic features of speech at kSpeechSampleRate: 25 ms Hamming windows every
// 10 ms. Used by the aligner; independent of the speaker's level (everything is normalised
// per recording).
struct SpeechFeatures
{
    static constexpr double kHop = 0.010; // seconds between frames
    static constexpr int kCepstra = 12; // c1..c12
    // The vector DTW compares: normalised c1..c12, their deltas, energy and voicing.
    static constexpr int kDim = 2 * kCepstra + 6;

    int frames = 0;
    std::vector<float> vectors; // frames × kDim
    std::vector<float> logEnergy; // natural log of the frame's power
    std::vector<float> loudness; // log power in 300–3000 Hz, smoothed over ±20 ms
    std::vector<float> band; // the same log power unsmoothed (sharp steps for boundaries)
    std::vector<float> loudnessNorm; // loudness between its 5th (0) and 95th (1) percentile, clamped
    std::vector<float> voicing; // 0..1: peak of the normalised autocorrelation at 70–400 Hz
    std::vector<float> silence; // 0..1: how surely the frame is silence (or noise)
    float noiseFloor = 0; // log energy of the quiet frames
    float speechLevel = 0; // log energy of the loud frames

    const float *vector(int frame) const { return vectors.data() + size_t(frame) * kDim; }
    double time(int frame) const { return frame * kHop + 0.0125; } // window centre
    int frameAt(double seconds) const; // nearest frame, clamped
    double speechDuration() const; // seconds of frames more likely speech than silence
};

// How much each channel of the DTW vector weighs.
struct FeatureWeights
{
    // The broad channels that speakers (and a synthesizer) share weigh most; the finer
    // cepstra, which describe the speaker as much as the sound, weigh nothing.
    float cepstra = 0.5f; // c1..c(broadCepstra)
    float fineCepstra = 0.0f; // the rest
    float delta = 0.5f;
    float loudness = 2.0f;
    float loudnessDelta = 2.0f;
    float voicing = 1.0f;
    float high = 1.0f;
    float low = 1.0f;
    int broadCepstra = 4;
};
const FeatureWeights &featureWeights();

// requires: audio at kSpeechSampleRate (use resampled() first).
SpeechFeatures computeSpeechFeatures(const Audio &audio, const std::atomic_bool *cancel = nullptr);

// The same features computed as the samples come (at kSpeechSampleRate), a block of frames at
// a time: only the frames' raw measures are kept, never the audio. push() as often as
// needed, then finish() once; the result equals computeSpeechFeatures of all the samples.
class SpeechFeatureStream
{
public:
    explicit SpeechFeatureStream(const std::atomic_bool *cancel = nullptr);
    void push(const float *samples, qsizetype count);
    SpeechFeatures finish(); // empty when cancelled
    qint64 samples() const { return m_samples; } // pushed so far
    // Computes the frames two blocks at a time, one of them on a second thread (the same
    // features): for a recording decoded while the second core has little else to do.
    void useSecondCore() { m_twoCores = true; }

private:
    // Per frame: c1..c12, log energy, mid band, high and low shares, voicing.
    struct Rows
    {
        std::vector<float> cep, logEnergy, band, hf, lf, voicing;
        void clear();
        void append(const Rows &more);
    };
    // Frames `count` windows from `samples` on into `out`.
    static void frameBlock(const float *samples, int count, Rows &out);
    const std::atomic_bool *m_cancel;
    qint64 m_samples = 0;
    bool m_twoCores = false;
    std::vector<float> m_pending; // samples from the next frame's start on
    Rows m_rows;
    Rows m_first, m_second; // two blocks computed at once
};

} // namespace toonface
