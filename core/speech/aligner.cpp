#include "speech/aligner.h"

#include "i18n/coretext.h"
#include "speech/boundaryrefine.h"
#include "speech/dtw.h"
#include "speech/features.h"
#include "speech/hiddeninitials.h"
#include "speech/onsetsignals.h"
#include "speech/paceprobe.h"
#include "speech/pinyin.h"
#include "speech/referencefeatures.h"
#include "speech/speakeradapt.h"
#include "speech/stagetimes.h"
#include "speech/syllableduration.h"
#include "speech/syllablesearch.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace toonface {

namespace {

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

// Each syllable's confidence from its doubts against the recording's (alignconfidence.h); 0 for
// the syllables not spoken.
void setConfidences(AlignResult *r)
{
    std::vector<Doubts> raw;
    for (const AlignedSyllable &s : std::as_const(r->syllables))
        raw.push_back(s.doubts);
    const std::vector<Doubts> relative = relativeDoubts(raw);
    for (qsizetype k = 0; k < r->syllables.size(); ++k)
        r->syllables[k].confidence = r->unspoken.contains(int(k)) ? 0.0 : syllableConfidence(relative[size_t(k)]);
}

using WarpPath = std::vector<std::pair<int, int>>;

// What the aligner reads of the recording's and the reference's pauses: the same for every
// pass (adapting the reference moves its vectors, not its loudness or silence).
struct PauseSignals
{
    OnsetSignals sig; // the recording's
    // Silence for the warp: quiet by the whole band's energy, or a pause by the mid band's
    // loudness. Steady noise (hum, a fan, a noisy line) can keep a pause's whole-band energy
    // near that of speech; counted as speech, the noise before the first word draws the first
    // syllables into it and squeezes them.
    std::vector<float> quietA, quietB;
    std::vector<float> longA, longB; // pauses, not closures
    double refSpeech = 0; // frames of the reference that are not pause

