#pragma once

#include <QObject>
#include <QString>

#include <optional>

namespace toonface {

// The sound a playback plays, in seconds of its file. PlaybackController drives it (which part
// of the file sounds when, from the timeline's audio clip) and reads its position as the audio
// clock. MediaAudioTrack plays through QtMultimedia; tests substitute their own.
class AudioTrack : public QObject
{
    Q_OBJECT

public:
    using QObject::QObject;

    // Opens `path` for playing. False with *error naming the file and the problem when it cannot
    // be played (missing, unreadable); a problem found later while decoding is told by failed().
    virtual bool open(const QString &path, QString *error) = 0;
    // Sounds the file from `seconds` on.
    virtual void play(double seconds) = 0;
    virtual void pause() = 0;
    // Whether the sound is playing (false once it has ended by itself).
    virtual bool isPlaying() const = 0;
    // Seconds into the file the listener hears now: nullopt unless playing, and until the sound
    // has begun to flow after play() (so a device's start-up delay is not read as a position).
    virtual std::optional<double> position() const = 0;

Q_SIGNALS:
    // The sound cannot be played after all; names the file and the problem.
    void failed(const QString &message);
};

} // namespace toonface
