#pragma once

#include "export/videoencoder.h"
#include "media/ffmpegutil.h"

#include <QColor>
#include <QImage>
#include <QSize>
#include <QString>

#include <memory>

// The encoders behind VideoWriter, one per format (mp4sink.cpp, gifsink.cpp, pngsink.cpp).
namespace toonface::av {

// One output format's encoder: frames in, a file (or folder) out.
class Sink
{
public:
    virtual ~Sink() = default;
    virtual bool addFrame(const QImage &frame, QString *error) = 0;
    virtual bool finish(QString *error) = 0;
    virtual void cancel() = 0;
};

// MP4 and GIF: one libavformat output written to a temporary file beside the target.
class MuxedSink : public Sink
{
public:
    ~MuxedSink() override { cancel(); }

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
    // Flushes everything but the video encoder (which finish() flushes last).
    virtual bool finishStreams(QString *) { return true; }

    void closeAll();

    QString m_path;
    QString m_temp;
    AVFormatContext *m_fmt = nullptr;
    CodecPtr m_video;
    CodecPtr m_audio;
    AVStream *m_videoStream = nullptr;
    AVStream *m_audioStream = nullptr;
    PacketPtr m_packet;
    int64_t m_frameDuration = 1; // in the video encoder's time base
    bool m_headerWritten = false;
    bool m_trailerOnCancel = false;
};

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

} // namespace toonface::av
