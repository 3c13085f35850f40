#include "face/mouthshape.h"

#include "face/facemodel.h"
#include "face/fapu.h"

namespace toonface {

QString mouthShapeName(MouthShape shape)
{
    static const char *const names[] = {"m", "f", "h", "a", "i", "u", "e", "o", "n"};
    return QString::fromLatin1(names[int(shape)]);
}

std::optional<MouthShape> mouthShapeFromName(const QString &name)
{
    for (MouthShape s : kAllMouthShapes) {
        if (mouthShapeName(s) == name)
            return s;
    }
    return std::nullopt;
}

double FapuTerm::evaluate(const Fapu &f) const
{
    return mns * f.mns0 + mw * f.mw0 + lowerLip * f.lowerLipH + px * f.pixel();
}

namespace {

FapuOffset dyMns(double k)
{
    return {{}, {k, 0, 0, 0}};
}

} // namespace

MouthShapePreset MouthShapeSet::defaultPreset(MouthShape shape)
{
    MouthShapePreset p;
    auto &o = p.offsets;
    switch (shape) {
    case MouthShape::M: break;
    case MouthShape::F:
        // face-model.md note 1: the lower lip tucked up under the upper lip.
        o[Down] = {{}, {0, 0, -0.5, 0}};
        break;
    case MouthShape::H:
    case MouthShape::U:
        // note 2: h's up point moves in y, as u's does.
        o[Up] = dyMns(-0.3);
        o[Down] = dyMns(0.3);
        o[Left] = {{}, {0, 0, 0, -1}};
        o[Right] = {{}, {0, 0, 0, -1}};
        break;
    case MouthShape::A:
        o[Up] = dyMns(-0.3);
        o[Down] = dyMns(0.8);
        o[Left] = {{0, 1.0 / 8, 0, 0}, {}};
        o[Right] = {{0, -1.0 / 8, 0, 0}, {}};
        break;
    case MouthShape::I:
        o[Down] = dyMns(1.0 / 6);
        o[Left] = {{0, -1.0 / 12, 0, 0}, {0, 0, 0, -3}};
        o[Right] = {{0, 1.0 / 12, 0, 0}, {0, 0, 0, -3}};
        break;
    case MouthShape::E:
        o[Down] = dyMns(0.5);
        o[Left] = {{0, -1.0 / 12, 0, 0}, {0, 0, 0, -3}};
        o[Right] = {{0, 1.0 / 12, 0, 0}, {0, 0, 0, -3}};
        break;
    case MouthShape::O:
        o[Up] = dyMns(-0.3);
        o[Down] = dyMns(0.5);
        o[Left] = {{0, 0.2, 0, 0}, {}};
        o[Right] = {{0, -0.2, 0, 0}, {}};
        p.cornersAtLipMiddle = true;
        break;
    case MouthShape::N:
        o[Up] = dyMns(-0.25);
        o[Down] = dyMns(0.5);
        p.cornersFromPrevious = true;
        break;
    }
    return p;
}

MouthShapeSet::MouthShapeSet()
{
    for (MouthShape s : kAllMouthShapes)
        m_presets[int(s)] = defaultPreset(s);
}

std::array<QPointF, 4> restingMouth(const FaceModel &face)
{
    std::array<QPointF, 4> d {};
    // A gap under a tenth of MNS0 is lips drawn touching (about the inner line's width): left as
    // photographed.
    const double gap = face.point("2.3").y() - face.point("2.2").y();
    if (gap > 0.1 * face.fapu().mns0) {
        d[Up] = QPointF(0, 0.25 * gap);
        d[Down] = QPointF(0, -0.75 * gap);
    }
    return d;
}

std::array<QPointF, 4> MouthShapeSet::displacements(
    MouthShape shape, const FaceModel &face, const std::array<QPointF, 4> *previous) const
{
    const Fapu f = face.fapu();
    const MouthShapePreset &p = preset(shape);
    std::array<QPointF, 4> d = restingMouth(face);
    for (int k = 0; k < 4; ++k)
        d[k] += QPointF(p.offsets[k].dx.evaluate(f), p.offsets[k].dy.evaluate(f));
    if (p.cornersAtLipMiddle) {
        const double upY = face.point("8.9").y() + d[Up].y();
        const double dnY = face.point("8.2").y() + d[Down].y();
        const double midY = (upY + dnY) / 2.0;
        // The preset's own dy (zero by default) is added on top of the midway height.
        d[Left].setY(midY - face.point("8.4").y() + d[Left].y());
        d[Right].setY(midY - face.point("8.3").y() + d[Right].y());
    }
    if (p.cornersFromPrevious) {
        d[Left] = previous ? (*previous)[Left] : QPointF();
        d[Right] = previous ? (*previous)[Right] : QPointF();
    }
    return d;
}

} // namespace toonface

#include "face/pose.h"

namespace toonface {

Pose mouthPose(
    const FaceModel &face, const MouthShapeSet &shapes, MouthShape shape, const std::array<QPointF, 4> *previous)
{
    const auto d = shapes.displacements(shape, face, previous);
    Pose pose;
    for (int k = 0; k < 4; ++k)
        pose.offset[pt::idx(kMouthControlIds[k])] = d[k];
    return pose;
}

} // namespace toonface
