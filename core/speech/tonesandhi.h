#pragma once

#include "speech/script.h"

#include <QVector>

namespace toonface {

// The tones a Mandarin speaker says for `script`, which differ from the dictionary's (the
// script's) where neighbours change them:
// - 一 yī is yí before a 4th (or neutral, underlyingly 4th) tone and yì before a 1st, 2nd or
//   3rd; it stays yī at a phrase's end, when counting (beside another digit) and after 第;
//   between a repeated verb (看一看) it is neutral.
// - 不 bù is bú before a 4th tone, and neutral between a repeated word (是不是).
// - A 3rd tone before another 3rd is said as a 2nd: in a run of 3rd tones all but the last
//   rise (你好 ní hǎo).
// Sandhi never crosses a phrase break. English scripts keep their tones (0). Returns one tone
// (1-5) per syllable.
QVector<int> spokenTones(const Script &script);

} // namespace toonface
