#pragma once

#include "face/facemodel.h"
#include "face/mouthshape.h"
#include "render/style.h"

#include <QImage>
#include <QSize>

#include <array>

namespace toonface {

// The nine mouth shapes as small pictures of this character's own lips: each shape's pose
// (mouthPose with the project's presets) drawn by SvgFace, framed on the mouth. Built once per
// change of the face, style or presets (update() compares them) and then only read.
//
// Lives on the GUI thread; not thread-safe.
class MouthIcons
{
public:
    // `size` in device-independent pixels; images are made at `devicePixelRatio` times that.
    explicit MouthIcons(QSize size = QSize(30, 18), qreal devicePixelRatio = 2.0);

    // Rebuilds the pictures when the face, style or presets differ from the last call.
    // Returns whether it rebuilt. With no face, every picture is null.
    bool update(const FaceModel &face, const Style &style, const MouthShapeSet &shapes, bool hasFace);

    // Null when there is no face.
    const QImage &icon(MouthShape shape) const { return m_icons[int(shape)]; }
    QSize size() const { return m_size; }
    int buildCount() const { return m_builds; }

private:
    QSize m_size;
    qreal m_ratio;
    FaceModel m_face;
    Style m_style;
    MouthShapeSet m_shapes;
    bool m_hasFace = false;
    bool m_built = false;
    int m_builds = 0;
    std::array<QImage, kMouthShapeCount> m_icons;
};

} // namespace toonface
