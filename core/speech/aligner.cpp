#include "speech/aligner.h"

#include "speech/dtw.h"
#include "speech/features.h"
#include "speech/pinyin.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <optional>

namespace toonface {

namespace {

constexpr int kDefaultRate = 175;
constexpr double kReferencePad = 0.3; // seconds of silence added before and after the reference

AlignResult failure(AlignStatus status, const QString &why)
{
    AlignResult r;
    r.status = status;
    r.error = why;
    return r;
}

// The warping path seen from either side.
struct Warp
{
    std::vector<int> firstA, lastA; // per b frame: the a frames held against it
    Warp(const std::vector<std::pair<int, int>> &path, int bFrames)
        : firstA(size_t(bFrames), -1)
        , lastA(size_t(bFrames), -1)
    {
        for (const auto &[i, j] : path) {
            if (firstA[size_t(j)] < 0)
                firstA[size_t(j)] = i;
            lastA[size_t(j)] = i;
        }
    }
};

// How a syllable begins, which decides what its onset looks like in the signal.
enum class OnsetKind { Voiceless, Sonorant, Vowel, Any };

OnsetKind onsetKind(const ScriptSyllable &s)
{
    if (s.pinyin.isEmpty())
        return OnsetKind::Any; // English words: only a pause before them marks their onset
    const auto parts = splitPinyinSyllable(s.pinyin);
    if (!parts || parts->initial.isEmpty())
        return OnsetKind::Vowel;
    const QString &i = parts->initial;
    if (i == QLatin1String("m") || i == QLatin1String("n") || i == QLatin1String("l") || i == QLatin1String("r"))
        return OnsetKind::Sonorant;
    return OnsetKind::Voiceless;
}

// The recording's frame signals the segmentation scores, with O(1) window sums and maxima.
class Signals
{
public:
    explicit Signals(const SpeechFeatures &f)
        : m_frames(f.frames)
        , m_ln(f.loudness)
    {
        const size_t n = size_t(f.frames);
        m_loud = f.loudnessNorm;
        // The voicing a voiceless initial ends is a lasting loss: measured on the voicing averaged
        // over ±20 ms, since a rough or creaky voice's voicing flickers from frame to frame.
        m_lnVoiced.resize(n);
        for (size_t t = 0; t < n; ++t) {
            const size_t from = t >= 2 ? t - 2 : 0, to = std::min(n, t + 3);
            float voicing = 0;
            for (size_t u = from; u < to; ++u)
                voicing += f.voicing[u];
            voicing /= float(to - from);
            // voicing 1 → 0.1 lowers this by 4.6 (20 dB)
            m_lnVoiced[t] = m_ln[t] + 2.0f * std::log(std::clamp(voicing, 0.1f, 1.0f));
        }
        m_nucleus.resize(n);
        std::vector<float> speech(n);
        for (size_t t = 0; t < n; ++t) {
            // Voiced and loud: a syllable nucleus. Voicing below 0.4 counts as none.
            const float v = std::clamp((f.voicing[t] - 0.4f) / 0.4f, 0.0f, 1.0f);
            m_nucleus[t] = m_loud[t] * v;
            speech[t] = 1.0f - f.silence[t];
        }
        // A pause: at least 150 ms in which the mid-band loudness stays more than ~22 dB
        // (5 ln units) under the loud frames of speech, ±50 ms around each frame. Clicks and
        // breaths in a pause stay that far under; the frication of an initial after a pause
        // does not, once its vowel is within 50 ms. Shorter quiet runs are stop closures.
        m_ln = f.loudness;
        std::vector<float> sorted = m_ln;
        std::sort(sorted.begin(), sorted.end());
        const float level = sorted.empty() ? 0.0f : sorted[size_t(0.95 * double(sorted.size() - 1))];
        std::vector<bool> quiet(n);
        // Or: 50 ms that are all silence by their whole-band energy (a recording whose noise
        // floor sits less than 22 dB under its speech).
        auto silent = [&](int t) { return f.silence[size_t(std::clamp(t, 0, int(n) - 1))] > 0.5f; };
        for (size_t t = 0; t < n; ++t) {
            const int u = int(t);
            quiet[t] = maxLn(u - 5, u + 5) < level - 5.0
                || (silent(u - 2) && silent(u - 1) && silent(u) && silent(u + 1) && silent(u + 2));
        }
        m_pause.assign(n, 0.0f);
        for (size_t t = 0; t < n;) {
            if (!quiet[t]) {
                ++t;
                continue;
            }
            size_t e = t;
            while (e < n && quiet[e])
                ++e;
            // The ±50 ms look-around stops a pause short of the sound on either side; extend
            // it over the frames that are silence by their whole-band energy (the frication
            // of an initial is quiet in the mid band, not in the whole band).
            size_t a = t, z = e;
            while (a > 0 && f.silence[a - 1] > 0.5f)
                --a;
            while (z < n && f.silence[z] > 0.5f)
                ++z;
            if (z - a >= 15 || a == 0 || z == n)
                std::fill(m_pause.begin() + qsizetype(a), m_pause.begin() + qsizetype(z), 1.0f);
            t = e;
        }
        // Valleys: local loudness minima with their depth under the highest frames within
        // 150 ms either side, and where those peaks are. Two peaks inside one syllable with a
        // deep valley between them mean two syllables.
        const std::vector<double> pauses = prefix(m_pause);
        for (int t = 3; t + 3 < int(n); ++t) {
            if (m_ln[size_t(t)] > minLn(t - 3, t + 3) || pauses[size_t(t) + 4] - pauses[size_t(t) - 3] > 0)
                continue;
            int left = t - 1, right = t + 1;
            for (int u = std::max(0, t - 15); u < t; ++u)
                if (m_ln[size_t(u)] >= m_ln[size_t(left)])
                    left = u;
            for (int u = t + 1; u <= std::min(int(n) - 1, t + 15); ++u)
                if (m_ln[size_t(u)] > m_ln[size_t(right)])
                    right = u;
            const double depth = std::min(m_ln[size_t(left)], m_ln[size_t(right)]) - m_ln[size_t(t)];
            if (depth >= 1.0 && (m_valleys.empty() || m_valleys.back().at < t - 3))
                m_valleys.push_back({t, left, right, depth});
        }
        m_firstValley.assign(n + 1, int(m_valleys.size()));
        for (int t = int(n) - 1, v = int(m_valleys.size()); t >= 0; --t) {
            while (v > 0 && m_valleys[size_t(v) - 1].at >= t)
                --v;
            m_firstValley[size_t(t)] = v;
        }
        m_sumLoud = prefix(m_loud);
        m_sumNucleus = prefix(m_nucleus);
        m_sumSpeech = prefix(speech);
        m_sumPause = prefix(m_pause);
        m_maxNucleus = sparseMax(m_nucleus);
        m_maxLoud = sparseMax(m_loud);
        m_nextPause.assign(n + 1, int(n));
        for (int t = int(n) - 1; t >= 0; --t)
            m_nextPause[size_t(t)] = m_pause[size_t(t)] > 0.5f ? t : m_nextPause[size_t(t) + 1];
        m_nextSpeech.assign(n + 1, int(n));
        for (int t = int(n) - 1; t >= 0; --t)
            m_nextSpeech[size_t(t)] = m_pause[size_t(t)] > 0.5f ? m_nextSpeech[size_t(t) + 1] : t;
    }

