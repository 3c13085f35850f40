#pragma once

#include <QByteArray>
#include <QString>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/channel_layout.h>
#include <libavutil/opt.h>
#include <libavutil/pixdesc.h>
#include <libswresample/swresample.h>
#include <libswscale/swscale.h>
}

#include <memory>

// FFmpeg plumbing shared by the media readers (media/) and the encoders (export/): error text,
// owning pointers, decoders. Include only from .cpp files of toonface_core (FFmpeg's headers
// are private to it).
namespace toonface::av {

QString avError(int code);

// Sets *error to "<path>: <problem>" and returns false.
bool fail(QString *error, const QString &path, const QString &problem);

// FFmpeg prints every encoder's settings and statistics at the default level; the library is
// quiet unless something goes wrong (errors reach the caller through return values anyway).
void quietFfmpegLogs();

struct FormatInputCloser
{
    void operator()(AVFormatContext *c) const { avformat_close_input(&c); }
};
struct CodecContextFreer
{
    void operator()(AVCodecContext *c) const { avcodec_free_context(&c); }
};
struct FrameFreer
{
    void operator()(AVFrame *f) const { av_frame_free(&f); }
};
struct PacketFreer
{
    void operator()(AVPacket *p) const { av_packet_free(&p); }
};
struct SwrFreer
{
    void operator()(SwrContext *s) const { swr_free(&s); }
};
struct SwsFreer
{
    void operator()(SwsContext *s) const { sws_freeContext(s); }
};
using InputPtr = std::unique_ptr<AVFormatContext, FormatInputCloser>;
using CodecPtr = std::unique_ptr<AVCodecContext, CodecContextFreer>;
using FramePtr = std::unique_ptr<AVFrame, FrameFreer>;
using PacketPtr = std::unique_ptr<AVPacket, PacketFreer>;
using SwrPtr = std::unique_ptr<SwrContext, SwrFreer>;
using SwsPtr = std::unique_ptr<SwsContext, SwsFreer>;

// A path as FFmpeg takes it.
QByteArray localPath(const QString &path);

// An opened decoder of the best stream of `type` in `input`.
CodecPtr openDecoder(AVFormatContext *input, AVMediaType type, int *streamIndex, QString *problem);

} // namespace toonface::av
