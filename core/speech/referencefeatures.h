#pragma once

#include "speech/audio.h"
#include "speech/features.h"
#include "speech/script.h"
#include "speech/tts.h"

#include <vector>

namespace toonface {

// The synthetic reference as the aligner hears it: at kSpeechSampleRate, with
// kReferencePad of silence either side and a faint noise over all of it (a room's, so that
// silence before and after the speech in a recording has something to match). Its features
// are computed as the rendering's samples come: the rendering itself is never held.

inline constexpr double kReferencePad = 0.3; // seconds of silence added before and after the reference

class ReferenceListener
{
public:
    // `rate`: the rate of the samples pushed.
    ReferenceListener(int rate, const std::atomic_bool *cancel);
    ReferenceListener(const ReferenceListener &) = delete;
    ReferenceListener &operator=(const ReferenceListener &) = delete;

    void push(const float *samples, qsizetype count) { m_resampler.push(samples, count); }
    SpeechFeatures finish(); // the padded reference's features; empty when cancelled

private:
    void hear(const float *samples, qsizetype count);
    void silence();

    SpeechFeatureStream m_features;
    AudioResampler m_resampler;
    std::vector<float> m_block;
    quint32 m_noise = 12345;
};

// The features of the padded `reference` audio.
SpeechFeatures referenceFeatures(const Audio &reference, const std::atomic_bool *cancel = nullptr);

// Renders `script` (see synthesize) into `features` (the padded rendering's) without keeping
// its samples: the result's audio is empty.
TtsResult renderReference(const Script &script, const TtsOptions &options, SpeechFeatures *features,
    const std::atomic_bool *cancel = nullptr);

} // namespace toonface
