#include "speech/wavfile.h"

#include "i18n/coretext.h"
#include "speech/audioconvert.h"

#include <QFile>

#include <cstring>

namespace toonface {

namespace {

quint32 le32(const char *p)
{
    return quint32(quint8(p[0])) | quint32(quint8(p[1])) << 8 | quint32(quint8(p[2])) << 16
        | quint32(quint8(p[3])) << 24;
}

quint16 le16(const char *p)
{
    return quint16(quint8(p[0]) | quint8(p[1]) << 8);
}

// Bytes FFmpeg's WAV reader hands the decoder at a time: 4096, whole sample frames.
constexpr qint64 kPacketBytes = 4096;

} // namespace

std::optional<PlainWav> probePlainWav(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return std::nullopt;
    const qint64 size = f.size();
    char riff[12];
    if (f.read(riff, 12) != 12 || std::memcmp(riff, "RIFF", 4) != 0 || std::memcmp(riff + 8, "WAVE", 4) != 0)
        return std::nullopt;
    PlainWav w;
    bool haveFormat = false;
    qint64 at = 12;
    // The chunks up to "data": "fmt " first; others (LIST, fact, ...) are skipped.
    while (at + 8 <= size) {
        char head[8];
        if (!f.seek(at) || f.read(head, 8) != 8)
            return std::nullopt;
        const qint64 length = le32(head + 4);
        const qint64 body = at + 8;
        if (std::memcmp(head, "fmt ", 4) == 0) {
            char fmt[16];
            if (haveFormat || length < 16 || f.read(fmt, 16) != 16)
                return std::nullopt;
            const int tag = le16(fmt);
            w.channels = le16(fmt + 2);
            w.sampleRate = int(le32(fmt + 4));
            w.blockAlign = le16(fmt + 12);
            w.bitsPerSample = le16(fmt + 14);
            w.floating = tag == 3;
            const bool integers = tag == 1
                && (w.bitsPerSample == 8 || w.bitsPerSample == 16 || w.bitsPerSample == 24
                    || w.bitsPerSample == 32);
            const bool floats = tag == 3 && w.bitsPerSample == 32;
            if (!(integers || floats) || w.channels < 1 || w.channels > 2 || w.sampleRate < detail::kMinSampleRate
                || w.sampleRate > 384000 || w.blockAlign != w.channels * w.bitsPerSample / 8)
                return std::nullopt;
            haveFormat = true;
        } else if (std::memcmp(head, "data", 4) == 0) {
            // A data chunk of unknown length (0 or 0xffffffff, as written by a stream),
            // running past the end, or ending in a partial sample frame: FFmpeg's business.
            if (!haveFormat || length == 0 || length == 0xffffffffLL || body + length > size
                || length % w.blockAlign != 0)
                return std::nullopt;
            w.dataOffset = body;
            w.dataBytes = length;
            return w;
        }
        at = body + length + (length & 1);
    }
    return std::nullopt;
}

namespace detail {

AudioResult decodePlainWav(const QString &path, const PlainWav &wav, const AudioSink &sink,
    const SpeechProgressFn &progress, const std::atomic_bool *cancel)
{
    AudioResult r;
    auto fail = [&](AudioStatus status, const QString &what) {
        r.status = status;
        r.error = withProblem(path, what);
        r.audio = {};
        return r;
    };
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly) || !f.seek(wav.dataOffset))
        return fail(AudioStatus::Unreadable, SoundText::tr("not a readable sound or video file (%1)").arg(f.errorString()));
    const qint64 fileSize = f.size();
    // The sample formats FFmpeg's PCM decoders give: unsigned 8-bit, signed 16-bit, 24-bit
    // samples widened to 32 bits, signed 32-bit, float.
    const int bytes = wav.bitsPerSample / 8;
    const AVSampleFormat format = wav.floating ? AV_SAMPLE_FMT_FLT
        : bytes == 1                           ? AV_SAMPLE_FMT_U8
        : bytes == 2                           ? AV_SAMPLE_FMT_S16
                                               : AV_SAMPLE_FMT_S32;
    AVChannelLayout layout;
    av_channel_layout_default(&layout, wav.channels);
    SwrPtr swr = monoFloatResampler(&layout, format, wav.sampleRate, kSpeechSampleRate);
    av_channel_layout_uninit(&layout);
    if (!swr)
        return fail(AudioStatus::Unreadable, SoundText::tr("cannot convert its samples"));

    const qint64 packetBytes = std::max<qint64>(kPacketBytes / wav.blockAlign, 1) * wav.blockAlign;
    QByteArray packet;
    std::vector<qint32> widened; // 24-bit samples as 32-bit ones
    QVector<float> out;
    DecodedSound sound {r, sink};
    double lastReport = -1;
    for (qint64 done = 0; done < wav.dataBytes;) {
        if (isCancelled(cancel))
            return fail(AudioStatus::Cancelled, QStringLiteral("cancelled"));
        const qint64 want = std::min(packetBytes, wav.dataBytes - done);
        packet = f.read(want);
        if (packet.size() != want)
            return fail(AudioStatus::Unreadable, SoundText::tr("its sound track cannot be decoded (corrupt data)"));
        done += want;
        const int frames = int(want / wav.blockAlign);
        const uint8_t *in = reinterpret_cast<const uint8_t *>(packet.constData());
        if (bytes == 3) {
            widened.resize(size_t(frames) * size_t(wav.channels));
            for (size_t i = 0; i < widened.size(); ++i) {
                const char *p = packet.constData() + 3 * i;
                widened[i] = qint32(quint32(quint8(p[0])) << 8 | quint32(quint8(p[1])) << 16
                    | quint32(quint8(p[2])) << 24);
            }
            in = reinterpret_cast<const uint8_t *>(widened.data());
        }
        convertInto(swr.get(), &in, frames, kSpeechSampleRate, wav.sampleRate, out);
        sound.hand(out);
        r.sourceDuration += double(frames) / wav.sampleRate;
        if (progress && fileSize > 0) {
            const double fraction = double(wav.dataOffset + done) / double(fileSize);
            if (fraction - lastReport >= 0.05) {
                progress(std::min(fraction, 1.0), QStringLiteral("decoding"));
                lastReport = fraction;
            }
        }
    }
    convertInto(swr.get(), nullptr, 0, kSpeechSampleRate, wav.sampleRate, out);
    sound.hand(out);
    if (r.sampleCount == 0)
        return fail(AudioStatus::Empty, SoundText::tr("it holds no sound"));
    return sound.finish(path, progress);
}

} // namespace detail

} // namespace toonface
