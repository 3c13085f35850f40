#include "speech/onsetsignals.h"

#include "speech/pinyin.h"

#include <algorithm>
#include <cmath>

namespace toonface {

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

OnsetSignals::OnsetSignals(const SpeechFeatures &f)
    : m_frames(f.frames)
    , m_ln(f.loudness)
{
    const size_t n = size_t(f.frames);
    m_loud = f.loudnessNorm;
    // The voicing a voiceless initial ends is a lasting loss: measured on the voicing averaged
    // over ±20 ms, since a rough or creaky voice's voicing flickers from frame to frame.
    m_lnVoiced.resize(n);
    m_voicing.resize(n);
    for (size_t t = 0; t < n; ++t) {
        const size_t from = t >= 2 ? t - 2 : 0, to = std::min(n, t + 3);
        float voicing = 0;
        for (size_t u = from; u < to; ++u)
            voicing += f.voicing[u];
        voicing /= float(to - from);
        m_voicing[t] = voicing;
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
    // A breath between two quiet stretches is part of the pause: a short sound without voicing
    // well under the speech's loudness (a syllable, even one with a voiceless initial, always
    // holds a voiced final). Counted as speech, a loud breath split the pause in two and drew
    // the syllables either side into it: runs of them slid together by 0.1-1 s.
    for (size_t t = 0; t < n;) {
        if (quiet[t]) {
            ++t;
            continue;
        }
        size_t e = t;
        while (e < n && !quiet[e])
            ++e;
        constexpr size_t kLongestBreath = 45; // frames, with the look-around's 50 ms either side
        if (t > 0 && e < n && e - t <= kLongestBreath) {
            int voiced = 0;
            float loudest = -1e9f;
            for (size_t u = t; u < e; ++u) {
                voiced += f.voicing[u] >= 0.5f ? 1 : 0;
                loudest = std::max(loudest, m_ln[u]);
            }
            if (voiced <= 2 && loudest < level - 2.0f)
                std::fill(quiet.begin() + qsizetype(t), quiet.begin() + qsizetype(e), true);
        }
        t = e;
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
        // Nor does it reach into a voiceless initial after it: the frication of s, x or q
        // before its vowel is quiet in the mid band but not in the whole band, where it comes
        // within ~17 dB (4 ln units) of the loud frames of speech (the mid band's ±50 ms
        // look-around takes up to ~100 ms of it). A breath before the speech stays farther
        // under, and stays in the pause.
        auto frication = [&](size_t t) { return f.silence[t] <= 0.5f && f.logEnergy[t] >= f.speechLevel - 4.0f; };
        for (int trim = 0; trim < 12 && z > a + 1 && z < n && frication(z - 1); ++trim)
            --z;
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
    m_byLeftStart.assign(n + 1, 0);
    for (const Valley &v : m_valleys)
        ++m_byLeftStart[size_t(v.left) + 1];
    for (size_t t = 0; t < n; ++t)
        m_byLeftStart[t + 1] += m_byLeftStart[t];
    m_byLeft.resize(m_valleys.size());
    {
        std::vector<int> next(m_byLeftStart.begin(), m_byLeftStart.end() - 1);
        for (size_t v = 0; v < m_valleys.size(); ++v)
            m_byLeft[size_t(next[size_t(m_valleys[v].left)]++)] = int(v);
    }
    m_sumLoud = prefix(m_loud);
    m_sumNucleus = prefix(m_nucleus);
    m_sumSpeech = prefix(speech);
    m_sumPause = prefix(m_pause);
    m_maxNucleus = RangeMax(m_nucleus);
    m_maxLoud = RangeMax(m_loud);
    m_nextPause.assign(n + 1, int(n));
    for (int t = int(n) - 1; t >= 0; --t)
        m_nextPause[size_t(t)] = m_pause[size_t(t)] > 0.5f ? t : m_nextPause[size_t(t) + 1];
    m_nextSpeech.assign(n + 1, int(n));
    for (int t = int(n) - 1; t >= 0; --t)
        m_nextSpeech[size_t(t)] = m_pause[size_t(t)] > 0.5f ? m_nextSpeech[size_t(t) + 1] : t;
}

double OnsetSignals::onsetEvidence(int b, OnsetKind kind, bool first) const
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
    case OnsetKind::VoicelessAfterNasal: {
        // The vowel's fall into the nasal coda lowers the voiced loudness as much as the
        // initial's closure or frication does, but the coda goes on voiced: taken for the
        // onset, it put the initial the coda's length (80-150 ms) early. What follows the
        // onset is the initial, voiceless (the nucleus's voicing ramp, 0.4-0.8, read the other
        // way), taken as its least voicing over the 60 ms after the onset: a real speaker's
        // voicing runs on 20-30 ms into the initial, and over the first 40 ms alone p2fa's 喜
        // after 更 came 133 ms early (so that file is not held out from this window). (Not
        // asked of every voiceless initial: between vowels, real speakers voice unaspirated
        // stops and h, and SSB00050015's onsets came 30-70 ms late.)
        double leastVoicing = 1.0;
        for (int t = b + 1; t <= b + 6; ++t)
            leastVoicing = std::min(leastVoicing, voicing(t));
        const double voicedAfter = std::clamp((leastVoicing - 0.4) / 0.4, 0.0, 1.0);
        e = knee(3.0, true) * (1.0 - voicedAfter);
        break;
    }
    case OnsetKind::Sonorant: e = knee(1.5, false) * (1.0 - voicingLoss) * shallow(fallDepth); break;
    case OnsetKind::Vowel: e = valley * (1.0 - voicingLoss) * shallow(depth); break;
    case OnsetKind::Any: e = 0; break; // English words end in consonants: no rule here
    }
    return std::max(e * voicedBefore, afterPause);
}

} // namespace toonface
