#pragma once

#include <QImage>
#include <QString>
#include <QVector>

#include <optional>

namespace toonface {

// What a media file holds, read back by decoding it with FFmpeg (or, for a folder, by counting
// its frame_NNNNN.png files).
struct MediaInfo
{
    QString container; // FFmpeg's demuxer name ("mov,mp4,m4a,3gp,3g2,mj2", "gif", ...) or "png sequence"
    int frameCount = 0; // decoded video frames
    double fps = 0; // the stream's average frame rate (0 when unknown)
    int width = 0;
    int height = 0;
    double videoDurationS = 0; // from the first frame's start to the last frame's end
    QString videoCodec; // "h264", "gif", "png"
    QString pixelFormat; // "yuv420p", "pal8", ... (of the decoded pictures when they differ)
    bool hasAlpha = false; // the decoded pictures have an alpha channel (FFmpeg decodes GIF so)
    bool hasAudio = false;
    double audioDurationS = 0; // decoded samples / sample rate
    int audioSampleRate = 0;
    int audioChannels = 0;
    QString audioCodec; // "aac", ...
};

// On failure returns nullopt and sets *error to "<path>: <problem>".
std::optional<MediaInfo> probeMedia(const QString &path, QString *error);

// What is wrong with a media file whose packets run short of what its container says they
// hold (a copy cut short, a download broken off): "<path>: <problem>", or empty when every
// packet is whole. Reads the packets to the end without decoding them.
QString mediaDamage(const QString &path);

// Frame `index` (0-based, in display order) of a video file as an RGB32 image, or an ARGB32 one
// when the pictures have alpha (WebM's VP9 alpha included); nullopt with *error "<path>:
// <problem>" when the file cannot be decoded or has fewer frames.
std::optional<QImage> readVideoFrame(const QString &path, int index, QString *error);

// The sound of a file (audio, or a video's sound track) decoded, mixed down to mono and
// resampled to `sampleRate`; nullopt with *error "<path>: <problem>" on failure.
std::optional<QVector<float>> readAudio(const QString &path, int sampleRate, QString *error);

} // namespace toonface