    PauseSignals(const SpeechFeatures &a, const SpeechFeatures &b)
        : sig(a)
        , quietA(a.silence)
        , quietB(b.silence)
        , longA(size_t(a.frames), 0.0f)
        , longB(size_t(b.frames), 0.0f)
    {
        const OnsetSignals refSig(b);
        for (int t = 0; t < b.frames; ++t)
            if (refSig.isPause(t))
                quietB[size_t(t)] = longB[size_t(t)] = 1.0f;
        refSpeech = b.frames - refSig.pauseFrames(0, b.frames);
        for (int t = 0; t < a.frames; ++t)
            if (sig.isPause(t))
                quietA[size_t(t)] = longA[size_t(t)] = 1.0f;
    }
};

// The aligner proper, on the recording's features `a` and the padded reference's `b`. With
// `guide` (the warp of an earlier pass against a like reference) the warp searches near it
// (DtwOptions::guide); `warp` (optional) receives the warp.
AlignResult alignFeatures(const SpeechFeatures &a, const Script &script, const TtsResult &reference,
    const SpeechFeatures &b, const PauseSignals &in, bool refine, const SpeechProgressFn &progress,
    const std::atomic_bool *cancel, const WarpPath *guide = nullptr, WarpPath *warpOut = nullptr)
{
    const int n = int(script.syllables.size());
    if (!reference.ok() || reference.units.size() != n)
        return failure(AlignStatus::BadInput, ScriptText::tr("no reference rendering of the script"));
    if (isCancelled(cancel))
        return failure(AlignStatus::Cancelled, QStringLiteral("cancelled"));
    if (progress)
        progress(0.3, QStringLiteral("features"));

    // ln(power) spans at least ~12 dB between pauses and speech in any recording with speech.
    const double speech = a.speechDuration();
    if (a.frames < 10 || a.speechLevel - a.noiseFloor < 2.8f || speech < 0.08)
        return failure(AlignStatus::CannotAlign, ScriptText::tr("no speech found in the audio"));
    const double expected = b.speechDuration();
    if (speech < 0.3 * expected)
        return failure(AlignStatus::CannotAlign,
            ScriptText::tr("the script is far too long for the audio: its %1 syllables need about %2 s of "
                           "speech, the audio holds %3 s")
                .arg(n)
                .arg(expected, 0, 'f', 1)
                .arg(speech, 0, 'f', 1));
    if (speech > 6.0 * expected)
        return failure(AlignStatus::CannotAlign,
            ScriptText::tr("the audio holds far more speech (%1 s) than the script's %2 syllables (about "
                           "%3 s)")
                .arg(speech, 0, 'f', 1)
                .arg(n)
                .arg(expected, 0, 'f', 1));

    DtwOptions opt;
    opt.dim = SpeechFeatures::kDim;
    // Pauses the script does not mark and changes of pace move a moment of the recording
    // from its share of the speech by seconds, not by minutes.
    opt.band = 3000; // frames: ±30 s
    opt.maxFullCells = 6000000;
    // The coarsest level of a long recording averages 40-80 ms into a frame: where a pause the
    // script does not mark lies, it may put the pause one or two syllables off. The next level
    // may move the path by up to 30 of its frames (a syllable or two) to put it right; the
    // finer ones keep the default radius. (With the default at every level, sentences of
    // joined real recordings landed up to 1.9 s late; 20 at every level still left one.)
    opt.coarseRadius = 30;
    opt.guide = guide;
    // A long recording's coarsest level searches near a pilot one level coarser: the same
    // onsets on the shared recordings, joined to a minute, and on espeak-ng's held-out voices.
    opt.pilot = true;
    const std::vector<float> &quietA = in.quietA, &quietB = in.quietB;
    const OnsetSignals &sig = in.sig;
    const double refSpeech = in.refSpeech;
    // The speaker may pause between any two syllables, not only where the script marks a
    // break: the warp may hold the last frame of each of the reference's syllables over a
    // pause of the recording at a small cost (dtw.h). A stop's closure inside a syllable is
    // too short to be a pause (onsetsignals.h) and is not absorbed this way.
    std::vector<float> pauseB(size_t(b.frames), 0.0f);
    for (int k = 1; k < n; ++k) {
        const int j = b.frameAt(reference.units[k].start + kReferencePad) - 1;
        if (j >= 0 && j < b.frames)
            pauseB[size_t(j)] = 1.0f;
    }
    const auto path = dtwPath({a.vectors.data(), quietA.data(), a.frames, in.longA.data()},
        {b.vectors.data(), quietB.data(), b.frames, in.longB.data(), pauseB.data()}, opt, cancel);
    if (isCancelled(cancel))
        return failure(AlignStatus::Cancelled, QStringLiteral("cancelled"));
    if (path.empty())
        return failure(AlignStatus::CannotAlign, ScriptText::tr("the audio and the script could not be matched"));
    if (progress)
        progress(0.8, QStringLiteral("warping"));
    const Warp warp(path, b.frames);
    if (warpOut)
        *warpOut = path;

    // Reference time → audio time. Where the recording is slower, the warp holds one reference
    // frame against several of its frames, and the reference's moment may be any of them: an
    // onset takes the middle of those that are speech (a pause absorbed there belongs before
    // the syllable), not the first, which is early by half the hold.
    auto mapTime = [&](double tRef, bool onset) {
        const int j = b.frameAt(tRef);
        int i0 = warp.firstA[size_t(j)], i1 = warp.lastA[size_t(j)];
        if (onset) {
            int i = i0;
            while (i < i1 && quietA[size_t(i)] > 0.5f)
                ++i;
            while (i1 > i && quietA[size_t(i1)] > 0.5f)
                --i1;
            i0 = (i + i1) / 2;
        } else {
            int i = i1;
            while (i > i0 && quietA[size_t(i)] > 0.5f)
                --i;
            i0 = i;
        }
        return std::max(0.0, a.time(i0) + (tRef - b.time(j)));
    };

    // Warped estimates, then the segmentation that settles each onset on the signal.
    std::vector<int> prior(static_cast<size_t>(n));
    std::vector<double> expectedFrames(static_cast<size_t>(n));
    std::vector<OnsetKind> kinds(static_cast<size_t>(n));
    std::vector<bool> inMurmur(static_cast<size_t>(n), false); // a sonorant initial after a nasal coda
    // The speaker's pace against the reference's, pauses excluded.
    const double targetSpeech = a.frames - sig.pauseFrames(0, a.frames);
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
        // A voiceless initial after a nasal coda starts where the coda's voicing ends
        // (OnsetKind::VoicelessAfterNasal).
        if (k > 0) {
            const QString &before = script.syllables[k - 1].pinyin;
            if (before.endsWith(QLatin1Char('n')) || before.endsWith(QLatin1String("ng"))) {
                if (kinds[size_t(k)] == OnsetKind::Sonorant) {
                    kinds[size_t(k)] = OnsetKind::Any;
                    inMurmur[size_t(k)] = true;
                } else if (kinds[size_t(k)] == OnsetKind::Voiceless)
                    kinds[size_t(k)] = OnsetKind::VoicelessAfterNasal;
            }
        }
    }
    int first = 0, last = a.frames - 1;
    while (first < last && quietA[size_t(first)] > 0.5f)
        ++first;
    while (last > first && quietA[size_t(last)] > 0.5f)
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
    // How much of the recording's speech the warp gave each syllable, against its reference
    // length at the speaker's pace: a word the speaker left out has next to none (the warp
    // runs through its reference frames over a frame or two).
    std::vector<double> heard(static_cast<size_t>(n), 1.0);
    for (int k = 0; k < n; ++k) {
        const int j0 = b.frameAt(reference.units[k].start + kReferencePad);
        const int j1 = std::max(j0, b.frameAt(reference.units[k].end + kReferencePad) - 1);
        double refFrames = 0, recFrames = 0;
        for (int j = j0; j <= j1; ++j)
            refFrames += quietB[size_t(j)] > 0.5f ? 0.0 : 1.0;
        for (int i = warp.firstA[size_t(j0)]; i >= 0 && i <= warp.lastA[size_t(j1)]; ++i)
            recFrames += quietA[size_t(i)] > 0.5f ? 0.0 : 1.0;
        if (refFrames >= 3)
            heard[size_t(k)] = recFrames / (refFrames * pace);
    }
    // The duration model: each syllable's least plausible length at this speaker's pace (their
    // mean syllable length, pauses aside).
    const double meanSyllable = targetSpeech * SpeechFeatures::kHop / n;
    std::vector<double> minSeconds(static_cast<size_t>(n));
    std::vector<int> minFrames(static_cast<size_t>(n));
    for (int k = 0; k < n; ++k) {
        const ScriptSyllable &syl = script.syllables[k];
        minSeconds[size_t(k)] = minimumSyllableSeconds(syl.pinyin, syl.tone, meanSyllable / kOrdinarySyllable);
        minFrames[size_t(k)] = std::max(3, int(std::ceil(minSeconds[size_t(k)] / SpeechFeatures::kHop - 1e-9)));
    }
    // Where the speaker pauses and the script marks no break, the warp decides at which
    // boundary the pause goes from the sounds alone, and a vowel or glide after a like vowel
    // (wu wo) leaves that open: the syllables either side of such a pause are placed by
    // the signal (the rise out of the pause, their lengths) more than by the warp.
    std::vector<double> priorWeight(static_cast<size_t>(n), 1.0);
    for (int k = 0; k < n; ++k) {
        const int from = prior[size_t(std::max(k - 1, 0))], to = prior[size_t(std::min(k + 1, n - 1))];
        const bool marked = (k > 0 && script.syllables[k - 1].phraseBreakAfter) || script.syllables[k].phraseBreakAfter;
        if (!marked && sig.pauseFrames(from, to) >= 15)
            priorWeight[size_t(k)] = 0.25;
    }
    std::vector<double> evidence;
    std::vector<int> onsets
        = segmentSyllables(sig, prior, expectedFrames, minFrames, kinds, priorWeight, last + 1, &evidence);
    if (evidence.empty()) {
        // Too little speech for every syllable's minimum: the shortest the search allows.
        onsets = segmentSyllables(
            sig, prior, expectedFrames, std::vector<int>(size_t(n), 3), kinds, priorWeight, last + 1, &evidence);
        std::fill(minSeconds.begin(), minSeconds.end(), 0.03);
    }
    if (evidence.empty()) {
        for (int k = 0; k < n; ++k)
            evidence.push_back(sig.onsetEvidence(onsets[size_t(k)], kinds[size_t(k)], k == 0));
        std::fill(minSeconds.begin(), minSeconds.end(), 0.0);
    }

