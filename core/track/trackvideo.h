#pragma once

#include "track/mouthrange.h"
#include "track/tracker.h"

#include <QImage>
#include <QJsonObject>
#include <QSize>
#include <QString>
#include <QStringList>
#include <QVector>

#include <atomic>
#include <functional>
#include <optional>

namespace toonface {

struct TrackVideoOptions
{
    TrackerOptions tracker;
    int neutralFrame = 0; // the frame whose face is the neutral one
};

enum class TrackStatus { Ok, BadVideo, NoFace, ModelMissing, Cancelled };

// A whole clip tracked.
struct TrackResult
{
    TrackStatus status = TrackStatus::BadVideo;
    QString error; // "<path>: <problem>" when status != Ok
    QStringList warnings; // the job went on, e.g. a damaged file decoded around its bad packets

    QString videoPath;
    QSize size;
    double fps = 0;
    bool hasAudio = false;
    int neutralFrame = 0;
    QString method; // "landmarks" or "classic"
    DetectionResult neutral; // the neutral frame's detection (the face to draw)
    QImage neutralImage; // the neutral frame
    double neutralEs0 = 0; // pixels: the unit of the displacements
    QVector<TrackedFrame> frames; // every decoded frame, in order
    // With options.tracker.snapMouth: the clip's mouth range its frames were snapped with
    // (track/mouthrange.h), over the whole clip rather than frame by frame.
    std::optional<MouthRange> mouthRange;
    // With a snapped mouth and the clip's sound: the frames in its silences, snapped to `m`
    // (track/clipsilence.h); empty without sound.
    QVector<bool> silentFrames;
    double trackingMs = 0; // decoding and tracking, the neutral's detection excluded (wall clock)
    double trackingCpuMs = 0; // the same in CPU time of the process (every thread): what it costs
};

// Tracks every frame of the video at `path`, the face of frame options.neutralFrame being the
// neutral one. Decoding runs on a thread of its own beside the tracking. `progress(done, total)`
// is called from the calling thread after each frame (total -1 when the file does not say);
// `cancel` is polled every frame. With options.tracker.snapMouth the mouth is snapped once the
// whole clip is tracked, from its own closed mouth and range, and closed where its sound is
// silent (snapClipMouth()). Meant for a
// worker thread (QtConcurrent); no Qt event loop needed.
TrackResult trackVideo(const QString &path, const TrackVideoOptions &options,
    const std::function<void(int, int)> &progress = {}, const std::atomic_bool *cancel = nullptr);

// The track as JSON, format "toonface.track/1" (architecture.md): video {path, width, height,
// fps, frames}, neutralFrame, method, neutral (a face object), units ("ES0") and es0, and frames
// [{time, lost, confidence, points: [{id, x, y}], displacements: {ID: [dx, dy]}, eyes
// {left, right}, head {rotation, x, y, scale}, gaze [x, y], mouthOpen, mouthShape}]; with a snapped
// mouth, mouthRange {closed: {ID: [dx, dy]}, wideOpening, gain, silentFrames} (ES0; silentFrames
// counts the frames closed for the clip's silence).
QJsonObject trackToJson(const TrackResult &track);
inline constexpr const char *kTrackFormat = "toonface.track/1";

} // namespace toonface
