#pragma once

#include "speech/features.h"
#include "speech/rangemax.h"
#include "speech/script.h"

#include <algorithm>
#include <bit>
#include <vector>

namespace toonface {

// The aligner's view of a recording's syllable boundaries: pauses, loudness valleys, voiced
// nuclei, and the evidence that a syllable of a given kind starts at a frame.

// How a syllable begins, which decides what its onset looks like in the signal.
// VoicelessAfterNasal: a voiceless initial after a nasal coda, whose onset is where the
// coda's voicing ends (the aligner sets it; onsetKind gives Voiceless).
enum class OnsetKind { Voiceless, Sonorant, Vowel, VoicelessAfterNasal, Any };

OnsetKind onsetKind(const ScriptSyllable &s);

// The recording's frame signals the segmentation scores, with O(1) window sums and maxima.
class OnsetSignals
{
public:
    explicit OnsetSignals(const SpeechFeatures &f);

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
    double onsetEvidence(int b, OnsetKind kind, bool first) const;

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

    // The deepest valley (ln units) whose left peak is frame `left` and whose right peak lies
    // before to - 1 (0 when none): innerValley(from, to) is the largest of these over the
    // frames left >= from + 2, so a search that moves `from` back a frame at a time keeps it
    // with one look-up per frame.
    double valleyFromPeak(int left, int to) const
    {
        if (left < 0 || left >= m_frames)
            return 0;
        double deepest = 0;
        for (int v = m_byLeftStart[size_t(left)]; v < m_byLeftStart[size_t(left) + 1]; ++v) {
            const Valley &valley = m_valleys[size_t(m_byLeft[size_t(v)])];
            if (valley.right < to - 1)
                deepest = std::max(deepest, valley.depth);
        }
        return deepest;
    }

private:
    double rangeMax(const RangeMax &table, int from, int to) const
    {
        from = std::max(from, 0);
        to = std::min(to, m_frames);
        return to <= from ? 0.0 : double(table(from, to));
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
    // The voicing averaged over ±20 ms.
    double voicing(int t) const { return m_voicing[size_t(std::clamp(t, 0, m_frames - 1))]; }
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
    std::vector<float> m_ln, m_lnVoiced, m_voicing, m_loud, m_nucleus, m_pause;
    std::vector<double> m_sumLoud, m_sumNucleus, m_sumSpeech, m_sumPause;
    RangeMax m_maxNucleus, m_maxLoud;
    std::vector<int> m_nextPause, m_nextSpeech;
    std::vector<int> m_firstValley; // per frame: the first valley at or after it
    struct Valley
    {
        int at, left, right;
        double depth;
    };
    std::vector<Valley> m_valleys;
    std::vector<int> m_byLeft; // the valleys in the order of their left peaks
    std::vector<int> m_byLeftStart; // per frame: where its valleys start in m_byLeft
};

} // namespace toonface