    // Each onset's candidates: the segmentation's boundary, the warped estimate, their mean.
    // The signal's boundary is preferred only where it is clearly the better onset; where the
    // two agree within 40 ms, both are estimates of one event and their mean is preferred
    // (boundary conventions differ by about that much). The choice is made for all syllables
    // at once so that every syllable keeps its minimum length (the segmentation's boundaries
    // always do).
    struct Candidate
    {
        double start;
        double cost;
    };
    std::vector<std::array<Candidate, 3>> candidates(static_cast<size_t>(n));
    std::vector<double> warpGap(static_cast<size_t>(n), 0.0);
    for (int k = 0; k < n; ++k) {
        // A frame's onset is the start of its window's middle 10 ms.
        const double refined = a.time(onsets[size_t(k)]) - 0.5 * SpeechFeatures::kHop;
        const double warped = mapTime(reference.units[k].start + kReferencePad, true);
        const double atWarped
            = sig.onsetEvidence(a.frameAt(warped + 0.5 * SpeechFeatures::kHop), kinds[size_t(k)], k == 0);
        // A pause between the two settles it for the segmentation, which knows that a
        // syllable cannot begin before a pause and have its nucleus after it.
        const int w0 = std::min(onsets[size_t(k)], a.frameAt(warped)),
                  w1 = std::max(onsets[size_t(k)], a.frameAt(warped));
        const bool pauseBetween = sig.pauseFrames(w0, w1) > 0;
        // A sonorant initial in a nasal coda's murmur has no evidence either way, and the warp,
        // with nothing to hold on to inside the murmur, put it early (median 49 ms, up to 140 ms
        // on the held-out voices; p2fa's 老 after 欢 105 ms): the segmentation's boundary, placed
        // by the lengths of the syllables either side, is preferred there.
        const bool keepWarped = evidence[size_t(k)] - atWarped < 0.25 && !pauseBetween && !inMurmur[size_t(k)];
        const bool close = std::abs(refined - warped) <= 0.04;
        warpGap[size_t(k)] = std::abs(refined - warped);
        candidates[size_t(k)] = {{{refined, keepWarped || close ? 1.0 : 0.0}, {warped, keepWarped ? 0.0 : 2.0},
            {0.5 * (refined + warped), !keepWarped && close ? 0.0 : 1.5}}};
    }
    // Seconds of speech (pauses aside) between two moments.
    auto speechBetween = [&](double t0, double t1) {
        const int f0 = a.frameAt(t0 + 0.5 * SpeechFeatures::kHop), f1 = a.frameAt(t1 + 0.5 * SpeechFeatures::kHop);
        return (t1 - t0) - sig.pauseFrames(f0, f1) * SpeechFeatures::kHop;
    };
    std::vector<std::array<double, 3>> total(static_cast<size_t>(n));
    std::vector<std::array<int, 3>> back(static_cast<size_t>(n));
    for (int c = 0; c < 3; ++c)
        total[0][size_t(c)] = candidates[0][size_t(c)].cost;
    for (int k = 1; k < n; ++k) {
        for (int c = 0; c < 3; ++c) {
            double best = 1e18;
            int arg = 0;
            for (int q = 0; q < 3; ++q) {
                // The segmentation's own pair always fits; others must leave the minimum.
                const double room
                    = speechBetween(candidates[size_t(k) - 1][size_t(q)].start, candidates[size_t(k)][size_t(c)].start);
                const bool fits = (q == 0 && c == 0) || room >= minSeconds[size_t(k) - 1] - 1e-6;
                const double v = total[size_t(k) - 1][size_t(q)] + (fits ? 0.0 : 1e6);
                if (v < best) {
                    best = v;
                    arg = q;
                }
            }
            total[size_t(k)][size_t(c)] = best + candidates[size_t(k)][size_t(c)].cost;
            back[size_t(k)][size_t(c)] = arg;
        }
    }
    std::vector<int> chosen(static_cast<size_t>(n), 0);
    {
        int c = 0;
        for (int q = 1; q < 3; ++q)
            if (total[size_t(n) - 1][size_t(q)] < total[size_t(n) - 1][size_t(c)])
                c = q;
        for (int k = n - 1; k >= 0; --k) {
            chosen[size_t(k)] = c;
            c = back[size_t(k)][size_t(c)];
        }
    }

