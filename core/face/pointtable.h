#pragma once

#include <QLatin1StringView>
#include <QString>

#include <array>

namespace toonface {

// The feature groups of face-model.md, in drawing order.
enum class PointGroup { Hair, Contour, Ears, Eyebrows, Eyes, Nose, Mouth };

struct PointInfo
{
    const char *id; // the thesis' MPEG-4-style name, e.g. "8.9"
    PointGroup group;
    bool control; // moved by animation; every other point follows by rule
};

inline constexpr int kPointCount = 72;

// The 72 points in the order of face-model.md. Indices into this table are stable:
// file formats list points in this order.
const std::array<PointInfo, kPointCount> &pointTable();

// Index of a point ID in pointTable(), or -1 when the ID is unknown.
int pointIndex(QLatin1StringView id);
int pointIndex(const QString &id);

QString pointId(int index);
QString groupName(PointGroup group);
// Parses a name of groupName(); returns false for unknown names.
bool groupFromName(const QString &name, PointGroup *group);

// Compile-time-friendly indices of the points the rules refer to.
namespace pt {
int idx(const char *id);
} // namespace pt

} // namespace toonface
