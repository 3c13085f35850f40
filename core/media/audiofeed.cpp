#include "media/audiofeed.h"

#include "i18n/coretext.h"
#include "media/userfile.h"

#include <algorithm>

namespace toonface {

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

namespace av {

bool AudioFeed::open(const AudioSource &source, QString *error)
{
    m_source = source;
    if (!source.path.isEmpty()) {
        // Never handed to FFmpeg: a folder, a device or a pipe (a FIFO would block the open).
        if (const QString problem = irregularFileProblem(source.path); !problem.isEmpty())
            return fail(error, source.path, problem);
        AVFormatContext *raw = nullptr;
        int r = avformat_open_input(&raw, localPath(source.path).constData(), nullptr, nullptr);
        if (r < 0)
            return fail(error, source.path, SoundText::tr("cannot read the audio: %1").arg(avError(r)));
        m_input.reset(raw);
        r = avformat_find_stream_info(raw, nullptr);
        if (r < 0)
            return fail(error, source.path, SoundText::tr("cannot read the audio: %1").arg(avError(r)));
        QString problem = SoundText::tr("no audio stream");
        m_decoder = openDecoder(raw, AVMEDIA_TYPE_AUDIO, &m_stream, &problem);
        if (!m_decoder)
            return fail(error, source.path, SoundText::tr("cannot read the audio: %1").arg(problem));
        m_sourceRate = m_decoder->sample_rate;
        m_packet.reset(av_packet_alloc());
        m_frame.reset(av_frame_alloc());
    } else {
        if (source.sampleRate <= 0)
            return fail(
                error, SoundText::tr("audio samples"), SoundText::tr("invalid sample rate %1").arg(source.sampleRate));
        m_sourceRate = source.sampleRate;
    }
    if (m_sourceRate <= 0)
        return fail(error, source.path, SoundText::tr("the audio has no sample rate"));
    return true;
}

bool AudioFeed::readAll(QVector<float> *out, QString *error)
{
    out->clear();
    QVector<float> block;
    while (true) {
        if (!readBlock(&block, error))
            return false;
        if (block.isEmpty())
            return true;
        out->append(block);
    }
}

bool AudioFeed::readBlock(QVector<float> *out, QString *error)
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
        if (!out->isEmpty() || m_ended)
            return true;
        if (!decodeMore(error))
            return false;
    }
}

double AudioFeed::fractionRead() const
{
    if (!m_input || !m_input->pb)
        return 0;
    const int64_t size = avio_size(m_input->pb);
    return size > 0 ? std::clamp(double(avio_tell(m_input->pb)) / double(size), 0.0, 1.0) : 0.0;
}

bool AudioFeed::start(int rate, QString *error)
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
    int r = swr_alloc_set_opts2(&raw, &mono, AV_SAMPLE_FMT_FLT, rate, &inLayout, inFormat, m_sourceRate, 0, nullptr);
    av_channel_layout_uninit(&inLayout);
    m_swr.reset(raw);
    if (r >= 0)
        r = swr_init(raw);
    if (r < 0)
        return fail(error, sourceName(), SoundText::tr("cannot resample the audio: %1").arg(avError(r)));
    // A positive offset is silence first; a negative one skips the source's beginning.
    const qint64 shift = qint64(std::llround(m_source.offset * rate));
    m_silenceBefore = std::max<qint64>(0, shift);
    m_skip = std::max<qint64>(0, -shift);
    return true;
}

bool AudioFeed::read(float *dst, int n, QString *error)
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

bool AudioFeed::decodeMore(QString *error)
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
            const bool ok = convert(const_cast<const uint8_t **>(m_frame->extended_data), m_frame->nb_samples, error);
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
            return fail(error, m_source.path, SoundText::tr("cannot decode the audio: %1").arg(avError(r)));
        if (m_draining) // the decoder said EAGAIN after a flush: nothing more will come
            return flush(error);
        r = av_read_frame(m_input.get(), m_packet.get());
        if (r == AVERROR_EOF) {
            m_draining = true;
            avcodec_send_packet(m_decoder.get(), nullptr);
            continue;
        }
        if (r < 0)
            return fail(error, m_source.path, SoundText::tr("cannot read the audio: %1").arg(avError(r)));
        if (m_packet->stream_index == m_stream) {
            r = avcodec_send_packet(m_decoder.get(), m_packet.get());
            // A damaged packet is skipped, as players do.
            if (r < 0 && r != AVERROR(EAGAIN) && r != AVERROR_INVALIDDATA) {
                av_packet_unref(m_packet.get());
                return fail(error, m_source.path, SoundText::tr("cannot decode the audio: %1").arg(avError(r)));
            }
        }
        av_packet_unref(m_packet.get());
    }
}

bool AudioFeed::convert(const uint8_t **in, int n, QString *error)
{
    const int capacity = swr_get_out_samples(m_swr.get(), n);
    if (capacity <= 0)
        return true;
    const size_t old = m_buffer.size();
    m_buffer.resize(old + size_t(capacity));
    uint8_t *out = reinterpret_cast<uint8_t *>(m_buffer.data() + old);
    const int got = swr_convert(m_swr.get(), &out, capacity, in, n);
    if (got < 0)
        return fail(error, sourceName(), SoundText::tr("cannot resample the audio: %1").arg(avError(got)));
    m_buffer.resize(old + size_t(got));
    return true;
}

bool AudioFeed::flush(QString *error)
{
    m_ended = true;
    return convert(nullptr, 0, error);
}

} // namespace av

} // namespace toonface
