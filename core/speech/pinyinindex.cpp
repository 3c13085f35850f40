#include "speech/pinyinindex.h"

#include "i18n/coretext.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <vector>

namespace toonface {

namespace {

constexpr char kMagic[8] = {'T', 'F', 'P', 'Y', 'I', 'D', 'X', '\0'};
constexpr quint32 kVersion = 1;

// The fixed header at the start of a block.
struct Header
{
    char magic[8];
    quint32 version;
    quint32 maxPhraseLength;
    quint64 signature;
    quint64 checksum; // of the whole block, this field taken as 0
    quint32 syllableBytes; // "pinyin tone\n" lines
    quint32 syllableCount;
    quint32 charCount;
    quint32 charReadingCount;
    quint32 phraseCount;
    quint32 phraseCharCount;
};
static_assert(sizeof(Header) % 8 == 0);

size_t aligned4(size_t n)
{
    return (n + 3) & ~size_t(3);
}

// A 64-bit hash of the bytes (8 at a time; a mix per word): any changed byte changes it.
quint64 checksum(const char *data, size_t size, quint64 seed)
{
    quint64 h = seed ^ 0x9e3779b97f4a7c15ull ^ size;
    size_t i = 0;
    for (; i + 8 <= size; i += 8) {
        quint64 w;
        std::memcpy(&w, data + i, 8);
        h ^= w;
        h *= 0xff51afd7ed558ccdull;
        h ^= h >> 32;
    }
    for (; i < size; ++i) {
        h ^= quint8(data[i]);
        h *= 0xc4ceb9fe1a85ec53ull;
    }
    return h ^ (h >> 29);
}

// The checksum of a whole block: its header (with the checksum field zero) and its body.
quint64 blockChecksum(Header h, const char *body, size_t size)
{
    h.checksum = 0;
    return checksum(body, size, checksum(reinterpret_cast<const char *>(&h), sizeof h, 0));
}

template<typename T>
void append(QByteArray &out, const T &v)
{
    out.append(reinterpret_cast<const char *>(&v), sizeof(T));
}

void pad4(QByteArray &out)
{
    out.append(QByteArray(qsizetype(aligned4(size_t(out.size())) - size_t(out.size())), '\0'));
}

} // namespace

QByteArray PinyinIndex::build(const QHash<char32_t, QVector<PinyinSyllable>> &readings,
    const QHash<QString, QVector<PinyinSyllable>> &phrases, quint64 sourceSignature)
{
    // The distinct syllables, sorted (a stable block for the same sources).
    std::map<std::pair<QString, int>, quint16> syllableIds;
    for (const auto &list : readings)
        for (const PinyinSyllable &s : list)
            syllableIds.emplace(std::make_pair(s.pinyin, s.tone), 0);
    for (const auto &list : phrases)
        for (const PinyinSyllable &s : list)
            syllableIds.emplace(std::make_pair(s.pinyin, s.tone), 0);
    QByteArray syllableText;
    quint16 next = 0;
    for (auto &[key, id] : syllableIds) {
        id = next++;
        syllableText += key.first.toUtf8() + ' ' + QByteArray::number(key.second) + '\n';
    }
    auto idOf = [&](const PinyinSyllable &s) { return syllableIds.at(std::make_pair(s.pinyin, s.tone)); };

    std::vector<char32_t> chars;
    chars.reserve(size_t(readings.size()));
    for (auto it = readings.cbegin(); it != readings.cend(); ++it)
        if (!it.value().isEmpty())
            chars.push_back(it.key());
    std::sort(chars.begin(), chars.end());

    struct Phrase
    {
        std::u32string key;
        const QVector<PinyinSyllable> *reading;
    };
    std::vector<Phrase> sorted;
    quint32 maxLength = 1;
    for (auto it = phrases.cbegin(); it != phrases.cend(); ++it) {
        std::u32string key = it.key().toStdU32String();
        if (key.empty() || key.size() != size_t(it.value().size()))
            continue;
        maxLength = std::max(maxLength, quint32(key.size()));
        sorted.push_back({std::move(key), &it.value()});
    }
    std::sort(sorted.begin(), sorted.end(), [](const Phrase &a, const Phrase &b) { return a.key < b.key; });

    QByteArray body;
    body += syllableText;
    pad4(body);
    quint32 charReadingCount = 0;
    for (char32_t c : chars) {
        append(body, quint32(c));
        append(body, charReadingCount);
        const quint32 count = quint32(readings.value(c).size());
        append(body, count);
        charReadingCount += count;
    }
    for (char32_t c : chars)
        for (const PinyinSyllable &s : readings.value(c))
            append(body, idOf(s));
    pad4(body);
    quint32 phraseChars = 0;
    for (const Phrase &p : sorted) {
        append(body, phraseChars);
        append(body, quint32(p.key.size()));
        phraseChars += quint32(p.key.size());
    }
    for (const Phrase &p : sorted)
        for (char32_t c : p.key)
            append(body, quint32(c));
    for (const Phrase &p : sorted)
        for (const PinyinSyllable &s : *p.reading)
            append(body, idOf(s));
    pad4(body);

    Header h {};
    std::memcpy(h.magic, kMagic, sizeof kMagic);
    h.version = kVersion;
    h.maxPhraseLength = maxLength;
    h.signature = sourceSignature;
    h.syllableBytes = quint32(syllableText.size());
    h.syllableCount = quint32(syllableIds.size());
    h.charCount = quint32(chars.size());
    h.charReadingCount = charReadingCount;
    h.phraseCount = quint32(sorted.size());
    h.phraseCharCount = phraseChars;
    h.checksum = blockChecksum(h, body.constData(), size_t(body.size()));
    QByteArray out;
    out.reserve(qsizetype(sizeof h) + body.size());
    append(out, h);
    out += body;
    return out;
}

std::optional<PinyinIndex> PinyinIndex::fromBlock(QByteArray block, QString *error)
{
    auto fail = [&](const QString &why) {
        *error = why;
        return std::nullopt;
    };
    Header h;
    if (size_t(block.size()) < sizeof h)
        return fail(ScriptText::tr("too short to be a pinyin index"));
    std::memcpy(&h, block.constData(), sizeof h);
    if (std::memcmp(h.magic, kMagic, sizeof kMagic) != 0)
        return fail(ScriptText::tr("not a pinyin index"));
    if (h.version != kVersion)
        return fail(ScriptText::tr("pinyin index format %1, expected %2").arg(h.version).arg(kVersion));
    // The sections' sizes, in 64-bit arithmetic: a damaged header cannot overflow them.
    const quint64 syllables = aligned4(h.syllableBytes);
    const quint64 chars = 12ull * h.charCount;
    const quint64 charReadings = aligned4(2ull * h.charReadingCount);
    const quint64 phrases = 8ull * h.phraseCount;
    const quint64 phraseChars = 4ull * h.phraseCharCount;
    const quint64 phraseReadings = aligned4(2ull * h.phraseCharCount);
    const quint64 need = sizeof h + syllables + chars + charReadings + phrases + phraseChars + phraseReadings;
    if (quint64(block.size()) != need)
        return fail(ScriptText::tr("pinyin index of %1 bytes, its header describes %2").arg(block.size()).arg(need));
    if (blockChecksum(h, block.constData() + sizeof h, size_t(block.size()) - sizeof h) != h.checksum)
        return fail(ScriptText::tr("pinyin index checksum mismatch (damaged)"));

    PinyinIndex index;
    const QList<QByteArray> lines
        = QByteArray::fromRawData(block.constData() + sizeof h, qsizetype(h.syllableBytes)).split('\n');
    for (const QByteArray &line : lines) {
        if (line.isEmpty())
            continue;
        const qsizetype space = line.indexOf(' ');
        bool ok = false;
        const int tone = space > 0 ? line.mid(space + 1).toInt(&ok) : 0;
        if (!ok || tone < 1 || tone > 5)
            return fail(ScriptText::tr("pinyin index has a bad syllable '%1'").arg(QString::fromUtf8(line)));
        index.m_syllables.append({QString::fromUtf8(line.left(space)), tone});
    }
    if (quint32(index.m_syllables.size()) != h.syllableCount)
        return fail(ScriptText::tr("pinyin index syllable table is damaged"));
    index.m_chars = sizeof h + syllables;
    index.m_charReadings = index.m_chars + chars;
    index.m_phrases = index.m_charReadings + charReadings;
    index.m_phraseChars = index.m_phrases + phrases;
    index.m_phraseReadings = index.m_phraseChars + phraseChars;
    index.m_block = std::move(block);
    index.m_charCount = h.charCount;
    index.m_phraseCount = h.phraseCount;
    index.m_maxPhraseLength = std::max<quint32>(1, h.maxPhraseLength);
    index.m_signature = h.signature;
    // Every reference inside bounds, so that lookups never need to check.
    for (quint32 c = 0; c < h.charCount; ++c) {
        const quint64 first = index.u32(index.m_chars, 3 * c + 1), count = index.u32(index.m_chars, 3 * c + 2);
        if (first + count > h.charReadingCount
            || (c > 0 && index.u32(index.m_chars, 3 * c) <= index.u32(index.m_chars, 3 * (c - 1))))
            return fail(ScriptText::tr("pinyin index character table is damaged"));
    }
    for (quint32 k = 0; k < h.charReadingCount; ++k)
        if (index.u16(index.m_charReadings, k) >= h.syllableCount)
            return fail(ScriptText::tr("pinyin index character readings are damaged"));
    for (quint32 p = 0; p < h.phraseCount; ++p) {
        const quint64 first = index.u32(index.m_phrases, 2 * p), count = index.u32(index.m_phrases, 2 * p + 1);
        if (count == 0 || count > index.m_maxPhraseLength || first + count > h.phraseCharCount)
            return fail(ScriptText::tr("pinyin index phrase table is damaged"));
    }
    for (quint32 k = 0; k < h.phraseCharCount; ++k)
        if (index.u16(index.m_phraseReadings, k) >= h.syllableCount)
            return fail(ScriptText::tr("pinyin index phrase readings are damaged"));
    return index;
}

quint32 PinyinIndex::u32(size_t section, size_t index) const
{
    quint32 v;
    std::memcpy(&v, m_block.constData() + section + 4 * index, 4);
    return v;
}

quint16 PinyinIndex::u16(size_t section, size_t index) const
{
    quint16 v;
    std::memcpy(&v, m_block.constData() + section + 2 * index, 2);
    return v;
}

int PinyinIndex::findChar(char32_t han) const
{
    quint32 lo = 0, hi = m_charCount;
    while (lo < hi) {
        const quint32 mid = lo + (hi - lo) / 2;
        const quint32 c = u32(m_chars, 3 * size_t(mid));
        if (c == han)
            return int(mid);
        if (c < han)
            lo = mid + 1;
        else
            hi = mid;
    }
    return -1;
}

QVector<PinyinSyllable> PinyinIndex::readings(char32_t han) const
{
    QVector<PinyinSyllable> out;
    const int c = findChar(han);
    if (c < 0)
        return out;
    const quint32 first = u32(m_chars, 3 * size_t(c) + 1), count = u32(m_chars, 3 * size_t(c) + 2);
    for (quint32 k = 0; k < count; ++k)
        out.append(m_syllables[u16(m_charReadings, first + k)]);
    return out;
}

std::optional<PinyinSyllable> PinyinIndex::usualReading(char32_t han) const
{
    const int c = findChar(han);
    if (c < 0 || u32(m_chars, 3 * size_t(c) + 2) == 0)
        return std::nullopt;
    return m_syllables[u16(m_charReadings, u32(m_chars, 3 * size_t(c) + 1))];
}

std::optional<QVector<PinyinSyllable>> PinyinIndex::phrase(const std::u32string &han, size_t from, size_t len) const
{
    if (len == 0 || len > m_maxPhraseLength || from + len > han.size())
        return std::nullopt;
    // Lexicographic comparison of phrase p with the wanted characters.
    auto compare = [&](quint32 p) {
        const quint32 first = u32(m_phrases, 2 * size_t(p)), count = u32(m_phrases, 2 * size_t(p) + 1);
        for (size_t k = 0; k < std::min<size_t>(count, len); ++k) {
            const quint32 c = u32(m_phraseChars, first + k);
            if (c != han[from + k])
                return c < han[from + k] ? -1 : 1;
        }
        return count == len ? 0 : (count < len ? -1 : 1);
    };
    quint32 lo = 0, hi = m_phraseCount;
    while (lo < hi) {
        const quint32 mid = lo + (hi - lo) / 2;
        const int c = compare(mid);
        if (c == 0) {
            QVector<PinyinSyllable> out;
            const quint32 first = u32(m_phrases, 2 * size_t(mid));
            for (size_t k = 0; k < len; ++k)
                out.append(m_syllables[u16(m_phraseReadings, first + k)]);
            return out;
        }
        if (c < 0)
            lo = mid + 1;
        else
            hi = mid;
    }
    return std::nullopt;
}

} // namespace toonface