    AlignResult r;
    r.syllables.resize(n);
    for (int k = 0; k < n; ++k) {
        AlignedSyllable &s = r.syllables[k];
        s.start = candidates[size_t(k)][size_t(chosen[size_t(k)])].start;
    }
    // The second pass: each onset to its landmark nearby.
    std::vector<double> landmark(static_cast<size_t>(n), 0.0);
    if (refine) {
        BoundaryInput in;
        in.speechEnd = a.time(last + 1) - 0.5 * SpeechFeatures::kHop;
        for (int k = 0; k < n; ++k) {
            in.starts.push_back(r.syllables[k].start);
            in.kinds.push_back(onsetKind(script.syllables[k]));
            const QString before = k > 0 ? script.syllables[k - 1].pinyin : QString();
            in.afterNasal.push_back(before.endsWith(QLatin1Char('n')) || before.endsWith(QLatin1String("ng")));
            in.minSeconds.push_back(minSeconds[size_t(k)]);
        }
        const std::vector<RefinedBoundary> refined = refineBoundaries(a, sig, in);
        for (int k = 0; k < n; ++k) {
            at(r.syllables[k].doubts, Doubt::RefineMove) = std::abs(refined[size_t(k)].start - r.syllables[k].start);
            r.syllables[k].start = refined[size_t(k)].start;
            landmark[size_t(k)] = refined[size_t(k)].strength;
        }
    }
    moveOnsetsOfHiddenInitials(a, sig, script, reference, pace, &r);
    for (int k = 0; k < n; ++k) {
        AlignedSyllable &s = r.syllables[k];
        // A syllable ends where the next begins, or where a pause after it begins (never
        // before its minimum length).
        const double next = k + 1 < n ? r.syllables[k + 1].start : a.time(last + 1) - 0.5 * SpeechFeatures::kHop;
        int endFrame = a.frameAt(next + 0.5 * SpeechFeatures::kHop);
        const int startFrame = a.frameAt(s.start + 0.5 * SpeechFeatures::kHop);
        // The next onset may lie a few frames past the pause's end (the first sound of its
        // initial): the pause before it is still this syllable's end.
        // (Never ending the syllable before its minimum length.)
        for (int e = endFrame, back = 0; e - 1 > startFrame && back <= 5; --e, ++back)
            if (sig.isPause(e - 1)) {
                if (a.time(e) - 0.5 * SpeechFeatures::kHop >= s.start + minSeconds[size_t(k)] - 1e-9)
                    endFrame = e;
                break;
            }
        while (endFrame - 1 > startFrame && sig.isPause(endFrame - 1)
            && a.time(endFrame - 1) - 0.5 * SpeechFeatures::kHop >= s.start + minSeconds[size_t(k)])
            --endFrame;
        s.end = std::min(next, a.time(endFrame) - 0.5 * SpeechFeatures::kHop);
        s.end = std::max(s.end, s.start + 0.01);
        // What may make the onset doubtful (alignconfidence.h).
        Doubts &d = s.doubts;
        at(d, Doubt::Unclear) = 1.0 - std::max(std::clamp(evidence[size_t(k)] / 0.5, 0.0, 1.0), landmark[size_t(k)]);
        at(d, Doubt::WarpGap) = warpGap[size_t(k)];
        at(d, Doubt::PriorShift) = std::abs(onsets[size_t(k)] - prior[size_t(k)]) * SpeechFeatures::kHop;
        at(d, Doubt::Match) = match[size_t(k)];
        {
            double around = 0;
            int count = 0;
            for (const int j : {k - 1, k + 1})
                if (j >= 0 && j < n) {
                    around += match[size_t(j)];
                    ++count;
                }
            at(d, Doubt::MatchExcess) = count ? match[size_t(k)] - around / count : 0.0;
            at(d, Doubt::NeighbourGap)
                = std::max(k > 0 ? warpGap[size_t(k) - 1] : 0.0, k + 1 < n ? warpGap[size_t(k) + 1] : 0.0);
        }
        const double length = std::max(s.end - s.start, 0.01);
        at(d, Doubt::LengthMisfit) = std::abs(std::log(length / (expectedFrames[size_t(k)] * SpeechFeatures::kHop)));
        at(d, Doubt::AtMinimum) = length < 1.2 * minSeconds[size_t(k)] ? 1.0 : 0.0;
        {
            // Frames to the nearest pause either side of the onset (the speech before the
            // first syllable and after the last counts as pause).
            constexpr int kFar = 100; // 1 s
            int nearest = kFar;
            for (int t = startFrame, steps = 0; steps < kFar; --t, ++steps)
                if (t < first || sig.isPause(t)) {
                    nearest = steps;
                    break;
                }
            nearest = std::min(nearest, std::max(0, std::min(sig.nextPause(startFrame), last + 1) - startFrame));
            at(d, Doubt::NearPause) = 1.0 - std::min(nearest, kFar) / double(kFar);
        }
        at(d, Doubt::HeardMisfit) = std::abs(std::log(std::max(heard[size_t(k)], 0.05)));
        s.heard = heard[size_t(k)];
        if (s.heard < kUnspokenShare)
            r.unspoken.append(k);
        const TtsUnit &u = reference.units[k];
        // Phonemes: warped times, moved with the onset and kept inside the syllable.
        const double delta = s.start - mapTime(u.start + kReferencePad, true);
        for (const TtsPhoneme &p : u.phonemes)
            s.phonemes.append({p.name, std::clamp(mapTime(p.start + kReferencePad, true) + delta, s.start, s.end)});
    }
    setConfidences(&r);
    r.speechStart = a.time(first) - 0.0125;
    r.speechEnd = a.time(last) + 0.0125;
    r.status = AlignStatus::Ok;
    if (progress)
        progress(1.0, QStringLiteral("aligned"));
    return r;
}

