#include "export/videosink.h"

#include "i18n/coretext.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace toonface::av {

namespace {

// What each format with alpha is made of.
struct AlphaFormat
{
    const char *name; // for messages
    const char *muxer;
    const char *videoEncoder;
    AVPixelFormat pixelFormat;
    bool evenSize; // chroma subsampled: each side rounded up to even
    const char *audioEncoder; // null: silent
    AVSampleFormat sampleFormat;
};

AlphaFormat alphaFormat(VideoFormat format)
{
    switch (format) {
    case VideoFormat::WebM:
        return {"WebM", "webm", "libvpx-vp9", AV_PIX_FMT_YUVA420P, true, "libopus", AV_SAMPLE_FMT_FLT};
    case VideoFormat::Mov:
        return {"MOV", "mov", "prores_ks", AV_PIX_FMT_YUVA444P10LE, false, "pcm_s16le", AV_SAMPLE_FMT_S16};
    case VideoFormat::Apng: return {"APNG", "apng", "apng", AV_PIX_FMT_RGBA, false, nullptr, AV_SAMPLE_FMT_NONE};
    case VideoFormat::WebP:
        return {"WebP", "webp", "libwebp_anim", AV_PIX_FMT_RGB32, false, nullptr, AV_SAMPLE_FMT_NONE};
    case VideoFormat::Mp4:
    case VideoFormat::Gif:
    case VideoFormat::PngSequence: break;
    }
    return {};
}

// Transparent pixels pass through as they are: straight (not premultiplied) RGBA in, the
// format's own pixels out through swscale, which converts the alpha plane with the colours.
class AlphaSink : public MuxedSink
{
public:
    bool open(const QString &path, VideoFormat format, QSize size, double fps, const AudioSource &audio,
        const VideoOptions &options, QString *error)
    {
        m_format = alphaFormat(format);
        const bool alpha = format != VideoFormat::WebM || options.keepAlpha;
        if (!alpha)
            m_format.pixelFormat = AV_PIX_FMT_YUV420P;
        const QString name = QString::fromLatin1(m_format.name);
        const AVCodec *codec = avcodec_find_encoder_by_name(m_format.videoEncoder);
        if (!codec)
            return fail(error, path,
                ExportText::tr("cannot write %1: FFmpeg has no %2 encoder")
                    .arg(name, QString::fromLatin1(m_format.videoEncoder)));
        if (size.width() < 2 || size.height() < 2 || size.width() > 8192 || size.height() > 8192)
            return fail(error, path,
                ExportText::tr("unsupported size %1x%2 (%3 takes 2 to 8192 pixels a side)")
                    .arg(size.width())
                    .arg(size.height())
                    .arg(name));
        m_encoded
            = m_format.evenSize ? QSize(size.width() + size.width() % 2, size.height() + size.height() % 2) : size;
        m_fps = fps;
        if (!openOutput(path, m_format.muxer, error))
            return false;

        m_video.reset(avcodec_alloc_context3(codec));
        AVCodecContext *v = m_video.get();
        v->width = m_encoded.width();
        v->height = m_encoded.height();
        v->pix_fmt = m_format.pixelFormat;
        v->framerate = frameRateOf(fps);
        v->time_base = av_inv_q(v->framerate);
        v->thread_count = options.threads;
        if (m_fmt->oformat->flags & AVFMT_GLOBALHEADER)
            v->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
        const bool yuv = format == VideoFormat::WebM || format == VideoFormat::Mov;
        if (yuv) {
            v->color_range = AVCOL_RANGE_MPEG;
            v->colorspace = AVCOL_SPC_BT709;
            v->color_primaries = AVCOL_PRI_BT709;
            v->color_trc = AVCOL_TRC_BT709;
        }
        AVDictionary *codecOptions = nullptr;
        switch (format) {
        case VideoFormat::WebM:
            v->gop_size = std::max(1, int(std::lround(2 * fps)));
            v->bit_rate = 0; // constant quality
            av_dict_set_int(&codecOptions, "crf", std::clamp(options.vp9Crf, 0, 63), 0);
            av_dict_set(&codecOptions, "deadline", "good", 0);
            av_dict_set_int(&codecOptions, "cpu-used", 4, 0);
            av_dict_set_int(&codecOptions, "row-mt", 1, 0);
            break;
        case VideoFormat::Mov:
            av_dict_set(&codecOptions, "profile", "4444", 0);
            av_dict_set(&codecOptions, "vendor", "apl0", 0);
            break;
        case VideoFormat::Apng: av_dict_set(&codecOptions, "pred", "mixed", 0); break;
        case VideoFormat::WebP:
            av_dict_set_int(&codecOptions, "quality", std::clamp(options.webpQuality, 0, 100), 0);
            break;
        default: break;
        }
        int r = avcodec_open2(v, codec, &codecOptions);
        av_dict_free(&codecOptions);
        if (r < 0) {
            cancel();
            return fail(error, path,
                ExportText::tr("cannot start the %1 encoder at %2x%3: %4")
                    .arg(QString::fromLatin1(m_format.videoEncoder))
                    .arg(m_encoded.width())
                    .arg(m_encoded.height())
                    .arg(avError(r)));
        }
        m_videoStream = addStream(v, error);
        if (!m_videoStream) {
            cancel();
            return false;
        }
        // Matroska keeps VP9's alpha as block additions; this tag tells players to read them.
        if (format == VideoFormat::WebM && alpha)
            av_dict_set(&m_videoStream->metadata, "alpha_mode", "1", 0);

        if (!audio.isEmpty() && m_format.audioEncoder) {
            const AVCodec *audioCodec = avcodec_find_encoder_by_name(m_format.audioEncoder);
            if (!audioCodec) {
                cancel();
                return fail(error, path,
                    ExportText::tr("cannot write %1: FFmpeg has no %2 encoder")
                        .arg(name, QString::fromLatin1(m_format.audioEncoder)));
            }
            const bool opus = format == VideoFormat::WebM;
            if (!openAudio(audio, audioCodec, m_format.sampleFormat,
                    opus ? std::initializer_list<int> {48000} : std::initializer_list<int> {48000, 44100},
                    options.audioBitRate, error)) {
                cancel();
                return false;
            }
        }

        if (!openFrames(m_format.pixelFormat, yuv, size,
                ExportText::tr("cannot convert %1x%2 RGBA for %3").arg(size.width()).arg(size.height()).arg(name),
                error))
            return false;

        AVDictionary *muxerOptions = nullptr;
        if (format == VideoFormat::Apng)
            av_dict_set(&muxerOptions, "plays", "0", 0); // loop for ever, as stickers do
        else if (format == VideoFormat::WebP)
            av_dict_set(&muxerOptions, "loop", "0", 0);
        if (!startWriting(&muxerOptions, error)) {
            cancel();
            return false;
        }
        return true;
    }

