#include "speech/pinyindictionary.h"

#include "i18n/coretext.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QMutex>
#include <QMutexLocker>
#include <QSaveFile>
#include <QSet>
#include <QStandardPaths>

#include <bzlib.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <string_view>
#include <vector>

namespace toonface {

namespace {

// The whole of a bzip2 file, or of the plain file beside it; empty on failure.
QByteArray readMaybeCompressed(const QString &bz2Path, QString *error)
{
    QString plain = bz2Path;
    plain.chop(4);
    if (QFile::exists(plain)) {
        QFile f(plain);
        if (f.open(QIODevice::ReadOnly))
            return f.readAll();
    }
    QFile f(bz2Path);
    if (!f.open(QIODevice::ReadOnly)) {
        *error = ScriptText::tr("cannot read %1").arg(bz2Path);
        return {};
    }
    const QByteArray packed = f.readAll();
    bz_stream s {};
    if (BZ2_bzDecompressInit(&s, 0, 0) != BZ_OK) {
        *error = ScriptText::tr("cannot start bzip2 decompression of %1").arg(bz2Path);
        return {};
    }
    QByteArray out;
    out.resize(std::max<qsizetype>(packed.size() * 6, 1 << 16));
    s.next_in = const_cast<char *>(packed.constData());
    s.avail_in = unsigned(packed.size());
    int rc = BZ_OK;
    qsizetype used = 0;
    while (rc == BZ_OK) {
        if (used == out.size())
            out.resize(out.size() * 2);
        s.next_out = out.data() + used;
        s.avail_out = unsigned(std::min<qsizetype>(out.size() - used, std::numeric_limits<int>::max()));
        const unsigned before = s.avail_out;
        rc = BZ2_bzDecompress(&s);
        used += before - s.avail_out;
        if (rc == BZ_OK && s.avail_in == 0 && before == s.avail_out)
            break; // truncated input
    }
    BZ2_bzDecompressEnd(&s);
    if (rc != BZ_STREAM_END) {
        *error = ScriptText::tr("%1 is not a valid bzip2 file").arg(bz2Path);
        return {};
    }
    out.resize(used);
    return out;
}

using std::string_view;

std::vector<string_view> splitView(string_view s, char sep)
{
    std::vector<string_view> out;
    size_t from = 0;
    while (true) {
        const size_t at = s.find(sep, from);
        out.push_back(s.substr(from, at == string_view::npos ? string_view::npos : at - from));
        if (at == string_view::npos)
            return out;
        from = at + 1;
    }
}

// Calls fn(line) for each line of `data`, without its '\n' (and '\r').
template<typename Fn>
void forEachLine(const QByteArray &data, Fn fn)
{
    const string_view all(data.constData(), size_t(data.size()));
    size_t from = 0;
    while (from < all.size()) {
        size_t at = all.find('\n', from);
        if (at == string_view::npos)
            at = all.size();
        string_view line = all.substr(from, at - from);
        if (!line.empty() && line.back() == '\r')
            line.remove_suffix(1);
        fn(line);
        from = at + 1;
    }
}

QString utf8(string_view v)
{
    return QString::fromUtf8(v.data(), qsizetype(v.size()));
}

char32_t parseCodePoint(string_view field) // "U+9280"
{
    if (!field.starts_with("U+"))
        return 0;
    bool ok = false;
    const uint v = QByteArray(field.data() + 2, qsizetype(field.size() - 2)).toUInt(&ok, 16);
    return ok ? char32_t(v) : 0;
}

// parsePinyinSyllable, remembered: the tables repeat a few thousand spellings many times.
std::optional<PinyinSyllable> parseCached(const QString &text)
{
    thread_local QHash<QString, std::optional<PinyinSyllable>> memo;
    const auto it = memo.constFind(text);
    if (it != memo.cend())
        return *it;
    const auto s = parsePinyinSyllable(text);
    memo.insert(text, s);
    return s;
}

void appendReading(QVector<PinyinSyllable> &list, const PinyinSyllable &s)
{
    if (!list.contains(s))
        list.append(s);
}

// One Unihan reading value → its syllables, e.g. "0442.080:háng 0443.050:hàng",
// "20811.060:háng,xìng", "xíng(2943) háng(218)", "xíng".
QVector<PinyinSyllable> unihanSyllables(const QString &value)
{
    QVector<PinyinSyllable> out;
    for (QString item : value.split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
        const qsizetype colon = item.indexOf(QLatin1Char(':'));
        if (colon >= 0)
            item = item.mid(colon + 1);
        const qsizetype paren = item.indexOf(QLatin1Char('('));
        if (paren >= 0)
            item.truncate(paren);
        for (const QString &one : item.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
            if (const auto s = parseCached(one))
                appendReading(out, *s);
        }
    }
    return out;
}

// Lines of a Rime dictionary after its YAML header ("..."): text, code, optional weight.
template<typename Fn>
void forEachRimeEntry(const QByteArray &data, Fn fn)
{
    bool body = false;
    forEachLine(data, [&](string_view line) {
        if (!body) {
            body = line.starts_with("...");
            return;
        }
        if (line.empty() || line.starts_with('#'))
            return;
        const auto cols = splitView(line, '\t');
        if (cols.size() < 2)
            return;
        fn(utf8(cols[0]), utf8(cols[1]), cols.size() > 2 ? utf8(cols[2]) : QString());
    });
}

double rimeWeight(const QString &w) // "98%" → 98, "4221" → 4221, "" → -1
{
    if (w.isEmpty())
        return -1;
    QString v = w.trimmed();
    if (v.endsWith(QLatin1Char('%')))
        v.chop(1);
    bool ok = false;
    const double d = v.toDouble(&ok);
    return ok ? d : -1;
}

// The parsed sources, before they become an index.
struct Sources
{
    QHash<char32_t, QVector<PinyinSyllable>> readings;
    QHash<QString, QVector<PinyinSyllable>> phrases;
    void addPhrase(const QString &key, const QVector<PinyinSyllable> &reading)
    {
        if (!phrases.contains(key))
            phrases.insert(key, reading);
    }
};

// Bumped whenever the parsing below changes what it makes of the same sources.
constexpr quint64 kParserVersion = 3;

// The source files, in the order they are read: the plain file beside each .bz2 is read
// instead when it exists.
QStringList sourcePaths(const QString &root)
{
    QStringList paths;
    for (const char *bz2 : {"/unicode/Unihan_Readings.txt.bz2", "/unicode/Unihan_Variants.txt.bz2"}) {
        QString path = root + QString::fromLatin1(bz2);
        QString plain = path;
        plain.chop(4);
        paths.append(QFile::exists(plain) ? plain : path);
    }
    paths.append(root + QStringLiteral("/rime-data/terra_pinyin.dict.yaml"));
    paths.append(root + QStringLiteral("/rime-data/pinyin_simp.dict.yaml"));
    return paths;
}

// What the sources are now: their paths, sizes and modification times (and the parser's
// version), hashed. Any source replaced, edited, added or removed changes it.
quint64 sourceSignature(const QString &root)
{
    QByteArray all = QByteArray::number(kParserVersion);
    for (const QString &path : sourcePaths(root)) {
        const QFileInfo info(path);
        all += '\n' + path.toUtf8();
        if (info.exists())
            all += ' ' + QByteArray::number(info.size()) + ' '
                + QByteArray::number(info.lastModified().toMSecsSinceEpoch());
        else
            all += " missing";
    }
    quint64 h = 1469598103934665603ull; // FNV-1a
    for (char c : all) {
        h ^= quint8(c);
        h *= 1099511628211ull;
    }
    return h;
}

// Terra writes 一 and 不 in some phrases with the tone they take before the next syllable (一樣
// yi2, 不是 bu2): their own tone is kept, the sandhi (tonesandhi.h) changes it as spoken.
PinyinSyllable underlyingTone(char32_t han, PinyinSyllable s)
{
    if (han == U'一' && (s.tone == 2 || s.tone == 4))
        s.tone = 1;
    else if (han == U'不' && s.tone == 2)
        s.tone = 4;
    return s;
}

std::optional<Sources> parseSources(const QString &root, QString *error)
{
    QString err;
    Sources d;

    const QString readingsPath = root + QStringLiteral("/unicode/Unihan_Readings.txt.bz2");
    const QByteArray readings = readMaybeCompressed(readingsPath, &err);
    if (readings.isEmpty()) {
        *error = ScriptText::tr("Chinese character readings are missing (%1; install the Debian package unicode-data)")
                     .arg(err);
        return std::nullopt;
    }
    // Field order decides which reading comes first: kMandarin is the usual one.
    static const string_view fields[] = {"kMandarin", "kHanyuPinlu", "kTGHZ2013", "kXHC1983", "kHanyuPinyin"};
    QHash<char32_t, std::array<QVector<PinyinSyllable>, 5>> perField;
    forEachLine(readings, [&](string_view line) {
        if (!line.starts_with("U+"))
            return;
        const auto cols = splitView(line, '\t');
        if (cols.size() < 3)
            return;
        for (int f = 0; f < 5; ++f) {
            if (cols[1] == fields[f]) {
                if (const char32_t c = parseCodePoint(cols[0]))
                    perField[c][f] = unihanSyllables(utf8(cols[2]));
            }
        }
    });
    // How often each reading is heard: kHanyuPinlu counts readings in a corpus of modern
    // Mandarin ("hǎo(6060) hāo(142) hào(115)"), a spoken frequency where the input method's
    // weights below count what people type.
    QHash<char32_t, QVector<QPair<PinyinSyllable, double>>> heard;
    forEachLine(readings, [&](string_view line) {
        if (!line.starts_with("U+"))
            return;
        const auto cols = splitView(line, '\t');
        if (cols.size() < 3 || cols[1] != "kHanyuPinlu")
            return;
        const char32_t c = parseCodePoint(cols[0]);
        for (const QString &item : utf8(cols[2]).split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
            const qsizetype paren = item.indexOf(QLatin1Char('('));
            const auto syl = paren > 0 ? parseCached(item.left(paren)) : std::nullopt;
            if (c && syl)
                heard[c].append({*syl, item.mid(paren + 1).chopped(1).toDouble()});
        }
    });
    for (auto it = perField.cbegin(); it != perField.cend(); ++it) {
        QVector<PinyinSyllable> all;
        for (const auto &list : it.value())
            for (const auto &s : list)
                appendReading(all, s);
        if (!all.isEmpty())
            d.readings.insert(it.key(), all);
    }
    if (d.readings.size() < 1000) {
        *error = ScriptText::tr("%1 holds no Mandarin readings").arg(readingsPath);
        return std::nullopt;
    }

    QHash<char32_t, char32_t> simplified;
    const QByteArray variants = readMaybeCompressed(root + QStringLiteral("/unicode/Unihan_Variants.txt.bz2"), &err);
    forEachLine(variants, [&](string_view line) {
        if (!line.starts_with("U+"))
            return;
        const auto cols = splitView(line, '\t');
        if (cols.size() >= 3 && cols[1] == "kSimplifiedVariant") {
            const char32_t from = parseCodePoint(cols[0]);
            const char32_t to = parseCodePoint(splitView(cols[2], ' ').front());
            if (from && to && from != to)
                simplified.insert(from, to);
        }
    });
    // A traditional form with no simplified variant of its own whose semantic variant has one
    // (爲 → 為 → 为): terra writes many phrases with it (認爲, 因爲).
    {
        QSet<char32_t> targets;
        for (const char32_t to : std::as_const(simplified))
            targets.insert(to);
        QHash<char32_t, char32_t> more;
        forEachLine(variants, [&](string_view line) {
            if (!line.starts_with("U+"))
                return;
            const auto cols = splitView(line, '\t');
            if (cols.size() < 3 || cols[1] != "kSemanticVariant")
                return;
            const char32_t from = parseCodePoint(cols[0]);
            const char32_t via = parseCodePoint(splitView(splitView(cols[2], ' ').front(), '<').front());
            if (from && via && !simplified.contains(from) && !targets.contains(from) && simplified.contains(via))
                more.insert(from, simplified.value(via));
        });
        simplified.insert(more);
    }

    const QString terraPath = root + QStringLiteral("/rime-data/terra_pinyin.dict.yaml");
    QFile terra(terraPath);
    if (!terra.open(QIODevice::ReadOnly)) {
        *error
            = ScriptText::tr("the phrase dictionary %1 is missing (install the Debian package rime-data-terra-pinyin)")
                  .arg(terraPath);
        return std::nullopt;
    }
    QHash<char32_t, QVector<QPair<PinyinSyllable, double>>> charWeights;
    // Terra lists some phrases more than once (不好 as bù hǎo and as bú hào, 着急 as zhāo jí
    // and zháo jí): all are kept until the characters' weights can choose among them.
    QHash<QString, QVector<QVector<PinyinSyllable>>> candidates;
    QStringList candidateOrder;
    auto addCandidate = [&](const QString &key, const QVector<PinyinSyllable> &reading) {
        auto it = candidates.find(key);
        if (it == candidates.end()) {
            candidateOrder.append(key);
            candidates.insert(key, {reading});
        } else if (!it->contains(reading)) {
            it->append(reading);
        }
    };
    forEachRimeEntry(terra.readAll(), [&](const QString &text, const QString &code, const QString &weight) {
        const std::u32string han = text.toStdU32String();
        const QStringList codes = code.split(QLatin1Char(' '), Qt::SkipEmptyParts);
        if (han.empty() || size_t(codes.size()) != han.size())
            return;
        QVector<PinyinSyllable> reading;
        for (qsizetype i = 0; i < codes.size(); ++i) {
            const auto s = parseCached(codes[i]);
            if (!s)
                return;
            reading.append(han.size() > 1 ? underlyingTone(han[size_t(i)], *s) : *s);
        }
        if (han.size() == 1) {
            const double w = rimeWeight(weight);
            if (w >= 0)
                charWeights[han[0]].append({reading[0], w});
            return;
        }
        addCandidate(text, reading);
        std::u32string simp = han;
        for (char32_t &c : simp)
            c = simplified.value(c, c);
        if (simp != han)
            addCandidate(QString::fromStdU32String(simp), reading);
    });
    // Terra lists phrases only where its own usual readings would be wrong, so a character's
    // usual reading must be terra's when terra weighs several.
    for (auto it = charWeights.begin(); it != charWeights.end(); ++it) {
        auto &weighted = it.value();
        if (weighted.size() < 2)
            continue;
        std::stable_sort(
            weighted.begin(), weighted.end(), [](const auto &a, const auto &b) { return a.second > b.second; });
        QVector<PinyinSyllable> ordered;
        for (const auto &w : weighted)
            appendReading(ordered, w.first);
        for (const auto &s : d.readings.value(it.key()))
            appendReading(ordered, s);
        d.readings.insert(it.key(), ordered);
    }
    // How usual a reading of a character is, 0..1: its share of the corpus counts where there
    // are some, else of terra's weights, else by its place in the list of readings.
    auto share = [&](char32_t c, const PinyinSyllable &s) {
        auto shareIn = [&](const QVector<QPair<PinyinSyllable, double>> &counts) {
            double all = 0, mine = 0;
            for (const auto &[r, n] : counts) {
                all += n;
                mine += r == s ? n : 0.0;
            }
            return all > 0 ? mine / all : -1.0;
        };
        double v = shareIn(heard.value(c));
        if (v < 0)
            v = shareIn(charWeights.value(c));
        if (v < 0) {
            const qsizetype rank = d.readings.value(c).indexOf(s);
            v = rank < 0 ? 0.0 : 1.0 / double(rank + 1);
        }
        return std::max(v, 0.005);
    };
    for (const QString &key : std::as_const(candidateOrder)) {
        const QVector<QVector<PinyinSyllable>> &list = candidates[key];
        const std::u32string han = key.toStdU32String();
        qsizetype best = 0;
        double bestScore = -1e300;
        for (qsizetype r = 0; r < list.size(); ++r) {
            double score = 0;
            for (size_t i = 0; i < han.size(); ++i)
                score += std::log(share(han[i], list[r][qsizetype(i)]));
            if (score > bestScore) {
                bestScore = score;
                best = r;
            }
        }
        d.addPhrase(key, list[best]);
    }

    QFile simp(root + QStringLiteral("/rime-data/pinyin_simp.dict.yaml"));
    if (simp.open(QIODevice::ReadOnly)) {
        QHash<QString, QPair<QVector<PinyinSyllable>, double>> best;
        forEachRimeEntry(simp.readAll(), [&](const QString &text, const QString &code, const QString &weight) {
            const std::u32string han = text.toStdU32String();
            const QStringList codes = code.split(QLatin1Char(' '), Qt::SkipEmptyParts);
            if (han.size() < 2 || size_t(codes.size()) != han.size())
                return;
            QVector<PinyinSyllable> reading;
            for (size_t i = 0; i < han.size(); ++i) {
                const auto toneless = parseCached(codes[qsizetype(i)]);
                if (!toneless)
                    return;
                PinyinSyllable s = *toneless;
                // The tone of the character's most usual reading with this spelling (跑得 pǎo
                // de: 得's neutral de is heard far more often than dé).
                double bestShare = -1;
                for (const auto &r : d.readings.value(han[i])) {
                    if (r.pinyin == s.pinyin && share(han[i], r) > bestShare) {
                        bestShare = share(han[i], r);
                        s.tone = r.tone;
                    }
                }
                reading.append(s);
            }
            const double w = rimeWeight(weight);
            auto it = best.find(text);
            if (it == best.end() || it->second < w)
                best.insert(text, {reading, w});
        });
        for (auto it = best.cbegin(); it != best.cend(); ++it)
            d.addPhrase(it.key(), it.value().first);
    }
    return d;
}

// The index block built from the sources under `root`, or empty with *error set.
QByteArray buildBlock(const QString &root, QString *error)
{
    const quint64 signature = sourceSignature(root);
    const std::optional<Sources> sources = parseSources(root, error);
    if (!sources)
        return {};
    return PinyinIndex::build(sources->readings, sources->phrases, signature);
}

} // namespace

namespace {
std::atomic_bool g_sharedLoaded {false};
}

bool PinyinDictionary::isLoaded()
{
    return g_sharedLoaded.load(std::memory_order_acquire);
}

std::shared_ptr<const PinyinDictionary> PinyinDictionary::shared(QString *error)
{
    static QMutex mutex;
    static std::shared_ptr<const PinyinDictionary> dict;
    static QString loadError;
    QMutexLocker lock(&mutex);
    if (!dict && loadError.isEmpty()) {
        QString root = qEnvironmentVariable("TOONFACE_DICT_ROOT");
        if (root.isEmpty())
            root = QStringLiteral("/usr/share");
        dict = loadCached(root, cacheDirectory(), &loadError);
        g_sharedLoaded.store(true, std::memory_order_release);
    }
    if (!dict && error)
        *error = loadError;
    return dict;
}

QString PinyinDictionary::cacheDirectory()
{
    const QString env = qEnvironmentVariable("TOONFACE_CACHE_DIR");
    if (!env.isEmpty())
        return env;
    return QStandardPaths::writableLocation(QStandardPaths::GenericCacheLocation) + QStringLiteral("/toonface");
}

std::shared_ptr<const PinyinDictionary> PinyinDictionary::load(const QString &root, QString *error)
{
    QByteArray block = buildBlock(root, error);
    if (block.isEmpty())
        return nullptr;
    std::optional<PinyinIndex> index = PinyinIndex::fromBlock(std::move(block), error);
    if (!index)
        return nullptr;
    return std::shared_ptr<const PinyinDictionary>(new PinyinDictionary(std::move(*index)));
}

std::shared_ptr<const PinyinDictionary> PinyinDictionary::loadCached(
    const QString &root, const QString &cacheDir, QString *error, CacheUse *use, QString *cacheNote)
{
    CacheUse how = CacheUse::Built;
    QString note;
    const QString cachePath = cacheDir + QStringLiteral("/pinyin-index.bin");
    const quint64 signature = sourceSignature(root);
    QFile cached(cachePath);
    if (cached.exists()) {
        QString why;
        std::optional<PinyinIndex> index;
        if (cached.open(QIODevice::ReadOnly))
            index = PinyinIndex::fromBlock(cached.readAll(), &why);
        else
            why = cached.errorString();
        cached.close();
        if (index && index->sourceSignature() == signature) {
            if (use)
                *use = CacheUse::Reused;
            return std::shared_ptr<const PinyinDictionary>(new PinyinDictionary(std::move(*index)));
        }
        how = index ? CacheUse::RebuiltStale : CacheUse::RebuiltDamaged;
        note = index ? ScriptText::tr("%1: built from other sources").arg(cachePath) : withProblem(cachePath, why);
    }
    QByteArray block = buildBlock(root, error);
    if (block.isEmpty())
        return nullptr;
    // Written whole or not at all: a reader never sees half a file.
    QSaveFile out(cachePath);
    if (!QDir().mkpath(cacheDir) || !out.open(QIODevice::WriteOnly) || out.write(block) != block.size()
        || !out.commit()) {
        how = CacheUse::NotWritten;
        note = ScriptText::tr("cannot write %1: %2").arg(cachePath, out.errorString());
    }
    std::optional<PinyinIndex> index = PinyinIndex::fromBlock(std::move(block), error);
    if (!index)
        return nullptr;
    if (use)
        *use = how;
    if (cacheNote)
        *cacheNote = note;
    return std::shared_ptr<const PinyinDictionary>(new PinyinDictionary(std::move(*index)));
}

namespace {

// The reading of han[i], a character in no phrase of the dictionaries, where its neighbours
// make it a particle: 得 after another character marks a complement (跑得快 pǎo de kuài).
// Otherwise none: the usual reading.
std::optional<PinyinSyllable> loneReading(const std::u32string &han, size_t i)
{
    if (han[i] == U'得' && i > 0)
        return PinyinSyllable {QStringLiteral("de"), 5};
    return std::nullopt;
}

// 地 after a doubled syllable makes an adverb (慢慢地 màn màn de, 好好地), whatever phrase the
// dictionaries found it in (their toneless 好地 hao di).
bool adverbialDe(const std::u32string &han, size_t i)
{
    return han[i] == U'地' && i >= 2 && han[i - 1] == han[i - 2];
}

} // namespace

QVector<PinyinSyllable> PinyinDictionary::readRun(const std::u32string &han) const
{
    const size_t n = han.size();
    // best[i]: fewest words covering han[0, i), ties broken by the larger sum of squared
    // word lengths (longer phrases win); from[i]: where the last word starts.
    struct Cell
    {
        int words = std::numeric_limits<int>::max();
        int squares = 0;
        size_t from = 0;
        bool phrase = false;
    };
    std::vector<Cell> best(n + 1);
    best[0].words = 0;
    for (size_t i = 0; i < n; ++i) {
        if (best[i].words == std::numeric_limits<int>::max())
            continue;
        const size_t maxLen = std::min(n - i, size_t(m_index.maxPhraseLength()));
        for (size_t len = 1; len <= maxLen; ++len) {
            const bool isPhrase = len > 1 && m_index.phrase(han, i, len).has_value();
            if (len > 1 && !isPhrase)
                continue;
            Cell c {best[i].words + 1, best[i].squares + int(len * len), i, isPhrase};
            Cell &t = best[i + len];
            if (c.words < t.words || (c.words == t.words && c.squares > t.squares))
                t = c;
        }
    }
    QVector<PinyinSyllable> out;
    out.resize(qsizetype(n));
    for (size_t end = n; end > 0;) {
        const Cell &c = best[end];
        if (c.phrase) {
            const auto reading = *m_index.phrase(han, c.from, end - c.from);
            for (size_t k = c.from; k < end; ++k)
                out[qsizetype(k)] = reading[qsizetype(k - c.from)];
        } else {
            out[qsizetype(c.from)]
                = loneReading(han, c.from)
                      .value_or(m_index.usualReading(han[c.from]).value_or(PinyinSyllable {QString(), 5}));
        }
        end = c.from;
    }
    for (size_t i = 0; i < n; ++i)
        if (adverbialDe(han, i))
            out[qsizetype(i)] = PinyinSyllable {QStringLiteral("de"), 5};
    return out;
}

} // namespace toonface
