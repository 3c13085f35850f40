#pragma once

#include "speech/syllableshapes.h"
#include "speech/tts.h"

#include <QString>
#include <QVector>

namespace toonface {

// English speech onto the nine mouth shapes, from espeak-ng's English phoneme mnemonics.
// The table, by what the lips do:
//   lips closed          p b m                                 → m
//   lower lip under teeth f v                                  → f
//   rounded, protruded   w, r, u: U (goose, foot), S Z tS dZ    → u
//   rounded, open        0 O: O@ (lot, thought), oU/@U (goat)  → o (oU → o u)
//   open                 a aa A: V A@ (trap, palm, strut)       → a (aI → a i, aU → a u)
//   half open, spread    E e@ 3: (dress, square, nurse)        → e (eI → e i)
//   spread               I i i: j I@ i@3 (kit, fleece, yes)     → i
//   tongue up, jaw half  n N l                                  → n
//   open neutral         @ and other vowels                     → h
//   other consonants     t d k g s z T D h ...                  → h' (as in Mandarin: dropped
//                                                                  before a vowel shape)
// Returns the shapes of one phoneme (h' as MouthShape::H with *hPrime set); empty for
// pauses.
QVector<MouthShape> englishPhonemeShapes(const QString &mnemonic, bool *hPrime = nullptr);

// The mouth keys of one English word from its phonemes (times in seconds): each phoneme's
// shapes start at the phoneme's start (a diphthong's second shape halfway to the next
// phoneme), h' is dropped before a vowel shape, equal neighbours merge. A word without
// phonemes opens the mouth (h) at `start`.
QVector<ShapeKey> englishWordKeys(const QVector<TtsPhoneme> &phonemes, double start, double end);

} // namespace toonface
