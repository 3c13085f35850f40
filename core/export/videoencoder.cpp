#include "export/videoencoder.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImageWriter>
#include <QPainter>
#include <QRegularExpression>
#include <QSaveFile>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/channel_layout.h>
#include <libavutil/opt.h>
#include <libavutil/pixdesc.h>
#include <libswresample/swresample.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <vector>

namespace toonface {

namespace {

QString avError(int code)
{
    char buf[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, buf, sizeof buf);
    return QString::fromUtf8(buf);
}

bool fail(QString *error, const QString &path, const QString &problem)
{
    if (error)
        *error = QDir::toNativeSeparators(path) + QStringLiteral(": ") + problem;
    return false;
}

// FFmpeg prints every encoder's settings and statistics at the default level; the library is
// quiet unless something goes wrong (errors reach the caller through return values anyway).
void quietFfmpegLogs()
{
    static std::once_flag once;
    std::call_once(once, [] {
        if (av_log_get_level() == AV_LOG_INFO)
            av_log_set_level(AV_LOG_ERROR);
    });
}

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

QByteArray localPath(const QString &path)
{
    return QFile::encodeName(path);
}

// An opened decoder of the best stream of `type` in `input`.
CodecPtr openDecoder(AVFormatContext *input, AVMediaType type, int *streamIndex, QString *problem)
{
    const int index = av_find_best_stream(input, type, -1, -1, nullptr, 0);
    if (index < 0)
        return {};
    const AVStream *stream = input->streams[index];
    const AVCodec *codec = avcodec_find_decoder(stream->codecpar->codec_id);
    if (!codec) {
        *problem = QStringLiteral("no decoder for its %1 codec '%2'")
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
        *problem = QStringLiteral("cannot open its %1 decoder: %2").arg(QString::fromLatin1(codec->name), avError(r));
        return {};
    }
    *streamIndex = index;
    return ctx;
}

// ---- Audio: the source, delayed by its offset, resampled to mono float at the encoder's rate

class AudioFeed
{
public:
    // Opens the source; sourceRate() is then known.
    bool open(const AudioSource &source, QString *error)
    {
        m_source = source;
        if (!source.path.isEmpty()) {
            AVFormatContext *raw = nullptr;
            int r = avformat_open_input(&raw, localPath(source.path).constData(), nullptr, nullptr);
            if (r < 0)
                return fail(error, source.path, QStringLiteral("cannot read the audio: %1").arg(avError(r)));
            m_input.reset(raw);
            r = avformat_find_stream_info(raw, nullptr);
            if (r < 0)
                return fail(error, source.path, QStringLiteral("cannot read the audio: %1").arg(avError(r)));
            QString problem = QStringLiteral("no audio stream");
            m_decoder = openDecoder(raw, AVMEDIA_TYPE_AUDIO, &m_stream, &problem);
            if (!m_decoder)
                return fail(error, source.path, QStringLiteral("cannot read the audio: %1").arg(problem));
            m_sourceRate = m_decoder->sample_rate;
            m_packet.reset(av_packet_alloc());
            m_frame.reset(av_frame_alloc());
        } else {
            if (source.sampleRate <= 0)
                return fail(error, QStringLiteral("audio samples"),
                    QStringLiteral("invalid sample rate %1").arg(source.sampleRate));
            m_sourceRate = source.sampleRate;
        }
        if (m_sourceRate <= 0)
            return fail(error, source.path, QStringLiteral("the audio has no sample rate"));
        return true;
    }

    int sourceRate() const { return m_sourceRate; }

    // Everything the source has left (offset applied), up to its end.
    bool readAll(QVector<float> *out, QString *error)
    {
        out->fill(0.0f, qsizetype(m_silenceBefore));
        m_silenceBefore = 0;
        while (true) {
            if (m_skip > 0) {
                const qint64 k = std::min<qint64>(m_skip, qint64(m_buffer.size() - m_buffered));
                m_buffered += size_t(k);
                m_skip -= k;
            }
            out->append(QVector<float>(m_buffer.begin() + qsizetype(m_buffered), m_buffer.end()));
            m_buffer.clear();
            m_buffered = 0;
            if (m_ended)
                return true;
            if (!decodeMore(error))
                return false;
        }
    }

