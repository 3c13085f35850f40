#pragma once

#include "face/mouthshape.h"

#include <QString>
#include <QVector>

namespace toonface {

// The mouth shapes of one Mandarin syllable, by face-model.md's rules ("From a syllable to
// mouth shapes"). `pinyin` is one toneless Hanyu pinyin syllable in lower case; ü may be
// written ü, v or u: (lü, lv, lu:). A tone number or tone marks are ignored.
// ensures: 1 to 4 shapes for every standard syllable, no two equal neighbours; empty when
// `pinyin` is not spelled like a Mandarin syllable.
QVector<MouthShape> syllableShapes(const QString &pinyin);

// The shapes' letters as face-model.md writes them, e.g. "m i a u" (diagnostics and tests).
QString shapeSpelling(const QVector<MouthShape> &shapes);

// f_k of face-model.md's timing table: shape k (0-based) of `count` starts at t0 + f_k·T.
// requires: 1 <= count <= 4 and 0 <= k < count. Counts above 4 (never produced for a
// syllable) spread the remaining shapes evenly after the table's last row.
double shapeStartFraction(int count, int k);

// One key of the mouth track: `shape` held from `start` (seconds).
struct ShapeKey
{
    MouthShape shape = MouthShape::M;
    double start = 0;
    bool operator==(const ShapeKey &) const = default;
};

// The keys of one syllable spoken from `start` for `duration` seconds.
QVector<ShapeKey> syllableShapeKeys(const QVector<MouthShape> &shapes, double start, double duration);

} // namespace toonface
