#include "export/videosink.h"

#include "i18n/coretext.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace toonface::av {

namespace {

class Mp4Sink : public MuxedSink
{
public:
    bool open(const QString &path, QSize size, double fps, const AudioSource &audio, const VideoOptions &options,
        QString *error)
    {
        const AVCodec *h264 = avcodec_find_encoder_by_name("libx264");
        if (!h264)
            return fail(error, path, ExportText::tr("cannot write MP4: FFmpeg has no H.264 encoder (libx264)"));
        if (size.width() < 2 || size.height() < 2 || size.width() > 8192 || size.height() > 8192)
            return fail(error, path,
                ExportText::tr("unsupported size %1x%2 (MP4 takes 2 to 8192 pixels a side)")
                    .arg(size.width())
                    .arg(size.height()));
        m_size = size;
        m_encoded = QSize(size.width() + size.width() % 2, size.height() + size.height() % 2);
        m_fps = fps;
        m_background = options.background;
        if (!openOutput(path, "mp4", error))
            return false;

        m_video.reset(avcodec_alloc_context3(h264));
        AVCodecContext *v = m_video.get();
        v->width = m_encoded.width();
        v->height = m_encoded.height();
        v->pix_fmt = AV_PIX_FMT_YUV420P;
        v->framerate = frameRateOf(fps);
        v->time_base = av_inv_q(v->framerate);
        v->gop_size = std::max(1, int(std::lround(2 * fps))); // a key frame every 2 s for seeking
        v->thread_count = options.threads;
        v->color_range = AVCOL_RANGE_MPEG;
        v->colorspace = AVCOL_SPC_BT709;
        v->color_primaries = AVCOL_PRI_BT709;
        v->color_trc = AVCOL_TRC_BT709;
        if (m_fmt->oformat->flags & AVFMT_GLOBALHEADER)
            v->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
        av_opt_set(v->priv_data, "preset", options.preset.toUtf8().constData(), 0);
        av_opt_set_double(v->priv_data, "crf", options.crf, 0);
        int r = avcodec_open2(v, h264, nullptr);
        if (r < 0) {
            cancel();
            return fail(error, path,
                ExportText::tr("cannot start the H.264 encoder at %1x%2: %3")
                    .arg(m_encoded.width())
                    .arg(m_encoded.height())
                    .arg(avError(r)));
        }
        m_videoStream = addStream(v, error);
        if (!m_videoStream) {
            cancel();
            return false;
        }

        if (!audio.isEmpty()) {
            const AVCodec *aac = avcodec_find_encoder(AV_CODEC_ID_AAC);
            if (!aac) {
                cancel();
                return fail(error, path, ExportText::tr("cannot write MP4: FFmpeg has no AAC encoder"));
            }
            // The 44.1 kHz family stays in it; everything else becomes 48 kHz, unless the options
            // name a rate.
            const bool ownRate = options.mp4AudioRate > 0;
            if (!openAudio(audio, aac, AV_SAMPLE_FMT_FLTP,
                    ownRate ? std::initializer_list<int> {options.mp4AudioRate}
                            : std::initializer_list<int> {48000, 44100},
                    options.audioBitRate, error)) {
                cancel();
                return false;
            }
        }

        if (!openFrames(AV_PIX_FMT_YUV420P, true, size,
                ExportText::tr("cannot convert %1x%2 RGB to YUV").arg(size.width()).arg(size.height()), error))
            return false;

        AVDictionary *opts = nullptr;
        av_dict_set(&opts, "movflags", "+faststart", 0);
        if (!startWriting(&opts, error)) {
            cancel();
            return false;
        }
        return true;
    }

    QSize encodedSize() const { return m_encoded; }

protected:
    bool encodeFrame(const QImage &frame, QString *error) override
    {
        const QImage rgb = padded(opaqueRgb32(frame, m_background), m_encoded);
        if (av_frame_make_writable(m_frame.get()) < 0)
            return fail(error, m_path, ExportText::tr("out of memory"));
        // swscale reads and writes whole SIMD blocks: it gets FFmpeg's padded buffers, not QImage's.
        for (int y = 0; y < rgb.height(); ++y)
            std::memcpy(
                m_rgb->data[0] + qsizetype(y) * m_rgb->linesize[0], rgb.constScanLine(y), size_t(rgb.width()) * 4);
        sws_scale(m_sws.get(), m_rgb->data, m_rgb->linesize, 0, rgb.height(), m_frame->data, m_frame->linesize);
        m_frame->pts = m_videoFrames;
        if (!drain(m_video.get(), m_videoStream, m_frame.get(), error))
            return false;
        ++m_videoFrames;
        // Keep the sound level with the pictures so the muxer can interleave them.
        return encodeAudioUntilFrame(m_videoFrames, m_fps, false, error);
    }

private:
    QSize m_size;
    QColor m_background;
};

} // namespace

std::unique_ptr<Sink> openMp4Sink(const QString &path, QSize size, double fps, const AudioSource &audio,
    const VideoOptions &options, QSize *encodedSize, QString *error)
{
    auto sink = std::make_unique<Mp4Sink>();
    if (!sink->open(path, size, fps, audio, options, error))
        return nullptr;
    *encodedSize = sink->encodedSize();
    return sink;
}

} // namespace toonface::av
