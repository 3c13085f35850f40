#pragma once

#include "speech/progress.h"

#include <QString>
#include <QVector>

namespace toonface {

// Every sound Toonface analyses is mono float at this rate.
inline constexpr int kSpeechSampleRate = 16000;

// Mono samples in [-1, 1] at `sampleRate` Hz. A plain value type.
struct Audio
{
    QVector<float> samples;
    int sampleRate = kSpeechSampleRate;

    double duration() const { return sampleRate > 0 ? double(samples.size()) / sampleRate : 0.0; }
    bool isEmpty() const { return samples.isEmpty(); }
};

enum class AudioStatus { Ok, Unreadable, Empty, Silent, Cancelled };

struct AudioResult
{
    AudioStatus status = AudioStatus::Unreadable;
    QString error; // names the file and the problem when status != Ok
    Audio audio; // at kSpeechSampleRate, mono
    double sourceDuration = 0; // seconds, as decoded
    bool ok() const { return status == AudioStatus::Ok; }
};

// Decodes any file FFmpeg reads that holds sound (WAV, FLAC, MP3, OGG/Vorbis or Opus,
// M4A/AAC, and the sound track of a video) to mono float at kSpeechSampleRate; channels are
// averaged. Unreadable, sound-less, empty or silent (peak below -60 dBFS) input is an error
// naming the file. Thread-safe; reports progress by the position in the file.
AudioResult loadAudio(
    const QString &path, const SpeechProgressFn &progress = {}, const std::atomic_bool *cancel = nullptr);

// Resamples `audio` to `rate` (FFmpeg's resampler). Returns `audio` unchanged at that rate.
Audio resampled(const Audio &audio, int rate);

// Writes `audio` to `path`, the format chosen by the suffix: .wav (16-bit PCM), .flac, .mp3,
// .ogg (Vorbis), .opus, .m4a/.aac (AAC). The file is written at the audio's own rate, or at the
// nearest rate the codec allows. False with *error naming the file on failure.
bool writeAudio(const QString &path, const Audio &audio, QString *error);

} // namespace toonface
