#pragma once

#include "track/framesource.h"

#include <QString>
#include <QStringList>

#include <atomic>
#include <memory>

namespace toonface {

// The frames of a video file, decoded by FFmpeg.
//
// Unpaced (the default) it decodes as fast as it can: for tracking a whole clip. Paced, it
// delivers each frame at its own time after the first next() (times `speed`), as a camera would:
// for live mode and its tests with no camera. A paced source whose reader falls behind drops
// the frames that are already late rather than queueing them (dropLate), as cameras do.
//
// Thread safety: as FrameSource (one reading thread; stop() from any thread).
class VideoFileSource : public FrameSource
{
public:
    struct Options
    {
        bool paced = false;
        double speed = 1.0; // paced: 2 plays twice as fast
        bool dropLate = true; // paced: skip frames more than one frame period late
    };

    VideoFileSource();
    ~VideoFileSource() override;

    // Opens `path`; false with *error "<path>: <problem>" when it is missing, not a video FFmpeg
    // can read, or has no video stream.
    bool open(const QString &path, const Options &options, QString *error);
    bool open(const QString &path, QString *error) { return open(path, Options {}, error); }

    std::optional<VideoFrame> next() override;
    // Positions an unpaced source for a jump: next() then delivers a frame at or before frame
    // `index` (a key frame's, found through the file's index), so reading on reaches `index`
    // without decoding the clip from its start. Frames keep the indices and times they have
    // when read from the start (for files of a constant frame rate). False when the file cannot
    // be positioned (no timestamps, no seeking, a paced source, a frame past the end): the source
    // is then at an unknown place and must be reopened.
    bool seek(int index);
    double frameRate() const override;
    QSize frameSize() const override;
    // From the container's header (frame count, else duration x rate); -1 when it says neither.
    int frameCount() const override;
    QString error() const override;
    void stop() override;

    QString path() const;
    bool hasAudio() const;
    double duration() const; // seconds, from the container; 0 when unknown
    int droppedFrames() const; // paced: frames skipped because the reader was late
    // Packets the decoder rejected (a damaged file decodes around them); each is counted once.
    int damagedPackets() const;

private:
    struct Private;
    std::unique_ptr<Private> d;
};

} // namespace toonface