// Where the initial of each syllable ends: its second phoneme's start (the first is the
// initial), or its start when it has none.
std::vector<double> initialEnds(const Script &script, const std::vector<double> &starts,
    const std::vector<const QVector<TtsPhoneme> *> &phonemes, double offset)
{
    std::vector<double> out(starts);
    for (qsizetype k = 0; k < script.syllables.size(); ++k) {
        const std::optional<PinyinParts> parts = splitPinyinSyllable(script.syllables[k].pinyin);
        if (parts && !parts->initial.isEmpty() && phonemes[size_t(k)]->size() > 1)
            out[size_t(k)] = (*phonemes[size_t(k)])[1].start + offset;
    }
    return out;
}

// alignFeatures, then re-aligned against the reference adapted to the speaker as the
// alignment heard them (speakeradapt.h) until the onsets stop moving.
AlignResult alignPasses(const SpeechFeatures &a, const Script &script, const TtsResult &reference,
    const SpeechFeatures &b, bool refine, bool adapt, const SpeechProgressFn &progress, const std::atomic_bool *cancel)
{
    if (!reference.ok() || reference.units.size() != script.syllables.size())
        return failure(AlignStatus::BadInput, ScriptText::tr("no reference rendering of the script"));
    const PauseSignals pauses(a, b);
    WarpPath warp;
    AlignResult r = alignFeatures(a, script, reference, b, pauses, refine, progress, cancel, nullptr, &warp);
    markStage("first alignment");
    const int n = int(script.syllables.size());
    // Too few syllables say too little about the voice: on single sentences (10-20
    // syllables) the adapted reference moved runs of onsets by 100-250 ms where the first
    // alignment had them within 30 ms.
    if (!adapt || !r.ok() || script.language == Language::English || n < kAdaptMinSyllables)
        return r;
    std::vector<int> refClasses;
    {
        std::vector<double> starts, ends;
        std::vector<const QVector<TtsPhoneme> *> phonemes;
        for (const TtsUnit &u : reference.units) {
            starts.push_back(u.start + kReferencePad);
            ends.push_back(u.end + kReferencePad);
            phonemes.push_back(&u.phonemes);
        }
        refClasses = soundClasses(b, script, starts, initialEnds(script, starts, phonemes, kReferencePad), ends);
    }
    std::vector<double> firstPass;
    for (const AlignedSyllable &syl : r.syllables)
        firstPass.push_back(syl.start);
    // Each round moves the onsets less; past a few the changes are within a frame.
    constexpr int kMaxRounds = 2;
    constexpr double kStable = 0.01; // seconds
    for (int round = 0; round < kMaxRounds; ++round) {
        std::vector<double> starts, ends;
        std::vector<const QVector<TtsPhoneme> *> phonemes;
        for (const AlignedSyllable &s : r.syllables) {
            starts.push_back(s.start);
            ends.push_back(s.end);
            phonemes.push_back(&s.phonemes);
        }
        SpeechFeatures adapted = b;
        adaptReference(
            a, soundClasses(a, script, starts, initialEnds(script, starts, phonemes, 0.0), ends), &adapted, refClasses);
        // The adapted reference warps onto the recording much as the plain one did: near the
        // warp before (within DtwOptions::guideRadius; the band's search found the same onsets).
        WarpPath nextWarp;
        AlignResult next = alignFeatures(a, script, reference, adapted, pauses, refine, {}, cancel, &warp, &nextWarp);
        markStage("adapted alignment");
        if (!next.ok())
            break;
        double moved = 0;
        for (int k = 0; k < n; ++k)
            moved = std::max(moved, std::abs(next.syllables[k].start - r.syllables[k].start));
        r = std::move(next);
        warp = std::move(nextWarp);
        if (moved < kStable)
            break;
    }
    // Where adapting moved an onset far, the first pass and the adapted one disagree: doubt.
    for (int k = 0; k < n; ++k)
        at(r.syllables[k].doubts, Doubt::PassMove) = std::abs(r.syllables[k].start - firstPass[size_t(k)]);
    setConfidences(&r);
    return r;
}

