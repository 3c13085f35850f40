#include "media/mediareader.h"

#include "i18n/coretext.h"
#include "media/audiofeed.h"
#include "media/ffmpegutil.h"
#include "media/pngframes.h"
#include "media/userfile.h"

#include <QDir>
#include <QFileInfo>

#include <algorithm>
#include <climits>
#include <cstring>

namespace toonface {

using namespace av;

namespace {

// Why FFmpeg could not open a file (avformat_open_input's error `r`), as the sound loader words it.
QString unopenable(int r)
{
    return VideoText::tr("not a readable sound or video file (%1)").arg(avError(r));
}

std::optional<MediaInfo> probePngSequence(const QString &folder, QString *error)
{
    const QDir dir(folder);
    MediaInfo info;
    info.container = QStringLiteral("png sequence");
    info.videoCodec = QStringLiteral("png");
    QString first;
    for (const QString &name : dir.entryList({QStringLiteral("frame_*.png")}, QDir::Files, QDir::Name)) {
        if (!pngFramePattern().match(name).hasMatch())
            continue;
        if (first.isEmpty())
            first = name;
        ++info.frameCount;
    }
    if (info.frameCount == 0) {
        fail(error, folder, VideoText::tr("no frame_NNNNN.png files in the folder"));
        return std::nullopt;
    }
    const QImage image(dir.filePath(first));
    info.width = image.width();
    info.height = image.height();
    return info;
}

} // namespace

std::optional<MediaInfo> probeMedia(const QString &path, QString *error)
{
    quietFfmpegLogs();
    if (QFileInfo(path).isDir())
        return probePngSequence(path, error);
    if (const QString problem = irregularFileProblem(path); !problem.isEmpty()) {
        fail(error, path, problem);
        return std::nullopt;
    }
    AVFormatContext *raw = nullptr;
    int r = avformat_open_input(&raw, localPath(path).constData(), nullptr, nullptr);
    if (r < 0) {
        fail(error, path, unopenable(r));
        return std::nullopt;
    }
    InputPtr input(raw);
    r = avformat_find_stream_info(raw, nullptr);
    if (r < 0) {
        fail(error, path, VideoText::tr("cannot read the streams: %1").arg(avError(r)));
        return std::nullopt;
    }
    MediaInfo info;
    info.container = QString::fromLatin1(raw->iformat->name);
    QString problem;
    int videoIndex = -1;
    int audioIndex = -1;
    CodecPtr video = openDecoder(raw, AVMEDIA_TYPE_VIDEO, &videoIndex, &problem);
    CodecPtr audio = openDecoder(raw, AVMEDIA_TYPE_AUDIO, &audioIndex, &problem);
    if (!video && !audio) {
        fail(error, path, problem.isEmpty() ? VideoText::tr("no video or audio stream") : problem);
        return std::nullopt;
    }
    if (video) {
        const AVStream *s = raw->streams[videoIndex];
        info.width = video->width;
        info.height = video->height;
        info.videoCodec = QString::fromLatin1(avcodec_get_name(s->codecpar->codec_id));
        const char *pix = av_get_pix_fmt_name(video->pix_fmt);
        info.pixelFormat = pix ? QString::fromLatin1(pix) : QString();
        if (s->avg_frame_rate.num > 0 && s->avg_frame_rate.den > 0)
            info.fps = av_q2d(s->avg_frame_rate);
    }
    if (audio) {
        info.hasAudio = true;
        info.audioSampleRate = audio->sample_rate;
        info.audioChannels = audio->ch_layout.nb_channels;
        info.audioCodec = QString::fromLatin1(avcodec_get_name(raw->streams[audioIndex]->codecpar->codec_id));
    }

    PacketPtr packet(av_packet_alloc());
    FramePtr frame(av_frame_alloc());
    int64_t videoStart = INT64_MAX;
    int64_t videoEnd = INT64_MIN;
    int64_t audioSamples = 0;
    auto receive = [&](AVCodecContext *ctx, bool isVideo) {
        while (avcodec_receive_frame(ctx, frame.get()) >= 0) {
            if (isVideo) {
                if (info.frameCount++ == 0) {
                    const AVPixFmtDescriptor *desc = av_pix_fmt_desc_get(AVPixelFormat(frame->format));
                    info.hasAlpha = desc && (desc->flags & AV_PIX_FMT_FLAG_ALPHA);
                    if (desc)
                        info.pixelFormat = QString::fromLatin1(desc->name);
                }
            } else
                audioSamples += frame->nb_samples;
            av_frame_unref(frame.get());
        }
    };
    while (av_read_frame(raw, packet.get()) >= 0) {
        const bool isVideo = video && packet->stream_index == videoIndex;
        const bool isAudio = audio && packet->stream_index == audioIndex;
        if (isVideo && packet->pts != AV_NOPTS_VALUE) {
            videoStart = std::min(videoStart, packet->pts);
            videoEnd = std::max(videoEnd, packet->pts + packet->duration);
        }
        if (isVideo || isAudio) {
            AVCodecContext *ctx = isVideo ? video.get() : audio.get();
            if (avcodec_send_packet(ctx, packet.get()) >= 0)
                receive(ctx, isVideo);
        }
        av_packet_unref(packet.get());
    }
    if (video) {
        avcodec_send_packet(video.get(), nullptr);
        receive(video.get(), true);
        if (videoEnd > videoStart)
            info.videoDurationS = double(videoEnd - videoStart) * av_q2d(raw->streams[videoIndex]->time_base);
        if (info.fps == 0 && info.videoDurationS > 0)
            info.fps = info.frameCount / info.videoDurationS;
    }
    if (audio) {
        avcodec_send_packet(audio.get(), nullptr);
        receive(audio.get(), false);
        if (info.audioSampleRate > 0)
            info.audioDurationS = double(audioSamples) / info.audioSampleRate;
    }
    return info;
}

QString mediaDamage(const QString &path)
{
    quietFfmpegLogs();
    if (QFileInfo(path).isDir())
        return {};
    if (const QString problem = irregularFileProblem(path); !problem.isEmpty())
        return withProblem(path, problem);
    AVFormatContext *raw = avformat_alloc_context();
    if (!raw)
        return {};
    // The demuxer's packets as the file holds them: a parser joining them into frames (as
    // decoding does) drops the mark of a packet the file ends inside of.
    raw->flags |= AVFMT_FLAG_NOPARSE | AVFMT_FLAG_NOFILLIN;
    int r = avformat_open_input(&raw, localPath(path).constData(), nullptr, nullptr);
    if (r < 0)
        return withProblem(path, unopenable(r));
    InputPtr input(raw);
    PacketPtr packet(av_packet_alloc());
    if (!packet)
        return {};
    while ((r = av_read_frame(raw, packet.get())) >= 0) {
        // FFmpeg marks a packet the file ended inside of (or that failed its checks) corrupt.
        const bool corrupt = packet->flags & AV_PKT_FLAG_CORRUPT;
        const AVStream *stream = raw->streams[packet->stream_index];
        const double at = packet->pts != AV_NOPTS_VALUE ? packet->pts * av_q2d(stream->time_base) : 0;
        av_packet_unref(packet.get());
        if (corrupt)
            return withProblem(path,
                VideoText::tr("the file is cut short or damaged: its data breaks off at %1 s")
                    .arg(std::max(0.0, at), 0, 'f', 2));
    }
    if (r != AVERROR_EOF)
        return withProblem(path, VideoText::tr("the file is cut short or damaged: %1").arg(avError(r)));
    return {};
}

std::optional<QImage> readVideoFrame(const QString &path, int index, QString *error)
{
    quietFfmpegLogs();
    if (const QString problem = irregularFileProblem(path); !problem.isEmpty()) {
        fail(error, path, problem);
        return std::nullopt;
    }
    AVFormatContext *raw = nullptr;
    int r = avformat_open_input(&raw, localPath(path).constData(), nullptr, nullptr);
    if (r < 0) {
        fail(error, path, unopenable(r));
        return std::nullopt;
    }
    InputPtr input(raw);
    r = avformat_find_stream_info(raw, nullptr);
    QString problem = VideoText::tr("no video stream");
    int stream = -1;
    CodecPtr video = r < 0 ? nullptr : openDecoder(raw, AVMEDIA_TYPE_VIDEO, &stream, &problem);
    if (!video) {
        fail(error, path, problem);
        return std::nullopt;
    }
    PacketPtr packet(av_packet_alloc());
    FramePtr frame(av_frame_alloc());
    int seen = 0;
    std::optional<QImage> result;
    auto receive = [&] {
        while (!result && avcodec_receive_frame(video.get(), frame.get()) >= 0) {
            if (seen++ == index) {
                const AVPixFmtDescriptor *desc = av_pix_fmt_desc_get(AVPixelFormat(frame->format));
                const bool alpha = desc && (desc->flags & AV_PIX_FMT_FLAG_ALPHA);
                QImage image(frame->width, frame->height, alpha ? QImage::Format_ARGB32 : QImage::Format_RGB32);
                FramePtr rgb(av_frame_alloc());
                rgb->format = AV_PIX_FMT_RGB32;
                rgb->width = frame->width;
                rgb->height = frame->height;
                SwsPtr sws(av_frame_get_buffer(rgb.get(), 0) < 0
                        ? nullptr
                        : sws_getContext(frame->width, frame->height, AVPixelFormat(frame->format), frame->width,
                            frame->height, AV_PIX_FMT_RGB32, SWS_BILINEAR, nullptr, nullptr, nullptr));
                if (sws) {
                    const int space = frame->colorspace == AVCOL_SPC_BT709 ? SWS_CS_ITU709 : SWS_CS_DEFAULT;
                    const int *coefficients = sws_getCoefficients(space);
                    sws_setColorspaceDetails(sws.get(), coefficients, frame->color_range == AVCOL_RANGE_JPEG,
                        coefficients, 1, 0, 1 << 16, 1 << 16);
                    sws_scale(sws.get(), frame->data, frame->linesize, 0, frame->height, rgb->data, rgb->linesize);
                    for (int y = 0; y < image.height(); ++y)
                        std::memcpy(image.scanLine(y), rgb->data[0] + qsizetype(y) * rgb->linesize[0],
                            size_t(image.width()) * 4);
                    result = image;
                }
            }
            av_frame_unref(frame.get());
        }
    };
    while (!result && av_read_frame(raw, packet.get()) >= 0) {
        if (packet->stream_index == stream && avcodec_send_packet(video.get(), packet.get()) >= 0)
            receive();
        av_packet_unref(packet.get());
    }
    if (!result) {
        avcodec_send_packet(video.get(), nullptr);
        receive();
    }
    if (!result)
        fail(error, path, VideoText::tr("has no frame %1 (it has %2)").arg(index).arg(seen));
    return result;
}

std::optional<QVector<float>> readAudio(const QString &path, int sampleRate, QString *error)
{
    quietFfmpegLogs();
    if (sampleRate <= 0) {
        fail(error, path, VideoText::tr("invalid sample rate %1").arg(sampleRate));
        return std::nullopt;
    }
    AudioFeed feed;
    QVector<float> samples;
    if (!feed.open(AudioSource::fromFile(path), error) || !feed.start(sampleRate, error)
        || !feed.readAll(&samples, error))
        return std::nullopt;
    return samples;
}

} // namespace toonface
