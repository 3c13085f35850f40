#include "speech/speakeradapt.h"

#include "speech/pinyin.h"

#include <algorithm>
#include <array>

namespace toonface {

namespace {

// Initials by how they sound: unaspirated and aspirated stops and affricates, fricatives,
// nasals, liquids (classes 1-7).
int initialClass(const QString &initial)
{
    static const std::array<QStringList, 7> groups = {
        QStringList {QStringLiteral("b"), QStringLiteral("d"), QStringLiteral("g")},
        QStringList {QStringLiteral("p"), QStringLiteral("t"), QStringLiteral("k")},
        QStringList {QStringLiteral("z"), QStringLiteral("zh"), QStringLiteral("j")},
        QStringList {QStringLiteral("c"), QStringLiteral("ch"), QStringLiteral("q")},
        QStringList {
            QStringLiteral("f"), QStringLiteral("s"), QStringLiteral("sh"), QStringLiteral("x"), QStringLiteral("h")},
        QStringList {QStringLiteral("m"), QStringLiteral("n")},
        QStringList {QStringLiteral("l"), QStringLiteral("r")},
    };
    for (size_t g = 0; g < groups.size(); ++g)
        if (groups[g].contains(initial))
            return int(g) + 1;
    return 0;
}

// Finals by their first vowel (classes 8-13): a, o, e, i, u, ü (and syllabic nasals with e).
int finalClass(const QString &final)
{
    static const QString vowels = QStringLiteral("aoeiuü");
    for (const QChar c : final) {
        const qsizetype v = vowels.indexOf(c);
        if (v >= 0)
            return 8 + int(v);
    }
    return 10;
}

// The channels a class's mean is moved in: the static ones (cepstra, loudness, voicing, the
// high and low shares). Deltas describe movement, which a mean per class does not.
bool isStatic(int d)
{
    constexpr int C = SpeechFeatures::kCepstra;
    return d < C || d == 2 * C || d == 2 * C + 2 || d == 2 * C + 3 || d == 2 * C + 5;
}

} // namespace

std::vector<int> soundClasses(const SpeechFeatures &f, const Script &script, const std::vector<double> &starts,
    const std::vector<double> &initialEnds, const std::vector<double> &ends)
{
    std::vector<int> classes(size_t(f.frames), 0);
    for (qsizetype k = 0; k < script.syllables.size() && size_t(k) < starts.size(); ++k) {
        const std::optional<PinyinParts> parts = splitPinyinSyllable(script.syllables[k].pinyin);
        const int initial = parts ? initialClass(parts->initial) : 0;
        const int final = parts ? finalClass(parts->final) : 10;
        const int t0 = f.frameAt(starts[size_t(k)]), t1 = f.frameAt(ends[size_t(k)]);
        const int split = f.frameAt(initialEnds[size_t(k)]);
        for (int t = t0; t < t1; ++t) {
            if (f.silence[size_t(t)] > 0.5f)
                continue;
            classes[size_t(t)] = initial > 0 && t < split ? initial : final;
        }
    }
    return classes;
}

int adaptReference(const SpeechFeatures &recording, const std::vector<int> &recClasses, SpeechFeatures *reference,
    const std::vector<int> &refClasses)
{
    constexpr int dim = SpeechFeatures::kDim;
    std::array<std::array<double, dim>, kSoundClasses> sumA {}, sumB {};
    std::array<int, kSoundClasses> countA {}, countB {};
    auto accumulate = [](const SpeechFeatures &f, const std::vector<int> &classes, auto &sum, auto &count) {
        for (int t = 0; t < f.frames && size_t(t) < classes.size(); ++t) {
            const int c = classes[size_t(t)];
            const float *v = f.vector(t);
            for (int d = 0; d < dim; ++d)
                sum[size_t(c)][size_t(d)] += v[d];
            ++count[size_t(c)];
        }
    };
    accumulate(recording, recClasses, sumA, countA);
    accumulate(*reference, refClasses, sumB, countB);
    std::array<std::array<float, dim>, kSoundClasses> shift {};
    int moved = 0;
    for (int c = 0; c < kSoundClasses; ++c) {
        if (countA[size_t(c)] == 0 || countB[size_t(c)] == 0)
            continue;
        // Shrunk toward no shift by the frames of the rarer side.
        const double n = std::min(countA[size_t(c)], countB[size_t(c)]);
        const double weight = n / (n + kPriorFrames);
        for (int d = 0; d < dim; ++d)
            shift[size_t(c)][size_t(d)] = !isStatic(d) ? 0.0f
                                                       : float(weight
                                                           * (sumA[size_t(c)][size_t(d)] / countA[size_t(c)]
                                                               - sumB[size_t(c)][size_t(d)] / countB[size_t(c)]));
        ++moved;
    }
    for (int t = 0; t < reference->frames && size_t(t) < refClasses.size(); ++t) {
        float *v = reference->vectors.data() + size_t(t) * dim;
        const auto &s = shift[size_t(refClasses[size_t(t)])];
        for (int d = 0; d < dim; ++d)
            v[d] += s[size_t(d)];
    }
    return moved;
}

} // namespace toonface
