#pragma once

#include "export/smilchannels.h"
#include "export/svgxml.h"

#include <QSet>
#include <QVector>

// Animated elements drawn in tenths of a pixel, so that their SMIL values are whole numbers.
namespace toonface::smil {

// The values of a part's geometry are offsets quantized to 0.1 px (Channel::decimals = 1).
// Written as decimals they spend a point, and often a digit, on each number ("-1.2", ".3",
// "12.4"); a talking mouth writes hundreds of thousands of them. An element that carries
// transform="scale(.1)", with its geometry and stroke width ten times larger, draws the same
// shape, and its values are the same positions to the same 0.1 px as whole numbers ("-12",
// "3", "124").
//
// Rewrites so, in `document`, the elements of the parts `animated` (indices into `parts`) whose
// drawing such a scale leaves unchanged: a path, circle or ellipse whose attributes are its
// geometry (every numeric one a channel of `channels`), its id and plain paint (colours,
// opacities, fill rule, line caps and joins, a stroke width of its own when it strokes) —
// nothing that a scale would change or that would change with it: no transform, clip path,
// mask, filter, style, paint server or dash pattern — and that nothing references (a <use> in
// a clip path draws the element with its transform). Returns the indices of the parts
// rewritten; their values are written with one decimal fewer (smilexport.cpp).
QSet<int> writeInTenths(
    XmlNode &document, const QVector<FacePart> &parts, const QVector<Channel> &channels, const QSet<int> &animated);

} // namespace toonface::smil
