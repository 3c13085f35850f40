#pragma once

#include <QFont>

namespace toonface {

// Pinyin's tone marks in every font the editor draws with. Some fonts claim the third tone's
// vowels (ǎ ǒ ǐ ǔ, Latin Extended-B) and draw nothing for them: WenQuanYi Micro Hei, the sans
// serif fontconfig gives a Chinese locale on many Linux systems, does, and "hǎo" reads "h o".

// True when `font` draws every tone-marked pinyin vowel it claims to hold (a vowel it lacks is
// left to Qt's fallback fonts).
bool drawsToneMarks(const QFont &font);

// `font` with a family that draws the tone marks put before its own (which still draws what
// the first lacks, such as Chinese characters); `font` itself when it draws them already or no
// installed family does.
QFont withToneMarks(const QFont &font);

// Makes the application font draw the tone marks (see withToneMarks). Call once after the
// QApplication is made, before the windows.
void ensureToneMarks();

} // namespace toonface
