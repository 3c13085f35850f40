#include "speech/hiddeninitials.h"

#include "speech/pinyin.h"
#include "speech/syllableduration.h"

#include <QStringList>

#include <algorithm>
#include <optional>

namespace toonface {

namespace {

// Whether a syllable begins with a long noise: a fricative, an affricate or an aspirated stop.
bool hasNoisyInitial(const QString &pinyin)
{
    const std::optional<PinyinParts> parts = splitPinyinSyllable(pinyin);
    static const QStringList noisy
        = {QStringLiteral("h"), QStringLiteral("f"), QStringLiteral("s"), QStringLiteral("sh"), QStringLiteral("x"),
            QStringLiteral("c"), QStringLiteral("ch"), QStringLiteral("q"), QStringLiteral("k"), QStringLiteral("p"),
            QStringLiteral("t"), QStringLiteral("j"), QStringLiteral("z"), QStringLiteral("zh")};
    return parts && noisy.contains(parts->initial);
}

} // namespace

void moveOnsetsOfHiddenInitials(const SpeechFeatures &a, const OnsetSignals &sig, const Script &script,
    const TtsResult &reference, double pace, AlignResult *r)
{
    // Only noise within 30 dB of the speech (6.9 ln units) can hide such an initial: in a
    // cleaner recording its noise is heard, and a pause before it is silence.
    if (a.speechLevel - a.noiseFloor >= 6.9f)
        return;
    for (qsizetype k = 0; k < r->syllables.size(); ++k) {
        AlignedSyllable &s = r->syllables[k];
        const TtsUnit &u = reference.units[k];
        if (!hasNoisyInitial(script.syllables[k].pinyin) || u.phonemes.size() < 2)
            continue;
        const int onset = a.frameAt(s.start + 0.5 * SpeechFeatures::kHop);
        int pauseEnd = -1;
        for (int t = onset; t >= onset - 3 && t >= 0; --t)
            if (sig.isPause(t)) {
                pauseEnd = t;
                break;
            }
        if (pauseEnd < 0)
            continue;
        double voiced = 0;
        for (int t = pauseEnd + 1; t <= pauseEnd + 3; ++t)
            voiced += a.voicing[size_t(std::clamp(t, 0, a.frames - 1))] / 3.0;
        if (voiced < 0.5)
            continue;
        int pauseStart = pauseEnd;
        while (pauseStart > 0 && sig.isPause(pauseStart - 1))
            --pauseStart;
        const double initial = std::min((u.phonemes[1].start - u.start) * pace, 0.25);
        const double earliest = std::max(a.time(pauseStart) - 0.5 * SpeechFeatures::kHop,
            k > 0 ? r->syllables[k - 1].start + kShortestSyllable : 0.0);
        const double moved
            = std::max(std::min(s.start, a.time(pauseEnd + 1) - 0.5 * SpeechFeatures::kHop) - initial, earliest);
        s.start = std::min(s.start, moved);
    }
}

} // namespace toonface
