#pragma once

#include <QString>

#include <atomic>
#include <functional>

namespace toonface {

enum class SoundCopyStatus {
    Done,
    Cancelled, // the target was removed
    BadInput, // the source cannot be read or holds no sound
    Failed, // the target cannot be written
};

struct SoundCopy
{
    SoundCopyStatus status = SoundCopyStatus::Failed;
    QString error; // names the file and the problem
    qint64 samples = 0; // written, at the rate asked for
    double seconds = 0;
    bool ok() const { return status == SoundCopyStatus::Done; }
};

// Re-encodes the sound of `source` (any file FFmpeg reads, a video's sound track included;
// channels mixed to mono) into `target` at `sampleRate`, the codec chosen by the target's
// suffix (openAudioFileWriter), a block at a time: what it holds does not grow with the
// recording's length. Reports the part of the source read (0..1) after each block and stops
// soon after *cancel becomes true. On any failure or cancel the target is removed.
SoundCopy copySound(const QString &source, const QString &target, int sampleRate,
    const std::function<void(double)> &progress = {}, const std::atomic_bool *cancel = nullptr);

} // namespace toonface
