#include "export/videoencoder.h"

#include "export/videosink.h"
#include "i18n/coretext.h"

#include <QDir>
#include <QFileInfo>

#include <cmath>

namespace toonface {

using namespace av;

std::optional<VideoFormat> videoFormatForPath(const QString &path)
{
    if (path.endsWith(QLatin1Char('/')) || path.endsWith(QDir::separator()) || QFileInfo(path).isDir())
        return VideoFormat::PngSequence;
    const QString ext = QFileInfo(path).suffix().toLower();
    if (ext == u"mp4")
        return VideoFormat::Mp4;
    if (ext == u"gif")
        return VideoFormat::Gif;
    if (ext == u"webm")
        return VideoFormat::WebM;
    if (ext == u"mov")
        return VideoFormat::Mov;
    if (ext == u"apng")
        return VideoFormat::Apng;
    if (ext == u"webp")
        return VideoFormat::WebP;
    return std::nullopt;
}

bool videoFormatHasAlpha(VideoFormat format)
{
    return format != VideoFormat::Mp4 && format != VideoFormat::Gif;
}

bool videoFormatHasSound(VideoFormat format)
{
    return format == VideoFormat::Mp4 || format == VideoFormat::WebM || format == VideoFormat::Mov;
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
        return fail(error, path, ExportText::tr("the writer is already writing %1").arg(d->path));
    quietFfmpegLogs();
    if (!std::isfinite(fps) || fps <= 0 || fps > 240)
        return fail(
            error, path, ExportText::tr("unsupported frame rate %1 (expected more than 0, up to 240)").arg(fps));
    if (size.isEmpty())
        return fail(error, path, ExportText::tr("unsupported size %1x%2").arg(size.width()).arg(size.height()));
    d->path = path;
    d->size = size;
    d->encoded = size;
    d->fps = fps;
    d->outFps = fps;
    d->frames = 0;
    d->failed = false;
    switch (format) {
    case VideoFormat::Mp4: d->sink = openMp4Sink(path, size, fps, audio, options, &d->encoded, error); break;
    case VideoFormat::Gif: d->sink = openGifSink(path, size, fps, options, &d->outFps, error); break;
    case VideoFormat::PngSequence: d->sink = openPngSink(path, size, error); break;
    case VideoFormat::WebM:
    case VideoFormat::Mov:
    case VideoFormat::Apng:
    case VideoFormat::WebP: d->sink = openAlphaSink(path, format, size, fps, audio, options, &d->encoded, error); break;
    }
    return d->sink != nullptr;
}

bool VideoWriter::addFrame(const QImage &frame, QString *error)
{
    if (!d->sink)
        return fail(
            error, d->path.isEmpty() ? QStringLiteral("video") : d->path, ExportText::tr("the writer is not open"));
    if (d->failed)
        return fail(error, d->path, ExportText::tr("an earlier frame failed; cancel the writer"));
    if (frame.size() != d->size)
        return fail(error, d->path,
            ExportText::tr("frame %1 is %2x%3, the video is %4x%5")
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
            error, d->path.isEmpty() ? QStringLiteral("video") : d->path, ExportText::tr("the writer is not open"));
    if (d->failed || d->frames == 0) {
        cancel();
        return fail(error, d->path,
            d->failed ? ExportText::tr("an earlier frame failed; nothing was written")
                      : ExportText::tr("no frames to write"));
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

} // namespace toonface
