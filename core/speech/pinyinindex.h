#pragma once

#include "speech/pinyin.h"

#include <QByteArray>
#include <QHash>
#include <QString>
#include <QVector>

#include <optional>
#include <string>

namespace toonface {

// The character → pinyin dictionary as one compact, immutable block of bytes that is looked up
// in place: a table of the distinct toned syllables, the characters sorted by code point with
// their readings (indices into that table), and the phrases sorted by their characters with
// one syllable per character. Built once from the parsed sources and cached on disk as is, so
// that loading it is reading a file and checking its checksum.
//
// The block: a header (magic "TFPYIDX", format version, section sizes, the signature of the
// sources it was built from, a 64-bit checksum of everything after the header), then the
// sections, each 4-byte aligned.
class PinyinIndex
{
public:
    PinyinIndex() = default;

    // The block for these readings (most usual first) and phrases (one syllable per character),
    // tagged with `sourceSignature` (what the sources were when it was built).
    static QByteArray build(const QHash<char32_t, QVector<PinyinSyllable>> &readings,
        const QHash<QString, QVector<PinyinSyllable>> &phrases, quint64 sourceSignature);

    // Checks and adopts a block: nullopt, with *error saying what is wrong (not an index, another
    // format version, truncated, checksum mismatch, a section out of bounds), when it cannot be used.
    static std::optional<PinyinIndex> fromBlock(QByteArray block, QString *error);

    quint64 sourceSignature() const { return m_signature; }
    int characterCount() const { return int(m_charCount); }
    int phraseCount() const { return int(m_phraseCount); }
    int maxPhraseLength() const { return int(m_maxPhraseLength); }
    const QByteArray &block() const { return m_block; }

    bool contains(char32_t han) const { return findChar(han) >= 0; }
    QVector<PinyinSyllable> readings(char32_t han) const;
    // The usual reading, or nullopt when the character is unknown.
    std::optional<PinyinSyllable> usualReading(char32_t han) const;
    // The reading of the phrase han[from, from + len), when it is one.
    std::optional<QVector<PinyinSyllable>> phrase(const std::u32string &han, size_t from, size_t len) const;

private:
    int findChar(char32_t han) const;
    quint32 u32(size_t section, size_t index) const;
    quint16 u16(size_t section, size_t index) const;

    QByteArray m_block;
    QVector<PinyinSyllable> m_syllables;
    quint64 m_signature = 0;
    quint32 m_charCount = 0, m_phraseCount = 0, m_maxPhraseLength = 1;
    // Byte offsets of the sections in m_block.
    size_t m_chars = 0; // per character: code point, first reading, reading count (3 × u32)
    size_t m_charReadings = 0; // u16 syllable indices
    size_t m_phrases = 0; // per phrase: offset, length (2 × u32) into the two arrays below
    size_t m_phraseChars = 0; // u32 code points
    size_t m_phraseReadings = 0; // u16 syllable indices, parallel to m_phraseChars
};

} // namespace toonface
