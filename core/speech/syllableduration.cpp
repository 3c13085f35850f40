#include "speech/syllableduration.h"

#include "speech/pinyin.h"

#include <algorithm>

namespace toonface {

namespace {

// The least time of an initial at an ordinary pace (seconds): the short burst of an
// unaspirated stop, the longer aspiration of p t k, the frication of affricates and fricatives
// (roughly the shortest tenth of each in read speech, not their usual length).
double initialSeconds(const QString &initial)
{
    if (initial.isEmpty())
        return 0.0;
    static const struct
    {
        const char *initials;
        double seconds;
    } table[] = {
        {" b d g ", 0.010},
        {" p t k ", 0.025},
        {" z zh j ", 0.020},
        {" c ch q ", 0.030},
        {" f s sh x h ", 0.030},
        {" m n l r ", 0.020},
    };
    const QString key = QLatin1Char(' ') + initial + QLatin1Char(' ');
    for (const auto &row : table)
        if (QString::fromLatin1(row.initials).contains(key))
            return row.seconds;
    return 0.02;
}

// The least time of a final: one vowel; a diphthong, or a vowel and a nasal coda; three parts
// (a medial, a vowel and a glide or a nasal).
double finalSeconds(const QString &final)
{
    int parts = 0;
    for (int k = 0; k < final.size(); ++k) {
        const QChar c = final[k];
        if (c == QLatin1Char('n') && k + 1 < final.size() && final[k + 1] == QLatin1Char('g'))
            continue; // ng is one sound
        ++parts;
    }
    if (parts <= 1 || final == QLatin1String("er"))
        return 0.030;
    return parts == 2 ? 0.040 : 0.045;
}

} // namespace

double minimumSyllableSeconds(const QString &pinyin, int tone, double pace)
{
    const auto parts = pinyin.isEmpty() ? std::nullopt : splitPinyinSyllable(pinyin);
    if (!parts)
        return kShortestSyllable;
    const double final = finalSeconds(parts->final) * (tone == 5 ? 0.6 : 1.0);
    const double seconds = (initialSeconds(parts->initial) + final) * std::clamp(pace, 0.5, 1.5);
    return std::max(kShortestSyllable, seconds);
}

} // namespace toonface
