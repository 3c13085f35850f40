#include "i18n/coretext.h"
#include "media/ffmpegutil.h"
#include "speech/audioconvert.h"

#include <QFile>
#include <QFileInfo>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/channel_layout.h>
#include <libavutil/opt.h>
#include <libswresample/swresample.h>
}

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>

// FFmpeg's decoding and encoding of sound: the only part of core/speech that uses FFmpeg's
// formats and codecs. Nothing else may go into this file: the light toonface-cli replaces
// it (app/cli/nomediacodecs.cpp) and so never loads libavcodec or libavformat.
namespace toonface::detail {

namespace {

using av::avError;

// No speech codec a recording is made with spends fewer bytes on a second of sound (Opus's
// lowest speech rate is 750 bytes a second, AMR's 600, PCM thousands): a file decoding to more
// seconds than its size allows at this rate (plus a little for headers and silence) is damaged
// or made to blow up, and is refused before it is decoded whole.
constexpr double kMinBytesPerSecond = 100;
constexpr double kFreeSeconds = 30;

struct FormatOutputDeleter
{
    void operator()(AVFormatContext *c) const
    {
        if (c->pb && !(c->oformat->flags & AVFMT_NOFILE))
            avio_closep(&c->pb);
        avformat_free_context(c);
    }
};

} // namespace

AudioResult decodeWithFfmpeg(
    const QString &path, const AudioSink &sink, const SpeechProgressFn &progress, const std::atomic_bool *cancel)
{
    AudioResult r;
    auto fail = [&](AudioStatus status, const QString &what) { return failed(r, path, status, what); };
    AVFormatContext *rawFmt = nullptr;
    const QByteArray local = QFile::encodeName(path);
    int rc = avformat_open_input(&rawFmt, local.constData(), nullptr, nullptr);
    if (rc < 0)
        return fail(AudioStatus::Unreadable, SoundText::tr("not a readable sound or video file (%1)").arg(avError(rc)));
    av::InputPtr fmt(rawFmt);
    // A WAV file's PCM is probed for other codecs packed inside it, by default over its first
    // 5 MB (a tenth of the work of aligning a minute of speech); its first 64 kB tell as much.
    if (fmt->iformat && std::strcmp(fmt->iformat->name, "wav") == 0)
        fmt->probesize = 1 << 16;
    if ((rc = avformat_find_stream_info(fmt.get(), nullptr)) < 0)
        return fail(AudioStatus::Unreadable, SoundText::tr("cannot read its streams (%1)").arg(avError(rc)));
    const AVCodec *codec = nullptr;
    const int stream = av_find_best_stream(fmt.get(), AVMEDIA_TYPE_AUDIO, -1, -1, &codec, 0);
    if (stream < 0 || !codec)
        return fail(AudioStatus::Unreadable,
            stream == AVERROR_DECODER_NOT_FOUND ? SoundText::tr("no decoder for its sound track")
                                                : SoundText::tr("it has no sound track"));
    av::CodecPtr dec(avcodec_alloc_context3(codec));
    if (!dec || avcodec_parameters_to_context(dec.get(), fmt->streams[stream]->codecpar) < 0
        || avcodec_open2(dec.get(), codec, nullptr) < 0)
        return fail(
            AudioStatus::Unreadable, SoundText::tr("cannot open the %1 decoder").arg(QString::fromUtf8(codec->name)));

    if (dec->ch_layout.order == AV_CHANNEL_ORDER_UNSPEC) {
        const int n = dec->ch_layout.nb_channels > 0 ? dec->ch_layout.nb_channels : 1;
        av_channel_layout_uninit(&dec->ch_layout);
        av_channel_layout_default(&dec->ch_layout, n);
    }
    SwrPtr swr;
    int swrRate = 0;
    AVSampleFormat swrFormat = AV_SAMPLE_FMT_NONE;

    av::PacketPtr packet(av_packet_alloc());
    av::FramePtr frame(av_frame_alloc());
    const int64_t fileSize = fmt->pb ? avio_size(fmt->pb) : -1;
    // Each conversion lands here and goes on to the sink at once.
    QVector<float> out;
    DecodedSound sound {r, sink};
    auto hand = [&] { sound.hand(out); };
    int badPackets = 0;
    int64_t decodedFrames = 0;
    double lastReport = -1;

    const double plausibleSeconds
        = fileSize > 0 ? kFreeSeconds + double(fileSize) / kMinBytesPerSecond : std::numeric_limits<double>::infinity();
    QString refusal; // why drain() stopped, when it did
    auto drain = [&]() -> bool {
        while (avcodec_receive_frame(dec.get(), frame.get()) >= 0) {
            if (frame->sample_rate < kMinSampleRate) {
                refusal = SoundText::tr("its sample rate (%1 Hz) is too low for speech (at least %2 Hz)")
                              .arg(frame->sample_rate)
                              .arg(kMinSampleRate);
                return false;
            }
            if (!swr || frame->sample_rate != swrRate || frame->format != swrFormat) {
                if (swr) {
                    convertInto(swr.get(), nullptr, 0, kSpeechSampleRate, swrRate, out);
                    hand();
                }
                AVChannelLayout layout;
                if (frame->ch_layout.nb_channels > 0 && frame->ch_layout.order != AV_CHANNEL_ORDER_UNSPEC)
                    av_channel_layout_copy(&layout, &frame->ch_layout);
                else
                    av_channel_layout_default(&layout, std::max(frame->ch_layout.nb_channels, 1));
                swrRate = frame->sample_rate;
                swrFormat = AVSampleFormat(frame->format);
                swr = monoFloatResampler(&layout, swrFormat, swrRate, kSpeechSampleRate);
                av_channel_layout_uninit(&layout);
                if (!swr) {
                    refusal = SoundText::tr("cannot convert its samples");
                    return false;
                }
            }
            convertInto(swr.get(), const_cast<const uint8_t **>(frame->extended_data), frame->nb_samples,
                kSpeechSampleRate, swrRate, out);
            hand();
            r.sourceDuration += double(frame->nb_samples) / std::max(frame->sample_rate, 1);
            ++decodedFrames;
            av_frame_unref(frame.get());
            if (r.sourceDuration > plausibleSeconds) {
                refusal = SoundText::tr("it is damaged: it decodes to more than %1 s of sound, more than its %2 bytes "
                                        "can hold")
                              .arg(int(plausibleSeconds))
                              .arg(fileSize);
                return false;
            }
        }
        return true;
    };

    while ((rc = av_read_frame(fmt.get(), packet.get())) >= 0) {
        if (isCancelled(cancel))
            return fail(AudioStatus::Cancelled, QStringLiteral("cancelled"));
        if (packet->stream_index == stream) {
            if (avcodec_send_packet(dec.get(), packet.get()) < 0)
                ++badPackets;
            if (!drain())
                return fail(AudioStatus::Unreadable, refusal);
        }
        av_packet_unref(packet.get());
        if (progress && fileSize > 0) {
            const double f = double(avio_tell(fmt->pb)) / double(fileSize);
            if (f - lastReport >= 0.05) {
                progress(std::min(f, 1.0), QStringLiteral("decoding"));
                lastReport = f;
            }
        }
    }
    avcodec_send_packet(dec.get(), nullptr);
    if (!drain())
        return fail(AudioStatus::Unreadable, refusal);
    if (swr) {
        convertInto(swr.get(), nullptr, 0, kSpeechSampleRate, swrRate, out);
        hand();
    }

    if (r.sampleCount == 0) {
        if (badPackets > 0 || decodedFrames == 0)
            return fail(decodedFrames == 0 && badPackets == 0 ? AudioStatus::Empty : AudioStatus::Unreadable,
                badPackets > 0 ? SoundText::tr("its sound track cannot be decoded (corrupt data)")
                               : SoundText::tr("it holds no sound"));
        return fail(AudioStatus::Empty, SoundText::tr("it holds no sound"));
    }
    return sound.finish(path, progress);
}

bool encodeWithFfmpeg(const QString &path, const Audio &audio, QString *error)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    quietFfmpegLog();
    auto fail = [&](const QString &what) {
        *error = SoundText::tr("cannot write %1: %2").arg(path, what);
        return false;
    };
    const AVCodec *codec = nullptr;
    if (suffix == QLatin1String("flac"))
        codec = avcodec_find_encoder(AV_CODEC_ID_FLAC);
    else if (suffix == QLatin1String("mp3"))
        codec = avcodec_find_encoder(AV_CODEC_ID_MP3);
    else if (suffix == QLatin1String("ogg"))
        codec = avcodec_find_encoder_by_name("libvorbis");
    else if (suffix == QLatin1String("opus"))
        codec = avcodec_find_encoder_by_name("libopus");
    else if (suffix == QLatin1String("m4a") || suffix == QLatin1String("aac"))
        codec = avcodec_find_encoder(AV_CODEC_ID_AAC);
    else
        return fail(SoundText::tr("unknown sound format '.%1' (use wav, flac, mp3, ogg, opus or m4a)").arg(suffix));
    if (!codec)
        return fail(SoundText::tr("this FFmpeg has no encoder for .%1").arg(suffix));

