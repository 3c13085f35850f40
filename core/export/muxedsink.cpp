#include "export/videosink.h"

#include "i18n/coretext.h"
#include "media/audiofeed.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QPainter>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>

namespace toonface::av {

AVRational frameRateOf(double fps)
{
    if (std::abs(fps - std::round(fps)) < 1e-9)
        return {int(std::lround(fps)), 1};
    return av_d2q(fps, 100000);
}

QImage opaqueRgb32(const QImage &frame, const QColor &background)
{
    if (!frame.hasAlphaChannel())
        return frame.format() == QImage::Format_RGB32 ? frame : frame.convertToFormat(QImage::Format_RGB32);
    QImage canvas(frame.size(), QImage::Format_RGB32);
    canvas.fill(background.rgb());
    QPainter p(&canvas);
    p.drawImage(0, 0, frame);
    p.end();
    return canvas;
}

QImage padded(const QImage &rgb32, QSize size)
{
    if (rgb32.size() == size)
        return rgb32;
    QImage out(size, QImage::Format_RGB32);
    const int w = rgb32.width();
    for (int y = 0; y < size.height(); ++y) {
        const auto *src = reinterpret_cast<const QRgb *>(rgb32.constScanLine(std::min(y, rgb32.height() - 1)));
        auto *dst = reinterpret_cast<QRgb *>(out.scanLine(y));
        std::copy_n(src, w, dst);
        std::fill(dst + w, dst + size.width(), src[w - 1]);
    }
    return out;
}

MuxedSink::MuxedSink() = default;

MuxedSink::~MuxedSink()
{
    cancel();
}

bool MuxedSink::addFrame(const QImage &frame, QString *error)
{
    if (!m_fmt)
        return fail(error, m_path, ExportText::tr("the writer is closed"));
    return encodeFrame(frame, error);
}

bool MuxedSink::finish(QString *error)
{
    if (!m_fmt)
        return fail(error, m_path, ExportText::tr("the writer is closed"));
    if (!finishStreams(error) || !drain(m_video.get(), m_videoStream, nullptr, error)) {
        cancel();
        return false;
    }
    m_headerWritten = false; // the trailer is written once, whatever it returns
    int r = av_write_trailer(m_fmt);
    if (r >= 0)
        r = avio_closep(&m_fmt->pb);
    if (r < 0) {
        cancel();
        return fail(error, m_path, ExportText::tr("cannot write: %1").arg(avError(r)));
    }
    closeAll();
    if (!finishFile(m_temp, error)) {
        cancel();
        return false;
    }
    if (QFileInfo::exists(m_path)) // a replaced file keeps its permissions, as with QSaveFile
        QFile::setPermissions(m_temp, QFile::permissions(m_path));
    std::error_code ec;
    std::filesystem::rename(std::filesystem::path(localPath(m_temp).toStdString()),
        std::filesystem::path(localPath(m_path).toStdString()), ec);
    if (ec) {
        QFile::remove(m_temp);
        return fail(error, m_path, ExportText::tr("cannot write: %1").arg(QString::fromStdString(ec.message())));
    }
    m_temp.clear();
    return true;
}

void MuxedSink::cancel()
{
    // FFmpeg 5.1's GIF muxer holds the last packet (to learn its delay) and frees it only
    // in its trailer.
    if (m_fmt && m_headerWritten && m_trailerOnCancel)
        av_write_trailer(m_fmt);
    closeAll();
    if (!m_temp.isEmpty()) {
        QFile::remove(m_temp);
        m_temp.clear();
    }
}

bool MuxedSink::openOutput(const QString &path, const char *formatName, QString *error)
{
    m_path = path;
    const QFileInfo info(path);
    const QString dir = info.absolutePath();
    if (!QFileInfo(dir).isDir())
        return fail(error, path, ExportText::tr("cannot write: the folder %1 does not exist").arg(dir));
    if (info.isDir())
        return fail(error, path, ExportText::tr("cannot write: it is a folder"));
    // A new file (NewOnly) gets the usual permissions, 0666 less the umask, unlike a
    // QTemporaryFile's 0600.
    static std::atomic<int> serial = 0;
    for (int attempt = 0; m_temp.isEmpty(); ++attempt) {
        const QString name = QStringLiteral("%1/.%2.%3-%4.part")
                                 .arg(dir, info.fileName())
                                 .arg(QCoreApplication::applicationPid())
                                 .arg(serial++);
        QFile temp(name);
        if (temp.open(QIODevice::WriteOnly | QIODevice::NewOnly))
            m_temp = name;
        else if (!QFileInfo::exists(name) || attempt > 100)
            return fail(error, path,
                ExportText::tr("cannot write in the folder %1: %2")
                    .arg(QDir::toNativeSeparators(dir), temp.errorString()));
    }
    int r = avformat_alloc_output_context2(&m_fmt, nullptr, formatName, localPath(m_temp).constData());
    if (r < 0 || !m_fmt)
        return fail(
            error, path, ExportText::tr("FFmpeg has no %1 muxer: %2").arg(QString::fromLatin1(formatName), avError(r)));
    return true;
}

bool MuxedSink::openFrames(
    AVPixelFormat pixelFormat, bool bt709, QSize size, const QString &convertProblem, QString *error)
{
    m_frame.reset(av_frame_alloc());
    m_frame->format = pixelFormat;
    m_frame->width = m_encoded.width();
    m_frame->height = m_encoded.height();
    if (bt709) {
        m_frame->color_range = AVCOL_RANGE_MPEG;
        m_frame->colorspace = AVCOL_SPC_BT709;
    }
    m_rgb.reset(av_frame_alloc());
    m_rgb->format = AV_PIX_FMT_RGB32;
    m_rgb->width = m_encoded.width();
    m_rgb->height = m_encoded.height();
    int r = av_frame_get_buffer(m_frame.get(), 0);
    if (r >= 0)
        r = av_frame_get_buffer(m_rgb.get(), 0);
    if (r < 0) {
        cancel();
        return fail(
            error, m_path, ExportText::tr("out of memory for a %1x%2 frame").arg(size.width()).arg(size.height()));
    }
    m_sws.reset(sws_getContext(m_encoded.width(), m_encoded.height(), AV_PIX_FMT_RGB32, m_encoded.width(),
        m_encoded.height(), pixelFormat, SWS_BILINEAR, nullptr, nullptr, nullptr));
    if (!m_sws) {
        cancel();
        return fail(error, m_path, convertProblem);
    }
    if (bt709) {
        // RGB (full range) to BT.709 limited-range YUV, matching the stream's colour tags.
        const int *coefficients = sws_getCoefficients(SWS_CS_ITU709);
        sws_setColorspaceDetails(m_sws.get(), coefficients, 1, coefficients, 0, 0, 1 << 16, 1 << 16);
    }
    return true;
}

bool MuxedSink::startWriting(AVDictionary **options, QString *error)
{
    int r = avio_open(&m_fmt->pb, localPath(m_temp).constData(), AVIO_FLAG_WRITE);
    if (r < 0)
        return fail(error, m_path, ExportText::tr("cannot write: %1").arg(avError(r)));
    r = avformat_write_header(m_fmt, options);
    av_dict_free(options);
    if (r < 0)
        return fail(error, m_path, ExportText::tr("cannot write the header: %1").arg(avError(r)));
    m_headerWritten = true;
    m_packet.reset(av_packet_alloc());
    return true;
}

AVStream *MuxedSink::addStream(AVCodecContext *ctx, QString *error)
{
    AVStream *stream = avformat_new_stream(m_fmt, nullptr);
    if (!stream) {
        fail(error, m_path, ExportText::tr("out of memory"));
        return nullptr;
    }
    stream->time_base = ctx->time_base;
    const int r = avcodec_parameters_from_context(stream->codecpar, ctx);
    if (r < 0) {
        fail(error, m_path, ExportText::tr("cannot set up the stream: %1").arg(avError(r)));
        return nullptr;
    }
    return stream;
}

bool MuxedSink::drain(AVCodecContext *ctx, AVStream *stream, AVFrame *frame, QString *error)
{
    int r = avcodec_send_frame(ctx, frame);
    if (r < 0 && !(frame == nullptr && r == AVERROR_EOF))
        return fail(error, m_path,
            ExportText::tr("cannot encode (%1): %2").arg(QString::fromLatin1(ctx->codec->name), avError(r)));
    while (true) {
        r = avcodec_receive_packet(ctx, m_packet.get());
        if (r == AVERROR(EAGAIN) || r == AVERROR_EOF)
            return true;
        if (r < 0)
            return fail(error, m_path,
                ExportText::tr("cannot encode (%1): %2").arg(QString::fromLatin1(ctx->codec->name), avError(r)));
        if (m_packet->duration == 0 && ctx->codec_type == AVMEDIA_TYPE_VIDEO)
            m_packet->duration = m_frameDuration;
        av_packet_rescale_ts(m_packet.get(), ctx->time_base, stream->time_base);
        m_packet->stream_index = stream->index;
        r = av_interleaved_write_frame(m_fmt, m_packet.get());
        if (r < 0)
            return fail(error, m_path, ExportText::tr("cannot write: %1").arg(avError(r)));
    }
}

bool MuxedSink::finishStreams(QString *error)
{
    if (!encodeAudioUntilFrame(m_videoFrames, m_fps, true, error))
        return false;
    return !m_audio || drain(m_audio.get(), m_audioStream, nullptr, error);
}

bool MuxedSink::openAudio(const AudioSource &audio, const AVCodec *codec, AVSampleFormat sampleFormat,
    std::initializer_list<int> rates, int bitRate, QString *error)
{
    m_feed = std::make_unique<AudioFeed>();
    if (!m_feed->open(audio, error))
        return false;
    int rate = *rates.begin();
    if (m_feed->sourceRate() % 11025 == 0 && std::find(rates.begin(), rates.end(), 44100) != rates.end())
        rate = 44100;
    if (!m_feed->start(rate, error))
        return false;
    m_audio.reset(avcodec_alloc_context3(codec));
    AVCodecContext *a = m_audio.get();
    a->sample_fmt = sampleFormat;
    a->sample_rate = rate;
    av_channel_layout_default(&a->ch_layout, 1);
    a->bit_rate = bitRate;
    a->time_base = {1, rate};
    if (m_fmt->oformat->flags & AVFMT_GLOBALHEADER)
        a->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    // FFmpeg's own AAC encoder with its "fast" coder (its default until 2016) instead of the
    // two-loop search: ten minutes of 48 kHz mono at 96 kb/s cost 5.0 CPU-s instead of 8.6, the
    // largest share of a read-aloud book's video pages after the drawing.
    if (codec->id == AV_CODEC_ID_AAC)
        av_opt_set(a->priv_data, "aac_coder", "fast", 0);
    const int r = avcodec_open2(a, codec, nullptr);
    if (r < 0)
        return fail(error, m_path,
            ExportText::tr("cannot start the %1 encoder: %2").arg(QString::fromLatin1(codec->name), avError(r)));
    m_audioStream = addStream(a, error);
    if (!m_audioStream)
        return false;
    m_audioFrame.reset(av_frame_alloc());
    m_audioFrame->format = sampleFormat;
    m_audioFrame->sample_rate = rate;
    av_channel_layout_default(&m_audioFrame->ch_layout, 1);
    // PCM takes frames of any length.
    m_audioFrame->nb_samples = a->frame_size > 0 ? a->frame_size : 1024;
    if (av_frame_get_buffer(m_audioFrame.get(), 0) < 0)
        return fail(error, m_path, ExportText::tr("out of memory"));
    return true;
}

bool MuxedSink::encodeAudioUntilFrame(int64_t frames, double fps, bool last, QString *error)
{
    if (!m_audio)
        return true;
    const int64_t until = av_rescale_q(frames, av_inv_q(frameRateOf(fps)), {1, m_audio->sample_rate});
    const int frameSize = m_audio->frame_size > 0 ? m_audio->frame_size : 1024;
    const bool fixedSize
        = m_audio->frame_size > 0 && !(m_audio->codec->capabilities & AV_CODEC_CAP_VARIABLE_FRAME_SIZE);
    while (m_audioSamples < until) {
        const int64_t left = until - m_audioSamples;
        if (left < frameSize && !last)
            return true;
        const int n = int(std::min<int64_t>(frameSize, left));
        if (av_frame_make_writable(m_audioFrame.get()) < 0)
            return fail(error, m_path, ExportText::tr("out of memory"));
        // An encoder of fixed frames (Opus) takes the last one padded with silence.
        m_audioFrame->nb_samples
            = fixedSize && !(m_audio->codec->capabilities & AV_CODEC_CAP_SMALL_LAST_FRAME) ? frameSize : n;
        m_audioBuffer.fill(0.0f, m_audioFrame->nb_samples);
        if (!m_feed->read(m_audioBuffer.data(), n, error))
            return false;
        if (m_audio->sample_fmt == AV_SAMPLE_FMT_S16) {
            auto *out = reinterpret_cast<int16_t *>(m_audioFrame->data[0]);
            for (int i = 0; i < m_audioFrame->nb_samples; ++i)
                out[i] = int16_t(std::lround(std::clamp(m_audioBuffer[i], -1.0f, 1.0f) * 32767.0f));
        } else { // mono float, planar or not, is one plane
            std::copy_n(
                m_audioBuffer.constData(), m_audioFrame->nb_samples, reinterpret_cast<float *>(m_audioFrame->data[0]));
        }
        m_audioFrame->pts = m_audioSamples;
        if (!drain(m_audio.get(), m_audioStream, m_audioFrame.get(), error))
            return false;
        m_audioSamples += n;
    }
    return true;
}

void MuxedSink::closeAll()
{
    if (m_fmt) {
        if (m_fmt->pb)
            avio_closep(&m_fmt->pb);
        avformat_free_context(m_fmt);
        m_fmt = nullptr;
    }
    m_headerWritten = false;
    m_video.reset();
    m_audio.reset();
}

} // namespace toonface::av