    // Starts resampling to `rate`.
    bool start(int rate, QString *error)
    {
        m_rate = rate;
        AVChannelLayout mono;
        av_channel_layout_default(&mono, 1);
        AVChannelLayout inLayout;
        AVSampleFormat inFormat = AV_SAMPLE_FMT_FLT;
        if (m_decoder) {
            if (m_decoder->ch_layout.order == AV_CHANNEL_ORDER_NATIVE)
                av_channel_layout_copy(&inLayout, &m_decoder->ch_layout);
            else
                av_channel_layout_default(&inLayout, std::max(1, m_decoder->ch_layout.nb_channels));
            inFormat = m_decoder->sample_fmt;
        } else {
            av_channel_layout_default(&inLayout, 1);
        }
        SwrContext *raw = nullptr;
        int r
            = swr_alloc_set_opts2(&raw, &mono, AV_SAMPLE_FMT_FLT, rate, &inLayout, inFormat, m_sourceRate, 0, nullptr);
        av_channel_layout_uninit(&inLayout);
        m_swr.reset(raw);
        if (r >= 0)
            r = swr_init(raw);
        if (r < 0)
            return fail(error, sourceName(), QStringLiteral("cannot resample the audio: %1").arg(avError(r)));
        // A positive offset is silence first; a negative one skips the source's beginning.
        const qint64 shift = qint64(std::llround(m_source.offset * rate));
        m_silenceBefore = std::max<qint64>(0, shift);
        m_skip = std::max<qint64>(0, -shift);
        return true;
    }

    // Fills dst with the next n samples (silence once the source has ended).
    bool read(float *dst, int n, QString *error)
    {
        int done = 0;
        while (done < n) {
            if (m_silenceBefore > 0) {
                const int k = int(std::min<qint64>(m_silenceBefore, n - done));
                std::fill(dst + done, dst + done + k, 0.0f);
                m_silenceBefore -= k;
                done += k;
                continue;
            }
            if (m_buffered == m_buffer.size()) {
                m_buffer.clear();
                m_buffered = 0;
                if (m_ended || !decodeMore(error)) {
                    if (!m_ended)
                        return false;
                    std::fill(dst + done, dst + n, 0.0f);
                    return true;
                }
                continue;
            }
            if (m_skip > 0) {
                const qint64 k = std::min<qint64>(m_skip, qint64(m_buffer.size() - m_buffered));
                m_buffered += size_t(k);
                m_skip -= k;
                continue;
            }
            const size_t k = std::min(size_t(n - done), m_buffer.size() - m_buffered);
            std::copy_n(m_buffer.begin() + qsizetype(m_buffered), k, dst + done);
            m_buffered += k;
            done += int(k);
        }
        return true;
    }

private:
    QString sourceName() const { return m_source.path.isEmpty() ? QStringLiteral("audio samples") : m_source.path; }

    // Appends resampled samples to m_buffer; at the source's end flushes the resampler and
    // sets m_ended. Returns false on a decoding error.
    bool decodeMore(QString *error)
    {
        if (!m_decoder) {
            constexpr qsizetype kChunk = 8192;
            const qsizetype left = m_source.samples.size() - m_memoryPos;
            if (left <= 0)
                return flush(error);
            const int n = int(std::min(kChunk, left));
            const auto *in = reinterpret_cast<const uint8_t *>(m_source.samples.constData() + m_memoryPos);
            m_memoryPos += n;
            return convert(&in, n, error);
        }
        while (true) {
            int r = avcodec_receive_frame(m_decoder.get(), m_frame.get());
            if (r >= 0) {
                const bool ok
                    = convert(const_cast<const uint8_t **>(m_frame->extended_data), m_frame->nb_samples, error);
                av_frame_unref(m_frame.get());
                if (!ok)
                    return false;
                if (!m_buffer.empty())
                    return true;
                continue;
            }
            if (r == AVERROR_EOF)
                return flush(error);
            if (r != AVERROR(EAGAIN))
                return fail(error, m_source.path, QStringLiteral("cannot decode the audio: %1").arg(avError(r)));
            if (m_draining) // the decoder said EAGAIN after a flush: nothing more will come
                return flush(error);
            r = av_read_frame(m_input.get(), m_packet.get());
            if (r == AVERROR_EOF) {
                m_draining = true;
                avcodec_send_packet(m_decoder.get(), nullptr);
                continue;
            }
            if (r < 0)
                return fail(error, m_source.path, QStringLiteral("cannot read the audio: %1").arg(avError(r)));
            if (m_packet->stream_index == m_stream) {
                r = avcodec_send_packet(m_decoder.get(), m_packet.get());
                // A damaged packet is skipped, as players do.
                if (r < 0 && r != AVERROR(EAGAIN) && r != AVERROR_INVALIDDATA) {
                    av_packet_unref(m_packet.get());
                    return fail(error, m_source.path, QStringLiteral("cannot decode the audio: %1").arg(avError(r)));
                }
            }
            av_packet_unref(m_packet.get());
        }
    }

