#include "speech/boundaryrefine.h"

#include <algorithm>
#include <cmath>

namespace toonface {

namespace {

// The frames' signals the landmarks are read from, clamped at the ends.
struct Tracks
{
    const SpeechFeatures &f;
    double band(int t) const { return f.band[size_t(std::clamp(t, 0, f.frames - 1))]; }
    double energy(int t) const { return f.logEnergy[size_t(std::clamp(t, 0, f.frames - 1))]; }
    // The mid band lowered where voicing is lost (voicing averaged over ±10 ms: a rough
    // voice's voicing flickers): voicing 1 → 0.1 lowers it by 4.6 ln units (20 dB).
    double voiced(int t) const
    {
        double v = 0;
        for (int d = -1; d <= 1; ++d)
            v += f.voicing[size_t(std::clamp(t + d, 0, f.frames - 1))];
        return band(t) + 2.0 * std::log(std::clamp(v / 3.0, 0.1, 1.0));
    }
    // How far the broad spectrum (the normalised c1..c4 and the loudness channel of the DTW
    // vector) moves from frame t-1 to t+1.
    double change(int t) const
    {
        const float *x = f.vector(std::clamp(t - 1, 0, f.frames - 1));
        const float *y = f.vector(std::clamp(t + 1, 0, f.frames - 1));
        double acc = 0;
        for (int c = 0; c < 4; ++c)
            acc += double(x[c] - y[c]) * (x[c] - y[c]);
        const int loud = 2 * SpeechFeatures::kCepstra;
        acc += double(x[loud] - y[loud]) * (x[loud] - y[loud]);
        return std::sqrt(acc);
    }
};

// The offset (-0.5..0.5 frames) of the peak of a parabola through three samples around it.
double peakOffset(double before, double at, double after)
{
    const double curvature = before - 2 * at + after;
    if (curvature >= 0)
        return 0;
    return std::clamp(0.5 * (before - after) / curvature, -0.5, 0.5);
}

} // namespace

std::vector<RefinedBoundary> refineBoundaries(const SpeechFeatures &f, const OnsetSignals &sig, const BoundaryInput &in)
{
    const int n = int(in.starts.size());
    std::vector<RefinedBoundary> out(static_cast<size_t>(n));
    for (int k = 0; k < n; ++k)
        out[size_t(k)].start = in.starts[size_t(k)];
    if (f.frames < 3 || f.band.size() != size_t(f.frames))
        return out;
    const Tracks tr {f};
    // Frame t's window is centred on f.time(t): a step in the signal between the centres of
    // frames t-1 and t+1 shows as the largest difference across t, at f.time(t).
    auto frameOf = [&](double seconds) { return (seconds - f.time(0)) / SpeechFeatures::kHop; };
    for (int k = 0; k < n; ++k) {
        const double start = in.starts[size_t(k)];
        double lo = start - kRefineWindow, hi = start + kRefineWindow;
        if (k > 0)
            lo = std::max(lo, out[size_t(k) - 1].start + in.minSeconds[size_t(k) - 1]);
        const double next = k + 1 < n ? in.starts[size_t(k) + 1] : in.speechEnd;
        hi = std::min(hi, next - in.minSeconds[size_t(k)]);
        const int t0 = std::max(1, int(std::ceil(frameOf(lo)))),
                  t1 = std::min(f.frames - 2, int(std::floor(frameOf(hi))));
        if (t1 < t0)
            continue;
        // What marks this onset, per frame (ln units per 20 ms, or a valley's depth), and the
        // size that counts as a clear landmark.
        const int at = int(std::lround(frameOf(start)));
        const bool afterPause = sig.pauseFrames(at - 8, at - 1) >= 4 || (k == 0 && sig.isPause(at - 3));
        OnsetKind kind = in.kinds[size_t(k)];
        double clear = 3.0;
        auto score = [&](int t) -> double {
            if (afterPause)
                return tr.energy(t + 1) - tr.energy(t - 1);
            switch (kind) {
            case OnsetKind::Voiceless:
            case OnsetKind::VoicelessAfterNasal: return tr.voiced(t - 1) - tr.voiced(t + 1);
            case OnsetKind::Sonorant: return in.afterNasal[size_t(k)] ? tr.change(t) : tr.band(t - 1) - tr.band(t + 1);
            case OnsetKind::Vowel: {
                // The bottom of the valley: how far under the loudest frames 60 ms either side.
                double left = tr.band(t), right = tr.band(t);
                for (int d = 1; d <= 6; ++d) {
                    left = std::max(left, tr.band(t - d));
                    right = std::max(right, tr.band(t + d));
                }
                return std::min(left, right) - tr.band(t);
            }
            case OnsetKind::Any: return 0;
            }
            return 0;
        };
        if (afterPause)
            clear = 3.0;
        else if (kind == OnsetKind::Sonorant)
            clear = in.afterNasal[size_t(k)] ? 1.0 : 1.5;
        else if (kind == OnsetKind::Vowel)
            clear = 2.0;
        else if (kind == OnsetKind::Any)
            continue; // English words: no landmark rule
        int best = -1;
        double bestScore = 0;
        for (int t = t0; t <= t1; ++t) {
            const double s = score(t);
            if (best < 0 || s > bestScore) {
                best = t;
                bestScore = s;
            }
        }
        const double strength = std::clamp(bestScore / clear, 0.0, 1.0);
        // A weak landmark is no better evidence than the segmentation's: the onset stays.
        if (best < 0 || strength < 0.34)
            continue;
        double onset = f.time(best) + peakOffset(score(best - 1), bestScore, score(best + 1)) * SpeechFeatures::kHop;
        // A fall into a closure or a murmur, or a rise out of a pause, takes 20-40 ms; the
        // consonant begins where it starts, not at its steepest (the middle): its leading
        // edge, where the step first reaches half its steepest, interpolated between frames.
        // (At the steepest point, voiceless onsets were about 20 ms late against a forced
        // aligner's boundaries on a real speaker; the mouth may lead the sound, never trail it.)
        if (afterPause || kind == OnsetKind::Voiceless || (kind == OnsetKind::Sonorant && !in.afterNasal[size_t(k)])) {
            const double half = 0.5 * bestScore;
            int t = best;
            while (t - 1 >= t0 && score(t - 1) >= half)
                --t;
            const double before = score(t - 1), here = score(t);
            const double share = here > before ? std::clamp((here - half) / (here - before), 0.0, 1.0) : 0.0;
            // score(t) spans frames t-1..t+1: it widens a fall by a frame either side, so
            // the fall itself starts a frame after the half-way crossing (a sharp step stays
            // at the peak).
            onset = std::min(onset, f.time(t) + (1.0 - share) * SpeechFeatures::kHop);
        }
        out[size_t(k)].start = std::clamp(onset, lo, hi);
        out[size_t(k)].strength = strength;
    }
    return out;
}

} // namespace toonface
