#pragma once

#include "anim/timeline.h"
#include "export/exportbackground.h"
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
#include <memory>
#include <optional>

namespace toonface {

class KeptFrames;
struct Project;

// What an animation is exported as.
enum class AnimationFormat {
    SmilSvg, // one SVG document animated by SMIL, with its sound (exportSmilSvg)
    HtmlPlayer, // a web page playing the SVG with its sound (exportHtmlPlayer)
    Mp4, // H.264 + AAC
    Gif, // animated GIF, silent
    PngSequence, // a folder of frame_00001.png, ..., with alpha, silent
    WebM, // VP9 with alpha + Opus
    Mov, // ProRes 4444 with alpha + PCM, for video editors
    Apng, // animated PNG with alpha, silent
    WebP, // animated WebP with alpha, silent
};

inline constexpr AnimationFormat kAllAnimationFormats[] = {AnimationFormat::SmilSvg, AnimationFormat::HtmlPlayer,
    AnimationFormat::Mp4, AnimationFormat::Gif, AnimationFormat::PngSequence, AnimationFormat::WebM,
    AnimationFormat::Mov, AnimationFormat::Apng, AnimationFormat::WebP};

// "svg", "html", "mp4", "gif", "webm", "mov", "apng", "webp"; empty for a PNG sequence (a folder).
QString animationFormatSuffix(AnimationFormat format);
// The format a path asks for by its suffix (.svg, .html/.htm, .mp4, .gif, .webm, .mov, .apng,
// .webp, any case) or, ending in '/', a PNG sequence; nullopt otherwise.
std::optional<AnimationFormat> animationFormatForPath(const QString &path);
// Whether the format is a picture sequence drawn at ExportRequest::size (all but SVG and HTML).
bool isRasterFormat(AnimationFormat format);
// Whether the format keeps alpha (PNG frames, WebM, MOV, APNG, WebP): its automatic background
// is transparent. GIF can be transparent when asked (one transparent colour, hard edges); MP4
// cannot; SVG and HTML draw no background.
bool animationFormatHasAlpha(AnimationFormat format);
bool animationFormatCanBeTransparent(AnimationFormat format);
// Whether the format carries the sound (SVG, HTML, MP4, WebM, MOV).
bool animationFormatHasSound(AnimationFormat format);
// Why `format` cannot be drawn over `background` (MP4 transparent; SVG or HTML over a colour or
// photo), or empty.
QString backgroundProblem(AnimationFormat format, const ExportBackground &background);

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
    // Raster formats: what is behind the face (Automatic: transparent where the format keeps
    // alpha, white otherwise). SVG and HTML draw none and take only Automatic or Transparent.
    ExportBackground background;
    // Raster formats: the stretch of the timeline exported, in seconds (duration 0: to the end).
    double start = 0;
    double duration = 0;
    // No sound even where the format carries it.
    bool silent = false;
    // WebM: VP9's constant quality, 0 (best) .. 63; -1: the encoder's default for stickers.
    int vp9Crf = -1;
    // Raster formats: when set, the frames are taken from it if it holds this export's frames
    // (their size, first frame and count), else drawn and kept in it for the next export of
    // the same request at another quality (keptframes.h).
    std::shared_ptr<KeptFrames> keptFrames;

    FaceModel face;
    Style style;
    Timeline timeline;
    MouthShapeSet mouthShapes;
    QStringList layerFiles; // extra SVG layers drawn over the face
    // The sound, from the animation's start; empty: the timeline's audio track, its clips
    // mixed into one sound (media/audiomix.h). GIF and PNG sequences are silent.
    QString audioPath;
};

// The animation of `project` (its face, style, timeline with its sound, mouth shapes and layers)
// as a request; the format, output path, size, rate and framing keep their defaults.
ExportRequest exportRequestFor(const Project &project);

// Where the drawing of `request` shows, in photo pixels (its framing).
QRectF exportFrame(const ExportRequest &request);
// The size of the frames MP4, GIF and PNG exports of `request` have.
QSize exportFrameSize(const ExportRequest &request);
// Frames of the export (at its frame rate, within its start and duration), for all formats.
int exportFrameCount(const ExportRequest &request);
// The export's length in seconds: its frames at its frame rate.
double exportDuration(const ExportRequest &request);
// The background `request` is drawn over: Automatic resolved for its format.
ExportBackground effectiveBackground(const ExportRequest &request);

enum class ExportStatus {
    Done,
    Cancelled, // the cancel flag was set; nothing was written
    BadInput, // a layer or sound file cannot be read, or the request is invalid
    Failed, // the output cannot be written or encoded
    OverLimit, // an export preset's limit (length, file size) cannot be met; nothing was written
};

struct ExportResult
{
    ExportStatus status = ExportStatus::Failed;
    // Names the file and the problem: "<output>: cancelled", "<layer.svg>: ...", "<out.mp4>:
    // cannot write: ...".
    QString error;
    // Raster formats: the frames drawn, and the times they were encoded (a preset's size limit
    // encodes the frames drawn once again at lower qualities).
    int framesDrawn = 0;
    int encodings = 0;
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
