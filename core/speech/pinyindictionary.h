#pragma once

#include "speech/pinyin.h"
#include "speech/pinyinindex.h"

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
// The parsed dictionaries are kept as a compact index (PinyinIndex) that is cached on disk, in
// the folder named by the environment variable TOONFACE_CACHE_DIR or else the user's cache
// folder (…/toonface): a later start reads the index instead of the sources. The index records
// the size and modification time of each source it was built from and is rebuilt when they
// change; a damaged cache file is ignored and replaced.
// Immutable after loading; safe to share between threads.
class PinyinDictionary
{
public:
    // The process-wide dictionary, loaded on first use from `/usr/share` (or the folder in the
    // environment variable TOONFACE_DICT_ROOT, which stands for /usr/share) through the cache.
    // Null, with `error` set to what is missing and which package ships it, when it cannot be
    // loaded.
    static std::shared_ptr<const PinyinDictionary> shared(QString *error = nullptr);
    // Whether shared() has finished loading (or failing): a call now would not wait. Never
    // blocks.
    static bool isLoaded();

    // Loads from `root` (a folder laid out like /usr/share), parsing the sources.
    static std::shared_ptr<const PinyinDictionary> load(const QString &root, QString *error);

    // How loadCached found the cache.
    enum class CacheUse {
        Reused, // a valid index built from the same sources
        Built, // none there: built from the sources and written
        RebuiltStale, // built from sources that have changed since: rebuilt and replaced
        RebuiltDamaged, // unreadable or damaged (cacheNote says how): rebuilt and replaced
        NotWritten, // built from the sources; the cache could not be written (cacheNote says why)
    };
    // Loads from `root` through the index cached in `cacheDir` (created when missing).
    static std::shared_ptr<const PinyinDictionary> loadCached(const QString &root, const QString &cacheDir,
        QString *error, CacheUse *use = nullptr, QString *cacheNote = nullptr);

    // The cache folder shared() uses.
    static QString cacheDirectory();

    bool contains(char32_t han) const { return m_index.contains(han); }

    // The readings of one character, most usual first; empty when unknown.
    QVector<PinyinSyllable> readings(char32_t han) const { return m_index.readings(han); }

    // A run of Chinese characters → one reading per character, chosen phrase by phrase (fewest
    // dictionary words; a character outside any phrase takes its usual reading). Characters
    // the dictionary does not know get an empty pinyin.
    QVector<PinyinSyllable> readRun(const std::u32string &han) const;

    int phraseCount() const { return m_index.phraseCount(); }

private:
    explicit PinyinDictionary(PinyinIndex index)
        : m_index(std::move(index))
    { }

    PinyinIndex m_index;
};

} // namespace toonface
