#include "export/videosink.h"

#include "i18n/coretext.h"

#include <QFile>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace toonface::av {

namespace {

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

    // requires: the images are RGB32, or ARGB32 whose pixels less than half opaque are left out
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
                    if (qAlpha(c) < 128)
                        continue;
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

    // Writes the palette index of each pixel of an RGB32 image, or of an ARGB32 one whose
    // pixels less than half opaque take the transparent entry.
    void map(const QImage &rgb32, uint8_t *out, int stride)
    {
        for (int y = 0; y < rgb32.height(); ++y) {
            const auto *line = reinterpret_cast<const QRgb *>(rgb32.constScanLine(y));
            uint8_t *o = out + qsizetype(y) * stride;
            for (int x = 0; x < rgb32.width(); ++x) {
                const QRgb c = line[x];
                if (qAlpha(c) < 128) {
                    o[x] = kTransparent;
                    continue;
                }
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

// Sets the disposal method of every graphic control extension of the GIF in `data`, walking
// its blocks; false when it is not a GIF as the encoder writes them.
bool setGifDisposal(QByteArray *data, int disposal)
{
    const auto at = [data](qsizetype i) { return i < data->size() ? uint8_t(data->at(i)) : uint8_t(0); };
    if (!data->startsWith("GIF89a") || data->size() < 13)
        return false;
    qsizetype i = 13;
    if (at(10) & 0x80) // global colour table
        i += 3 * (qsizetype(1) << ((at(10) & 7) + 1));
    // Skips data sub-blocks from i to just past their terminator.
    const auto skipSubBlocks = [&](qsizetype j) {
        while (j < data->size() && at(j) != 0)
            j += at(j) + 1;
        return j + 1;
    };
    while (i < data->size()) {
        const uint8_t kind = at(i);
        if (kind == 0x3b) // trailer
            return true;
        if (kind == 0x21) { // extension
            if (at(i + 1) == 0xf9 && at(i + 2) == 4)
                (*data)[i + 3] = char((at(i + 3) & ~0x1c) | (disposal << 2));
            i = skipSubBlocks(i + 2);
        } else if (kind == 0x2c) { // image: descriptor, local colour table, LZW size, data
            qsizetype j = i + 10;
            if (at(i + 9) & 0x80)
                j += 3 * (qsizetype(1) << ((at(i + 9) & 7) + 1));
            i = skipSubBlocks(j + 1);
        } else {
            return false;
        }
    }
    return false;
}

class GifSink : public MuxedSink
{
public:
    bool open(const QString &path, QSize size, double fps, const VideoOptions &options, QString *error)
    {
        const AVCodec *gif = avcodec_find_encoder(AV_CODEC_ID_GIF);
        if (!gif)
            return fail(error, path, ExportText::tr("cannot write GIF: FFmpeg has no GIF encoder"));
        if (size.width() < 1 || size.height() < 1 || size.width() > 65535 || size.height() > 65535)
            return fail(error, path,
                ExportText::tr("unsupported size %1x%2 (GIF takes 1 to 65535 pixels a side)")
                    .arg(size.width())
                    .arg(size.height()));
        m_step = std::max(1, int(std::ceil(fps / std::max(1.0, options.gifMaxFps) - 1e-9)));
        m_outFps = fps / m_step;
        m_background = options.background;
        m_transparent = options.background.alpha() == 0;
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
        AVDictionary *codecOptions = nullptr;
        // Transparent frames are written whole: the encoder's cropping and its marking of
        // unchanged pixels as transparent assume each frame is drawn over the last one.
        if (m_transparent)
            av_dict_set(&codecOptions, "gifflags", "0", 0);
        int r = avcodec_open2(v, gif, &codecOptions);
        av_dict_free(&codecOptions);
        if (r < 0) {
            cancel();
            return fail(error, path, ExportText::tr("cannot start the GIF encoder: %1").arg(avError(r)));
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
                error, path, ExportText::tr("out of memory for a %1x%2 frame").arg(size.width()).arg(size.height()));
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
        const QImage rgb = pixelsOf(frame);
        if (m_written == 0) {
            QVector<QImage> images = {rgb};
            for (const QImage &sample : m_paletteSamples)
                images.append(pixelsOf(sample));
            m_palette.build(images);
        }
        if (av_frame_make_writable(m_frame.get()) < 0)
            return fail(error, m_path, ExportText::tr("out of memory"));
        m_palette.map(rgb, m_frame->data[0], m_frame->linesize[0]);
        std::copy(
            m_palette.colours().begin(), m_palette.colours().end(), reinterpret_cast<uint32_t *>(m_frame->data[1]));
        const auto at = [this](int64_t n) { return int64_t(std::llround(double(n) * 100.0 / m_outFps)); };
        m_frame->pts = at(m_written);
        m_frameDuration = at(m_written + 1) - at(m_written);
        ++m_written;
        return drain(m_video.get(), m_videoStream, m_frame.get(), error);
    }

    // FFmpeg's GIF muxer leaves each frame in place under the next ("do not dispose"), so
    // pixels that turn transparent would keep showing the last frame: a transparent GIF's frames
    // are disposed of ("restore to background", clearing to transparent) instead.
    bool finishFile(const QString &temp, QString *error) override
    {
        if (!m_transparent)
            return true;
        QFile file(temp);
        if (!file.open(QIODevice::ReadWrite))
            return fail(error, m_path, ExportText::tr("cannot write: %1").arg(file.errorString()));
        QByteArray data = file.readAll();
        if (!setGifDisposal(&data, 2))
            return fail(error, m_path, ExportText::tr("cannot write: the GIF encoder wrote an unexpected file"));
        if (!file.seek(0) || file.write(data) != data.size() || !file.flush())
            return fail(error, m_path, ExportText::tr("cannot write: %1").arg(file.errorString()));
        return true;
    }

private:
    // RGB32 over the background, or straight ARGB32 for a transparent GIF.
    QImage pixelsOf(const QImage &frame) const
    {
        return m_transparent ? frame.convertToFormat(QImage::Format_ARGB32) : opaqueRgb32(frame, m_background);
    }

    int m_step = 1;
    double m_outFps = 25;
    bool m_transparent = false;
    QColor m_background;
    GifPalette m_palette;
    QVector<QImage> m_paletteSamples;
    int m_input = 0;
    int64_t m_written = 0;
};

} // namespace

std::unique_ptr<Sink> openGifSink(
    const QString &path, QSize size, double fps, const VideoOptions &options, double *outputFps, QString *error)
{
    auto sink = std::make_unique<GifSink>();
    if (!sink->open(path, size, fps, options, error))
        return nullptr;
    *outputFps = sink->outputFps();
    return sink;
}

} // namespace toonface::av
