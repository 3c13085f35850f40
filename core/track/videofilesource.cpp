#include "track/videofilesource.h"

#include "i18n/coretext.h"
#include "media/userfile.h"

#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libswscale/swscale.h>
}

#include <chrono>
#include <cmath>
#include <cstring>
#include <thread>
#include <utility>

namespace toonface {

namespace {

QString avError(int code)
{
    char text[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, text, sizeof text);
    return QString::fromLocal8Bit(text);
}

} // namespace

struct VideoFileSource::Private
{
    QString path;
    Options options;
    AVFormatContext *input = nullptr;
    AVCodecContext *codec = nullptr;
    SwsContext *sws = nullptr;
    AVPacket *packet = nullptr;
    AVFrame *frame = nullptr;
    AVFrame *rgb = nullptr;
    int stream = -1;
    double timeBase = 0;
    double fps = 0;
    QSize size;
    int headerFrames = -1;
    double duration = 0;
    bool audio = false;
    std::optional<int64_t> firstPts;
    std::optional<VideoFrame> pending; // read by seek(), delivered by the next next()
    bool resync = false; // after a seek: the next frame's index comes from its timestamp
    int decoded = 0;
    int dropped = 0;
    int damaged = 0;
    bool flushing = false;
    bool finished = false;
    QString error;
    std::atomic_bool stopped {false};
    QElapsedTimer clock;

    ~Private()
    {
        sws_freeContext(sws);
        av_frame_free(&frame);
        av_frame_free(&rgb);
        av_packet_free(&packet);
        avcodec_free_context(&codec);
        avformat_close_input(&input);
    }

    bool fail(QString *out, const QString &problem)
    {
        error = withProblem(path, problem);
        if (out)
            *out = error;
        return false;
    }

    // Decodes the next picture into `frame`; false at the end or on an error.
    bool decodeNext()
    {
        for (;;) {
            const int r = avcodec_receive_frame(codec, frame);
            if (r >= 0)
                return true;
            if (r == AVERROR_EOF)
                return false;
            if (r != AVERROR(EAGAIN)) {
                error = VideoText::tr("%1: the video cannot be decoded (%2)").arg(path, avError(r));
                return false;
            }
            if (flushing)
                return false;
            const int read = av_read_frame(input, packet);
            if (read < 0) {
                flushing = true;
                avcodec_send_packet(codec, nullptr);
                continue;
            }
            if (packet->stream_index == stream) {
                const int sent = avcodec_send_packet(codec, packet);
                if (sent < 0 && sent != AVERROR(EAGAIN))
                    ++damaged;
            }
            av_packet_unref(packet);
        }
    }

    std::optional<VideoFrame> convert()
    {
        if (frame->width <= 0 || frame->height <= 0)
            return std::nullopt;
        QImage image(frame->width, frame->height, QImage::Format_RGB32);
        sws = sws_getCachedContext(sws, frame->width, frame->height, AVPixelFormat(frame->format), frame->width,
            frame->height, AV_PIX_FMT_RGB32, SWS_BILINEAR, nullptr, nullptr, nullptr);
        if (!sws) {
            error = VideoText::tr("%1: cannot convert the video's pixel format").arg(path);
            return std::nullopt;
        }
        const int space = frame->colorspace == AVCOL_SPC_BT709 ? SWS_CS_ITU709 : SWS_CS_DEFAULT;
        const int *coefficients = sws_getCoefficients(space);
        sws_setColorspaceDetails(
            sws, coefficients, frame->color_range == AVCOL_RANGE_JPEG, coefficients, 1, 0, 1 << 16, 1 << 16);
        // sws_scale may write past a line's end (SIMD): into FFmpeg's padded buffer, then copied.
        if (!rgb || rgb->width != frame->width || rgb->height != frame->height) {
            av_frame_free(&rgb);
            rgb = av_frame_alloc();
            rgb->format = AV_PIX_FMT_RGB32;
            rgb->width = frame->width;
            rgb->height = frame->height;
            if (av_frame_get_buffer(rgb, 0) < 0) {
                error = VideoText::tr("%1: out of memory").arg(path);
                return std::nullopt;
            }
        }
        sws_scale(sws, frame->data, frame->linesize, 0, frame->height, rgb->data, rgb->linesize);
        for (int y = 0; y < image.height(); ++y)
            std::memcpy(image.scanLine(y), rgb->data[0] + qsizetype(y) * rgb->linesize[0], size_t(image.width()) * 4);

        const int64_t pts = frame->best_effort_timestamp;
        if (std::exchange(resync, false) && firstPts && pts != AV_NOPTS_VALUE)
            decoded = int(std::llround(double(pts - *firstPts) * timeBase * fps));
        VideoFrame out;
        out.index = decoded;
        if (pts != AV_NOPTS_VALUE && timeBase > 0) {
            if (!firstPts)
                firstPts = pts;
            out.time = double(pts - *firstPts) * timeBase;
        } else {
            out.time = fps > 0 ? decoded / fps : 0.0;
        }
        out.image = std::move(image);
        ++decoded;
        av_frame_unref(frame);
        return out;
    }