    QSize encodedSize() const { return m_encoded; }

protected:
    bool encodeFrame(const QImage &frame, QString *error) override
    {
        QImage argb = frame.convertToFormat(QImage::Format_ARGB32);
        if (argb.size() != m_encoded) { // repeat the last column and row, alpha included
            QImage grown(m_encoded, QImage::Format_ARGB32);
            for (int y = 0; y < m_encoded.height(); ++y) {
                const auto *src = reinterpret_cast<const QRgb *>(argb.constScanLine(std::min(y, argb.height() - 1)));
                auto *dst = reinterpret_cast<QRgb *>(grown.scanLine(y));
                std::copy_n(src, argb.width(), dst);
                std::fill(dst + argb.width(), dst + m_encoded.width(), src[argb.width() - 1]);
            }
            argb = grown;
        }
        if (av_frame_make_writable(m_frame.get()) < 0)
            return fail(error, m_path, ExportText::tr("out of memory"));
        for (int y = 0; y < argb.height(); ++y)
            std::memcpy(
                m_rgb->data[0] + qsizetype(y) * m_rgb->linesize[0], argb.constScanLine(y), size_t(argb.width()) * 4);
        if (m_format.pixelFormat == AV_PIX_FMT_RGB32) {
            av_frame_copy(m_frame.get(), m_rgb.get());
        } else {
            sws_scale(m_sws.get(), m_rgb->data, m_rgb->linesize, 0, argb.height(), m_frame->data, m_frame->linesize);
        }
        m_frame->pts = m_videoFrames;
        if (!drain(m_video.get(), m_videoStream, m_frame.get(), error))
            return false;
        ++m_videoFrames;
        return encodeAudioUntilFrame(m_videoFrames, m_fps, false, error);
    }

private:
    AlphaFormat m_format {};
};

} // namespace

std::unique_ptr<Sink> openAlphaSink(const QString &path, VideoFormat format, QSize size, double fps,
    const AudioSource &audio, const VideoOptions &options, QSize *encodedSize, QString *error)
{
    auto sink = std::make_unique<AlphaSink>();
    if (!sink->open(path, format, size, fps, audio, options, error))
        return nullptr;
    *encodedSize = sink->encodedSize();
    return sink;
}

} // namespace toonface::av
