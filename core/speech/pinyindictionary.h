#pragma once

#include "speech/pinyin.h"

#include <QHash>
#include <QString>
#include <QStringList>
#include <QVector>

#include <memory>

namespace toonface {

// Chinese characters → pinyin, from dictionaries Debian ships, read at run time:
// - Unihan (package unicode-data, /usr/share/unicode/Unihan_Readings.txt.bz2): every reading
//   of a character (kMandarin first) and, from Unihan_Variants, traditional → simplified forms;
// - Rime's terra_pinyin (rime-data-terra-pinyin): toned readings of polyphonic phrases, mostly
//   in traditional characters (also indexed under their simplified form), and the relative
//   weight of each character's readings;
// - Rime's pinyin_simp (rime-data-pinyin-simp, optional): common simplified phrases without
//   tones (the tones come from the characters' own readings).
// Immutable after loading; safe to share between threads.
class PinyinDictionary
{
public:
    // The process-wide dictionary, loaded on first use from `/usr/share` (or the folder in the
    // environment variable TOONFACE_DICT_ROOT, which stands for /usr/share). Null, with
    // `error` set to what is missing and which package ships it, when it cannot be loaded.
    static std::shared_ptr<const PinyinDictionary> shared(QString *error = nullptr);

    // Loads from `root` (a folder laid out like /usr/share).
    static std::shared_ptr<const PinyinDictionary> load(const QString &root, QString *error);

    bool contains(char32_t han) const { return m_readings.contains(han); }

    // The readings of one character, most usual first; empty when unknown.
    QVector<PinyinSyllable> readings(char32_t han) const { return m_readings.value(han); }

    // A run of Chinese characters → one reading per character, chosen phrase by phrase (fewest
    // dictionary words; a character outside any phrase takes its usual reading). Characters
    // the dictionary does not know get an empty pinyin.
    QVector<PinyinSyllable> readRun(const std::u32string &han) const;

    int phraseCount() const { return int(m_phrases.size()); }

private:
    PinyinDictionary() = default;
    void addPhrase(const QString &key, const QVector<PinyinSyllable> &reading, bool replace);
    std::optional<QVector<PinyinSyllable>> phrase(const std::u32string &han, size_t from, size_t len) const;

    QHash<char32_t, QVector<PinyinSyllable>> m_readings;
    QHash<QString, QVector<PinyinSyllable>> m_phrases;
    int m_maxPhraseLength = 1;
};

} // namespace toonface
