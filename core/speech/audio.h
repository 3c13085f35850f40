#pragma once

#include "speech/progress.h"

#include <QString>
#include <QVector>

#include <functional>
#include <memory>

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

enum class AudioStatus {
    Ok,
    Unreadable,
    Empty,
    Silent,
    Cancelled,
    Unwritable, // copyAudio: the target cannot be written
};

struct AudioResult
{
    AudioStatus status = AudioStatus::Unreadable;
    QString error; // names the file and the problem when status != Ok
    Audio audio; // at kSpeechSampleRate, mono
    double sourceDuration = 0; // seconds, as decoded
    qint64 sampleCount = 0; // samples at kSpeechSampleRate decoded (kept in `audio` or handed to a sink)
    bool ok() const { return status == AudioStatus::Ok; }
};

// Decodes any file FFmpeg reads that holds sound (WAV, FLAC, MP3, OGG/Vorbis or Opus,
// M4A/AAC, and the sound track of a video) to mono float at kSpeechSampleRate; channels are
// averaged. Unreadable, sound-less, empty or silent (peak below -60 dBFS) input is an error
// naming the file. Thread-safe; reports progress by the position in the file.
AudioResult loadAudio(
    const QString &path, const SpeechProgressFn &progress = {}, const std::atomic_bool *cancel = nullptr);

// Receives mono float samples a block at a time.
using AudioSink = std::function<void(const float *samples, qsizetype count)>;

// Decodes like loadAudio, but hands the samples to `sink` as they come instead of keeping
// them (a long recording need never be held whole): the result's `audio` stays empty and
// `sampleCount` counts them. The same errors as loadAudio.
AudioResult streamAudio(const QString &path, const AudioSink &sink, const SpeechProgressFn &progress = {},
    const std::atomic_bool *cancel = nullptr);

// Decodes like loadAudio and writes the samples to `target` (at kSpeechSampleRate, the format
// chosen by the suffix as writeAudio does) as they come, never holding the sound whole: the
// same file as loadAudio followed by writeAudio. The same errors as loadAudio, and the
// target's (status Unwritable); on any failure or cancel (Cancelled) no target is left. The result's
// `audio` stays empty.
AudioResult copyAudio(const QString &source, const QString &target, const SpeechProgressFn &progress = {},
    const std::atomic_bool *cancel = nullptr);

// Resamples `audio` to `rate` (FFmpeg's resampler). Returns `audio` unchanged at that rate.
Audio resampled(const Audio &audio, int rate);

// Resamples mono float samples pushed a block at a time (FFmpeg's resampler), handing the
// result to a sink as it comes; passes them through when the rates are equal.
class AudioResampler
{
public:
    AudioResampler(int inRate, int outRate, AudioSink sink);
    ~AudioResampler();
    AudioResampler(const AudioResampler &) = delete;
    AudioResampler &operator=(const AudioResampler &) = delete;

    bool ok() const; // false when FFmpeg cannot convert between the rates
    void push(const float *samples, qsizetype count);
    void finish(); // flushes what the resampler still holds

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

// Writes `audio` to `path`, the format chosen by the suffix: .wav (16-bit PCM), .flac, .mp3,
// .ogg (Vorbis), .opus, .m4a/.aac (AAC). The file is written at the audio's own rate, or at the
// nearest rate the codec allows. False with *error naming the file on failure.
bool writeAudio(const QString &path, const Audio &audio, QString *error);

// A sound file written a block at a time, so that a long recording need never be held whole.
// The file is whole only after finish(); a writer destroyed before it leaves a partial file
// for the caller to remove. Not thread-safe.
class AudioFileWriter
{
public:
    virtual ~AudioFileWriter() = default;
    // Encodes mono samples in [-1, 1] at the rate the writer was opened with.
    virtual bool write(const float *samples, qsizetype count, QString *error) = 0;
    // Flushes the encoder and closes the file; the writer is closed after it either way.
    virtual bool finish(QString *error) = 0;
};

// Opens `path` for mono sound at `sampleRate`, the format chosen by the suffix as writeAudio
// does (.wav as 16-bit PCM, .flac, .mp3, .ogg, .opus, .m4a/.aac). Null with *error naming the file on
// failure.
std::unique_ptr<AudioFileWriter> openAudioFileWriter(const QString &path, int sampleRate, QString *error);

} // namespace toonface
