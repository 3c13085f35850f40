#pragma once

// The layout of a landmark model's block of bytes (LandmarkPredictor::flat(), the cache file's
// block): a header, the mean shape, a table of cascades, then each cascade's arrays, every one
// starting on a 64-byte boundary, at offsets from the block's start that the table gives (so
// that any order of the sections is read alike). Private to core/detect: the two readers of
// dlib's model file (landmarkpredictor.cpp, shapemodelfile.cpp) lay blocks out by it.

#include "detect/landmarkmap.h"

#include <QtGlobal>

#include <cstddef>

namespace toonface::flat {

constexpr int kShapeValues = 2 * kIbugPointCount;
constexpr char kMagic[8] = {'T', 'F', 'L', 'M', 'F', 'L', 'A', 'T'};
constexpr quint32 kVersion = 1;
constexpr size_t kSectionAlignment = 64;
constexpr quint32 kMaxCascades = 1000;
constexpr quint32 kMaxTrees = 100000;
constexpr quint32 kMaxSplitsPerTree = 65535;
constexpr quint32 kMaxFeatures = 65536; // a split names its features in 16 bits

struct Header
{
    char magic[8];
    quint32 version;
    quint32 points;
    quint32 cascades;
    quint32 reserved;
    quint64 initialAt; // 2 x points floats
    quint64 tableAt; // `cascades` Cascade
};

struct Cascade
{
    quint32 trees;
    quint32 splitsPerTree;
    quint32 features;
    quint32 reserved;
    quint64 anchorsAt; // `features` quint32
    quint64 deltasAt; // `features` pairs of floats
    quint64 splitFeaturesAt; // trees x splitsPerTree x 2 quint16
    quint64 thresholdsAt; // trees x splitsPerTree floats
    quint64 leavesAt; // trees x (splitsPerTree + 1) x 136 floats
};

constexpr size_t alignUp(size_t at)
{
    return (at + kSectionAlignment - 1) / kSectionAlignment * kSectionAlignment;
}

} // namespace toonface::flat