    double nucleus(int t) const { return m_nucleus[size_t(std::clamp(t, 0, m_frames - 1))]; }
    // The first pause frame at or after t (frames() when none).
    int nextPause(int t) const { return m_nextPause[size_t(std::clamp(t, 0, m_frames))]; }
    // The first frame at or after t that is not a pause (frames() when none).
    int nextSpeech(int t) const { return m_nextSpeech[size_t(std::clamp(t, 0, m_frames))]; }

    int frames() const { return m_frames; }
    bool isPause(int t) const { return t >= 0 && t < m_frames && m_pause[size_t(t)] > 0.5f; }
    double pauseFrames(int from, int to) const { return sum(m_sumPause, from, to); }

    // Evidence (about -1..1) that a syllable of this kind starts at frame b. Loudness
    // contrasts are in natural-log power units, which do not depend on the recording level:
    // ln 10^1.3 ≈ 3 (13 dB) is a clear fall from a vowel into a closure or frication, half of
    // that from a vowel into a nasal or liquid.
    double onsetEvidence(int b, OnsetKind kind, bool first) const
    {
        constexpr int w = 3;
        if (first && b == 0)
            return 1.0 - mean(m_sumPause, 0, w); // speech from the very start
        // Only a real pause counts here: a stop's closure is silent too, and its syllable
        // starts where the closure does, not at the release.
        // A click or breath in a pause is not an onset: a syllable's nucleus follows within 150 ms.
        const double afterPause = mean(m_sumPause, b - 2 * w, b) * (1.0 - mean(m_sumPause, b, b + w))
            * std::min(1.0, 2.0 * maxNucleus(b, b + 15));
        // The knee where the previous syllable's loudness starts to fall: the slope changes from
        // flat (40 ms before b) to falling (40 ms after).
        auto knee = [&](double clear, bool voicing) {
            // A voiceless initial also ends the voicing: a nasal coda before it is quiet in the
            // mid band but voiced, so the voiceless onset is where voicing stops.
            auto level = [&](int t) { return voicing ? lnVoiced(t) : lnLoud(t); };
            const double here = level(b - 1);
            const double fallAfter = here - level(b + 3);
            const double fallBefore = level(b - 5) - here;
            return std::clamp((fallAfter - std::max(fallBefore, 0.0)) / clear, -1.0, 1.0);
        };
        if (first)
            return afterPause; // nothing before the first syllable falls into it
        // Only the end of a voiced nucleus falls into an onset.
        const double voicedBefore = std::min(1.0, 2.0 * mean(m_sumNucleus, b - w, b));
        // The bottom of a valley between two nuclei: deep (3 ln units is clear), and the lowest
        // point within ±40 ms.
        const double depth = std::min(maxLn(b - 12, b), maxLn(b + 1, b + 13)) - lnLoud(b);
        const double aboveBottom = lnLoud(b) - minLn(b - 4, b + 4);
        const double valley = std::clamp(depth / 3.0, 0.0, 1.0) - std::clamp(aboveBottom / 1.0, 0.0, 1.0);
        // Voicing lost across b (beyond what the loudness says): a voiceless initial's mark,
        // which a nasal, a liquid or a vowel onset does not have.
        const double voicingLoss
            = std::clamp(((lnVoiced(b - 1) - lnVoiced(b + 3)) - (lnLoud(b - 1) - lnLoud(b + 3))) / 2.0, 0.0, 1.0);
        // A nasal, a liquid or a glide dips the mid band by up to ~3.5 ln units (15 dB); a
        // deeper fall is a closure or frication, the onset of a voiceless initial.
        const double fallDepth = lnLoud(b - 1) - minLn(b, b + 12);
        auto shallow = [](double d) { return std::clamp((5.0 - d) / 1.5, 0.0, 1.0); };
        double e = 0;
        switch (kind) {
        case OnsetKind::Voiceless: e = knee(3.0, true); break;
        case OnsetKind::Sonorant: e = knee(1.5, false) * (1.0 - voicingLoss) * shallow(fallDepth); break;
        case OnsetKind::Vowel: e = valley * (1.0 - voicingLoss) * shallow(depth); break;
        case OnsetKind::Any: e = 0; break; // English words end in consonants: no rule here
        }
        return std::max(e * voicedBefore, afterPause);
    }

