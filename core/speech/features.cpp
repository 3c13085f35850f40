#include "speech/features.h"

#include "speech/localnorm.h"
#include "speech/realfft.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <thread>

namespace toonface {

namespace {

constexpr int kWindow = 400; // 25 ms
constexpr int kHopSamples = 160;
constexpr int kFftBits = 10;
constexpr int kFft = 1 << kFftBits; // twice the window and more: the autocorrelation does not wrap
constexpr int kBins = kFft / 2 + 1;
constexpr int kMelBands = 24;

struct MelBank
{
    struct Band
    {
        int from, to;
        std::vector<float> weights;
    };
    std::vector<Band> bands;
    std::array<std::array<float, SpeechFeatures::kCepstra>, kMelBands> dctByBand; // [band][cepstrum]
    // The bands by bin: bin k's weights in binWeight[binStart[k] .. binStart[k + 1]), of the
    // bands binBand[...].
    std::vector<int> binStart, binBand;
    std::vector<float> binWeight;
    MelBank()
    {
        auto mel = [](double hz) { return 2595.0 * std::log10(1.0 + hz / 700.0); };
        auto hz = [](double m) { return 700.0 * (std::pow(10.0, m / 2595.0) - 1.0); };
        const double lo = mel(80), hi = mel(7000);
        std::array<double, kMelBands + 2> edges;
        for (int k = 0; k < kMelBands + 2; ++k)
            edges[size_t(k)] = hz(lo + (hi - lo) * k / (kMelBands + 1)) * kFft / kSpeechSampleRate;
        for (int b = 0; b < kMelBands; ++b) {
            Band band;
            band.from = int(std::floor(edges[size_t(b)]));
            band.to = int(std::ceil(edges[size_t(b + 2)]));
            for (int k = band.from; k <= band.to; ++k) {
                const double l = edges[size_t(b)], c = edges[size_t(b + 1)], r = edges[size_t(b + 2)];
                const double w = k < c ? (k - l) / (c - l) : (r - k) / (r - c);
                band.weights.push_back(float(std::max(0.0, w)));
            }
            bands.push_back(std::move(band));
        }
        binStart.assign(kBins + 1, 0);
        for (int k = 0; k < kBins; ++k) {
            binStart[size_t(k)] = int(binBand.size());
            for (int b = 0; b < kMelBands; ++b) {
                const Band &band = bands[size_t(b)];
                if (k >= band.from && k <= band.to) {
                    binBand.push_back(b);
                    binWeight.push_back(band.weights[size_t(k - band.from)]);
                }
            }
        }
        binStart[kBins] = int(binBand.size());
        for (int c = 0; c < SpeechFeatures::kCepstra; ++c)
            for (int b = 0; b < kMelBands; ++b)
                dctByBand[size_t(b)][size_t(c)] = float(std::cos(M_PI * (c + 1) * (b + 0.5) / kMelBands));
    }
};

float percentile(std::vector<float> v, double p)
{
    if (v.empty())
        return 0;
    const size_t k = std::min(v.size() - 1, size_t(p * double(v.size() - 1)));
    std::nth_element(v.begin(), v.begin() + qsizetype(k), v.end());
    return v[k];
}

} // namespace

const FeatureWeights &featureWeights()
{
    static const FeatureWeights w;
    return w;
}

int SpeechFeatures::frameAt(double seconds) const
{
    return std::clamp(int(std::lround((seconds - 0.0125) / kHop)), 0, std::max(frames - 1, 0));
}

double SpeechFeatures::speechDuration() const
{
    double n = 0;
    for (float s : silence)
        n += s < 0.5f;
    return n * kHop;
}

namespace {

const MelBank &melBank()
{
    static const MelBank bank;
    return bank;
}

const std::array<float, kWindow> &hammingWindow()
{
    static const std::array<float, kWindow> w = [] {
        std::array<float, kWindow> h;
        for (int i = 0; i < kWindow; ++i)
            h[size_t(i)] = float(0.54 - 0.46 * std::cos(2 * M_PI * i / (kWindow - 1)));
        return h;
    }();
    return w;
}

// The Hamming window's normalised autocorrelation, per lag.
const std::array<float, kWindow> &windowAutocorrelation()
{
    static const std::array<float, kWindow> r = [] {
        const auto &hamming = hammingWindow();
        std::array<float, kWindow> a;
        double r0 = 0;
        for (int i = 0; i < kWindow; ++i)
            r0 += double(hamming[size_t(i)]) * hamming[size_t(i)];
        for (int lag = 0; lag < kWindow; ++lag) {
            double acc = 0;
            for (int i = 0; i + lag < kWindow; ++i)
                acc += double(hamming[size_t(i)]) * hamming[size_t(i + lag)];
            a[size_t(lag)] = float(std::max(acc / r0, 1e-3));
        }
        return a;
    }();
    return r;
}

constexpr int kBlock = 256; // frames per call of frameBlock

// The real FFT of kFft points with its work buffer: one per thread, set up once.
struct FrameFft
{
    RealFft fft {kFft};
    std::array<float, kFft> buffer {};
    float *data = buffer.data();
};

FrameFft &realFft()
{
    thread_local FrameFft fft;
    return fft;
}

} // namespace

SpeechFeatureStream::SpeechFeatureStream(const std::atomic_bool *cancel)
    : m_cancel(cancel)
{ }

void SpeechFeatureStream::push(const float *samples, qsizetype count)
{
    if (count <= 0 || isCancelled(m_cancel))
        return;
    m_samples += count;
    m_pending.insert(m_pending.end(), samples, samples + count);
    constexpr size_t kNeed = size_t(kBlock - 1) * kHopSamples + kWindow;
    constexpr size_t kBlockSamples = size_t(kBlock) * kHopSamples;
    size_t used = 0;
    if (m_twoCores) {
        // Two blocks at a time (the rest waits for more samples, or for finish()): the first
        // on a helper thread, the second here, appended in order.
        while (m_pending.size() - used >= kNeed + kBlockSamples && !isCancelled(m_cancel)) {
            m_first.clear();
            m_second.clear();
            std::thread helper([&] { frameBlock(m_pending.data() + used, kBlock, m_first); });
            frameBlock(m_pending.data() + used + kBlockSamples, kBlock, m_second);
            helper.join();
            m_rows.append(m_first);
            m_rows.append(m_second);
            used += 2 * kBlockSamples;
        }
    } else {
        while (m_pending.size() - used >= kNeed && !isCancelled(m_cancel)) {
            frameBlock(m_pending.data() + used, kBlock, m_rows);
            used += kBlockSamples;
        }
    }
    m_pending.erase(m_pending.begin(), m_pending.begin() + qsizetype(used));
}

void SpeechFeatureStream::Rows::clear()
{
    for (std::vector<float> *v : {&cep, &logEnergy, &band, &hf, &lf, &voicing})
        v->clear();
}

void SpeechFeatureStream::Rows::append(const Rows &more)
{
    cep.insert(cep.end(), more.cep.begin(), more.cep.end());
    logEnergy.insert(logEnergy.end(), more.logEnergy.begin(), more.logEnergy.end());
    band.insert(band.end(), more.band.begin(), more.band.end());
    hf.insert(hf.end(), more.hf.begin(), more.hf.end());
    lf.insert(lf.end(), more.lf.begin(), more.lf.end());
    voicing.insert(voicing.end(), more.voicing.begin(), more.voicing.end());
}

void SpeechFeatureStream::frameBlock(const float *samples, int count, Rows &out)
{
    const MelBank &bank = melBank();
    const auto &hamming = hammingWindow();
    static const std::array<float, kWindow> inverseWindowAutocorr = [] {
        std::array<float, kWindow> inv;
        for (int lag = 0; lag < kWindow; ++lag)
            inv[size_t(lag)] = 1.0f / windowAutocorrelation()[size_t(lag)];
        return inv;
    }();
    const int bandLo = 300 * kFft / kSpeechSampleRate, bandHi = 3000 * kFft / kSpeechSampleRate;
    const int highLo = 3500 * kFft / kSpeechSampleRate, lowHi = 400 * kFft / kSpeechSampleRate;
    const int lagLo = kSpeechSampleRate / 400, lagHi = kSpeechSampleRate / 70;
    std::array<float, kBins> power;
    std::array<float, kMelBands> logMel;
    FrameFft &fft = realFft();
    float *z = fft.data;
    // The frames' means, four frames at a time (each summed in the order of its samples).
    thread_local std::vector<float> means;
    means.resize(size_t(std::max(count, 0)));
    {
        int r = 0;
        for (; r + 4 <= count; r += 4) {
            std::array<float, 4> sum {0, 0, 0, 0};
            for (int i = 0; i < kWindow; ++i)
                for (int q = 0; q < 4; ++q)
                    sum[size_t(q)] += samples[size_t(r + q) * kHopSamples + size_t(i)];
            for (int q = 0; q < 4; ++q)
                means[size_t(r + q)] = sum[size_t(q)] / kWindow;
        }
        for (; r < count; ++r) {
            float sum = 0;
            for (int i = 0; i < kWindow; ++i)
                sum += samples[size_t(r) * kHopSamples + size_t(i)];
            means[size_t(r)] = sum / kWindow;
        }
    }
    for (int r = 0; r < count; ++r) {
        const float *s = samples + size_t(r) * kHopSamples;
        const float mean = means[size_t(r)];
        for (int i = 0; i < kWindow; ++i)
            z[i] = (s[i] - mean) * hamming[size_t(i)];
        std::fill(z + kWindow, z + kFft, 0.0f);
        // The packed real layout: Re0, Re(N/2), Re1, Im1, ..., Re(N/2-1), Im(N/2-1).
        fft.fft.forward(z);
        power[0] = z[0] * z[0];
        for (int k = 1; k < kBins - 1; ++k)
            power[size_t(k)] = z[2 * k] * z[2 * k] + z[2 * k + 1] * z[2 * k + 1];
        power[kBins - 1] = z[1] * z[1];
        // One pass over the bins: the whole-band sum's long chain of additions leaves room for
        // the bands' and the mel bands' (each summed in the order of its bins as before).
        double total = 0, mid = 0, high = 0, low = 0;
        std::array<double, kMelBands> e {};
        for (int k = 0; k < kBins; ++k) {
            const float pk = power[size_t(k)];
            total += pk;
            if (k >= bandLo && k <= bandHi)
                mid += pk;
            if (k >= highLo)
                high += pk;
            if (k <= lowHi)
                low += pk;
            for (int m = bank.binStart[size_t(k)]; m < bank.binStart[size_t(k) + 1]; ++m)
                e[size_t(bank.binBand[size_t(m)])] += bank.binWeight[size_t(m)] * pk;
        }
        out.logEnergy.push_back(float(std::log(total + 1e-9)));
        out.band.push_back(float(std::log(mid + 1e-9)));
        out.hf.push_back(float(std::log(high + 1e-9) - std::log(total + 1e-9)));
        out.lf.push_back(float(std::log(low + 1e-9) - std::log(total + 1e-9)));
        for (int b = 0; b < kMelBands; ++b)
            logMel[size_t(b)] = float(std::log(e[size_t(b)] + 1e-8));
        // Every cepstrum's sum over the bands in the same order, all cepstra at once.
        std::array<float, SpeechFeatures::kCepstra> cep {};
        for (int b = 0; b < kMelBands; ++b)
            for (int c = 0; c < SpeechFeatures::kCepstra; ++c)
                cep[size_t(c)] += bank.dctByBand[size_t(b)][size_t(c)] * logMel[size_t(b)];
        out.cep.insert(out.cep.end(), cep.begin(), cep.end());
        // The autocorrelation: the inverse transform of the power spectrum (its scale does
        // not matter, only its ratio to lag 0).
        z[0] = power[0];
        z[1] = power[kBins - 1];
        for (int k = 1; k < kBins - 1; ++k) {
            z[2 * k] = power[size_t(k)];
            z[2 * k + 1] = 0;
        }
        fft.fft.inverse(z);
        const float *ac = z;
        const float r0 = ac[0];
        float best = 0;
        if (r0 > 0) {
            // Divided by the window's own autocorrelation at this lag (Boersma 1993): the
            // Hamming taper alone lowers a 70 Hz voice's peak to a seventh.
            // Four running maxima, then theirs: the same maximum, without one long chain.
            std::array<float, 4> most {0, 0, 0, 0};
            int lag = lagLo;
            for (; lag + 3 <= lagHi; lag += 4)
                for (int q = 0; q < 4; ++q)
                    most[size_t(q)] = std::max(most[size_t(q)], ac[lag + q] * inverseWindowAutocorr[size_t(lag + q)]);
            for (; lag <= lagHi; ++lag)
                most[0] = std::max(most[0], ac[lag] * inverseWindowAutocorr[size_t(lag)]);
            best = std::max(std::max(most[0], most[1]), std::max(most[2], most[3]));
            best /= r0;
        }
        out.voicing.push_back(std::clamp(best, 0.0f, 1.0f));
    }
}

SpeechFeatures computeSpeechFeatures(const Audio &audio, const std::atomic_bool *cancel)
{
    SpeechFeatureStream stream(cancel);
    // In pieces, so that the stream never holds a copy of the whole recording.
    constexpr qsizetype kPiece = 1 << 16;
    for (qsizetype at = 0; at < audio.samples.size(); at += kPiece)
        stream.push(audio.samples.constData() + at, std::min(kPiece, audio.samples.size() - at));
    return stream.finish();
}

SpeechFeatures SpeechFeatureStream::finish()
{
    // The last windows, fewer than a block.
    while (m_pending.size() >= size_t(kWindow) && !isCancelled(m_cancel)) {
        const int count = std::min(kBlock, int((m_pending.size() - kWindow) / kHopSamples) + 1);
        frameBlock(m_pending.data(), count, m_rows);
        m_pending.erase(m_pending.begin(), m_pending.begin() + qsizetype(size_t(count) * kHopSamples));
    }
    m_pending = {};
    if (isCancelled(m_cancel))
        return {};
    SpeechFeatures f;
    f.frames = int(m_rows.logEnergy.size());
    if (f.frames == 0)
        return f;
    const int frames = f.frames;
    std::vector<float> cep = std::move(m_rows.cep);
    std::vector<float> band = std::move(m_rows.band);
    std::vector<float> hf = std::move(m_rows.hf), lf = std::move(m_rows.lf);
    f.logEnergy = std::move(m_rows.logEnergy);
    f.voicing = std::move(m_rows.voicing);
    // Every level measured against the speech around it (see levelOffsets).
    const std::vector<float> offsets = levelOffsets(f.logEnergy);
    for (int t = 0; t < frames; ++t) {
        f.logEnergy[size_t(t)] += offsets[size_t(t)];
        band[size_t(t)] += offsets[size_t(t)];
    }

    // Loudness: the mid band smoothed over ±2 frames.
    f.loudness.resize(size_t(frames));
    for (int t = 0; t < frames; ++t) {
        double acc = 0;
        int cnt = 0;
        for (int d = -2; d <= 2; ++d) {
            const int u = t + d;
            if (u >= 0 && u < frames) {
                acc += band[size_t(u)];
                ++cnt;
            }
        }
        f.loudness[size_t(t)] = float(acc / cnt);
    }
    f.band = std::move(band);

    // Silence: below a threshold between the noise floor and the speech level, softly.
    f.noiseFloor = percentile(f.logEnergy, 0.05);
    f.speechLevel = percentile(f.logEnergy, 0.95);
    const float range = std::max(f.speechLevel - f.noiseFloor, 1e-3f);
    // Speech lies within ~35 dB (ln 10^3.5 ≈ 8) of its loud frames; noise sits near the floor.
    const float threshold = std::max(f.noiseFloor + 0.25f * range, f.speechLevel - 8.0f);
    const float width = std::max(0.05f * range, 0.2f);
    f.silence.resize(size_t(frames));
    for (int t = 0; t < frames; ++t)
        f.silence[size_t(t)] = 1.0f / (1.0f + std::exp((f.logEnergy[size_t(t)] - threshold) / width));

    // Cepstral mean and variance normalisation over the speech frames around each frame
    // (all frames when there is next to no speech).
    const int C = SpeechFeatures::kCepstra;
    std::vector<float> speechWeight(static_cast<size_t>(frames));
    double weight = 0;
    for (int t = 0; t < frames; ++t)
        weight += speechWeight[size_t(t)] = 1.0f - f.silence[size_t(t)];
    if (weight < 5)
        std::fill(speechWeight.begin(), speechWeight.end(), 1.0f);
    // A window is drawn toward the whole recording's moments as if it held a second of them.
    constexpr double kPriorFrames = 100;
    {
        const LocalMoments cepMoments(cep.data(), frames, C, speechWeight, kPriorFrames);
        for (int t = 0; t < frames; ++t)
            for (int c = 0; c < C; ++c)
                cep[size_t(t) * C + size_t(c)] = cepMoments.normalised(t, c, cep[size_t(t) * C + size_t(c)]);
    }

    // Broad, speaker-robust channels: loudness between its floor and level, the share of
    // high (> 3.5 kHz: frication) and low (< 400 Hz: voice bar, nasals) energy, z-scored.
    const float loudFloor = percentile(f.loudness, 0.05), loudLevel = percentile(f.loudness, 0.95);
    const float loudRange = std::max(loudLevel - loudFloor, 1e-3f);
    auto zscore = [&](std::vector<float> &v) {
        const LocalMoments moments(v.data(), frames, 1, speechWeight, kPriorFrames);
        for (int t = 0; t < frames; ++t)
            v[size_t(t)] = std::clamp(moments.normalised(t, 0, v[size_t(t)]), -4.0f, 4.0f);
    };
    zscore(hf);
    zscore(lf);

    const FeatureWeights &w = featureWeights();
    f.vectors.assign(size_t(frames) * SpeechFeatures::kDim, 0.0f);
    auto norm = [&](int t, int c) {
        const int u = std::clamp(t, 0, frames - 1);
        return cep[size_t(u) * C + size_t(c)];
    };
    f.loudnessNorm.resize(size_t(frames));
    for (int t = 0; t < frames; ++t)
        f.loudnessNorm[size_t(t)] = std::clamp((f.loudness[size_t(t)] - loudFloor) / loudRange, 0.0f, 1.0f);
    auto loud = [&](int t) {
        const int u = std::clamp(t, 0, frames - 1);
        return std::clamp((f.loudness[size_t(u)] - loudFloor) / loudRange, -0.5f, 1.5f);
    };
    auto at = [&](const std::vector<float> &v, int t) { return v[size_t(std::clamp(t, 0, frames - 1))]; };
    for (int t = 0; t < frames; ++t) {
        float *v = f.vectors.data() + size_t(t) * SpeechFeatures::kDim;
        for (int c = 0; c < C; ++c) {
            const float cw = c < w.broadCepstra ? w.cepstra : w.fineCepstra;
            v[c] = cw * norm(t, c);
            // Delta over ±2 frames (regression slope).
            v[C + c]
                = cw * w.delta * (2 * (norm(t + 2, c) - norm(t - 2, c)) + (norm(t + 1, c) - norm(t - 1, c))) / 10.0f;
        }
        float *x = v + 2 * C;
        x[0] = w.loudness * loud(t);
        x[1] = w.loudnessDelta * (2 * (loud(t + 2) - loud(t - 2)) + (loud(t + 1) - loud(t - 1))) / 10.0f * 5.0f;
        x[2] = w.voicing * f.voicing[size_t(t)];
        x[3] = w.high * at(hf, t);
        x[4] = w.high * w.delta * (2 * (at(hf, t + 2) - at(hf, t - 2)) + (at(hf, t + 1) - at(hf, t - 1))) / 10.0f;
        x[5] = w.low * at(lf, t);
    }
    return f;
}

} // namespace toonface