    bool convert(const uint8_t **in, int n, QString *error)
    {
        const int capacity = swr_get_out_samples(m_swr.get(), n);
        if (capacity <= 0)
            return true;
        const size_t old = m_buffer.size();
        m_buffer.resize(old + size_t(capacity));
        uint8_t *out = reinterpret_cast<uint8_t *>(m_buffer.data() + old);
        const int got = swr_convert(m_swr.get(), &out, capacity, in, n);
        if (got < 0)
            return fail(error, sourceName(), QStringLiteral("cannot resample the audio: %1").arg(avError(got)));
        m_buffer.resize(old + size_t(got));
        return true;
    }

    bool flush(QString *error)
    {
        m_ended = true;
        return convert(nullptr, 0, error);
    }

    AudioSource m_source;
    int m_sourceRate = 0;
    int m_rate = 0;
    InputPtr m_input;
    CodecPtr m_decoder;
    int m_stream = -1;
    PacketPtr m_packet;
    FramePtr m_frame;
    SwrPtr m_swr;
    qsizetype m_memoryPos = 0;
    bool m_draining = false;
    bool m_ended = false;
    qint64 m_silenceBefore = 0;
    qint64 m_skip = 0;
    std::vector<float> m_buffer;
    size_t m_buffered = 0; // samples of m_buffer already read
};

// ---- GIF palette

// One palette for the whole GIF, made by median cut of the colours of the first frame and the
// caller's samples (so flat cartoon colours come out exact), plus a coarse 3x3x3 colour cube
// for colours that appear only later, plus one transparent entry that lets the encoder skip
// unchanged pixels. (FFmpeg's GIF encoder writes every frame whose palette differs from the
// first one whole, so the palette stays fixed.) Pixels map to the nearest entry through a lazily filled
// 6-bit-per-channel table.
class GifPalette
{
public:
    static constexpr int kAdaptive = 228;
    static constexpr int kTransparent = 255;

    // requires: the images are RGB32
    void build(const QVector<QImage> &images)
    {
        struct Bin
        {
            quint32 count = 0;
            quint64 r = 0, g = 0, b = 0;
        };
        std::vector<Bin> bins(1 << 15);
        for (const QImage &rgb32 : images) {
            for (int y = 0; y < rgb32.height(); ++y) {
                const auto *line = reinterpret_cast<const QRgb *>(rgb32.constScanLine(y));
                for (int x = 0; x < rgb32.width(); ++x) {
                    const QRgb c = line[x];
                    Bin &bin = bins[((qRed(c) >> 3) << 10) | ((qGreen(c) >> 3) << 5) | (qBlue(c) >> 3)];
                    ++bin.count;
                    bin.r += qRed(c);
                    bin.g += qGreen(c);
                    bin.b += qBlue(c);
                }
            }
        }
        struct Entry
        {
            int key;
            quint32 count;
            double r, g, b; // the bin's mean colour
        };
        std::vector<Entry> entries;
        for (int k = 0; k < int(bins.size()); ++k) {
            if (bins[k].count)
                entries.push_back({k, bins[k].count, double(bins[k].r) / bins[k].count,
                    double(bins[k].g) / bins[k].count, double(bins[k].b) / bins[k].count});
        }
        // Boxes are ranges of `entries`; the box with the largest squared error is split at the
        // weighted median of its widest channel.
        struct Box
        {
            size_t begin, end;
            double error;
            int axis;
        };
        auto channel = [](const Entry &e, int axis) { return axis == 0 ? e.r : axis == 1 ? e.g : e.b; };
        auto measure = [&](size_t begin, size_t end) {
            Box box {begin, end, 0, 0};
            double best = -1;
            for (int axis = 0; axis < 3; ++axis) {
                double n = 0, s = 0, s2 = 0;
                for (size_t i = begin; i < end; ++i) {
                    const double v = channel(entries[i], axis);
                    n += entries[i].count;
                    s += v * entries[i].count;
                    s2 += v * v * entries[i].count;
                }
                const double sse = s2 - s * s / n;
                box.error += sse;
                if (sse > best) {
                    best = sse;
                    box.axis = axis;
                }
            }
            return box;
        };
        std::vector<Box> boxes;
        if (!entries.empty())
            boxes.push_back(measure(0, entries.size()));
        while (int(boxes.size()) < kAdaptive) {
            auto worst = std::max_element(boxes.begin(), boxes.end(), [](const Box &a, const Box &b) {
                return (a.end - a.begin < 2 ? -1.0 : a.error) < (b.end - b.begin < 2 ? -1.0 : b.error);
            });
            if (worst == boxes.end() || worst->end - worst->begin < 2 || worst->error <= 0)
                break;
            const Box box = *worst;
            std::sort(entries.begin() + qsizetype(box.begin), entries.begin() + qsizetype(box.end),
                [&](const Entry &a, const Entry &b) { return channel(a, box.axis) < channel(b, box.axis); });
            quint64 total = 0;
            for (size_t i = box.begin; i < box.end; ++i)
                total += entries[i].count;
            quint64 run = 0;
            size_t split = box.begin + 1;
            for (size_t i = box.begin; i < box.end - 1; ++i) {
                run += entries[i].count;
                split = i + 1;
                if (2 * run >= total)
                    break;
            }
            *worst = measure(box.begin, split);
            boxes.push_back(measure(split, box.end));
        }
        m_colours.fill(0xff000000);
        int n = 0;
        for (const Box &box : boxes) {
            double cnt = 0, r = 0, g = 0, b = 0;
            for (size_t i = box.begin; i < box.end; ++i) {
                cnt += entries[i].count;
                r += entries[i].r * entries[i].count;
                g += entries[i].g * entries[i].count;
                b += entries[i].b * entries[i].count;
            }
            m_colours[n++] = qRgb(int(std::lround(r / cnt)), int(std::lround(g / cnt)), int(std::lround(b / cnt)));
        }
        for (int r = 0; r < 3; ++r)
            for (int g = 0; g < 3; ++g)
                for (int b = 0; b < 3; ++b)
                    m_colours[n++] = qRgb(std::min(255, r * 128), std::min(255, g * 128), std::min(255, b * 128));
        m_used = n;
        m_colours[kTransparent] = 0x00000000;
        m_lookup.assign(1 << 18, -1);
    }

