#include "media/ffmpegutil.h"

#include "i18n/coretext.h"

#include <QDir>
#include <QFile>

#include <cerrno>
#include <mutex>

#include <cstring>

namespace toonface::av {

QString avError(int code)
{
    // The errors a user meets most, in the interface's language; FFmpeg's own words for the rest.
    switch (code) {
    case AVERROR_INVALIDDATA: return MediaText::tr("the data is invalid or damaged");
    case AVERROR_EOF: return MediaText::tr("the file ends early");
    case AVERROR_DECODER_NOT_FOUND: return MediaText::tr("no decoder for it");
    case AVERROR_ENCODER_NOT_FOUND: return MediaText::tr("no encoder for it");
    case AVERROR_DEMUXER_NOT_FOUND: return MediaText::tr("its format is not recognised");
    case AVERROR_MUXER_NOT_FOUND: return MediaText::tr("the format cannot be written");
    case AVERROR(ENOENT): return MediaText::tr("no such file or folder");
    case AVERROR(EACCES): return MediaText::tr("permission denied");
    case AVERROR(EISDIR): return MediaText::tr("it is a folder");
    case AVERROR(ENOSPC): return MediaText::tr("the disk is full");
    case AVERROR(EROFS): return MediaText::tr("the disk is read-only");
    case AVERROR(ENOMEM): return MediaText::tr("out of memory");
    default: break;
    }
    char buf[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, buf, sizeof buf);
    return QString::fromUtf8(buf);
}

bool fail(QString *error, const QString &path, const QString &problem)
{
    if (error)
        *error = withProblem(QDir::toNativeSeparators(path), problem);
    return false;
}

void quietFfmpegLogs()
{
    static std::once_flag once;
    std::call_once(once, [] {
        if (av_log_get_level() == AV_LOG_INFO)
            av_log_set_level(AV_LOG_ERROR);
    });
}

QByteArray localPath(const QString &path)
{
    return QFile::encodeName(path);
}

CodecPtr openDecoder(AVFormatContext *input, AVMediaType type, int *streamIndex, QString *problem)
{
    const int index = av_find_best_stream(input, type, -1, -1, nullptr, 0);
    if (index < 0)
        return {};
    const AVStream *stream = input->streams[index];
    const AVCodec *codec = avcodec_find_decoder(stream->codecpar->codec_id);
    // FFmpeg's own VP9 decoder drops the alpha that WebM keeps beside the picture; libvpx's
    // decodes it too.
    const AVDictionaryEntry *alphaMode = av_dict_get(stream->metadata, "alpha_mode", nullptr, 0);
    if (stream->codecpar->codec_id == AV_CODEC_ID_VP9 && alphaMode && std::strcmp(alphaMode->value, "0") != 0) {
        if (const AVCodec *withAlpha = avcodec_find_decoder_by_name("libvpx-vp9"))
            codec = withAlpha;
    }
    if (!codec) {
        *problem = VideoText::tr("no decoder for its %1 codec '%2'")
                       .arg(QString::fromLatin1(av_get_media_type_string(type)),
                           QString::fromLatin1(avcodec_get_name(stream->codecpar->codec_id)));
        return {};
    }
    CodecPtr ctx(avcodec_alloc_context3(codec));
    int r = avcodec_parameters_to_context(ctx.get(), stream->codecpar);
    if (r >= 0) {
        ctx->pkt_timebase = stream->time_base;
        r = avcodec_open2(ctx.get(), codec, nullptr);
    }
    if (r < 0) {
        *problem = VideoText::tr("cannot open its %1 decoder: %2").arg(QString::fromLatin1(codec->name), avError(r));
        return {};
    }
    *streamIndex = index;
    return ctx;
}

} // namespace toonface::av
