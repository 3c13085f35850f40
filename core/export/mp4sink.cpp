#include "export/videosink.h"

#include "i18n/coretext.h"
#include "media/audiofeed.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace toonface::av {

namespace {

AVRational frameRateOf(double fps)
{
    if (std::abs(fps - std::round(fps)) < 1e-9)
        return {int(std::lround(fps)), 1};
    return av_d2q(fps, 100000);
}

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

        if (!audio.isEmpty() && !openAudio(path, audio, options, error)) {
            cancel();
            return false;
        }

        m_frame.reset(av_frame_alloc());
        m_frame->format = AV_PIX_FMT_YUV420P;
        m_frame->width = m_encoded.width();
        m_frame->height = m_encoded.height();
        m_frame->color_range = AVCOL_RANGE_MPEG;
        m_frame->colorspace = AVCOL_SPC_BT709;
        m_rgb.reset(av_frame_alloc());
        m_rgb->format = AV_PIX_FMT_RGB32;
        m_rgb->width = m_encoded.width();
        m_rgb->height = m_encoded.height();
        r = av_frame_get_buffer(m_frame.get(), 0);
        if (r >= 0)
            r = av_frame_get_buffer(m_rgb.get(), 0);
        if (r < 0) {
            cancel();
            return fail(
                error, path, ExportText::tr("out of memory for a %1x%2 frame").arg(size.width()).arg(size.height()));
        }
        m_sws.reset(sws_getContext(m_encoded.width(), m_encoded.height(), AV_PIX_FMT_RGB32, m_encoded.width(),
            m_encoded.height(), AV_PIX_FMT_YUV420P, SWS_BILINEAR, nullptr, nullptr, nullptr));
        if (!m_sws) {
            cancel();
            return fail(
                error, path, ExportText::tr("cannot convert %1x%2 RGB to YUV").arg(size.width()).arg(size.height()));
        }
        // RGB (full range) to BT.709 limited-range YUV, matching the stream's colour tags.
        const int *coefficients = sws_getCoefficients(SWS_CS_ITU709);
        sws_setColorspaceDetails(m_sws.get(), coefficients, 1, coefficients, 0, 0, 1 << 16, 1 << 16);

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
        m_frame->pts = m_frames;
        if (!drain(m_video.get(), m_videoStream, m_frame.get(), error))
            return false;
        ++m_frames;
        // Keep the sound level with the pictures so the muxer can interleave them.
        return encodeAudioUntil(audioSamplesAt(m_frames), false, error);
    }

    bool finishStreams(QString *error) override
    {
        if (!encodeAudioUntil(audioSamplesAt(m_frames), true, error))
            return false;
        return !m_audio || drain(m_audio.get(), m_audioStream, nullptr, error);
    }

private:
    bool openAudio(const QString &path, const AudioSource &audio, const VideoOptions &options, QString *error)
    {
        const AVCodec *aac = avcodec_find_encoder(AV_CODEC_ID_AAC);
        if (!aac)
            return fail(error, path, ExportText::tr("cannot write MP4: FFmpeg has no AAC encoder"));
        m_feed = std::make_unique<AudioFeed>();
        if (!m_feed->open(audio, error))
            return false;
        // The 44.1 kHz family stays in it; everything else becomes 48 kHz.
        const int rate = m_feed->sourceRate() % 11025 == 0 ? 44100 : 48000;
        if (!m_feed->start(rate, error))
            return false;
        m_audio.reset(avcodec_alloc_context3(aac));
        AVCodecContext *a = m_audio.get();
        a->sample_fmt = AV_SAMPLE_FMT_FLTP;
        a->sample_rate = rate;
        av_channel_layout_default(&a->ch_layout, 1);
        a->bit_rate = options.audioBitRate;
        a->time_base = {1, rate};
        if (m_fmt->oformat->flags & AVFMT_GLOBALHEADER)
            a->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
        const int r = avcodec_open2(a, aac, nullptr);
        if (r < 0)
            return fail(error, path, ExportText::tr("cannot start the AAC encoder: %1").arg(avError(r)));
        m_audioStream = addStream(a, error);
        if (!m_audioStream)
            return false;
        m_audioFrame.reset(av_frame_alloc());
        m_audioFrame->format = AV_SAMPLE_FMT_FLTP;
        m_audioFrame->sample_rate = rate;
        av_channel_layout_default(&m_audioFrame->ch_layout, 1);
        m_audioFrame->nb_samples = a->frame_size;
        if (av_frame_get_buffer(m_audioFrame.get(), 0) < 0)
            return fail(error, path, ExportText::tr("out of memory"));
        return true;
    }

    int64_t audioSamplesAt(int frames) const
    {
        if (!m_audio)
            return 0;
        return av_rescale_q(frames, av_inv_q(frameRateOf(m_fps)), {1, m_audio->sample_rate});
    }

    // Encodes sound up to sample `until`: whole encoder frames, and at the end a last short one.
    bool encodeAudioUntil(int64_t until, bool last, QString *error)
    {
        if (!m_audio)
            return true;
        const int frameSize = m_audio->frame_size;
        while (m_audioSamples < until) {
            const int64_t left = until - m_audioSamples;
            if (left < frameSize && !last)
                return true;
            const int n = int(std::min<int64_t>(frameSize, left));
            if (av_frame_make_writable(m_audioFrame.get()) < 0)
                return fail(error, m_path, ExportText::tr("out of memory"));
            m_audioFrame->nb_samples = n;
            if (!m_feed->read(reinterpret_cast<float *>(m_audioFrame->data[0]), n, error))
                return false;
            m_audioFrame->pts = m_audioSamples;
            if (!drain(m_audio.get(), m_audioStream, m_audioFrame.get(), error))
                return false;
            m_audioSamples += n;
        }
        return true;
    }

    QSize m_size;
    QSize m_encoded;
    double m_fps = 25;
    QColor m_background;
    FramePtr m_frame;
    FramePtr m_rgb;
    SwsPtr m_sws;
    int64_t m_frames = 0;
    std::unique_ptr<AudioFeed> m_feed;
    FramePtr m_audioFrame;
    int64_t m_audioSamples = 0;
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
