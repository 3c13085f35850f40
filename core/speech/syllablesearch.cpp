#include "speech/syllablesearch.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace toonface {

std::vector<int> segmentSyllables(const OnsetSignals &sig, const std::vector<int> &prior,
    const std::vector<double> &expected, const std::vector<int> &minFrames, const std::vector<OnsetKind> &kinds,
    const std::vector<double> &priorWeight, int speechEnd, std::vector<double> *evidence)
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
    // The window counts frames of speech: a pause the script does not mark (or noise before
    // the speech that the warp took for it) does not use it up.
    std::vector<double> speechBefore(size_t(T) + 1, 0.0);
    for (int t = 0; t < T; ++t)
        speechBefore[size_t(t) + 1] = speechBefore[size_t(t)] + (sig.isPause(t) ? 0.0 : 1.0);
    for (int k = 0; k < n; ++k) {
        const double at = speechBefore[size_t(std::clamp(prior[size_t(k)], 0, T))];
        lo[size_t(k)]
            = int(std::lower_bound(speechBefore.begin(), speechBefore.end(), at - kWindow) - speechBefore.begin());
        hi[size_t(k)]
            = int(std::upper_bound(speechBefore.begin(), speechBefore.end(), at + kWindow) - speechBefore.begin()) - 1;
        lo[size_t(k)] = std::clamp(lo[size_t(k)], 0, T - 1);
        hi[size_t(k)] = std::clamp(hi[size_t(k)], 0, T - 1);
        if (k > 0)
            lo[size_t(k)] = std::max(lo[size_t(k)], lo[size_t(k) - 1] + minFrames[size_t(k) - 1]);
    }
    for (int k = n - 2; k >= 0; --k)
        hi[size_t(k)] = std::min(hi[size_t(k)], hi[size_t(k) + 1] - minFrames[size_t(k)]);
    // The windows of neighbouring syllables overlap: each frame's evidence for a kind of onset
    // is worked out once (NaN: not yet).
    constexpr int kKinds = int(OnsetKind::Any) + 1;
    std::array<std::vector<double>, kKinds> evidenceOf;
    auto onsetEvidence = [&](int b, int k) {
        if (k == 0)
            return sig.onsetEvidence(b, kinds[0], true);
        std::vector<double> &cache = evidenceOf[size_t(kinds[size_t(k)])];
        if (cache.empty())
            cache.assign(size_t(T), std::nan(""));
        double &e = cache[size_t(b)];
        if (std::isnan(e))
            e = sig.onsetEvidence(b, kinds[size_t(k)], false);
        return e;
    };
    auto node = [&](int k, int b) {
        const double d = (b - prior[size_t(k)]) / kPriorSigma;
        return kOnset * onsetEvidence(b, k) - kPrior * priorWeight[size_t(k)] * std::min(0.5 * d * d, kPriorCap);
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
    // A syllable over [from, to): its nucleus and its length (pauses excluded) score `base`,
    // from which `penalty` (never negative) is taken. base alone bounds the span's score from
    // above: the search skips the penalty where that bound cannot win.
    // (`speech` the span's frames less its pauses, `nucleus` its strongest nucleus.)
    auto baseOf = [&](int k, double speech, double nucleus) {
        const double len = std::max(1.0, speech);
        const double r
            = (len < double(logLength.size()) ? logLength[size_t(len)] : std::log(len)) - logExpected[size_t(k)];
        return kNucleus * nucleus - kDuration * r * r;
    };
    auto base = [&](int k, int from, int to) {
        return baseOf(k, (to - from) - sig.pauseFrames(from, to), sig.maxNucleus(from, to));
    };
    // (`valley` the span's sig.innerValley(from, to).)
    auto penaltyOf = [&](int from, int to, double valley) {
        // Two loud peaks inside with a valley of 3 ln units (13 dB) between them: a syllable
        // boundary missed.
        const double inside = std::clamp((valley - 1.0) / 2.0, 0.0, 1.0);
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
        return kValley * (inside + pauseInside);
    };
    auto penalty = [&](int from, int to) { return penaltyOf(from, to, sig.innerValley(from, to)); };
    constexpr double kNone = -1e18;
    std::vector<std::vector<double>> score(static_cast<size_t>(n));
    std::vector<std::vector<int>> from(static_cast<size_t>(n));
    // The best score of the syllable before at or before each of its onsets: with the
    // strongest nucleus the spans can hold, it bounds what the onsets further back can score
    // once their spans are longer than expected (and grow longer still): the search stops
    // where the bound cannot win.
    std::vector<double> bestBefore;
    for (int k = 0; k < n; ++k) {
        const int w = std::max(hi[size_t(k)] - lo[size_t(k)] + 1, 0);
        score[size_t(k)].assign(size_t(w), kNone);
        from[size_t(k)].assign(size_t(w), -1);
        if (k > 0) {
            const std::vector<double> &before = score[size_t(k) - 1];
            bestBefore.resize(before.size());
            for (size_t q = 0; q < before.size(); ++q)
                bestBefore[q] = q > 0 ? std::max(bestBefore[q - 1], before[q]) : before[q];
        }
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
            const int shortest = minFrames[size_t(k) - 1];
            // The span [p, b)'s pauses, strongest nucleus and deepest valley, kept as p moves
            // back a frame at a time (the same values as the window sums and maxima, without
            // their look-ups).
            const int start = std::min(hi[size_t(k) - 1], b - shortest);
            int pauses = start >= lo[size_t(k) - 1] ? int(sig.pauseFrames(start, b)) : 0;
            double nucleus = start >= lo[size_t(k) - 1] ? sig.maxNucleus(start, b) : 0.0;
            double valley = start >= lo[size_t(k) - 1] ? sig.innerValley(start, b) : 0.0;
            const double strongest = kNucleus * sig.maxNucleus(lo[size_t(k) - 1], b);
            for (int p = start; p >= lo[size_t(k) - 1]; --p) {
                if (p < start) {
                    pauses += sig.isPause(p) ? 1 : 0;
                    nucleus = std::max(nucleus, sig.nucleus(p));
                    valley = std::max(valley, sig.valleyFromPeak(p + 2, b));
                }
                const double speech = (b - p) - pauses;
                if (speech > longest)
                    break;
                {
                    const double len = std::max(1.0, speech);
                    const double r = (len < double(logLength.size()) ? logLength[size_t(len)] : std::log(len))
                        - logExpected[size_t(k) - 1];
                    if (r >= 0 && bestBefore[size_t(p - lo[size_t(k) - 1])] + (strongest - kDuration * r * r) <= best)
                        break;
                }
                if (speech < shortest)
                    continue;
                const double prev = score[size_t(k) - 1][size_t(p - lo[size_t(k) - 1])];
                if (prev <= kNone / 2)
                    continue;
                const double b0 = baseOf(k - 1, speech, nucleus);
                if (prev + b0 <= best)
                    continue;
                const double v = prev + (b0 - penaltyOf(p, b, valley));
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
        // The last syllable's minimum too, unless the speech ends too soon for any (then the
        // longest last syllable wins by its duration cost).
        const double speech = (speechEnd - b) - sig.pauseFrames(b, speechEnd);
        const int end = std::max(speechEnd, b + 1);
        const double v = s0 + (base(n - 1, b, end) - penalty(b, end))
            - (speech < minFrames[size_t(n) - 1] ? 1e6 * (minFrames[size_t(n) - 1] - speech) : 0.0);
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

} // namespace toonface