// alignPasses, with each syllable that ends at the next one's onset frame (no pause between
// them) ended at that onset itself: a frame's time falls up to a frame before the onset, and
// a syllable at its least length came out that much shorter. (The passes and the doubts keep
// the frame's time, as the confidence was fitted with it.)
AlignResult alignAdapted(const SpeechFeatures &a, const Script &script, const TtsResult &reference,
    const SpeechFeatures &b, bool refine, bool adapt, const SpeechProgressFn &progress, const std::atomic_bool *cancel)
{
    AlignResult r = alignPasses(a, script, reference, b, refine, adapt, progress, cancel);
    for (qsizetype k = 0; r.ok() && k + 1 < r.syllables.size(); ++k) {
        AlignedSyllable &s = r.syllables[k];
        const double next = r.syllables[k + 1].start;
        const double frame = a.time(a.frameAt(next + 0.5 * SpeechFeatures::kHop)) - 0.5 * SpeechFeatures::kHop;
        if (s.end >= std::min(next, frame) - 1e-9)
            s.end = std::max(s.end, next);
    }
    return r;
}

// The recording's features, or the failure that stops an alignment before it starts (an
// empty script or recording, a cancel while the features are computed).
std::optional<AlignResult> recordingFeatures(
    const Audio &audio, const Script &script, const std::atomic_bool *cancel, SpeechFeatures *out)
{
    if (script.syllables.isEmpty())
        return failure(AlignStatus::BadInput, ScriptText::tr("the script is empty"));
    if (audio.isEmpty())
        return failure(AlignStatus::BadInput, ScriptText::tr("the audio is empty"));
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
    if (!reference.ok() || reference.units.size() != script.syllables.size())
        return failure(AlignStatus::BadInput, ScriptText::tr("no reference rendering of the script"));
    return alignAdapted(a, script, reference, referenceFeatures(reference.audio, cancel), true, true, progress, cancel);
}

