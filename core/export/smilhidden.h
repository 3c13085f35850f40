#pragma once

#include "export/smilkeys.h"

#include <QVector>

// Keys that nobody sees: the position of a circle while its radius is 0.
namespace toonface::smil {

// A circle or ellipse of radius 0 draws nothing, wherever it is: a blush follows the cheeks
// as the mouth moves all through a talk but shows only while the face smiles. Drops the keys
// of such a part's other channels (cx, cy) whose intervals on both sides lie where a radius
// channel ("r", "rx" or "ry") of the same part is 0 or less throughout, so that a merged
// interval never reaches a time at which the part shows; the keys kept keep their values and
// times. `keys` holds the keys of every channel (buildGroup), the radii's already reduced.
void dropHiddenKeys(const QVector<Channel> &channels, QVector<ChannelKeys> &keys);

// Whether the channel is the radius of a circle or ellipse ("r", "rx", "ry").
bool isRadius(const Channel &c);

// The spans of grid time (from, to) over which channel `radius` keyed as `keys` is 0 or less.
QVector<std::pair<qint64, qint64>> zeroSpans(const Channel &radius, const ChannelKeys &keys);

} // namespace toonface::smil