    const std::array<quint32, 256> &colours() const { return m_colours; }

    // Writes the palette index of each pixel of an RGB32 image.
    void map(const QImage &rgb32, uint8_t *out, int stride)
    {
        for (int y = 0; y < rgb32.height(); ++y) {
            const auto *line = reinterpret_cast<const QRgb *>(rgb32.constScanLine(y));
            uint8_t *o = out + qsizetype(y) * stride;
            for (int x = 0; x < rgb32.width(); ++x) {
                const QRgb c = line[x];
                const int key = ((qRed(c) >> 2) << 12) | ((qGreen(c) >> 2) << 6) | (qBlue(c) >> 2);
                int16_t &idx = m_lookup[size_t(key)];
                if (idx < 0)
                    idx = nearest(c);
                o[x] = uint8_t(idx);
            }
        }
    }

private:
    int16_t nearest(QRgb c) const
    {
        int best = 0;
        int bestDistance = INT_MAX;
        for (int i = 0; i < m_used; ++i) {
            const int dr = qRed(c) - qRed(m_colours[i]);
            const int dg = qGreen(c) - qGreen(m_colours[i]);
            const int db = qBlue(c) - qBlue(m_colours[i]);
            // Weighted toward green, as the eye is.
            const int d = 2 * dr * dr + 4 * dg * dg + 3 * db * db;
            if (d < bestDistance) {
                bestDistance = d;
                best = i;
            }
        }
        return int16_t(best);
    }

    std::array<quint32, 256> m_colours {};
    int m_used = 0;
    std::vector<int16_t> m_lookup;
};

// ---- the sinks

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

// Pads to `size` by repeating the last column and row.
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

    bool addFrame(const QImage &frame, QString *error) override
    {
        if (!m_fmt)
            return fail(error, m_path, QStringLiteral("the writer is closed"));
        return encodeFrame(frame, error);
    }

    bool finish(QString *error) override
    {
        if (!m_fmt)
            return fail(error, m_path, QStringLiteral("the writer is closed"));
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
            return fail(error, m_path, QStringLiteral("cannot write: %1").arg(avError(r)));
        }
        closeAll();
        if (QFileInfo::exists(m_path)) // a replaced file keeps its permissions, as with QSaveFile
            QFile::setPermissions(m_temp, QFile::permissions(m_path));
        std::error_code ec;
        std::filesystem::rename(std::filesystem::path(localPath(m_temp).toStdString()),
            std::filesystem::path(localPath(m_path).toStdString()), ec);
        if (ec) {
            QFile::remove(m_temp);
            return fail(error, m_path, QStringLiteral("cannot write: %1").arg(QString::fromStdString(ec.message())));
        }
        m_temp.clear();
        return true;
    }

