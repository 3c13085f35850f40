#include "speech/audio.h"

#include "i18n/coretext.h"
#include "media/userfile.h"
#include "speech/audioconvert.h"
#include "speech/wavfile.h"

#include <QFile>
#include <QFileInfo>
#include <QSaveFile>

extern "C" {
#include <libavutil/opt.h>
}

#include <cmath>
#include <mutex>
#include <vector>

namespace toonface {

namespace {

// Less missing than this (10 ms) is a writer's rounding, not a lost part of the take.
constexpr double kShortestCut = 0.01;

} // namespace

namespace detail {

void quietFfmpegLog()
{
    static std::once_flag once;
    std::call_once(once, [] {
        if (qEnvironmentVariableIsEmpty("TOONFACE_FFMPEG_LOG"))
            av_log_set_level(AV_LOG_FATAL);
    });
}

// Appends everything `swr` gives for `in` (null = flush) as mono floats.
void convertInto(SwrContext *swr, const uint8_t **in, int inCount, int outRate, int inRate, QVector<float> &out)
{
    const int room = int(av_rescale_rnd(swr_get_delay(swr, inRate) + inCount, outRate, inRate, AV_ROUND_UP)) + 32;
    const qsizetype at = out.size();
    out.resize(at + room);
    uint8_t *dst = reinterpret_cast<uint8_t *>(out.data() + at);
    const int got = swr_convert(swr, &dst, room, in, inCount);
    out.resize(at + std::max(got, 0));
}

SwrPtr monoFloatResampler(AVChannelLayout *inLayout, AVSampleFormat inFormat, int inRate, int outRate)
{
    SwrContext *swr = nullptr;
    AVChannelLayout mono = AV_CHANNEL_LAYOUT_MONO;
    if (swr_alloc_set_opts2(&swr, &mono, AV_SAMPLE_FMT_FLT, outRate, inLayout, inFormat, inRate, 0, nullptr) < 0)
        return nullptr;
    SwrPtr p(swr);
    // Channels are averaged (FFmpeg's own downmix adds them at -3 dB each, which clips).
    // SoX's resampler when FFmpeg has it: several times faster than the default engine.
    av_opt_set_int(swr, "resampler", SWR_ENGINE_SOXR, 0);
    const int n = std::max(inLayout->nb_channels, 1);
    std::vector<double> matrix(size_t(n), 1.0 / n);
    if (n > 1 && swr_set_matrix(swr, matrix.data(), n) < 0)
        return nullptr;
    if (swr_init(swr) < 0) {
        av_opt_set_int(swr, "resampler", SWR_ENGINE_SWR, 0);
        if (swr_init(swr) < 0)
            return nullptr;
    }
    return p;
}

void DecodedSound::hand(QVector<float> &out)
{
    // A damaged float file can hold NaN or infinite samples (and the resampler spreads them
    // to their neighbours): they are heard as nothing, so they become silence instead of
    // poisoning every feature computed from them.
    for (float &s : out) {
        if (!std::isfinite(s))
            s = 0;
        peak = std::max(peak, std::abs(s));
    }
    result.sampleCount += out.size();
    if (!out.isEmpty() && sink)
        sink(out.constData(), out.size());
    out.resize(0);
}

AudioResult failed(AudioResult &r, const QString &path, AudioStatus status, const QString &problem)
{
    r.status = status;
    r.error = withProblem(path, problem);
    r.audio = {};
    return r;
}

AudioResult DecodedSound::finish(const QString &path, const SpeechProgressFn &progress)
{
    AudioResult &r = result;
    if (peak < 1e-3f)
        return failed(r, path, AudioStatus::Silent,
            SoundText::tr("it is silent (peak %1 dBFS)").arg(peak > 0 ? 20 * std::log10(peak) : -999.0, 0, 'f', 0));
    r.audio.sampleRate = kSpeechSampleRate;
    r.status = AudioStatus::Ok;
    if (progress)
        progress(1.0, QStringLiteral("decoding"));
    return r;
}

} // namespace detail

namespace {

using namespace detail;

void appendSamples(QVector<float> &to, const float *samples, qsizetype count)
{
    const qsizetype at = to.size();
    to.resize(at + count);
    std::copy(samples, samples + count, to.data() + at);
}

} // namespace

AudioResult streamAudio(
    const QString &path, const AudioSink &sink, const SpeechProgressFn &progress, const std::atomic_bool *cancel)
{
    AudioResult r;
    auto fail = [&](AudioStatus status, const QString &what) { return failed(r, path, status, what); };
    quietFfmpegLog();
    if (const QString problem = irregularFileProblem(path); !problem.isEmpty())
        return fail(AudioStatus::Unreadable, problem);
    if (QFileInfo(path).size() == 0)
        return fail(AudioStatus::Empty, SoundText::tr("the file is empty"));
    // A WAV file holding less than its header promises is damaged (copied or recorded only in
    // part): its sound would be lip-synced as if it were the whole take.
    if (const std::optional<WavExtent> extent = probeWavExtent(QFile::encodeName(path).constData());
        extent && extent->promisedSeconds - extent->heldSeconds >= kShortestCut)
        return fail(AudioStatus::Unreadable,
            SoundText::tr("cut short (its header promises %1 s, it holds %2 s)")
                .arg(extent->promisedSeconds, 0, 'f', 2)
                .arg(extent->heldSeconds, 0, 'f', 2));
    // Plain PCM WAV is read here; everything else by FFmpeg, which gives the same samples.
    if (const std::optional<PlainWav> wav = probePlainWav(path))
        return decodePlainWav(path, *wav, sink, progress, cancel);
    return decodeWithFfmpeg(path, sink, progress, cancel);
}

AudioResult loadAudio(const QString &path, const SpeechProgressFn &progress, const std::atomic_bool *cancel)
{
    QVector<float> samples;
    AudioResult r = streamAudio(
        path, [&](const float *s, qsizetype n) { appendSamples(samples, s, n); }, progress, cancel);
    if (r.ok())
        r.audio.samples = std::move(samples);
    return r;
}

struct AudioResampler::Impl
{
    int inRate, outRate;
    AudioSink sink;
    SwrPtr swr;
    QVector<float> out;
};

AudioResampler::AudioResampler(int inRate, int outRate, AudioSink sink)
    : m_impl(new Impl {inRate, outRate, std::move(sink), nullptr, {}})
{
    if (inRate != outRate && inRate > 0 && outRate > 0) {
        AVChannelLayout mono = AV_CHANNEL_LAYOUT_MONO;
        m_impl->swr = monoFloatResampler(&mono, AV_SAMPLE_FMT_FLT, inRate, outRate);
    }
}

AudioResampler::~AudioResampler() = default;

bool AudioResampler::ok() const
{
    return m_impl->inRate > 0 && m_impl->outRate > 0 && (m_impl->inRate == m_impl->outRate || m_impl->swr);
}

void AudioResampler::push(const float *samples, qsizetype count)
{
    Impl &d = *m_impl;
    if (count <= 0 || !ok())
        return;
    if (!d.swr) {
        d.sink(samples, count);
        return;
    }
    // In chunks: swr_convert sizes (and zeroes) its buffers by the input it is handed.
    constexpr qsizetype kChunk = 1 << 15;
    for (qsizetype at = 0; at < count; at += kChunk) {
        const uint8_t *in = reinterpret_cast<const uint8_t *>(samples + at);
        convertInto(d.swr.get(), &in, int(std::min(kChunk, count - at)), d.outRate, d.inRate, d.out);
        if (!d.out.isEmpty())
            d.sink(d.out.constData(), d.out.size());
        d.out.resize(0);
    }
}

void AudioResampler::finish()
{
    Impl &d = *m_impl;
    if (!d.swr)
        return;
    convertInto(d.swr.get(), nullptr, 0, d.outRate, d.inRate, d.out);
    if (!d.out.isEmpty())
        d.sink(d.out.constData(), d.out.size());
    d.out.resize(0);
}

Audio resampled(const Audio &audio, int rate)
{
    if (audio.sampleRate == rate || audio.isEmpty())
        return Audio {audio.samples, rate};
    Audio out;
    out.sampleRate = rate;
    out.samples.reserve(qsizetype(double(audio.samples.size()) * rate / audio.sampleRate) + 64);
    AudioResampler resampler(
        audio.sampleRate, rate, [&](const float *s, qsizetype n) { appendSamples(out.samples, s, n); });
    if (!resampler.ok())
        return out;
    resampler.push(audio.samples.constData(), audio.samples.size());
    resampler.finish();
    return out;
}

namespace {

// 16-bit PCM WAV written a block at a time: the header's lengths are filled in at finish().
// QSaveFile writes beside the target, so the file appears whole or not at all.
class WavFileWriter final : public AudioFileWriter
{
public:
    WavFileWriter(const QString &path, int sampleRate)
        : m_file(path)
        , m_sampleRate(sampleRate)
    { }

