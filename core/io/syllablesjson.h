#pragma once

#include "speech/lipsync.h"

#include <QJsonArray>
#include <QVector>

namespace toonface {

class JsonField;

// The timed syllables of a script (the editor's script row) as JSON: an array of
// {text, pinyin, tone, start, end, confidence, shapes: [{shape, start}]}, times in seconds.
// Lossless: syllablesFromJson(syllablesToJson(s)) == s for finite values.
QJsonArray syllablesToJson(const QVector<LipsyncSyllable> &syllables);

// Validates every field (names the bad one by its path, e.g. "script.syllables[3].end: ..."):
// numbers finite, 0 <= start <= end, tone 0..5, shapes named as face-model.md names them, each
// shape starting inside its syllable and in order.
bool syllablesFromJson(const JsonField &field, QVector<LipsyncSyllable> *out, QString *error);

} // namespace toonface