    void cancel() override
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

protected:
    // Creates the hidden temporary file and the muxer for `formatName`.
    bool openOutput(const QString &path, const char *formatName, QString *error)
    {
        m_path = path;
        const QFileInfo info(path);
        const QString dir = info.absolutePath();
        if (!QFileInfo(dir).isDir())
            return fail(error, path, QStringLiteral("cannot write: the folder %1 does not exist").arg(dir));
        if (info.isDir())
            return fail(error, path, QStringLiteral("cannot write: it is a folder"));
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
                    QStringLiteral("cannot write in the folder %1: %2")
                        .arg(QDir::toNativeSeparators(dir), temp.errorString()));
        }
        int r = avformat_alloc_output_context2(&m_fmt, nullptr, formatName, localPath(m_temp).constData());
        if (r < 0 || !m_fmt)
            return fail(error, path,
                QStringLiteral("FFmpeg has no %1 muxer: %2").arg(QString::fromLatin1(formatName), avError(r)));
        return true;
    }

    bool startWriting(AVDictionary **options, QString *error)
    {
        int r = avio_open(&m_fmt->pb, localPath(m_temp).constData(), AVIO_FLAG_WRITE);
        if (r < 0)
            return fail(error, m_path, QStringLiteral("cannot write: %1").arg(avError(r)));
        r = avformat_write_header(m_fmt, options);
        av_dict_free(options);
        if (r < 0)
            return fail(error, m_path, QStringLiteral("cannot write the header: %1").arg(avError(r)));
        m_headerWritten = true;
        m_packet.reset(av_packet_alloc());
        return true;
    }

    AVStream *addStream(AVCodecContext *ctx, QString *error)
    {
        AVStream *stream = avformat_new_stream(m_fmt, nullptr);
        if (!stream) {
            fail(error, m_path, QStringLiteral("out of memory"));
            return nullptr;
        }
        stream->time_base = ctx->time_base;
        const int r = avcodec_parameters_from_context(stream->codecpar, ctx);
        if (r < 0) {
            fail(error, m_path, QStringLiteral("cannot set up the stream: %1").arg(avError(r)));
            return nullptr;
        }
        return stream;
    }

    // Sends `frame` (null: flush) to the encoder and writes every packet it gives.
    bool drain(AVCodecContext *ctx, AVStream *stream, AVFrame *frame, QString *error)
    {
        int r = avcodec_send_frame(ctx, frame);
        if (r < 0 && !(frame == nullptr && r == AVERROR_EOF))
            return fail(error, m_path,
                QStringLiteral("cannot encode (%1): %2").arg(QString::fromLatin1(ctx->codec->name), avError(r)));
        while (true) {
            r = avcodec_receive_packet(ctx, m_packet.get());
            if (r == AVERROR(EAGAIN) || r == AVERROR_EOF)
                return true;
            if (r < 0)
                return fail(error, m_path,
                    QStringLiteral("cannot encode (%1): %2").arg(QString::fromLatin1(ctx->codec->name), avError(r)));
            if (m_packet->duration == 0 && ctx->codec_type == AVMEDIA_TYPE_VIDEO)
                m_packet->duration = m_frameDuration;
            av_packet_rescale_ts(m_packet.get(), ctx->time_base, stream->time_base);
            m_packet->stream_index = stream->index;
            r = av_interleaved_write_frame(m_fmt, m_packet.get());
            if (r < 0)
                return fail(error, m_path, QStringLiteral("cannot write: %1").arg(avError(r)));
        }
    }

    virtual bool encodeFrame(const QImage &frame, QString *error) = 0;
    // Flushes everything but the video encoder (which finish() flushes last).
    virtual bool finishStreams(QString *) { return true; }

    void closeAll()
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
            return fail(error, path, QStringLiteral("cannot write MP4: FFmpeg has no H.264 encoder (libx264)"));
        if (size.width() < 2 || size.height() < 2 || size.width() > 8192 || size.height() > 8192)
            return fail(error, path,
                QStringLiteral("unsupported size %1x%2 (MP4 takes 2 to 8192 pixels a side)")
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
                QStringLiteral("cannot start the H.264 encoder at %1x%2: %3")
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
                error, path, QStringLiteral("out of memory for a %1x%2 frame").arg(size.width()).arg(size.height()));
        }
        m_sws.reset(sws_getContext(m_encoded.width(), m_encoded.height(), AV_PIX_FMT_RGB32, m_encoded.width(),
            m_encoded.height(), AV_PIX_FMT_YUV420P, SWS_BILINEAR, nullptr, nullptr, nullptr));
        if (!m_sws) {
            cancel();
            return fail(
                error, path, QStringLiteral("cannot convert %1x%2 RGB to YUV").arg(size.width()).arg(size.height()));
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
            return fail(error, m_path, QStringLiteral("out of memory"));
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
            return fail(error, path, QStringLiteral("cannot write MP4: FFmpeg has no AAC encoder"));
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
            return fail(error, path, QStringLiteral("cannot start the AAC encoder: %1").arg(avError(r)));
        m_audioStream = addStream(a, error);
        if (!m_audioStream)
            return false;
        m_audioFrame.reset(av_frame_alloc());
        m_audioFrame->format = AV_SAMPLE_FMT_FLTP;
        m_audioFrame->sample_rate = rate;
        av_channel_layout_default(&m_audioFrame->ch_layout, 1);
        m_audioFrame->nb_samples = a->frame_size;
        if (av_frame_get_buffer(m_audioFrame.get(), 0) < 0)
            return fail(error, path, QStringLiteral("out of memory"));
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
                return fail(error, m_path, QStringLiteral("out of memory"));
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

class GifSink : public MuxedSink
{
public:
    bool open(const QString &path, QSize size, double fps, const VideoOptions &options, QString *error)
    {
        const AVCodec *gif = avcodec_find_encoder(AV_CODEC_ID_GIF);
        if (!gif)
            return fail(error, path, QStringLiteral("cannot write GIF: FFmpeg has no GIF encoder"));
        if (size.width() < 1 || size.height() < 1 || size.width() > 65535 || size.height() > 65535)
            return fail(error, path,
                QStringLiteral("unsupported size %1x%2 (GIF takes 1 to 65535 pixels a side)")
                    .arg(size.width())
                    .arg(size.height()));
        m_step = std::max(1, int(std::ceil(fps / std::max(1.0, options.gifMaxFps) - 1e-9)));
        m_outFps = fps / m_step;
        m_background = options.background;
        m_paletteSamples = options.paletteSamples;
        m_trailerOnCancel = true;
        if (!openOutput(path, "gif", error))
            return false;
        m_video.reset(avcodec_alloc_context3(gif));
        AVCodecContext *v = m_video.get();
        v->width = size.width();
        v->height = size.height();
        v->pix_fmt = AV_PIX_FMT_PAL8;
        v->time_base = {1, 100}; // GIF delays are in hundredths of a second
        v->framerate = av_d2q(m_outFps, 100000);
        int r = avcodec_open2(v, gif, nullptr);
        if (r < 0) {
            cancel();
            return fail(error, path, QStringLiteral("cannot start the GIF encoder: %1").arg(avError(r)));
        }
        m_videoStream = addStream(v, error);
        if (!m_videoStream) {
            cancel();
            return false;
        }
        m_frame.reset(av_frame_alloc());
        m_frame->format = AV_PIX_FMT_PAL8;
        m_frame->width = size.width();
        m_frame->height = size.height();
        if (av_frame_get_buffer(m_frame.get(), 0) < 0) {
            cancel();
            return fail(
                error, path, QStringLiteral("out of memory for a %1x%2 frame").arg(size.width()).arg(size.height()));
        }
        AVDictionary *opts = nullptr;
        av_dict_set(&opts, "loop", "0", 0);
        if (!startWriting(&opts, error)) {
            cancel();
            return false;
        }
        return true;
    }

    double outputFps() const { return m_outFps; }

protected:
    bool encodeFrame(const QImage &frame, QString *error) override
    {
        const int index = m_input++;
        if (index % m_step != 0)
            return true;
        const QImage rgb = opaqueRgb32(frame, m_background);
        if (m_written == 0) {
            QVector<QImage> images = {rgb};
            for (const QImage &sample : m_paletteSamples)
                images.append(opaqueRgb32(sample, m_background));
            m_palette.build(images);
        }
        if (av_frame_make_writable(m_frame.get()) < 0)
            return fail(error, m_path, QStringLiteral("out of memory"));
        m_palette.map(rgb, m_frame->data[0], m_frame->linesize[0]);
        std::copy(
            m_palette.colours().begin(), m_palette.colours().end(), reinterpret_cast<uint32_t *>(m_frame->data[1]));
        const auto at = [this](int64_t n) { return int64_t(std::llround(double(n) * 100.0 / m_outFps)); };
        m_frame->pts = at(m_written);
        m_frameDuration = at(m_written + 1) - at(m_written);
        ++m_written;
        return drain(m_video.get(), m_videoStream, m_frame.get(), error);
    }

private:
    int m_step = 1;
    double m_outFps = 25;
    QColor m_background;
    GifPalette m_palette;
    QVector<QImage> m_paletteSamples;
    FramePtr m_frame;
    int m_input = 0;
    int64_t m_written = 0;
};

const QRegularExpression &framePattern()
{
    static const QRegularExpression re(QStringLiteral("^frame_(\\d{5,})\\.png$"));
    return re;
}

QString frameName(int number)
{
    return QStringLiteral("frame_%1.png").arg(number, 5, 10, QLatin1Char('0'));
}

class PngSink : public Sink
{
public:
    ~PngSink() override { cancel(); }

    bool open(const QString &folder, QSize size, QString *error)
    {
        if (size.width() < 1 || size.height() < 1 || size.width() > 32768 || size.height() > 32768)
            return fail(error, folder,
                QStringLiteral("unsupported size %1x%2 (PNG frames take 1 to 32768 pixels a side)")
                    .arg(size.width())
                    .arg(size.height()));
        const QFileInfo info(folder);
        if (info.exists() && !info.isDir())
            return fail(error, folder, QStringLiteral("cannot write PNG frames: it is a file, not a folder"));
        if (!QDir().mkpath(folder))
            return fail(error, folder, QStringLiteral("cannot create the folder for PNG frames"));
        m_dir = QDir(folder);
        m_folder = folder;
        return true;
    }

    bool addFrame(const QImage &frame, QString *error) override
    {
        const QString path = m_dir.filePath(frameName(m_count + 1));
        QSaveFile file(path);
        if (!file.open(QIODevice::WriteOnly))
            return fail(
                error, m_folder, QStringLiteral("cannot write %1: %2").arg(frameName(m_count + 1), file.errorString()));
        QImageWriter writer(&file, "png");
        if (!writer.write(frame)) {
            file.cancelWriting();
            return fail(error, m_folder,
                QStringLiteral("cannot write %1: %2").arg(frameName(m_count + 1), writer.errorString()));
        }
        if (!file.commit())
            return fail(
                error, m_folder, QStringLiteral("cannot write %1: %2").arg(frameName(m_count + 1), file.errorString()));
        ++m_count;
        return true;
    }

    bool finish(QString *) override
    {
        const QStringList names = m_dir.entryList({QStringLiteral("frame_*.png")}, QDir::Files);
        for (const QString &name : names) {
            const QRegularExpressionMatch m = framePattern().match(name);
            if (m.hasMatch() && m.captured(1).toLongLong() > m_count)
                m_dir.remove(name);
        }
        m_count = -1; // done: nothing to cancel
        return true;
    }

    void cancel() override
    {
        for (int i = 1; i <= m_count; ++i)
            m_dir.remove(frameName(i));
        m_count = 0;
    }

private:
    QDir m_dir;
    QString m_folder;
    int m_count = 0;
};

} // namespace