    bool open(QString *error)
    {
        if (m_sampleRate <= 0) {
            *error = withProblem(m_file.fileName(), SoundText::tr("invalid sample rate %1").arg(m_sampleRate));
            return false;
        }
        if (!m_file.open(QIODevice::WriteOnly)) {
            *error = SoundText::tr("cannot write %1: %2").arg(m_file.fileName(), m_file.errorString());
            return false;
        }
        return writeOut(header(0), error);
    }

    bool write(const float *samples, qsizetype count, QString *error) override
    {
        if (!m_file.isOpen()) {
            *error = withProblem(m_file.fileName(), SoundText::tr("the writer is closed"));
            return false;
        }
        // The data chunk's length is 32 bits: at 16 kHz that is 37 hours of sound.
        if (m_dataBytes + 2 * count > kMaxDataBytes) {
            *error = withProblem(m_file.fileName(), SoundText::tr("too long for a WAV file"));
            m_file.cancelWriting();
            return false;
        }
        QByteArray pcm(2 * count, Qt::Uninitialized);
        for (qsizetype i = 0; i < count; ++i) {
            const float s = std::clamp(samples[i], -1.0f, 1.0f);
            const qint16 v = qint16(std::lround(s * 32767.0f));
            pcm[2 * i] = char(v & 0xff);
            pcm[2 * i + 1] = char((v >> 8) & 0xff);
        }
        m_dataBytes += pcm.size();
        return writeOut(pcm, error);
    }

