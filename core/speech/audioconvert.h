#pragma once

// Internal to core/speech's sound decoding: what audio.cpp, wavfile.cpp and audioffmpeg.cpp
// share. audioffmpeg.cpp alone uses FFmpeg's formats and codecs (libavformat, libavcodec);
// the rest only its resampler, so a program that reads plain WAV files never loads them
// (app/CMakeLists.txt: the light toonface-cli).

#include "speech/audio.h"
#include "speech/wavfile.h"

extern "C" {
#include <libavutil/channel_layout.h>
#include <libswresample/swresample.h>
}

#include <memory>

namespace toonface::detail {

struct SwrDeleter
{
    void operator()(SwrContext *c) const { swr_free(&c); }
};
using SwrPtr = std::unique_ptr<SwrContext, SwrDeleter>;

constexpr int kMinSampleRate = kMinSpeechSampleRate;

// FFmpeg's own log would repeat each problem of a corrupt file on stderr; the errors of the
// decoders say it once. TOONFACE_FFMPEG_LOG=1 keeps FFmpeg's log for debugging.
void quietFfmpegLog();

// Appends everything `swr` gives for `in` (null = flush) as mono floats.
void convertInto(SwrContext *swr, const uint8_t **in, int inCount, int outRate, int inRate, QVector<float> &out);

// Averages the channels into mono float at `outRate` (SoX's resampler when FFmpeg has it).
SwrPtr monoFloatResampler(AVChannelLayout *inLayout, AVSampleFormat inFormat, int inRate, int outRate);

// Ends a decode of `path` in `r` with `status`: the error names the file and the problem, and
// no sound is kept. Returns r.
AudioResult failed(AudioResult &r, const QString &path, AudioStatus status, const QString &problem);

// Where a decoder's converted samples go: non-finite samples become silence, the peak and
// the count are kept, and the samples are handed to the sink.
struct DecodedSound
{
    AudioResult &result;
    const AudioSink &sink;
    float peak = 0;
    void hand(QVector<float> &out);
    // The end of a decode that gave `result.sampleCount` > 0: silent sound is an error.
    AudioResult finish(const QString &path, const SpeechProgressFn &progress);
};

// Decodes a plain PCM WAV file (probePlainWav) with the same samples, chunking, progress and
// errors as FFmpeg's WAV reader gives through decodeWithFfmpeg.
AudioResult decodePlainWav(const QString &path, const PlainWav &wav, const AudioSink &sink,
    const SpeechProgressFn &progress, const std::atomic_bool *cancel);

// FFmpeg's decoding of any sound or video file, and its encoders (audioffmpeg.cpp).
AudioResult decodeWithFfmpeg(
    const QString &path, const AudioSink &sink, const SpeechProgressFn &progress, const std::atomic_bool *cancel);
// FFmpeg's encoders, by the path's suffix (flac, mp3, ogg, opus, m4a/aac); null with *error
// naming the file on failure.
std::unique_ptr<AudioFileWriter> openFfmpegAudioWriter(const QString &path, int sampleRate, QString *error);

} // namespace toonface::detail
