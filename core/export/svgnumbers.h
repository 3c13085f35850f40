#pragma once

#include <QByteArray>
#include <QByteArrayView>
#include <QVector>

// Numbers in SVG attribute text, read and written (locale-independent), for the SMIL export.
namespace toonface::smil {

// Every number of `text`, in order (locale-independent). Letters other than exponents go to
// *letters when given.
void parseNumbers(QByteArrayView text, QVector<double> *numbers, QByteArray *letters = nullptr);

// How many numbers follow an SVG path command letter.
int pathArity(char command);

// Path data as one command letter per command (implicit repetitions written out: the
// numbers after M beyond its first pair are L's) and its numbers. False when malformed.
bool parsePath(QByteArrayView d, QVector<double> *numbers, QByteArray *commands);

inline constexpr qint64 kPow10[] = {1, 10, 100, 1000, 10000, 100000, 1000000, 10000000, 100000000, 1000000000};

// n units of 10^-decimals as the shortest decimal text: no trailing zeros, no zero before the
// point (".5"), never "-0".
void appendFixed(QByteArray &out, qint64 n, int decimals);

// v in units of 10^-decimals (0 for NaN and infinities).
qint64 quantize(double v, int decimals);

// A SMIL clock value: unlike a number, it needs a digit before the point ("0.04s").
QByteArray seconds(double s);

// Path data from absolute numbers (already quantized): relative commands after the first
// moveto, which keeps the numbers short; quantizing the absolute coordinates first keeps the
// relative ones from accumulating rounding errors.
void appendRelativePath(QByteArray &out, const QByteArray &commands, const qint64 *v, int decimals);
// Path data with the commands as given (absolute), a command repeated left implicit ("C1 2 3 4
// 5 6 7 8 9 10 11 12" for two C's): the SMIL values, additive offsets of the same commands.
void appendAbsolutePath(QByteArray &out, const QByteArray &commands, const qint64 *v, int decimals);

// Commands appendRelativePath() can rewrite.
bool relativeWritable(const QByteArray &commands);

} // namespace toonface::smil