    // The strongest nucleus within [from, to).
    double maxNucleus(int from, int to) const { return rangeMax(m_maxNucleus, from, to); }
    // The loudest frame within [from, to) (0..1 between the recording's quiet and loud frames).
    double maxLoud(int from, int to) const { return rangeMax(m_maxLoud, from, to); }
    // The deepest valley (ln units) between two peaks that both lie inside [from, to).
    double innerValley(int from, int to) const
    {
        double deepest = 0;
        for (size_t v = size_t(m_firstValley[size_t(std::clamp(from, 0, m_frames))]);
             v < m_valleys.size() && m_valleys[v].at < to; ++v) {
            if (m_valleys[v].left > from + 1 && m_valleys[v].right < to - 1)
                deepest = std::max(deepest, m_valleys[v].depth);
        }
        return deepest;
    }

private:
    using SparseMax = std::vector<std::vector<float>>;
    static SparseMax sparseMax(const std::vector<float> &v)
    {
        SparseMax table {v};
        for (size_t len = 2; len <= v.size(); len *= 2) {
            const auto &prev = table.back();
            std::vector<float> next(v.size() - len + 1);
            for (size_t i = 0; i + len <= v.size(); ++i)
                next[i] = std::max(prev[i], prev[i + len / 2]);
            table.push_back(std::move(next));
        }
        return table;
    }
    double rangeMax(const SparseMax &table, int from, int to) const
    {
        from = std::max(from, 0);
        to = std::min(to, m_frames);
        if (to <= from)
            return 0;
        const int k = std::bit_width(unsigned(to - from)) - 1;
        const auto &row = table[size_t(k)];
        return std::max(row[size_t(from)], row[size_t(to - (1 << k))]);
    }

