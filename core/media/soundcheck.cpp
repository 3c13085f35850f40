#include "media/soundcheck.h"

#include "i18n/coretext.h"
#include "media/ffmpegutil.h"
#include "media/userfile.h"

#include <algorithm>

namespace toonface {

using namespace av;

namespace {

// Packets read at each sampled place before giving up on a frame: a decoder that needs a few
// packets to start (AAC's priming, an MP3's bit reservoir) has them, and a stretch of damage
// is not read to its end.
constexpr int kPacketsPerPlace = 48;

enum class Sample { Decoded, Ended, Failed };

// Reads packets from where the input stands until one frame of `stream` decodes.
Sample decodeOne(AVFormatContext *input, AVCodecContext *decoder, int stream, QString *problem)
{
    PacketPtr packet(av_packet_alloc());
    FramePtr frame(av_frame_alloc());
    int lastError = 0;
    for (int read = 0; read < kPacketsPerPlace;) {
        const int r = av_read_frame(input, packet.get());
        if (r < 0) {
            if (r != AVERROR_EOF) {
                *problem = avError(r);
                return Sample::Failed;
            }
            // The decoder's last frames, held back for look-ahead.
            avcodec_send_packet(decoder, nullptr);
            const bool got = avcodec_receive_frame(decoder, frame.get()) >= 0;
            if (!got && lastError < 0)
                *problem = avError(lastError);
            return got ? Sample::Decoded : lastError < 0 ? Sample::Failed : Sample::Ended;
        }
        if (packet->stream_index == stream) {
            ++read;
            const int sent = avcodec_send_packet(decoder, packet.get());
            if (sent < 0 && sent != AVERROR(EAGAIN))
                lastError = sent;
            if (avcodec_receive_frame(decoder, frame.get()) >= 0 && frame->nb_samples > 0)
                return Sample::Decoded;
        }
        av_packet_unref(packet.get());
    }
    *problem = lastError < 0 ? avError(lastError) : SoundText::tr("no samples in %1 packets").arg(kPacketsPerPlace);
    return Sample::Failed;
}

} // namespace

SoundCheck checkSound(const QString &path)
{
    quietFfmpegLogs();
    SoundCheck check;
    if (const QString problem = irregularFileProblem(path); !problem.isEmpty()) {
        check.error = withProblem(path, problem);
        return check;
    }
    AVFormatContext *raw = nullptr;
    int r = avformat_open_input(&raw, localPath(path).constData(), nullptr, nullptr);
    if (r < 0) {
        // The same words as when the sound is read in full (audioffmpeg.cpp): a text, a key or an
        // image named as the sound is no sound file at all.
        check.error = withProblem(path, SoundText::tr("not a readable sound or video file (%1)").arg(avError(r)));
        return check;
    }
    InputPtr input(raw);
    r = avformat_find_stream_info(raw, nullptr);
    if (r < 0) {
        check.error = withProblem(path, SoundText::tr("cannot read the audio: %1").arg(avError(r)));
        return check;
    }
    int stream = -1;
    QString problem;
    CodecPtr decoder = openDecoder(raw, AVMEDIA_TYPE_AUDIO, &stream, &problem);
    if (!decoder) {
        // A file with no audio stream at all holds no sound; one whose stream has no decoder says why.
        check.error = withProblem(path,
            av_find_best_stream(raw, AVMEDIA_TYPE_AUDIO, -1, -1, nullptr, 0) < 0
                ? SoundText::tr("holds no sound")
                : SoundText::tr("cannot read the audio: %1").arg(problem));
        return check;
    }
    const AVStream *s = raw->streams[stream];
    check.sampleRate = decoder->sample_rate;
    check.channels = decoder->ch_layout.nb_channels;
    check.codec = QString::fromLatin1(avcodec_get_name(s->codecpar->codec_id));
    if (s->duration != AV_NOPTS_VALUE && s->duration > 0)
        check.seconds = double(s->duration) * av_q2d(s->time_base);
    else if (raw->duration != AV_NOPTS_VALUE && raw->duration > 0)
        check.seconds = double(raw->duration) / AV_TIME_BASE;

    // The start, then the middle and near the end: a file whose sound stops decoding part way
    // (a broken download, another file's bytes) shows it at one of them.
    for (const double at : {0.0, 0.5, 0.95}) {
        if (at > 0) {
            if (check.seconds <= 0)
                break;
            const int64_t target = int64_t(at * check.seconds / av_q2d(s->time_base))
                + (s->start_time != AV_NOPTS_VALUE ? s->start_time : 0);
            // A container that cannot seek is checked at its start only.
            if (av_seek_frame(raw, stream, target, AVSEEK_FLAG_BACKWARD) < 0)
                break;
            avcodec_flush_buffers(decoder.get());
        }
        const Sample sample = decodeOne(raw, decoder.get(), stream, &problem);
        if (sample == Sample::Decoded)
            continue;
        if (at == 0.0 || sample == Sample::Failed)
            check.error = withProblem(path,
                sample == Sample::Ended ? SoundText::tr("holds no sound")
                                        : SoundText::tr("the sound does not decode at %1 s: %2")
                                              .arg(at * check.seconds, 0, 'f', 1)
                                              .arg(problem));
        if (!check.ok())
            return check;
        // The header promised more than the file holds past here: the decoder that reads it all
        // finds the end (mediaDamage() says whether it was cut short).
        break;
    }
    return check;
}

} // namespace toonface