// ---- public API

std::optional<VideoFormat> videoFormatForPath(const QString &path)
{
    if (path.endsWith(QLatin1Char('/')) || path.endsWith(QDir::separator()) || QFileInfo(path).isDir())
        return VideoFormat::PngSequence;
    const QString ext = QFileInfo(path).suffix().toLower();
    if (ext == u"mp4")
        return VideoFormat::Mp4;
    if (ext == u"gif")
        return VideoFormat::Gif;
    return std::nullopt;
}

AudioSource AudioSource::fromSamples(QVector<float> samples, int sampleRate, double offset)
{
    AudioSource a;
    a.samples = std::move(samples);
    a.sampleRate = sampleRate;
    a.offset = offset;
    return a;
}

AudioSource AudioSource::fromFile(const QString &path, double offset)
{
    AudioSource a;
    a.path = path;
    a.offset = offset;
    return a;
}

struct VideoWriter::Private
{
    std::unique_ptr<Sink> sink;
    QString path;
    QSize size;
    QSize encoded;
    double fps = 0;
    double outFps = 0;
    int frames = 0;
    bool failed = false;
};

VideoWriter::VideoWriter()
    : d(std::make_unique<Private>())
{ }

VideoWriter::~VideoWriter()
{
    cancel();
}

bool VideoWriter::open(const QString &path, VideoFormat format, QSize size, double fps, const AudioSource &audio,
    QString *error, const VideoOptions &options)
{
    if (d->sink)
        return fail(error, path, QStringLiteral("the writer is already writing %1").arg(d->path));
    quietFfmpegLogs();
    if (!std::isfinite(fps) || fps <= 0 || fps > 240)
        return fail(
            error, path, QStringLiteral("unsupported frame rate %1 (expected more than 0, up to 240)").arg(fps));
    if (size.isEmpty())
        return fail(error, path, QStringLiteral("unsupported size %1x%2").arg(size.width()).arg(size.height()));
    d->path = path;
    d->size = size;
    d->encoded = size;
    d->fps = fps;
    d->outFps = fps;
    d->frames = 0;
    d->failed = false;
    switch (format) {
    case VideoFormat::Mp4: {
        auto sink = std::make_unique<Mp4Sink>();
        if (!sink->open(path, size, fps, audio, options, error))
            return false;
        d->encoded = sink->encodedSize();
        d->sink = std::move(sink);
        break;
    }
    case VideoFormat::Gif: {
        auto sink = std::make_unique<GifSink>();
        if (!sink->open(path, size, fps, options, error))
            return false;
        d->outFps = sink->outputFps();
        d->sink = std::move(sink);
        break;
    }
    case VideoFormat::PngSequence: {
        auto sink = std::make_unique<PngSink>();
        if (!sink->open(path, size, error))
            return false;
        d->sink = std::move(sink);
        break;
    }
    }
    return true;
}

