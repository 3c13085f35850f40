#pragma once

#include <QPointF>
#include <QString>

#include <array>
#include <optional>

namespace toonface {

class FaceModel;
struct Fapu;

// The nine basic mouth shapes of face-model.md. `h'` (an initial's open mouth that a
// following vowel replaces) exists only while a syllable is turned into shapes, never here.
enum class MouthShape { M, F, H, A, I, U, E, O, N };

inline constexpr int kMouthShapeCount = 9;
inline constexpr std::array<MouthShape, kMouthShapeCount> kAllMouthShapes = {MouthShape::M, MouthShape::F,
    MouthShape::H, MouthShape::A, MouthShape::I, MouthShape::U, MouthShape::E, MouthShape::O, MouthShape::N};

QString mouthShapeName(MouthShape shape); // "m", "f", ... "n"
std::optional<MouthShape> mouthShapeFromName(const QString &name);

// One coordinate of a displacement, as a sum of FAPU terms, so that a preset fits every face:
// value = mns·MNS0 + mw·MW0 + lowerLip·LowerLipH + px·(ES0/100).
struct FapuTerm
{
    double mns = 0;
    double mw = 0;
    double lowerLip = 0;
    double px = 0;

    double evaluate(const Fapu &f) const;
    bool operator==(const FapuTerm &) const = default;
};

struct FapuOffset
{
    FapuTerm dx;
    FapuTerm dy;
    bool operator==(const FapuOffset &) const = default;
};

// The four mouth control points a shape moves, in this order.
enum MouthControl { Up = 0, Down = 1, Left = 2, Right = 3 }; // 8.9, 8.2, 8.4, 8.3
inline constexpr std::array<const char *, 4> kMouthControlIds = {"8.9", "8.2", "8.4", "8.3"};

// A mouth shape as the displacement of the four mouth control points from neutral.
struct MouthShapePreset
{
    std::array<FapuOffset, 4> offsets {};
    // `o`: the corners sit at the height midway between the moved 8.9 and 8.2.
    bool cornersAtLipMiddle = false;
    // `n`: the corners stay where the shape before put them.
    bool cornersFromPrevious = false;

    bool operator==(const MouthShapePreset &) const = default;
};

// The displacements of 8.9, 8.2, 8.4, 8.3 that shut lips photographed apart: the gap between
// the inner lips (2.2, 2.3) closes by the lower lip rising three quarters of it (the jaw closes)
// and the upper lip lowering a quarter; the lips keep their thickness. Zero when they touch or
// nearly (a gap under a tenth of MNS0).
std::array<QPointF, 4> restingMouth(const FaceModel &face);

// The editable set of nine presets a project carries; defaults() is face-model.md's table.
class MouthShapeSet
{
public:
    MouthShapeSet();
    static MouthShapePreset defaultPreset(MouthShape shape);

    const MouthShapePreset &preset(MouthShape shape) const { return m_presets[int(shape)]; }
    void setPreset(MouthShape shape, const MouthShapePreset &preset) { m_presets[int(shape)] = preset; }
    bool isDefault(MouthShape shape) const { return preset(shape) == defaultPreset(shape); }

    // Pixel displacements of 8.9, 8.2, 8.4, 8.3 for `shape` on `face`. `previous` are the
    // displacements of the shape before (used by `n`; neutral when absent). The table's neutral
    // is a face with its lips shut: on a face photographed with them apart every shape starts
    // from restingMouth(face) (so `m` shuts them).
    std::array<QPointF, 4> displacements(
        MouthShape shape, const FaceModel &face, const std::array<QPointF, 4> *previous = nullptr) const;

    bool operator==(const MouthShapeSet &) const = default;

private:
    std::array<MouthShapePreset, kMouthShapeCount> m_presets;
};

} // namespace toonface

namespace toonface {
struct Pose;
// The pose that holds `shape` (only the four mouth controls move).
Pose mouthPose(const FaceModel &face, const MouthShapeSet &shapes, MouthShape shape,
    const std::array<QPointF, 4> *previous = nullptr);
} // namespace toonface