    static std::vector<double> prefix(const std::vector<float> &v)
    {
        std::vector<double> p(v.size() + 1, 0.0);
        for (size_t i = 0; i < v.size(); ++i)
            p[i + 1] = p[i] + v[i];
        return p;
    }
    double sum(const std::vector<double> &p, int from, int to) const
    {
        from = std::clamp(from, 0, m_frames);
        to = std::clamp(to, 0, m_frames);
        return to > from ? p[size_t(to)] - p[size_t(from)] : 0.0;
    }
    double mean(const std::vector<double> &p, int from, int to) const
    {
        const int a = std::clamp(from, 0, m_frames), b = std::clamp(to, 0, m_frames);
        return b > a ? sum(p, a, b) / (b - a) : 0.0;
    }
    double lnLoud(int t) const { return m_ln[size_t(std::clamp(t, 0, m_frames - 1))]; }
    double lnVoiced(int t) const { return m_lnVoiced[size_t(std::clamp(t, 0, m_frames - 1))]; }
    double maxLn(int from, int to) const
    {
        double m = lnLoud(from);
        for (int t = from; t <= to; ++t)
            m = std::max(m, lnLoud(t));
        return m;
    }
    double minLn(int from, int to) const
    {
        double m = lnLoud(from);
        for (int t = from; t <= to; ++t)
            m = std::min(m, lnLoud(t));
        return m;
    }