    bool finish(QString *error) override
    {
        if (!m_file.isOpen()) {
            *error = withProblem(m_file.fileName(), SoundText::tr("the writer is closed"));
            return false;
        }
        if (!m_file.seek(0) || !writeOut(header(m_dataBytes), error))
            return false;
        if (!m_file.commit()) {
            *error = SoundText::tr("cannot write %1: %2").arg(m_file.fileName(), writeProblem(m_file));
            return false;
        }
        return true;
    }

private:
    static constexpr qint64 kMaxDataBytes = 0xffffffffLL - 36;

    QByteArray header(qint64 dataBytes) const
    {
        QByteArray h;
        auto u32 = [&](quint32 v) {
            for (int k = 0; k < 4; ++k)
                h.append(char((v >> (8 * k)) & 0xff));
        };
        auto u16 = [&](quint16 v) {
            h.append(char(v & 0xff));
            h.append(char(v >> 8));
        };
        h.append("RIFF");
        u32(quint32(36 + dataBytes));
        h.append("WAVEfmt ");
        u32(16);
        u16(1); // PCM
        u16(1); // mono
        u32(quint32(m_sampleRate));
        u32(quint32(m_sampleRate * 2));
        u16(2);
        u16(16);
        h.append("data");
        u32(quint32(dataBytes));
        return h;
    }

    bool writeOut(const QByteArray &bytes, QString *error)
    {
        if (m_file.write(bytes) == bytes.size())
            return true;
        *error = SoundText::tr("cannot write %1: %2").arg(m_file.fileName(), writeProblem(m_file));
        m_file.cancelWriting();
        return false;
    }

    QSaveFile m_file;
    int m_sampleRate;
    qint64 m_dataBytes = 0;
};

bool isWav(const QString &path)
{
    return QFileInfo(path).suffix().toLower() == QLatin1String("wav");
}

} // namespace

bool writeAudio(const QString &path, const Audio &audio, QString *error)
{
    std::unique_ptr<AudioFileWriter> writer = openAudioFileWriter(path, audio.sampleRate, error);
    return writer && writer->write(audio.samples.constData(), audio.samples.size(), error) && writer->finish(error);
}

std::unique_ptr<AudioFileWriter> openAudioFileWriter(const QString &path, int sampleRate, QString *error)
{
    if (isWav(path)) {
        auto wav = std::make_unique<WavFileWriter>(path, sampleRate);
        return wav->open(error) ? std::move(wav) : nullptr;
    }
    return detail::openFfmpegAudioWriter(path, sampleRate, error);
}

AudioResult copyAudio(
    const QString &source, const QString &target, const SpeechProgressFn &progress, const std::atomic_bool *cancel)
{
    QString error;
    std::unique_ptr<AudioFileWriter> writer = openAudioFileWriter(target, kSpeechSampleRate, &error);
    if (!writer) {
        AudioResult r;
        r.status = AudioStatus::Unwritable;
        r.error = error;
        return r;
    }
    // Decoding stops at the first block the writer refuses, or when *cancel becomes true.
    std::atomic_bool stop = false;
    bool written = true;
    AudioResult r = streamAudio(
        source,
        [&](const float *samples, qsizetype count) {
            if (isCancelled(cancel) || !written || !writer->write(samples, count, &error)) {
                written = written && isCancelled(cancel);
                stop = true;
            }
        },
        progress, &stop);
    if (!written) {
        r.status = AudioStatus::Unwritable;
        r.error = error;
    } else if (r.ok() && !writer->finish(&error)) {
        r.status = AudioStatus::Unwritable;
        r.error = error;
    }
    if (!r.ok()) {
        writer.reset();
        QFile::remove(target);
    }
    return r;
}

} // namespace toonface
