#pragma once

#include <QString>
#include <QVector>

namespace toonface {

// One interval of a Praat TextGrid tier, in seconds.
struct TextGridInterval
{
    double start = 0;
    double end = 0;
    QString text;
};

// The intervals of the interval tier named `tier` in a Praat TextGrid file (long or short text
// format), in file order. Empty with *error naming the file and the problem when the file cannot
// be read or has no such tier.
QVector<TextGridInterval> readTextGridTier(const QString &path, const QString &tier, QString *error = nullptr);

} // namespace toonface
