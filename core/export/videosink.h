#pragma once

#include "export/videoencoder.h"
#include "media/ffmpegutil.h"

#include <QColor>
#include <QImage>
#include <QSize>
#include <QString>
#include <QVector>

#include <initializer_list>
#include <memory>

// The encoders behind VideoWriter, one per format (mp4sink.cpp, gifsink.cpp, pngsink.cpp,
// alphasink.cpp for WebM, MOV, APNG and WebP).
namespace toonface::av {

class AudioFeed;

// One output format's encoder: frames in, a file (or folder) out.
class Sink
{
public:
    virtual ~Sink() = default;
    virtual bool addFrame(const QImage &frame, QString *error) = 0;
    virtual bool finish(QString *error) = 0;
    virtual void cancel() = 0;
};

// MP4, GIF, WebM, MOV, APNG, WebP: one libavformat output written to a temporary file beside
// the target, with an optional sound stream kept level with the pictures.
class MuxedSink : public Sink
{
public:
    MuxedSink();
    ~MuxedSink() override;

    bool addFrame(const QImage &frame, QString *error) override;

    bool finish(QString *error) override;

    void cancel() override;

protected:
    // Creates the hidden temporary file and the muxer for `formatName`.
    bool openOutput(const QString &path, const char *formatName, QString *error);

    bool startWriting(AVDictionary **options, QString *error);

    AVStream *addStream(AVCodecContext *ctx, QString *error);

    // Sends `frame` (null: flush) to the encoder and writes every packet it gives.
    bool drain(AVCodecContext *ctx, AVStream *stream, AVFrame *frame, QString *error);

    virtual bool encodeFrame(const QImage &frame, QString *error) = 0;
    // Flushes everything but the video encoder (which finish() flushes last); by default the
    // sound.
    virtual bool finishStreams(QString *error);
    // Rewrites the finished temporary file before it replaces the target, if the format needs it.
    virtual bool finishFile(const QString &, QString *) { return true; }

    // Opens the sound stream: `codec` at one of `rates` (the source's 44.1 kHz family keeps
    // 44100 when listed, else the first), mono, in `sampleFormat` (FLTP, FLT or S16).
    bool openAudio(const AudioSource &audio, const AVCodec *codec, AVSampleFormat sampleFormat,
        std::initializer_list<int> rates, int bitRate, QString *error);
    // Encodes sound up to the end of video frame `frames` (at `fps`); `last`: the final short
    // encoder frame too.
    bool encodeAudioUntilFrame(int64_t frames, double fps, bool last, QString *error);

    void closeAll();

    // The frames pictures are converted through: an RGB32 one and one in `pixelFormat`, both
    // m_encoded's size, and the converter between them (`bt709`: tagged and converted as BT.709
    // limited-range YUV). Failures name `size` (the pictures' size asked for) or `convertProblem`
    // (a converter that cannot be made); on failure the sink is cancelled.
    bool openFrames(AVPixelFormat pixelFormat, bool bt709, QSize size, const QString &convertProblem, QString *error);

    QString m_path;
    QString m_temp;
    AVFormatContext *m_fmt = nullptr;
    CodecPtr m_video;
    CodecPtr m_audio;
    AVStream *m_videoStream = nullptr;
    AVStream *m_audioStream = nullptr;
    PacketPtr m_packet;
    int64_t m_frameDuration = 1; // in the video encoder's time base
    int64_t m_videoFrames = 0; // frames sent to the video encoder
    double m_fps = 25;
    bool m_headerWritten = false;
    bool m_trailerOnCancel = false;
    QSize m_encoded; // the encoded pictures' size
    FramePtr m_frame; // in the encoder's pixel format
    FramePtr m_rgb;
    SwsPtr m_sws;

private:
    std::unique_ptr<AudioFeed> m_feed;
    FramePtr m_audioFrame;
    int64_t m_audioSamples = 0;
    QVector<float> m_audioBuffer;
};

// A frame rate as FFmpeg takes it: whole rates exactly, others to 1/100000.
AVRational frameRateOf(double fps);

// A frame without alpha: transparent pixels composed over `background`.
QImage opaqueRgb32(const QImage &frame, const QColor &background);

// Pads to `size` by repeating the last column and row.
QImage padded(const QImage &rgb32, QSize size);

// Opened sinks (see VideoWriter::open); null with *error set on failure.
std::unique_ptr<Sink> openMp4Sink(const QString &path, QSize size, double fps, const AudioSource &audio,
    const VideoOptions &options, QSize *encodedSize, QString *error);
std::unique_ptr<Sink> openGifSink(
    const QString &path, QSize size, double fps, const VideoOptions &options, double *outputFps, QString *error);
std::unique_ptr<Sink> openPngSink(const QString &folder, QSize size, QString *error);
// WebM, MOV, APNG or WebP (`format`); sound only for WebM and MOV.
std::unique_ptr<Sink> openAlphaSink(const QString &path, VideoFormat format, QSize size, double fps,
    const AudioSource &audio, const VideoOptions &options, QSize *encodedSize, QString *error);

} // namespace toonface::av
