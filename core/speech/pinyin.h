#pragma once

#include <QPair>
#include <QString>
#include <QVector>

#include <optional>

namespace toonface {

// One Mandarin syllable in normalised Hanyu pinyin: lower case, no tone marks, ü written ü
// (never v or u:), and its tone 1-4, or 5 for the neutral tone (also when none was written).
struct PinyinSyllable
{
    QString pinyin;
    int tone = 5;
    bool operator==(const PinyinSyllable &) const = default;
};

// A syllable taken apart as face-model.md spells it: the initial ("", b p m f d t n l g k h j
// q x zh ch sh r z c s) and the full final with the glides y/w folded in, ü written ü after
// j q x y, and pinyin's shortened finals spelled out (iu → iou, ui → uei, un → uen, ün → üen),
// e.g. "yun" → {"", "üen"}, "gui" → {"g", "uei"}. `erhua` is a trailing r on a final other
// than er. Syllabic nasals (m, n, ng, hm, hng) have the initial "" and the final as written.
struct PinyinParts
{
    QString initial;
    QString final;
    bool erhua = false;
};

// requires: a toneless, normalised syllable (see PinyinSyllable). nullopt when it is not
// spelled like a Mandarin syllable.
std::optional<PinyinParts> splitPinyinSyllable(const QString &toneless);
inline bool isMandarinSyllable(const QString &toneless)
{
    return splitPinyinSyllable(toneless).has_value();
}

// One written syllable ("nǐ", "ni3", "NI3", "lv4", "lü", "nu:3", "ê") → normalised form, or
// nullopt when it is not one valid syllable.
std::optional<PinyinSyllable> parsePinyinSyllable(const QString &text);

// A written pinyin word of one or more syllables ("nǐhǎo", "ni3hao3", "Xi'an", "xian") →
// its syllables; the longest first syllable that leaves a valid rest wins, so "xian" is one
// syllable and "xi'an" two. `spans`, when given, receives each syllable's {offset, length} in
// `word`. nullopt when the word cannot be read as pinyin.
std::optional<QVector<PinyinSyllable>> splitPinyinWord(const QString &word, QVector<QPair<int, int>> *spans = nullptr);

// "lü" tone 4 → "lv4": the tone-number spelling espeak-ng's cmn-latn-pinyin voice reads.
QString toneNumberSpelling(const PinyinSyllable &syllable);

// "lü" tone 4 → "lǜ": the tone-mark spelling (tone 5 unmarked).
QString toneMarkSpelling(const PinyinSyllable &syllable);

} // namespace toonface