AlignResult alignScript(const Audio &audio, const Script &script, const AlignOptions &options,
    const SpeechProgressFn &progress, const std::atomic_bool *cancel)
{
    SpeechFeatures a;
    if (std::optional<AlignResult> stopped = recordingFeatures(audio, script, cancel, &a))
        return *stopped;
    return alignScript(a, script, options, progress, cancel);
}

AlignResult alignScript(const SpeechFeatures &a, const Script &script, const AlignOptions &options,
    const SpeechProgressFn &progress, const std::atomic_bool *cancel)
{
    PaceProbe probe(script, options.reference);
    return alignScript(a, probe, script, options, progress, cancel);
}

AlignResult alignScript(const SpeechFeatures &a, PaceProbe &probe, const Script &script, const AlignOptions &options,
    const SpeechProgressFn &progress, const std::atomic_bool *cancel)
{
    if (script.syllables.isEmpty())
        return failure(AlignStatus::BadInput, ScriptText::tr("the script is empty"));
    TtsOptions tts = options.reference;
    if (probe.needed()) {
        // Speak the reference at the speaker's pace: less warping, fewer mistakes. The pace
        // at the default rate is measured on (at most) the first PaceProbe::kProbeSyllables
        // syllables; when they are the whole script, that rendering may serve as the reference
        // itself.
        tts.rate = kDefaultReferenceRate;
        const TtsResult &sample = probe.sample(cancel);
        if (isCancelled(cancel))
            return failure(AlignStatus::Cancelled, QStringLiteral("cancelled"));
        if (!sample.ok())
            return failure(AlignStatus::BadInput, sample.error);
        double spoken = 0;
        for (const TtsUnit &u : sample.units)
            spoken += u.end - u.start;
        spoken *= double(script.syllables.size()) / double(probe.syllables());
        const double ratio = a.speechDuration() / std::max(spoken, 0.01);
        if (ratio > 0.3 && ratio < 6 && std::abs(std::log(ratio)) > std::log(1.15))
            tts.rate = std::clamp(int(std::lround(kDefaultReferenceRate / ratio)), 80, 450);
        else if (probe.whole()) {
            if (progress)
                progress(0.1, QStringLiteral("reference"));
            return alignAdapted(a, script, sample, probe.features(), options.refineBoundaries, options.adaptToSpeaker,
                progress, cancel);
        }
    }
    SpeechFeatures b;
    const TtsResult reference = renderReference(script, tts, &b, cancel);
    markStage("reference");
    if (isCancelled(cancel))
        return failure(AlignStatus::Cancelled, QStringLiteral("cancelled"));
    if (!reference.ok())
        return failure(AlignStatus::BadInput, reference.error);
    if (progress)
        progress(0.1, QStringLiteral("reference"));
    return alignAdapted(a, script, reference, b, options.refineBoundaries, options.adaptToSpeaker, progress, cancel);
}

} // namespace toonface
