#pragma once

#include "export/smilkeys.h"

// Fewer keys for a channel of the SMIL export: keys that the interpolation between their
// neighbours gives within a tolerance are dropped.
namespace toonface::smil {

// Drops the keys of `keys` (a channel's, as buildGroup makes them) that a timing fitted between
// the keys around them reproduces: every number of the channel stays within `tolerance` pixels
// (through the channel's weight) of the keyed animation at every time, the kept keys' values
// and times unchanged. A hold next to an ease, an ease cut into pieces where the drawing bends
// and several eases in one direction become one interval with a fitted keySpline (free x
// control points); runs of keys on one line collapse to their ends. Each timing is written to
// as few decimals as keep that bound. tolerance <= 0 leaves the keys as they are.
void reduceKeys(const Channel &channel, double tolerance, ChannelKeys *keys);

// The value of a channel's keys at time n (grid steps), in the channel's units: the keyed
// animation as a browser plays it. out receives channel.size numbers.
void keyedValue(const Channel &channel, const ChannelKeys &keys, double n, double *out);

} // namespace toonface::smil
