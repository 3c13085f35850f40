#include "speech/referencefeatures.h"

#include "speech/samplerelay.h"

namespace toonface {

ReferenceListener::ReferenceListener(int rate, const std::atomic_bool *cancel)
    : m_features(cancel)
    , m_resampler(rate, kSpeechSampleRate, [this](const float *s, qsizetype n) { hear(s, n); })
{
    silence();
}

void ReferenceListener::hear(const float *samples, qsizetype count)
{
    m_block.assign(samples, samples + count);
    for (float &s : m_block) {
        m_noise = m_noise * 1664525u + 1013904223u;
        s += 1e-4f * (float(m_noise >> 8) / float(1u << 24) - 0.5f);
    }
    m_features.push(m_block.data(), count);
}

void ReferenceListener::silence()
{
    const std::vector<float> zeros(size_t(kReferencePad * kSpeechSampleRate), 0.0f);
    hear(zeros.data(), qsizetype(zeros.size()));
}

SpeechFeatures ReferenceListener::finish()
{
    m_resampler.finish();
    silence();
    return m_features.finish();
}

SpeechFeatures referenceFeatures(const Audio &reference, const std::atomic_bool *cancel)
{
    ReferenceListener listener(reference.sampleRate, cancel);
    constexpr qsizetype kPiece = 1 << 16;
    for (qsizetype at = 0; at < reference.samples.size(); at += kPiece)
        listener.push(reference.samples.constData() + at, std::min(kPiece, reference.samples.size() - at));
    return listener.finish();
}

TtsResult renderReference(
    const Script &script, const TtsOptions &options, SpeechFeatures *features, const std::atomic_bool *cancel)
{
    const int rate = ttsSampleRate();
    if (rate <= 0) {
        TtsResult failed;
        failed.error = ttsUnavailable();
        return failed;
    }
    ReferenceListener listener(rate, cancel);
    // The features are computed on another core while espeak-ng speaks.
    SampleRelay relay([&](const float *s, qsizetype n) { listener.push(s, n); });
    TtsResult r = synthesize(
        script, options, [&](const float *s, qsizetype n) { relay.push(s, n); }, {}, cancel);
    relay.finish();
    *features = r.ok() ? listener.finish() : SpeechFeatures {};
    return r;
}

} // namespace toonface
