#include "speech/wavfile.h"

#include "i18n/coretext.h"
#include "speech/audioconvert.h"

#include <QFile>

#include <algorithm>
#include <cstdint>

namespace toonface {

namespace {

// Bytes FFmpeg's WAV reader hands the decoder at a time: 4096, whole sample frames.
constexpr std::int64_t kPacketBytes = 4096;

} // namespace

std::optional<PlainWav> probePlainWav(const QString &path)
{
    return probePlainWav(QFile::encodeName(path).constData());
}

namespace detail {

AudioResult decodePlainWav(const QString &path, const PlainWav &wav, const AudioSink &sink,
    const SpeechProgressFn &progress, const std::atomic_bool *cancel)
{
    AudioResult r;
    auto fail = [&](AudioStatus status, const QString &what) { return failed(r, path, status, what); };
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly) || !f.seek(wav.dataOffset))
        return fail(
            AudioStatus::Unreadable, SoundText::tr("not a readable sound or video file (%1)").arg(f.errorString()));
    const std::int64_t fileSize = f.size();
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

    const std::int64_t packetBytes = std::max<std::int64_t>(kPacketBytes / wav.blockAlign, 1) * wav.blockAlign;
    QByteArray packet;
    std::vector<qint32> widened; // 24-bit samples as 32-bit ones
    QVector<float> out;
    DecodedSound sound {r, sink};
    double lastReport = -1;
    for (std::int64_t done = 0; done < wav.dataBytes;) {
        if (isCancelled(cancel))
            return fail(AudioStatus::Cancelled, QStringLiteral("cancelled"));
        const std::int64_t want = std::min(packetBytes, wav.dataBytes - done);
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
                widened[i]
                    = qint32(quint32(quint8(p[0])) << 8 | quint32(quint8(p[1])) << 16 | quint32(quint8(p[2])) << 24);
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
