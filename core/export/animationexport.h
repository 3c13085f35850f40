#pragma once

#include "anim/timeline.h"
#include "face/facemodel.h"
#include "face/mouthshape.h"
#include "render/style.h"

#include <QRectF>
#include <QSize>
#include <QSizeF>
#include <QString>
#include <QStringList>

#include <atomic>
#include <functional>
#include <optional>

namespace toonface {

struct Project;

// What an animation is exported as.
enum class AnimationFormat {
    SmilSvg, // one SVG document animated by SMIL, with its sound (exportSmilSvg)
    HtmlPlayer, // a web page playing the SVG with its sound (exportHtmlPlayer)
    Mp4, // H.264 + AAC
    Gif, // animated GIF, silent
    PngSequence, // a folder of frame_00001.png, ..., silent
};

inline constexpr AnimationFormat kAllAnimationFormats[] = {AnimationFormat::SmilSvg, AnimationFormat::HtmlPlayer,
    AnimationFormat::Mp4, AnimationFormat::Gif, AnimationFormat::PngSequence};

// "svg", "html", "mp4", "gif"; empty for a PNG sequence (a folder).
QString animationFormatSuffix(AnimationFormat format);
// The format a path asks for by its suffix (.svg, .html/.htm, .mp4, .gif, any case) or, ending
// in '/', a PNG sequence; nullopt otherwise.
std::optional<AnimationFormat> animationFormatForPath(const QString &path);
// Whether the format is a picture sequence (MP4, GIF, PNG) drawn at ExportRequest::size.
bool isRasterFormat(AnimationFormat format);

// Which part of the photo the animation shows.
enum class ExportFraming {
    Head, // the head with room for its motions (headFrame())
    Photo, // the whole photo
};

// Everything an export needs, by value (run it on any thread).
struct ExportRequest
{
    AnimationFormat format = AnimationFormat::Mp4;
    // The file, or for a PNG sequence the folder (created or reused; only its frame_NNNNN.png
    // files are replaced).
    QString outputPath;
    // MP4, GIF, PNG: the frames' longer side in pixels (16 to 4096; the other side follows the
    // framing's aspect, both rounded down to even). 0: automatic, the framing's own size kept
    // within 512-1280 pixels. SVG and HTML are vector drawings and ignore it.
    int size = 0;
    // Frames per second (up to 120); 0: the timeline's.
    double fps = 0;
    ExportFraming framing = ExportFraming::Head;

    FaceModel face;
    Style style;
    Timeline timeline;
    MouthShapeSet mouthShapes;
    QStringList layerFiles; // extra SVG layers drawn over the face
    // The sound; empty: the timeline's audio clip. It starts at the clip's offset. GIF and PNG
    // sequences are silent.
    QString audioPath;
};

// The animation of `project` (its face, style, timeline with its sound, mouth shapes and layers)
// as a request; the format, output path, size, rate and framing keep their defaults.
ExportRequest exportRequestFor(const Project &project);

// Where the drawing of `request` shows, in photo pixels (its framing).
QRectF exportFrame(const ExportRequest &request);
// The size of the frames MP4, GIF and PNG exports of `request` have.
QSize exportFrameSize(const ExportRequest &request);
// Frames of the export (at its frame rate), for all formats.
int exportFrameCount(const ExportRequest &request);

enum class ExportStatus {
    Done,
    Cancelled, // the cancel flag was set; nothing was written
    BadInput, // a layer or sound file cannot be read, or the request is invalid
    Failed, // the output cannot be written or encoded
};

struct ExportResult
{
    ExportStatus status = ExportStatus::Failed;
    // Names the file and the problem: "<output>: cancelled", "<layer.svg>: ...", "<out.mp4>:
    // cannot write: ...".
    QString error;
    bool ok() const { return status == ExportStatus::Done; }
};

// Exports the animation of `request`. Reports the fraction done (0..1, rising, 1 at the end) to
// `progress` on the calling thread; stops soon after *cancel becomes true.
//
// The output appears only when the export succeeds: files are written beside the target under
// a hidden temporary name and renamed over it at the end, a PNG sequence is written into a
// hidden temporary folder beside the target whose frames move into place at the end. A
// cancelled or failed export leaves nothing behind (an existing file of the same name is kept
// as it was). A plain function of its arguments: run it with QtConcurrent::run.
ExportResult exportAnimation(const ExportRequest &request, const std::function<void(double)> &progress = {},
    const std::atomic_bool *cancel = nullptr);

} // namespace toonface