bool VideoWriter::addFrame(const QImage &frame, QString *error)
{
    if (!d->sink)
        return fail(
            error, d->path.isEmpty() ? QStringLiteral("video") : d->path, QStringLiteral("the writer is not open"));
    if (d->failed)
        return fail(error, d->path, QStringLiteral("an earlier frame failed; cancel the writer"));
    if (frame.size() != d->size)
        return fail(error, d->path,
            QStringLiteral("frame %1 is %2x%3, the video is %4x%5")
                .arg(d->frames + 1)
                .arg(frame.width())
                .arg(frame.height())
                .arg(d->size.width())
                .arg(d->size.height()));
    if (!d->sink->addFrame(frame, error)) {
        d->failed = true;
        return false;
    }
    ++d->frames;
    return true;
}

bool VideoWriter::finish(QString *error)
{
    if (!d->sink)
        return fail(
            error, d->path.isEmpty() ? QStringLiteral("video") : d->path, QStringLiteral("the writer is not open"));
    if (d->failed || d->frames == 0) {
        cancel();
        return fail(error, d->path,
            d->failed ? QStringLiteral("an earlier frame failed; nothing was written")
                      : QStringLiteral("no frames to write"));
    }
    const bool ok = d->sink->finish(error);
    if (!ok)
        d->sink->cancel();
    d->sink.reset();
    return ok;
}

