#include "speech/hiddeninitials.h"

#include "speech/pinyin.h"
#include "speech/syllableduration.h"

#include <QStringList>

#include <algorithm>
#include <cmath>
#include <optional>

namespace toonface {

namespace {

// Whether a syllable begins with a voiceless initial: a fricative, an affricate or a stop
// (Mandarin's b, d, g are voiceless too; their closure after a pause is silence).
bool hasVoicelessInitial(const QString &pinyin)
{
    const std::optional<PinyinParts> parts = splitPinyinSyllable(pinyin);
    static const QStringList voiceless = {QStringLiteral("h"), QStringLiteral("f"), QStringLiteral("s"),
        QStringLiteral("sh"), QStringLiteral("x"), QStringLiteral("c"), QStringLiteral("ch"), QStringLiteral("q"),
        QStringLiteral("k"), QStringLiteral("p"), QStringLiteral("t"), QStringLiteral("j"), QStringLiteral("z"),
        QStringLiteral("zh"), QStringLiteral("b"), QStringLiteral("d"), QStringLiteral("g")};
    return parts && voiceless.contains(parts->initial);
}

// Whether a syllable begins with a closure: a stop or an affricate (aspirated or not), whose
// closure is silence.
bool hasClosedInitial(const QString &pinyin)
{
    const std::optional<PinyinParts> parts = splitPinyinSyllable(pinyin);
    static const QStringList stops = {QStringLiteral("b"), QStringLiteral("p"), QStringLiteral("d"),
        QStringLiteral("t"), QStringLiteral("g"), QStringLiteral("k"), QStringLiteral("j"), QStringLiteral("q"),
        QStringLiteral("z"), QStringLiteral("c"), QStringLiteral("zh"), QStringLiteral("ch")};
    return parts && stops.contains(parts->initial);
}

// How far above the quiet frames' energy (ln units: 4.3 dB) a frame before the vowel's rise
// counts as the initial's heard noise. (1.0 and 2.0 gave the same onsets but one, on the
// held-out voices at 45 dB and on every real file; 1.0 kept AISHELL's first onset nearer.)
constexpr float kHeardAboveQuiet = 1.0f;

// The first frame from `from` on whose voicing, averaged over three frames, is half or more,
// looking at most `frames` on (-1 when none).
int voicedFrom(const SpeechFeatures &a, int from, int frames)
{
    for (int t = from; t <= from + frames && t + 2 < a.frames; ++t) {
        double voiced = 0;
        for (int d = 0; d < 3; ++d)
            voiced += a.voicing[size_t(t + d)] / 3.0;
        if (voiced >= 0.5)
            return t;
    }
    return -1;
}

// The first frame from `from` on, looking at most `frames` on, that is voiced (as voicedFrom)
// and loud: above half the way from the quiet frames' energy to the speech's (a vowel, not a
// closure voiced through at a murmur's level); -1 when none.
int vowelFrom(const SpeechFeatures &a, int from, int frames)
{
    const float loud = 0.5f * (a.noiseFloor + a.speechLevel);
    for (int t = from; t <= from + frames && t + 2 < a.frames; ++t) {
        t = voicedFrom(a, t, from + frames - t);
        if (t < 0)
            return -1;
        if (a.logEnergy[size_t(t)] >= loud)
            return t;
    }
    return -1;
}

} // namespace

void moveOnsetsOfHiddenInitials(const SpeechFeatures &a, const OnsetSignals &sig, const Script &script,
    const TtsResult &reference, double pace, AlignResult *r)
{
    // Noise within 30 dB of the speech (6.9 ln units) can hide a whole initial; in a cleaner
    // recording its noise is heard, though not in the mid band the pauses are found by.
    const bool noisy = a.speechLevel - a.noiseFloor < 6.9f;
    for (qsizetype k = 0; k < r->syllables.size(); ++k) {
        AlignedSyllable &s = r->syllables[k];
        const TtsUnit &u = reference.units[k];
        if (!hasVoicelessInitial(script.syllables[k].pinyin) || u.phonemes.size() < 2)
            continue;
        const int onset = a.frameAt(s.start + 0.5 * SpeechFeatures::kHop);
        // The initial's length in the reference at the speaker's pace.
        const double initial = std::min((u.phonemes[1].start - u.start) * pace, 0.25);
        const int initialFrames = int(std::ceil(initial / SpeechFeatures::kHop));
        // A pause ending within the initial's length before the onset (at least 30 ms): the
        // onset may have landed anywhere in the initial's heard part. (Within 30 ms only, an
        // affricate's or a stop's onset found at its loudest part 40-190 ms after the pause
        // stayed there: ch +195, zh +58, g +72 ms on the held-out voices at 45 dB.)
        int pauseEnd = -1;
        for (int t = onset; t >= onset - std::max(3, initialFrames) && t >= 0; --t)
            if (sig.isPause(t)) {
                pauseEnd = t;
                break;
            }
        if (pauseEnd < 0)
            continue;
        int pauseStart = pauseEnd;
        while (pauseStart > 0 && sig.isPause(pauseStart - 1))
            --pauseStart;
        const double earliestAfterPrevious = k > 0 ? r->syllables[k - 1].start + kShortestSyllable : 0.0;
        if (!noisy) {
            // A fricative's or an affricate's noise lies mostly above the mid band (x, q, j,
            // ch, h): the pause seems to run up to the vowel, and the onset lands there, late
            // by the noise (50-80 ms on the held-out voices at 45 dB, the first syllable of a
            // sentence most of all). The whole band's energy hears it: the onset moves back
            // over the frames before it that stand above the quiet ones, at most the initial's
            // length.
            int t = onset - 1;
            const int stop = std::max(onset - initialFrames - 3, 0);
            while (t >= stop && a.logEnergy[size_t(t)] > a.noiseFloor + kHeardAboveQuiet)
                --t;
            double heard = a.time(t + 1) - 0.5 * SpeechFeatures::kHop;
            // A stop's or an affricate's closure after a pause is as silent as the pause, and
            // what is heard of it begins at the burst: the onset landed late by the closure
            // (medians b +31, d +40, g +47, t +32, j +32, q +26 ms on the held-out espeak-ng
            // voices at 45 dB), while the tongue or the lips had closed at its start. As in
            // noise, the onset moves to the initial's length (closure, burst, aspiration or
            // frication) before the vowel, never before the pause began. The vowel is the
            // first loud voiced frame: a closure voiced through (a murmur well under the
            // vowel) is heard, and the onset found over it stays.
            if (hasClosedInitial(script.syllables[k].pinyin)) {
                const int vowel = vowelFrom(a, pauseEnd + 1, initialFrames + 3);
                // Never further before the first sound heard than the reference's closure
                // (its word's start to its initial's first sound, 40-45 ms in espeak-ng) at
                // the speaker's pace: the burst and aspiration are heard.
                const double closure = std::clamp((u.phonemes[0].start - u.start) * pace, 0.0, initial);
                if (vowel >= 0)
                    heard = std::min(heard,
                        std::max({a.time(vowel) - 0.5 * SpeechFeatures::kHop - initial, heard - closure,
                            a.time(pauseStart) - 0.5 * SpeechFeatures::kHop}));
            }
            s.start = std::min(s.start, std::max(heard, earliestAfterPrevious));
            continue;
        }
        // In noise, the vowel's start is what is heard: the first voiced stretch from the
        // pause's end on. Voiced right away, the whole initial is hidden in the pause (an h of
        // 150 ms in a slow voice); voiced later, only the initial's loudest part was heard (an
        // affricate's or a fricative's end, a stop's burst) and the onset lands the rest late
        // (30-75 ms on the held-out voices, first syllables and those after a pause). The
        // onset moves to the initial's length before the vowel, never before the pause began.
        const int vowel = voicedFrom(a, pauseEnd + 1, initialFrames + 3);
        if (vowel < 0)
            continue;
        const double earliest = std::max(a.time(pauseStart) - 0.5 * SpeechFeatures::kHop, earliestAfterPrevious);
        const double moved = std::max(a.time(vowel) - 0.5 * SpeechFeatures::kHop - initial, earliest);
        s.start = std::min(s.start, moved);
    }
}

} // namespace toonface
