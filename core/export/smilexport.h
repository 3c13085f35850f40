#pragma once

#include <QByteArray>
#include <QRectF>
#include <QString>
#include <QStringList>

#include <atomic>
#include <functional>
#include <optional>

namespace toonface {

class FaceModel;
class MouthShapeSet;
class Timeline;
struct Style;

// How an exported animation carries the sound of the timeline's audio track.
enum class ExportAudio {
    Embed, // the sound decoded and encoded anew, as a data: URI inside the export
    Reference, // a relative URI of the file, as seen from the export's folder
    None, // silent
};

struct AnimationExportOptions
{
    // Smil: the drawing of the pose at time 0 with an <animate>/<animateTransform> on every
    // attribute that moves, over its key times. Frames: the thesis' form for players without
    // path animation, one group per frame shown by a <set> of its visibility.
    enum class Mode { Smil, Frames };
    Mode mode = Mode::Smil;

    ExportAudio audio = ExportAudio::Embed;
    // With ExportAudio::Embed the sound is decoded and encoded anew (never the file's own bytes:
    // a file that does not decode as sound is an error): as AAC in MP4 (mono, 64 kbit/s, at most
    // 32 kHz) — ten minutes of 16-bit 44.1 kHz stereo is 140 MB of base64, and 6.6 MB so; false:
    // as 16-bit PCM WAV (mono, at most 48 kHz). Either way the file must be a regular file.
    bool compressAudio = true;
    // The sound file, from the animation's start; empty means the timeline's audio track (one
    // clip heard whole: its file at its offset; else the clips mixed, which only embeds).
    // Without either the export is silent.
    QString audioPath;
    // With ExportAudio::Reference: the folder the export will be written to (empty: the
    // current directory), so the reference is relative to it.
    QString outputDir;

    // The part of the photo the animation shows (SvgFace::setFrame; headFrame() frames the
    // head); empty: the whole photo.
    QRectF frame;

    // Extra SVG layers (clothing, accessories) drawn above the face, as SvgFace::addLayerFile.
    QStringList layerFiles;

    // How far, in pixels, an interpolated coordinate may stray from the renderer's geometry at
    // any time between key times; coordinates are written to 0.1 px, which adds up to 0.05,
    // and those of moving paths and circles to 0.2 px (smilscale.h), up to 0.1.
    double tolerance = 0.08;
    // How much farther, in pixels, a coordinate may stray where keys are dropped: a key that
    // the interpolation between the keys around it gives within this of the animation above is
    // dropped, and timings are written to as few decimals as keep it (smilreduce.h). With the
    // defaults no coordinate strays more than 0.08 + 0.1 + 0.3 = 0.48 px; 0 keeps every key.
    double reduction = 0.3;

    // Called now and then on the calling thread with the fraction done (0..1).
    std::function<void(double)> progress;
    // When set and it becomes true, the export stops and fails with the error "cancelled".
    const std::atomic_bool *cancel = nullptr;
};

// The timeline on `face` as one self-contained SVG 1.1 document that plays in a browser.
//
// Smil mode: the document SvgFace::svg() writes for the pose at time 0 without the eye covers
// (a browser clips the eyeballs), unchanged but for
// - an <animate additive="sum"> child on every geometry attribute that moves ("d" of paths,
//   "cx"/"cy" of circles, "points" of polylines), whose values are offsets from the attribute
//   as written (path data with the same commands), so numbers that never move are 0;
// - on <g id="head">, four <animateTransform>s that rebuild SvgFace::headTransform():
//   translate (additive="replace"), rotate, scale and the constant translate back (additive="sum");
// - <metadata> with <tf:animation xmlns:tf="urn:toonface:animation:1" duration="s" fps="n"/>.
// Every animation begins at 0, lasts the timeline's duration and is frozen at its end; it has
// calcMode="spline" with ascending keyTimes from 0 to 1 and one keySpline per interval, or a
// single value when it is constant. Each attribute has its own key times: those of the tracks
// that move it (TimelineEvaluator::exportKeys: the mouth's for the mouth, the blinks' for the
// lids, ...) plus those needed where the drawing bends (lips that touch). Between two key times
// it follows one cubic timing: the ease of easing.h where the pose eases, a fitted one where
// eases overlap; key times are added until every coordinate stays within `tolerance` of
// SvgFace::parts(evaluate(t)) at all t; then the keys that their neighbours' interpolation
// gives within `reduction` are dropped (their intervals merged under one fitted keySpline,
// whose x control points may then differ from 1/3 and 2/3). Numbers are written to 0.1 px
// (angles 0.01 degree, scales 0.0001), key times to at most 0.1 ms. A moving path or circle
// that neither clips nor is clipped is drawn in fifths of a pixel: transform="scale(.2)", its
// geometry and stroke width five times larger, its values whole numbers (smilscale.h). The
// position of a circle is not keyed while its radius is 0 (smilhidden.h).
//
// With sound, <metadata> also holds
//   <tf:audio href="URI" offset="s" duration="s"/>
// (URI a data: URI or a relative reference, offset the clip's start in the animation), and a
// small script makes the document a player: the animation waits at time 0 behind a play
// button (<g id="tf-play">) until the sound may play (browsers block sound without a click),
// then runs locked to the audio clock; a click pauses and resumes. Without the script (an
// <img>, an old viewer) it plays silently from the start.
//
// Frames mode: the parts that never move are drawn once (in <defs>, used by every frame) and
// each frame i is <g visibility="hidden"> with <set attributeName="visibility" to="visible"
// begin="i/fps s" dur="1/fps s"/> (the last one frozen) holding the head transform and the
// moving parts, their ids suffixed "-f<i>"; metadata and sound as in Smil mode.
//
// Returns an empty array and sets *error (naming the file) when the audio or a layer file
// cannot be read, or when cancelled.
QByteArray exportSmilSvg(const FaceModel &face, const Style &style, const Timeline &timeline,
    const MouthShapeSet &shapes, const AnimationExportOptions &options = {}, QString *error = nullptr);

// The Smil-mode drawing as an <svg> element to place in a page (no XML declaration, metadata
// or player script), and the sound as exportSmilSvg() would carry it; see htmlplayer.h.
struct SmilElement
{
    QByteArray svg;
    QByteArray audioUri; // a data: URI or a relative reference; empty when silent
    double audioOffset = 0; // the sound's start in the animation, seconds
    double audioDuration = 0; // how much of the sound plays, seconds
    double duration = 0; // of the animation, seconds
};
std::optional<SmilElement> exportSmilElement(const FaceModel &face, const Style &style, const Timeline &timeline,
    const MouthShapeSet &shapes, const AnimationExportOptions &options = {}, QString *error = nullptr);

} // namespace toonface