void VideoWriter::cancel()
{
    if (d->sink) {
        d->sink->cancel();
        d->sink.reset();
    }
}

bool VideoWriter::isOpen() const
{
    return d->sink != nullptr;
}

int VideoWriter::framesAdded() const
{
    return d->frames;
}

QSize VideoWriter::encodedSize() const
{
    return d->encoded;
}

double VideoWriter::outputFps() const
{
    return d->outFps;
}

bool writeVideo(const QString &path, VideoFormat format, QSize size, double fps, int frameCount,
    const std::function<QImage(int)> &renderFrame, const AudioSource &audio, QString *error,
    const VideoOptions &options, const std::function<void(int, int)> &progress, const std::atomic<bool> *cancel)
{
    VideoWriter writer;
    if (!writer.open(path, format, size, fps, audio, error, options))
        return false;
    for (int i = 0; i < frameCount; ++i) {
        if (cancel && cancel->load()) {
            writer.cancel();
            return fail(error, path, QStringLiteral("cancelled"));
        }
        if (!writer.addFrame(renderFrame(i), error))
            return false;
        if (progress)
            progress(i + 1, frameCount);
    }
    if (cancel && cancel->load()) {
        writer.cancel();
        return fail(error, path, QStringLiteral("cancelled"));
    }
    return writer.finish(error);
}

// ---- probe

namespace {

std::optional<MediaInfo> probePngSequence(const QString &folder, QString *error)
{
    const QDir dir(folder);
    MediaInfo info;
    info.container = QStringLiteral("png sequence");
    info.videoCodec = QStringLiteral("png");
    QString first;
    for (const QString &name : dir.entryList({QStringLiteral("frame_*.png")}, QDir::Files, QDir::Name)) {
        if (!framePattern().match(name).hasMatch())
            continue;
        if (first.isEmpty())
            first = name;
        ++info.frameCount;
    }
    if (info.frameCount == 0) {
        fail(error, folder, QStringLiteral("no frame_NNNNN.png files in the folder"));
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
    AVFormatContext *raw = nullptr;
    int r = avformat_open_input(&raw, localPath(path).constData(), nullptr, nullptr);
    if (r < 0) {
        fail(error, path, QStringLiteral("cannot open: %1").arg(avError(r)));
        return std::nullopt;
    }
    InputPtr input(raw);
    r = avformat_find_stream_info(raw, nullptr);
    if (r < 0) {
        fail(error, path, QStringLiteral("cannot read the streams: %1").arg(avError(r)));
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
        fail(error, path, problem.isEmpty() ? QStringLiteral("no video or audio stream") : problem);
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
            if (isVideo)
                ++info.frameCount;
            else
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

std::optional<QImage> readVideoFrame(const QString &path, int index, QString *error)
{
    quietFfmpegLogs();
    AVFormatContext *raw = nullptr;
    int r = avformat_open_input(&raw, localPath(path).constData(), nullptr, nullptr);
    if (r < 0) {
        fail(error, path, QStringLiteral("cannot open: %1").arg(avError(r)));
        return std::nullopt;
    }
    InputPtr input(raw);
    r = avformat_find_stream_info(raw, nullptr);
    QString problem = QStringLiteral("no video stream");
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
                QImage image(frame->width, frame->height, QImage::Format_RGB32);
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
        fail(error, path, QStringLiteral("has no frame %1 (it has %2)").arg(index).arg(seen));
    return result;
}

std::optional<QVector<float>> readAudio(const QString &path, int sampleRate, QString *error)
{
    quietFfmpegLogs();
    if (sampleRate <= 0) {
        fail(error, path, QStringLiteral("invalid sample rate %1").arg(sampleRate));
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
