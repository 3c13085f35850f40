#pragma once

#include <QString>

namespace toonface {

// How short a Mandarin syllable can plausibly be, from the durations of its parts in read
// speech: an initial's closure, burst, aspiration or frication and a final's vowels and coda
// each take a least time, and a neutral-tone syllable is shortened (to about 60%). Figures are
// for an ordinary pace (syllables about 0.2 s long on average); `pace` scales them to the
// speaker's (their mean syllable length / 0.2 s, 0.5..1.5 taken into account). Never below
// kShortestSyllable: an initial and a final cannot both be shorter.
inline constexpr double kShortestSyllable = 0.06; // seconds
inline constexpr double kOrdinarySyllable = 0.2; // seconds: the pace the figures are for

// `pinyin` toneless and normalised (empty: an English word or unknown, which gets the floor).
double minimumSyllableSeconds(const QString &pinyin, int tone, double pace);

} // namespace toonface