    const QByteArray local = QFile::encodeName(path);
    AVFormatContext *rawOut = nullptr;
    if (avformat_alloc_output_context2(&rawOut, nullptr, nullptr, local.constData()) < 0 || !rawOut)
        return fail(SoundText::tr("no container for .%1").arg(suffix));
    std::unique_ptr<AVFormatContext, FormatOutputDeleter> oc(rawOut);
    av::CodecPtr enc(avcodec_alloc_context3(codec));
    enc->sample_fmt = codec->sample_fmts ? codec->sample_fmts[0] : AV_SAMPLE_FMT_FLTP;
    int rate = audio.sampleRate;
    if (codec->supported_samplerates) {
        int best = 0;
        for (const int *r = codec->supported_samplerates; *r; ++r) {
            if (best == 0 || (std::abs(*r - rate) < std::abs(best - rate)) || (*r >= rate && best < rate))
                best = *r;
        }
        rate = best;
    }
    enc->sample_rate = rate;
    AVChannelLayout mono = AV_CHANNEL_LAYOUT_MONO;
    av_channel_layout_copy(&enc->ch_layout, &mono);
    enc->time_base = AVRational {1, rate};
    if (suffix != QLatin1String("flac"))
        enc->bit_rate = 64000;
    if (oc->oformat->flags & AVFMT_GLOBALHEADER)
        enc->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    int rc = avcodec_open2(enc.get(), codec, nullptr);
    if (rc < 0)
        return fail(SoundText::tr("cannot open the %1 encoder (%2)").arg(QString::fromUtf8(codec->name), avError(rc)));
    AVStream *st = avformat_new_stream(oc.get(), nullptr);
    if (!st || avcodec_parameters_from_context(st->codecpar, enc.get()) < 0)
        return fail(SoundText::tr("cannot add a sound stream"));
    st->time_base = enc->time_base;
    if (!(oc->oformat->flags & AVFMT_NOFILE) && (rc = avio_open(&oc->pb, local.constData(), AVIO_FLAG_WRITE)) < 0)
        return fail(avError(rc));
    if ((rc = avformat_write_header(oc.get(), nullptr)) < 0)
        return fail(avError(rc));

