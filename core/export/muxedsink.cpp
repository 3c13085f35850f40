#include "export/videosink.h"

#include "i18n/coretext.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QPainter>

#include <algorithm>
#include <atomic>
#include <filesystem>

namespace toonface::av {

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
