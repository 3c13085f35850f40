#pragma once

#include "speech/pinyin.h"

#include <QString>
#include <QVector>

#include <optional>

namespace toonface {

// True for the Bopomofo letters (U+3105..U+312F, U+31A0..U+31BF) and the Zhuyin tone marks
// ˉ ˊ ˇ ˋ ˙.
bool isZhuyinChar(char32_t c);

// A run of Zhuyin (Bopomofo) syllables with optional tone marks, e.g. "ㄋㄧˇㄏㄠˇ", → pinyin.
// A syllable ends at a tone mark or where the next initial begins; the first tone is unmarked
// (ˉ may be written) and ˙ before or after a syllable is the neutral tone. `lengths`, when given,
// receives each syllable's length in characters of `run`. nullopt when the run is not Zhuyin.
std::optional<QVector<PinyinSyllable>> zhuyinToPinyin(const QString &run, QVector<int> *lengths = nullptr);

} // namespace toonface