    // All samples in the encoder's format and rate at once (mono: planar = packed).
    SwrContext *rawSwr = nullptr;
    if (swr_alloc_set_opts2(
            &rawSwr, &mono, enc->sample_fmt, rate, &mono, AV_SAMPLE_FMT_FLT, audio.sampleRate, 0, nullptr)
            < 0
        || swr_init(rawSwr) < 0) {
        swr_free(&rawSwr);
        return fail(SoundText::tr("cannot convert the samples"));
    }
    SwrPtr swr(rawSwr);
    const int bytesPerSample = av_get_bytes_per_sample(enc->sample_fmt);
    const int capacity = int(av_rescale_rnd(audio.samples.size(), rate, audio.sampleRate, AV_ROUND_UP)) + 256;
    QByteArray converted(qsizetype(capacity) * bytesPerSample, Qt::Uninitialized);
    uint8_t *dst = reinterpret_cast<uint8_t *>(converted.data());
    const uint8_t *src = reinterpret_cast<const uint8_t *>(audio.samples.constData());
    int total = swr_convert(swr.get(), &dst, capacity, &src, int(audio.samples.size()));
    if (total >= 0) {
        uint8_t *tail = dst + qsizetype(total) * bytesPerSample;
        const int more = swr_convert(swr.get(), &tail, capacity - total, nullptr, 0);
        total += std::max(more, 0);
    }
    if (total < 0)
        return fail(SoundText::tr("cannot convert the samples"));

    av::FramePtr frame(av_frame_alloc());
    av::PacketPtr pkt(av_packet_alloc());
    const int frameSize = enc->frame_size > 0 ? enc->frame_size : 1024;
    auto writePackets = [&]() -> bool {
        while (avcodec_receive_packet(enc.get(), pkt.get()) >= 0) {
            av_packet_rescale_ts(pkt.get(), enc->time_base, st->time_base);
            pkt->stream_index = st->index;
            if (av_interleaved_write_frame(oc.get(), pkt.get()) < 0)
                return false;
        }
        return true;
    };
    for (int at = 0; at < total; at += frameSize) {
        const int n = std::min(frameSize, total - at);
        av_frame_unref(frame.get());
        // Encoders with a fixed frame size want full frames: the last one is padded with silence
        // unless the encoder takes a short last frame (then the file keeps its exact length).
        const int frameSamples
            = (codec->capabilities & (AV_CODEC_CAP_VARIABLE_FRAME_SIZE | AV_CODEC_CAP_SMALL_LAST_FRAME)) ? n
                                                                                                         : frameSize;
        frame->nb_samples = frameSamples;
        frame->format = enc->sample_fmt;
        frame->sample_rate = rate;
        av_channel_layout_copy(&frame->ch_layout, &mono);
        if (av_frame_get_buffer(frame.get(), 0) < 0)
            return fail(SoundText::tr("out of memory"));
        memset(frame->data[0], 0, size_t(frameSamples) * size_t(bytesPerSample));
        memcpy(
            frame->data[0], converted.constData() + qsizetype(at) * bytesPerSample, size_t(n) * size_t(bytesPerSample));
        frame->pts = at;
        if (avcodec_send_frame(enc.get(), frame.get()) < 0 || !writePackets())
            return fail(SoundText::tr("encoding failed"));
    }
    avcodec_send_frame(enc.get(), nullptr);
    if (!writePackets() || av_write_trailer(oc.get()) < 0)
        return fail(SoundText::tr("encoding failed"));
    return true;
}

} // namespace toonface::detail
