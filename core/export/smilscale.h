#pragma once

#include "export/smilchannels.h"
#include "export/svgxml.h"

#include <QSet>
#include <QVector>

// Animated elements drawn in fifths of a pixel, so that their SMIL values are short whole
// numbers.
namespace toonface::smil {

// The values of a part's geometry are offsets in pixels. Written as decimals they spend a
// point, and often a digit, on each number ("-1.2", ".3", "12.4"); a talking mouth writes
// hundreds of thousands of them. An element that carries transform="scale(.2)", with its
// geometry and stroke width five times larger, draws the same shape, and its values are whole
// numbers of fifths of a pixel ("-6", "2", "62"). A fifth of a pixel is finer than the eye sees
// at the export's size: the values are rounded to it (Channel::grain), so a coordinate strays
// at most 0.1 px from the key's pose where tenths of a pixel strayed 0.05.
inline constexpr int kUnitsPerPixel = 5;

// The parts whose drawing such a scale leaves unchanged: a path, circle or ellipse whose
// attributes are its geometry (every numeric one a channel of `channels`), its id and plain
// paint (colours, opacities, fill rule, line caps and joins, a stroke width of its own when it
// strokes) — nothing that a scale would change or that would change with it: no transform,
// clip path, mask, filter, style, paint server or dash pattern — and that nothing in `document`
// references (a <use> in a clip path draws the element with its transform).
QSet<int> partsInFifths(const XmlNode &document, const QVector<FacePart> &parts, const QVector<Channel> &channels);

// Rewrites the elements of `which` (parts partsInFifths() allows) in `document`: geometry
// and stroke width five times larger (to 0.002 px), transform="scale(.2)".
void writeInFifths(
    XmlNode &document, const QVector<FacePart> &parts, const QVector<Channel> &channels, const QSet<int> &which);

} // namespace toonface::smil