    int m_frames;
    std::vector<float> m_ln, m_lnVoiced, m_loud, m_nucleus, m_pause;
    std::vector<double> m_sumLoud, m_sumNucleus, m_sumSpeech, m_sumPause;
    SparseMax m_maxNucleus, m_maxLoud;
    std::vector<int> m_nextPause, m_nextSpeech;
    std::vector<int> m_firstValley; // per frame: the first valley at or after it
    struct Valley
    {
        int at, left, right;
        double depth;
    };
    std::vector<Valley> m_valleys;
};

// Onset frames of the n syllables: the best chain of boundaries near the warped estimates
// `prior`, each where the signal shows the syllable's kind of onset, each syllable holding a
// voiced nucleus and lasting about as long as in the reference (`expected`, frames of speech,
// scaled to the speaker's rate). Returns the evidence of each chosen onset in `evidence`.
std::vector<int> segmentSyllables(const Signals &sig, const std::vector<int> &prior,
    const std::vector<double> &expected, const std::vector<OnsetKind> &kinds, int speechEnd,
    std::vector<double> *evidence)
{
    // Weights of the terms, in units of "one clear onset": a clear onset (evidence ~0.7) or a
    // clear nucleus are worth about as much as a syllable 1.5 times longer than expected costs.
    constexpr double kOnset = 4.0, kNucleus = 2.0, kDuration = 3.0, kPrior = 1.0, kValley = 4.0;
    // The warp's estimate holds within about kPriorSigma; farther off, the cost stops growing
    // (kPriorCap): one badly warped syllable cannot drag its neighbours, while shifting a run
    // of syllables by one costs every one of them.
    constexpr double kPriorSigma = 12.0; // frames
    constexpr double kPriorCap = 1.0;
    constexpr int kWindow = 80; // frames either side of the prior searched
    const int n = int(prior.size());
    const int T = sig.frames();
    std::vector<int> lo(static_cast<size_t>(n)), hi(static_cast<size_t>(n));
    for (int k = 0; k < n; ++k) {
        lo[size_t(k)] = std::clamp(prior[size_t(k)] - kWindow, 0, T - 1);
        hi[size_t(k)] = std::clamp(prior[size_t(k)] + kWindow, 0, T - 1);
        if (k > 0)
            lo[size_t(k)] = std::max(lo[size_t(k)], lo[size_t(k) - 1] + 1);
    }
    for (int k = n - 2; k >= 0; --k)
        hi[size_t(k)] = std::min(hi[size_t(k)], hi[size_t(k) + 1] - 1);
    auto node = [&](int k, int b) {
        const double d = (b - prior[size_t(k)]) / kPriorSigma;
        return kOnset * sig.onsetEvidence(b, kinds[size_t(k)], k == 0) - kPrior * std::min(0.5 * d * d, kPriorCap);
    };
    // A pause may follow a syllable's nucleus, never come between its onset and its nucleus.
    // Its nucleus is a rise after the dip that follows the onset (the first frames after an
    // onset still carry the falling end of the syllable before). Whether a syllable starting at
    // `from` lacks one before the next pause depends on `from` alone: computed once per frame.
    std::vector<float> noNucleusBeforePause(size_t(T), 0.0f);
    for (int from = 0; from < T; ++from) {
        const int pause = sig.nextPause(from + 1);
        if (pause >= T)
            continue;
        int dip = from;
        for (int t = from; t < std::min(from + 15, pause); ++t)
            if (sig.nucleus(t) < sig.nucleus(dip))
                dip = t;
        const double peak = sig.maxNucleus(dip, pause);
        noNucleusBeforePause[size_t(from)] = peak < 0.3 || peak - sig.nucleus(dip) < 0.15 ? 1.0f : 0.0f;
    }
    std::vector<double> logExpected(static_cast<size_t>(n));
    for (int k = 0; k < n; ++k)
        logExpected[size_t(k)] = std::log(std::max(expected[size_t(k)], 3.0));
    std::vector<double> logLength(512);
    for (size_t len = 1; len < logLength.size(); ++len)
        logLength[len] = std::log(double(len));
    // A syllable over [from, to): its nucleus and its length (pauses excluded).
    auto span = [&](int k, int from, int to) {
        const double len = std::max(1.0, (to - from) - sig.pauseFrames(from, to));
        const double r
            = (len < double(logLength.size()) ? logLength[size_t(len)] : std::log(len)) - logExpected[size_t(k)];
        // Two loud peaks inside with a valley of 3 ln units (13 dB) between them: a syllable
        // boundary missed.
        const double inside = std::clamp((sig.innerValley(from, to) - 1.0) / 2.0, 0.0, 1.0);
        // Nor does a syllable go on after a pause: a nucleus after the pause inside the span
        // belongs to the next syllable (stop closures are too short to count as pauses).
        const int pause = sig.nextPause(from + 1);
        double pauseInside = 0;
        if (pause < to) {
            // Loud sound after the pause counts as well as a voiced nucleus: a rough or creaky
            // voice's flickering voicing can hide a nucleus, not its loudness.
            const int resume = sig.nextSpeech(pause);
            const bool resumes = sig.maxNucleus(resume, to) >= 0.3 || sig.maxLoud(resume, to) >= 0.5;
            pauseInside = std::max(double(noNucleusBeforePause[size_t(from)]), resumes ? 1.0 : 0.0);
        }
        return kNucleus * sig.maxNucleus(from, to) - kDuration * r * r - kValley * (inside + pauseInside);
    };
    constexpr double kNone = -1e18;
    std::vector<std::vector<double>> score(static_cast<size_t>(n));
    std::vector<std::vector<int>> from(static_cast<size_t>(n));
    for (int k = 0; k < n; ++k) {
        const int w = std::max(hi[size_t(k)] - lo[size_t(k)] + 1, 0);
        score[size_t(k)].assign(size_t(w), kNone);
        from[size_t(k)].assign(size_t(w), -1);
        for (int b = lo[size_t(k)]; b <= hi[size_t(k)]; ++b) {
            const double here = node(k, b);
            if (k == 0) {
                score[0][size_t(b - lo[0])] = here;
                continue;
            }
            double best = kNone;
            int arg = -1;
            // Syllables more than four times their expected length (pauses aside) are not
            // considered: the search runs back from b and stops there.
            const double longest = 4.0 * std::max(expected[size_t(k) - 1], 3.0) + 10.0;
            for (int p = std::min(hi[size_t(k) - 1], b - 3); p >= lo[size_t(k) - 1]; --p) {
                if ((b - p) - sig.pauseFrames(p, b) > longest)
                    break;
                const double prev = score[size_t(k) - 1][size_t(p - lo[size_t(k) - 1])];
                if (prev <= kNone / 2)
                    continue;
                const double v = prev + span(k - 1, p, b);
                if (v > best) {
                    best = v;
                    arg = p;
                }
            }
            if (arg >= 0) {
                score[size_t(k)][size_t(b - lo[size_t(k)])] = best + here;
                from[size_t(k)][size_t(b - lo[size_t(k)])] = arg;
            }
        }
    }
    // The last syllable runs to the end of speech.
    double best = kNone;
    int arg = -1;
    for (int b = lo[size_t(n) - 1]; b <= hi[size_t(n) - 1]; ++b) {
        const double s0 = score[size_t(n) - 1][size_t(b - lo[size_t(n) - 1])];
        if (s0 <= kNone / 2)
            continue;
        const double v = s0 + span(n - 1, b, std::max(speechEnd, b + 1));
        if (v > best) {
            best = v;
            arg = b;
        }
    }
    if (arg < 0)
        return prior;
    std::vector<int> onsets(static_cast<size_t>(n));
    for (int k = n - 1; k >= 0; --k) {
        onsets[size_t(k)] = arg;
        if (k > 0)
            arg = from[size_t(k)][size_t(arg - lo[size_t(k)])];
    }
    evidence->resize(size_t(n));
    for (int k = 0; k < n; ++k)
        (*evidence)[size_t(k)] = sig.onsetEvidence(onsets[size_t(k)], kinds[size_t(k)], k == 0);
    return onsets;
}

} // namespace

namespace {

// The aligner proper, on the recording's features `a`.
AlignResult alignFeatures(const SpeechFeatures &a, const Script &script, const TtsResult &reference,
    const SpeechProgressFn &progress, const std::atomic_bool *cancel)
{
    const int n = int(script.syllables.size());
    if (!reference.ok() || reference.units.size() != n)
        return failure(AlignStatus::BadInput, QStringLiteral("no reference rendering of the script"));
    if (progress)
        progress(0.3, QStringLiteral("features"));
    // The reference gets silence either side (faint noise, as a room has), so that silence
    // before and after the speech in the recording has something to match.
    Audio ref16 = resampled(reference.audio, kSpeechSampleRate);
    {
        const qsizetype pad = qsizetype(kReferencePad * kSpeechSampleRate);
        // One allocation: fresh pages are costly, and ten minutes of speech are 40 MB.
        QVector<float> padded;
        padded.reserve(ref16.samples.size() + 2 * pad);
        padded.resize(pad, 0.0f);
        padded.append(ref16.samples);
        padded.resize(padded.size() + pad, 0.0f);
        quint32 state = 12345;
        for (float &s : padded) {
            state = state * 1664525u + 1013904223u;
            s += 1e-4f * (float(state >> 8) / float(1u << 24) - 0.5f);
        }
        ref16.samples = std::move(padded);
    }
    const SpeechFeatures b = computeSpeechFeatures(ref16, cancel);
    if (isCancelled(cancel))
        return failure(AlignStatus::Cancelled, QStringLiteral("cancelled"));

    // ln(power) spans at least ~12 dB between pauses and speech in any recording with speech.
    const double speech = a.speechDuration();
    if (a.frames < 10 || a.speechLevel - a.noiseFloor < 2.8f || speech < 0.08)
        return failure(AlignStatus::CannotAlign, QStringLiteral("no speech found in the audio"));
    const double expected = b.speechDuration();
    if (speech < 0.3 * expected)
        return failure(AlignStatus::CannotAlign,
            QStringLiteral("the script is far too long for the audio: its %1 syllables need about %2 s of "
                           "speech, the audio holds %3 s")
                .arg(n)
                .arg(expected, 0, 'f', 1)
                .arg(speech, 0, 'f', 1));
    if (speech > 6.0 * expected)
        return failure(AlignStatus::CannotAlign,
            QStringLiteral("the audio holds far more speech (%1 s) than the script's %2 syllables (about "
                           "%3 s)")
                .arg(speech, 0, 'f', 1)
                .arg(n)
                .arg(expected, 0, 'f', 1));

    DtwOptions opt;
    opt.dim = SpeechFeatures::kDim;
    const auto path = dtwPath(
        {a.vectors.data(), a.silence.data(), a.frames}, {b.vectors.data(), b.silence.data(), b.frames}, opt, cancel);
    if (isCancelled(cancel))
        return failure(AlignStatus::Cancelled, QStringLiteral("cancelled"));
    if (path.empty())
        return failure(AlignStatus::CannotAlign, QStringLiteral("the audio and the script could not be matched"));
    if (progress)
        progress(0.8, QStringLiteral("warping"));
    const Warp warp(path, b.frames);

    // Reference time → audio time. Where the recording is slower, the warp holds one reference
    // frame against several of its frames, and the reference's moment may be any of them: an
    // onset takes the middle of those that are speech (a pause absorbed there belongs before
    // the syllable), not the first, which is early by half the hold.
    auto mapTime = [&](double tRef, bool onset) {
        const int j = b.frameAt(tRef);
        int i0 = warp.firstA[size_t(j)], i1 = warp.lastA[size_t(j)];
        if (onset) {
            int i = i0;
            while (i < i1 && a.silence[size_t(i)] > 0.5f)
                ++i;
            while (i1 > i && a.silence[size_t(i1)] > 0.5f)
                --i1;
            i0 = (i + i1) / 2;
        } else {
            int i = i1;
            while (i > i0 && a.silence[size_t(i)] > 0.5f)
                --i;
            i0 = i;
        }
        return std::max(0.0, a.time(i0) + (tRef - b.time(j)));
    };

    // Warped estimates, then the segmentation that settles each onset on the signal.
    std::vector<int> prior(static_cast<size_t>(n));
    std::vector<double> expectedFrames(static_cast<size_t>(n));
    std::vector<OnsetKind> kinds(static_cast<size_t>(n));
    const Signals sig(a);
    const Signals refSig(b);
    // The speaker's pace against the reference's, pauses excluded.
    const double targetSpeech = a.frames - sig.pauseFrames(0, a.frames);
    const double refSpeech = b.frames - refSig.pauseFrames(0, b.frames);
    const double pace = targetSpeech / std::max(refSpeech, 1.0);
    for (int k = 0; k < n; ++k) {
        const TtsUnit &u = reference.units[k];
        prior[size_t(k)] = a.frameAt(mapTime(u.start + kReferencePad, true));
        if (k > 0)
            prior[size_t(k)] = std::max(prior[size_t(k)], prior[size_t(k) - 1] + 3);
        expectedFrames[size_t(k)] = std::max(3.0, (u.end - u.start) / SpeechFeatures::kHop * pace);
        kinds[size_t(k)] = onsetKind(script.syllables[k]);
        // After a nasal coda a nasal or liquid initial continues the murmur: the fall that
        // marks a sonorant onset elsewhere is the coda's here, and nothing in the loudness or
        // the voicing marks where the coda ends. The warp places these onsets.
        if (k > 0 && kinds[size_t(k)] == OnsetKind::Sonorant) {
            const QString &before = script.syllables[k - 1].pinyin;
            if (before.endsWith(QLatin1Char('n')) || before.endsWith(QLatin1String("ng")))
                kinds[size_t(k)] = OnsetKind::Any;
        }
    }
    int first = 0, last = a.frames - 1;
    while (first < last && a.silence[size_t(first)] > 0.5f)
        ++first;
    while (last > first && a.silence[size_t(last)] > 0.5f)
        --last;
    // How well the recording matched the reference over each syllable: the mean distance of
    // the warped frames (vectors of unit-variance channels, so ~1.4 means unrelated sounds).
    std::vector<double> match(static_cast<size_t>(n), 0.0);
    {
        std::vector<double> perRef(size_t(b.frames), 0.0);
        std::vector<int> countRef(size_t(b.frames), 0);
        for (const auto &[i, j] : path) {
            double acc = 0;
            for (int d = 0; d < SpeechFeatures::kDim; ++d) {
                const double x = a.vector(i)[d] - b.vector(j)[d];
                acc += x * x;
            }
            perRef[size_t(j)] += std::sqrt(acc / SpeechFeatures::kDim);
            ++countRef[size_t(j)];
        }
        for (int k = 0; k < n; ++k) {
            const int j0 = b.frameAt(reference.units[k].start + kReferencePad);
            const int j1 = b.frameAt(reference.units[k].end + kReferencePad);
            double acc = 0;
            int cnt = 0;
            for (int j = j0; j <= j1; ++j) {
                acc += perRef[size_t(j)];
                cnt += countRef[size_t(j)];
            }
            match[size_t(k)] = cnt ? acc / cnt : 1.0;
        }
    }
    std::vector<double> evidence;
    const std::vector<int> onsets = segmentSyllables(sig, prior, expectedFrames, kinds, last + 1, &evidence);

    AlignResult r;
    r.syllables.resize(n);
    for (int k = 0; k < n; ++k) {
        AlignedSyllable &s = r.syllables[k];
        // A frame's onset is the start of its window's middle 10 ms. The signal's boundary
        // replaces the warped estimate only where it is clearly the better onset; where the two
        // agree within 40 ms, both are estimates of one event and their mean is kept (boundary
        // conventions differ by about that much).
        const double refined = a.time(onsets[size_t(k)]) - 0.5 * SpeechFeatures::kHop;
        const double warped = mapTime(reference.units[k].start + kReferencePad, true);
        const double atWarped
            = sig.onsetEvidence(a.frameAt(warped + 0.5 * SpeechFeatures::kHop), kinds[size_t(k)], k == 0);
        // A pause between the two settles it for the segmentation, which knows that a
        // syllable cannot begin before a pause and have its nucleus after it.
        const int w0 = std::min(onsets[size_t(k)], a.frameAt(warped)),
                  w1 = std::max(onsets[size_t(k)], a.frameAt(warped));
        const bool pauseBetween = sig.pauseFrames(w0, w1) > 0;
        if (evidence[size_t(k)] - atWarped < 0.25 && !pauseBetween)
            s.start = warped;
        else
            s.start = std::abs(refined - warped) <= 0.04 ? 0.5 * (refined + warped) : refined;
        if (k > 0)
            s.start = std::max(s.start, r.syllables[k - 1].start + 0.02);
        // Confidence: a clear onset, where the warp expected it, over sounds that matched the
        // reference (a mean distance of 0.15 is the same sounds in another voice, 0.4 none).
        const double e = std::clamp(evidence.empty() ? 0.0 : evidence[size_t(k)] / 0.5, 0.0, 1.0);
        const double shift = std::abs(onsets[size_t(k)] - prior[size_t(k)]) * SpeechFeatures::kHop;
        const double matched = std::clamp((0.4 - match[size_t(k)]) / 0.25, 0.0, 1.0);
        s.confidence = std::clamp((e + std::exp(-shift / 0.1) + matched) / 3.0, 0.0, 1.0);
    }
    for (int k = 0; k < n; ++k) {
        AlignedSyllable &s = r.syllables[k];
        // A syllable ends where the next begins, or where a pause after it begins.
        int endFrame = k + 1 < n ? onsets[size_t(k) + 1] : last + 1;
        while (endFrame - 1 > onsets[size_t(k)] && sig.isPause(endFrame - 1))
            --endFrame;
        s.end = a.time(endFrame) - 0.5 * SpeechFeatures::kHop;
        if (k + 1 < n)
            s.end = std::min(s.end, r.syllables[k + 1].start);
        s.end = std::max(s.end, s.start + 0.01);
        const TtsUnit &u = reference.units[k];
        // Phonemes: warped times, moved with the onset and kept inside the syllable.
        const double delta = s.start - mapTime(u.start + kReferencePad, true);
        for (const TtsPhoneme &p : u.phonemes)
            s.phonemes.append({p.name, std::clamp(mapTime(p.start + kReferencePad, true) + delta, s.start, s.end)});
    }
    r.speechStart = a.time(first) - 0.0125;
    r.speechEnd = a.time(last) + 0.0125;
    r.status = AlignStatus::Ok;
    if (progress)
        progress(1.0, QStringLiteral("aligned"));
    return r;
}

// The recording's features, or the failure that stops an alignment before it starts (an
// empty script or recording, a cancel while the features are computed).
std::optional<AlignResult> recordingFeatures(
    const Audio &audio, const Script &script, const std::atomic_bool *cancel, SpeechFeatures *out)
{
    if (script.syllables.isEmpty())
        return failure(AlignStatus::BadInput, QStringLiteral("the script is empty"));
    if (audio.isEmpty())
        return failure(AlignStatus::BadInput, QStringLiteral("the audio is empty"));
    *out = computeSpeechFeatures(resampled(audio, kSpeechSampleRate), cancel);
    if (isCancelled(cancel))
        return failure(AlignStatus::Cancelled, QStringLiteral("cancelled"));
    return std::nullopt;
}

} // namespace

AlignResult alignToReference(const Audio &audio, const Script &script, const TtsResult &reference,
    const SpeechProgressFn &progress, const std::atomic_bool *cancel)
{
    SpeechFeatures a;
    if (std::optional<AlignResult> stopped = recordingFeatures(audio, script, cancel, &a))
        return *stopped;
    return alignFeatures(a, script, reference, progress, cancel);
}

AlignResult alignScript(const Audio &audio, const Script &script, const AlignOptions &options,
    const SpeechProgressFn &progress, const std::atomic_bool *cancel)
{
    SpeechFeatures a;
    if (std::optional<AlignResult> stopped = recordingFeatures(audio, script, cancel, &a))
        return *stopped;
    TtsOptions tts = options.reference;
    const bool matchRate = tts.rate <= 0;
    if (matchRate)
        tts.rate = kDefaultRate;
    if (matchRate) {
        // Speak the reference at the speaker's pace: less warping, fewer mistakes. The pace
        // at the default rate is measured on (at most) the first 120 syllables.
        Script probe = script;
        if (probe.syllables.size() > 120)
            probe.syllables.resize(120);
        const TtsResult sample = synthesize(probe, tts, {}, cancel);
        if (isCancelled(cancel))
            return failure(AlignStatus::Cancelled, QStringLiteral("cancelled"));
        if (!sample.ok())
            return failure(AlignStatus::BadInput, sample.error);
        double spoken = 0;
        for (const TtsUnit &u : sample.units)
            spoken += u.end - u.start;
        spoken *= double(script.syllables.size()) / double(probe.syllables.size());
        const double ratio = a.speechDuration() / std::max(spoken, 0.01);
        if (ratio > 0.3 && ratio < 6 && std::abs(std::log(ratio)) > std::log(1.15))
            tts.rate = std::clamp(int(std::lround(kDefaultRate / ratio)), 80, 450);
        else if (probe.syllables.size() == script.syllables.size()) {
            if (progress)
                progress(0.1, QStringLiteral("reference"));
            return alignFeatures(a, script, sample, progress, cancel);
        }
    }
    const TtsResult reference = synthesize(script, tts, {}, cancel);
    if (isCancelled(cancel))
        return failure(AlignStatus::Cancelled, QStringLiteral("cancelled"));
    if (!reference.ok())
        return failure(AlignStatus::BadInput, reference.error);
    if (progress)
        progress(0.1, QStringLiteral("reference"));
    return alignFeatures(a, script, reference, progress, cancel);
}

} // namespace toonface
