#pragma once

#include "face/facemodel.h"
#include "face/pose.h"
#include "render/style.h"

#include <QByteArray>
#include <QImage>
#include <QRectF>
#include <QString>
#include <QVector>

#include <memory>
#include <utility>
#include <vector>

namespace toonface {

// One drawn component of a posed face: its SVG id, the element kind and its geometry as
// SVG attribute values. The SMIL exporter animates these same attributes over time, so the
// structure (element kinds, path command sequence) never depends on the pose.
struct FacePart
{
    QString id; // stable SVG id, e.g. "mouth-upper-lip"
    QString layer; // "static" or "dynamic"
    QString element; // "path", "circle", "polyline", "polygon"
    QMap<QString, QString> geometry; // e.g. {"d": "M ..."} or {"cx","cy","r"}
    QString styleKey; // key into Style::components
    QString clipPath; // id of a clip path, or empty
    QMap<QString, QString> paint; // presentation attributes (fill, stroke, stroke-width, ...), pose-independent
};

// Writes a face in a pose as SVG 1.1. Thread-safe for concurrent const use.
//
// Layout: <svg viewBox="0 0 W H"> (W x H = the photo's size) holding
//   <defs> clip paths (eyes), the body, the style's still layers behind the head
//   (<g id="style-layer-N">), then <g id="head" transform=head motion> with the style's layers
//   behind that follow the head,
//   <g id="static-layer"> hair, ears, face, nose, hat, eyebrows and
//   <g id="dynamic-layer"> jaw, beard, mouth, moustache, eyes (eyeballs clipped by the eye
//   outline), glasses, and the style's layers in front that follow the head;
// then the style's still layers in front, and the extra layers (<g id="layer-N">) in order. Because QSvgRenderer before
// Qt 6.7 ignores clip-path, each eye also has a skin-coloured cover ("eye-left-cover") around
// its opening, so the eyeballs stay hidden outside the lids in every renderer.
//
// The style's appearance adds the elements "glasses", "moustache", "beard" and "hat" only when
// it has them (a bald head has no hair element: the face's outline runs over the skull), and
// its caricature factor exaggerates the face's own proportions (face/caricature.h).
namespace svgparts {
struct Part;
}

class SvgFace
{
public:
    SvgFace(const FaceModel &face, const Style &style);

    // Extra layers from user SVG files (clothing, accessories), drawn above the face.
    // Returns false and sets *error when the file cannot be read or parsed.
    bool addLayerFile(const QString &svgPath, QString *error = nullptr);
    void addLayer(const QByteArray &svgContent);

    // The drawn components in drawing order (invisible components left out). svg() writes
    // exactly these, each as <element id=... geometry... clip-path=... paint...>.
    QVector<FacePart> parts(const Pose &pose = {}) const;
    // The geometry of the parts that move with the pose: parts(pose) from index
    // stillPartCount() on, with only their ids and geometry attributes (names and values in the
    // order svg() writes them; ids and names are string literals). For callers that read many
    // poses (the SMIL export samples thousands): it skips building each part's paint and Qt
    // strings, which cost more than the geometry itself.
    struct PartGeometry
    {
        const char *id;
        std::vector<std::pair<const char *, QByteArray>> attributes;
    };
    // With `ids`, only the parts made together with those (the mouth's five, an eye's parts):
    // sampling one group of channels skips drawing the others. Parts not drawn are left out.
    std::vector<PartGeometry> posedGeometry(const Pose &pose, const QVector<QByteArray> &ids = {}) const;
    // How many parts of parts() never move: those before the posed ones.
    qsizetype stillPartCount() const;
    QByteArray svg(const Pose &pose = {}) const;
    // svg(pose) as two documents that, drawn one over the other (rasterizeSvg() of `under`,
    // then drawSvg() of `over` on it), give its pixels: `under` holds what lies beneath the
    // dynamic layer (the body, the still layers behind, the head's static layer, in the head's
    // transform), `over` the rest, both with svg()'s <svg> element, `over` with its <defs>.
    // `under` changes only when the head or a brow moves, so video export rasterizes it once
    // for many frames; its hair and hat outlines are the costliest strokes of a frame.
    struct Passes
    {
        QByteArray under, over;
    };
    Passes svgPasses(const Pose &pose) const;
    // The transform attribute of <g id="head">: the head motion about the face centre, always
    // of the form "translate(x,y) rotate(a) scale(s) translate(-cx,-cy)".
    QString headTransform(const HeadPose &head) const;

    // The part of the photo the drawing shows (its viewBox and size), in photo pixels. By
    // default the whole photo — or, for a face placed without one, the points with equal margins.
    void setFrame(const QRectF &frame) { m_frame = frame; }
    QRectF frame() const;

    // The eye covers above are on by default; a drawing meant only for renderers that clip
    // (a browser) leaves them out.
    void setEyeCovers(bool on) { m_eyeCovers = on; }
    bool eyeCovers() const { return m_eyeCovers; }

    const FaceModel &face() const { return m_face; }
    const Style &style() const { return m_style; }

private:
    struct Geometry; // what does not depend on the pose, computed once
    enum class Pass { Whole, Under, Over }; // which elements a document holds (svgPasses())
    QByteArray document(const std::vector<svgparts::Part> &parts, const Pose &pose, Pass pass) const;

    FaceModel m_face;
    Style m_style;
    std::shared_ptr<const Geometry> m_geometry;
    QVector<QByteArray> m_layers;
    bool m_eyeCovers = true;
    QRectF m_frame;
};

// A frame around the head for a talking face: the 72 points (hair and ears included) with room
// for the head's motions and the jaw's drop, widened to `aspect` (width / height) about the
// head's centre. It may reach beyond the photo.
QRectF headFrame(const FaceModel &face, double aspect = 1.0);

// Renders SVG content to an image of `size` (aspect kept, centred, transparent outside)
// through QSvgRenderer. Returns a null image when the SVG does not parse.
QImage rasterizeSvg(const QByteArray &svg, QSize size, QColor background = Qt::white);
// Draws SVG content over `image` as rasterizeSvg() would draw it on an image of that size (the
// same placement and clip, no background). Returns false when the SVG does not parse.
bool drawSvg(const QByteArray &svg, QImage *image);

} // namespace toonface