    // Seeks to the key frame at or before `seconds` after the first frame (to the file's first
    // byte when `fromStart`) and reads its first picture into `pending`; false when FFmpeg cannot
    // or the picture has no timestamp.
    bool seekAndRead(double seconds, bool fromStart = false)
    {
        const int64_t target = *firstPts + std::llround(std::max(0.0, seconds) / timeBase);
        const int r = fromStart ? av_seek_frame(input, -1, 0, AVSEEK_FLAG_BYTE)
                                : av_seek_frame(input, stream, target, AVSEEK_FLAG_BACKWARD);
        if (r < 0)
            return false;
        avcodec_flush_buffers(codec);
        flushing = false;
        finished = false;
        pending.reset();
        if (!decodeNext() || frame->best_effort_timestamp == AV_NOPTS_VALUE) {
            av_frame_unref(frame);
            return false;
        }
        resync = true;
        pending = convert();
        return pending.has_value();
    }

    bool seek(int index)
    {
        if (!codec || options.paced || fps <= 0 || timeBase <= 0 || index < 0
            || (headerFrames > 0 && index >= headerFrames))
            return false;
        if (!firstPts) {
            // Frame 0's timestamp anchors every index: read it first.
            if (pending || decoded > 0 || !decodeNext() || frame->best_effort_timestamp == AV_NOPTS_VALUE)
                return false;
            firstPts = frame->best_effort_timestamp;
            av_frame_unref(frame);
        }
        // Some containers (MPEG program streams) seek by byte position and may land a little
        // after the time asked for: step further back until the picture read is not past it,
        // and near the start go to the first byte, where reading from the start begins.
        const double at = index / fps;
        for (const double back : {0.0, 1.0, 4.0, 16.0}) {
            if (at - back <= 0)
                break;
            if (!seekAndRead(at - back))
                return false;
            if (pending->index <= index)
                return true;
        }
        if ((seekAndRead(0) && pending->index <= index) || (seekAndRead(0, true) && pending->index <= index))
            return true;
        pending.reset();
        return false;
    }
};

VideoFileSource::VideoFileSource()
    : d(std::make_unique<Private>())
{ }

VideoFileSource::~VideoFileSource() = default;

bool VideoFileSource::open(const QString &path, const Options &options, QString *error)
{
    d = std::make_unique<Private>();
    d->path = path;
    d->options = options;
    av_log_set_level(AV_LOG_QUIET);
    if (const QString problem = irregularFileProblem(path); !problem.isEmpty())
        return d->fail(error, problem);
    int r = avformat_open_input(&d->input, QFile::encodeName(path).constData(), nullptr, nullptr);
    if (r < 0)
        return d->fail(error, VideoText::tr("not a video FFmpeg can read (%1)").arg(avError(r)));
    r = avformat_find_stream_info(d->input, nullptr);
    if (r < 0)
        return d->fail(error, VideoText::tr("not a video FFmpeg can read (%1)").arg(avError(r)));
    const AVCodec *decoder = nullptr;
    d->stream = av_find_best_stream(d->input, AVMEDIA_TYPE_VIDEO, -1, -1, &decoder, 0);
    if (d->stream < 0 || !decoder)
        return d->fail(error, VideoText::tr("the file holds no video"));
    d->audio = av_find_best_stream(d->input, AVMEDIA_TYPE_AUDIO, -1, -1, nullptr, 0) >= 0;
    AVStream *s = d->input->streams[d->stream];
    d->codec = avcodec_alloc_context3(decoder);
    if (!d->codec || avcodec_parameters_to_context(d->codec, s->codecpar) < 0)
        return d->fail(error, VideoText::tr("cannot set up the video decoder"));
    d->codec->thread_count = 1; // the tracker runs beside the decoder; small frames gain nothing
    r = avcodec_open2(d->codec, decoder, nullptr);
    if (r < 0)
        return d->fail(error, VideoText::tr("cannot open the video decoder (%1)").arg(avError(r)));
    d->timeBase = av_q2d(s->time_base);
    const AVRational rate = s->avg_frame_rate.num > 0 ? s->avg_frame_rate : s->r_frame_rate;
    d->fps = rate.num > 0 && rate.den > 0 ? av_q2d(rate) : 0.0;
    d->size = QSize(s->codecpar->width, s->codecpar->height);
    if (d->size.isEmpty())
        return d->fail(error, VideoText::tr("the video has no picture size"));
    if (d->input->duration > 0)
        d->duration = d->input->duration / double(AV_TIME_BASE);
    if (s->nb_frames > 0)
        d->headerFrames = int(s->nb_frames);
    else if (d->duration > 0 && d->fps > 0)
        d->headerFrames = int(std::lround(d->duration * d->fps));
    d->packet = av_packet_alloc();
    d->frame = av_frame_alloc();
    if (!d->packet || !d->frame)
        return d->fail(error, VideoText::tr("out of memory"));
    return true;
}

std::optional<VideoFrame> VideoFileSource::next()
{
    if (!d->codec || d->finished)
        return std::nullopt;
    if (d->pending)
        return std::exchange(d->pending, std::nullopt);
    for (;;) {
        if (d->stopped.load() || !d->decodeNext()) {
            d->finished = true;
            return std::nullopt;
        }
        std::optional<VideoFrame> f = d->convert();
        if (!f) {
            d->finished = true;
            return std::nullopt;
        }
        if (!d->options.paced)
            return f;
        if (!d->clock.isValid())
            d->clock.start();
        const double speed = d->options.speed > 0 ? d->options.speed : 1.0;
        const double due = f->time / speed;
        const double now = d->clock.nsecsElapsed() / 1e9;
        const double period = d->fps > 0 ? 1.0 / (d->fps * speed) : 0.04;
        if (d->options.dropLate && now - due > period) {
            ++d->dropped;
            continue;
        }
        // Sleeps in short steps so that stop() is heard.
        while (!d->stopped.load()) {
            const double wait = due - d->clock.nsecsElapsed() / 1e9;
            if (wait <= 0)
                break;
            std::this_thread::sleep_for(std::chrono::duration<double>(std::min(wait, 0.02)));
        }
        return f;
    }
}

bool VideoFileSource::seek(int index)
{
    return d->seek(index);
}

double VideoFileSource::frameRate() const
{
    return d->fps;
}

QSize VideoFileSource::frameSize() const
{
    return d->size;
}

int VideoFileSource::frameCount() const
{
    return d->headerFrames;
}

QString VideoFileSource::error() const
{
    return d->error;
}

void VideoFileSource::stop()
{
    d->stopped = true;
}

QString VideoFileSource::path() const
{
    return d->path;
}

bool VideoFileSource::hasAudio() const
{
    return d->audio;
}

double VideoFileSource::duration() const
{
    return d->duration;
}

int VideoFileSource::droppedFrames() const
{
    return d->dropped;
}

int VideoFileSource::damagedPackets() const
{
    return d->damaged;
}

} // namespace toonface
