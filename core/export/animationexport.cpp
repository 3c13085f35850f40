#include "export/animationexport.h"

#include "export/framerenderer.h"
#include "export/htmlplayer.h"
#include "export/keptframes.h"
#include "export/partfiles.h"
#include "export/smilexport.h"
#include "export/videoencoder.h"
#include "face/pose.h"
#include "i18n/coretext.h"
#include "io/project.h"
#include "media/audiomix.h"
#include "media/audiosource.h"
#include "media/mediareader.h"
#include "media/pngframes.h"
#include "media/soundcheck.h"
#include "media/userfile.h"
#include "render/svgface.h"
#include "speech/progress.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QSaveFile>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace toonface {

namespace {

constexpr int kMinSize = 16;
constexpr int kMaxSize = 4096;
constexpr double kMaxFps = 120;

VideoFormat videoFormatOf(AnimationFormat format)
{
    switch (format) {
    case AnimationFormat::Mp4: return VideoFormat::Mp4;
    case AnimationFormat::Gif: return VideoFormat::Gif;
    case AnimationFormat::WebM: return VideoFormat::WebM;
    case AnimationFormat::Mov: return VideoFormat::Mov;
    case AnimationFormat::Apng: return VideoFormat::Apng;
    case AnimationFormat::WebP: return VideoFormat::WebP;
    case AnimationFormat::SmilSvg:
    case AnimationFormat::HtmlPlayer:
    case AnimationFormat::PngSequence: break;
    }
    return VideoFormat::PngSequence;
}

ExportResult result(ExportStatus status, const QString &file, const QString &problem)
{
    return {status, withProblem(QDir::toNativeSeparators(file), problem)};
}

// Reports rising fractions of the whole export: [from, to] of it for one stage.
class Progress
{
public:
    explicit Progress(const std::function<void(double)> &report)
        : m_report(report)
    { }
    void stage(double from, double to)
    {
        m_from = from;
        m_to = to;
    }
    // The whole export is done.
    void finish()
    {
        stage(1.0, 1.0);
        (*this)(1.0);
    }
    void operator()(double fraction)
    {
        const double at = m_from + (m_to - m_from) * std::clamp(fraction, 0.0, 1.0);
        if (m_report && at > m_last) {
            m_last = at;
            m_report(at);
        }
    }

private:
    const std::function<void(double)> &m_report;
    double m_from = 0;
    double m_to = 1;
    double m_last = -1;
};

// The request's timeline at the request's frame rate.
Timeline exportTimeline(const ExportRequest &request)
{
    Timeline timeline = request.timeline;
    if (request.fps > 0)
        timeline.setFrameRate(request.fps);
    return timeline;
}

// The files the export's sound comes from: the request's, else every clip's.
QStringList soundPaths(const ExportRequest &request)
{
    if (!request.audioPath.isEmpty())
        return {request.audioPath};
    QStringList paths;
    for (const AudioClip &clip : soundingClips(request.timeline.audioClips()))
        paths << clip.path;
    return paths;
}

// The sound of an MP4: the request's file from the start, else the timeline's clips mixed.
std::optional<AudioSource> videoSound(
    const ExportRequest &request, const Timeline &timeline, QString *error, const std::atomic_bool *cancel)
{
    if (!request.audioPath.isEmpty())
        return AudioSource::fromFile(request.audioPath);
    if (soundingClips(timeline.audioClips()).isEmpty())
        return AudioSource {};
    std::optional<MixedSound> mix = mixAudioClips(timeline.audioClips(), 0, error, cancel);
    if (!mix)
        return std::nullopt;
    if (mix->samples.isEmpty())
        return AudioSource {};
    return AudioSource::fromSamples(std::move(mix->samples), mix->sampleRate, mix->start);
}

// What makes the request impossible before anything is drawn: the status and message, or
// nullopt when it is valid. Reads the layers into `face`.
std::optional<ExportResult> checkRequest(const ExportRequest &request, SvgFace *face)
{
    const QString out = request.outputPath;
    if (out.isEmpty())
        return ExportResult {ExportStatus::BadInput, ExportText::tr("no output file given")};
    if (request.size != 0 && (request.size < kMinSize || request.size > kMaxSize))
        return result(ExportStatus::BadInput, out,
            ExportText::tr("unsupported size %1 (from %2 to %3 pixels)").arg(request.size).arg(kMinSize).arg(kMaxSize));
    if (!std::isfinite(request.fps) || request.fps < 0 || request.fps > kMaxFps)
        return result(ExportStatus::BadInput, out,
            ExportText::tr("unsupported frame rate %1 (more than 0, up to %2)").arg(request.fps).arg(kMaxFps));
    if (const QString problem = backgroundProblem(request.format, request.background); !problem.isEmpty())
        return result(ExportStatus::BadInput, out, problem);
    if (!std::isfinite(request.start) || !std::isfinite(request.duration) || request.start < 0 || request.duration < 0)
        return result(ExportStatus::BadInput, out,
            ExportText::tr("the start (%1 s) and duration (%2 s) must be 0 or more")
                .arg(request.start)
                .arg(request.duration));
    if ((request.start > 0 || request.duration > 0) && !isRasterFormat(request.format))
        return result(ExportStatus::BadInput, out,
            ExportText::tr("SVG and HTML play the whole animation; a start or duration needs a video or picture "
                           "format"));
    const Timeline whole = exportTimeline(request);
    const double length = std::max(1, whole.frameCount()) / (whole.frameRate() > 0 ? whole.frameRate() : 25.0);
    if (request.start > 0 && request.start >= length)
        return result(ExportStatus::BadInput, out,
            ExportText::tr("the start (%1 s) is past the end of the animation (%2 s)")
                .arg(request.start, 0, 'f', 2)
                .arg(length, 0, 'f', 2));
    for (const QString &layer : request.layerFiles) {
        QString error;
        if (!face->addLayerFile(layer, &error))
            return ExportResult {ExportStatus::BadInput, error};
    }
    const bool silent = request.silent || !animationFormatHasSound(request.format);
    for (const QString &sound : silent ? QStringList() : soundPaths(request)) {
        // The sound must be a regular file that decodes as sound: nothing else reaches a file
        // the user hands on (a shared project may name any file as its sound).
        if (const QString problem = irregularFileProblem(sound); !problem.isEmpty())
            return result(ExportStatus::BadInput, sound, problem);
        // Its header and a few sampled packets: an hour of sound is not decoded twice.
        if (const SoundCheck check = checkSound(sound); !check.ok())
            return ExportResult {ExportStatus::BadInput, check.error};
    }
    const QFileInfo target(QDir::cleanPath(out));
    if (!target.absoluteDir().exists())
        return result(ExportStatus::Failed, out,
            ExportText::tr("cannot write: the folder %1 does not exist")
                .arg(QDir::toNativeSeparators(target.absolutePath())));
    if (request.format == AnimationFormat::PngSequence ? target.exists() && !target.isDir() : target.isDir())
        return result(ExportStatus::Failed, out,
            request.format == AnimationFormat::PngSequence
                ? ExportText::tr("cannot write PNG frames: it is a file, not a folder")
                : ExportText::tr("cannot write: it is a folder"));
    return std::nullopt;
}

ExportResult exportDocument(const ExportRequest &request, const SvgFace &face, const Timeline &timeline,
    Progress &progress, const std::atomic_bool *cancel)
{
    const QString out = request.outputPath;
    AnimationExportOptions options;
    options.audio = ExportAudio::Embed;
    options.audioPath = request.audioPath;
    options.layerFiles = request.layerFiles;
    options.frame = face.frame();
    options.cancel = cancel;
    progress.stage(0, 0.95);
    options.progress = [&progress](double f) { progress(f); };
    QString error;
    const QByteArray data = request.format == AnimationFormat::SmilSvg
        ? exportSmilSvg(request.face, request.style, timeline, request.mouthShapes, options, &error)
        : exportHtmlPlayer(request.face, request.style, timeline, request.mouthShapes, options, &error);
    if (isCancelled(cancel))
        return result(ExportStatus::Cancelled, out, QStringLiteral("cancelled"));
    if (data.isEmpty())
        return result(ExportStatus::Failed, out, error);
    // QSaveFile writes beside the target and renames at commit(); it removes its temporary file
    // when it is not committed.
    QSaveFile file(out);
    if (!file.open(QIODevice::WriteOnly) || file.write(data) != data.size())
        return result(ExportStatus::Failed, out, ExportText::tr("cannot write: %1").arg(writeProblem(file)));
    if (isCancelled(cancel)) {
        file.cancelWriting();
        return result(ExportStatus::Cancelled, out, QStringLiteral("cancelled"));
    }
    if (!file.commit())
        return result(ExportStatus::Failed, out, ExportText::tr("cannot write: %1").arg(writeProblem(file)));
    progress.finish();
    return {ExportStatus::Done, {}};
}

// A hidden folder beside `target` that a PNG sequence is written into, removed with its
// content unless released.
class TemporaryFolder
{
public:
    explicit TemporaryFolder(const QString &target)
    {
        const QFileInfo info(QDir::cleanPath(target));
        static std::atomic<int> serial = 0;
        for (int attempt = 0; attempt < 100 && m_path.isEmpty(); ++attempt) {
            const QString name = QStringLiteral("%1/.%2.%3-%4.part")
                                     .arg(info.absolutePath(), info.fileName())
                                     .arg(QCoreApplication::applicationPid())
                                     .arg(serial++);
            if (!QFileInfo::exists(name) && QDir().mkdir(name))
                m_path = name;
        }
    }
    ~TemporaryFolder()
    {
        if (!m_path.isEmpty())
            QDir(m_path).removeRecursively();
    }
    TemporaryFolder(const TemporaryFolder &) = delete;
    TemporaryFolder &operator=(const TemporaryFolder &) = delete;

    const QString &path() const { return m_path; }
    void release() { m_path.clear(); }

private:
    QString m_path;
};

// Moves the frames of `from` (a finished sequence) to the folder `to`: the folder itself when
// `to` does not exist; otherwise each frame over its namesake, and frames of an earlier, longer
// sequence removed.
bool placeFrames(TemporaryFolder &from, const QString &to, QString *problem)
{
    const QString target = QDir::cleanPath(QFileInfo(to).absoluteFilePath());
    std::error_code ec;
    if (!QFileInfo::exists(target)) {
        std::filesystem::rename(
            QFile::encodeName(from.path()).toStdString(), QFile::encodeName(target).toStdString(), ec);
        if (ec) {
            *problem = ExportText::tr("cannot write: %1").arg(QString::fromStdString(ec.message()));
            return false;
        }
        from.release();
        return true;
    }
    const QDir source(from.path());
    const QDir dir(target);
    const QStringList names = source.entryList({QStringLiteral("frame_*.png")}, QDir::Files, QDir::Name);
    for (const QString &name : names) {
        std::filesystem::rename(QFile::encodeName(source.filePath(name)).toStdString(),
            QFile::encodeName(dir.filePath(name)).toStdString(), ec);
        if (ec) {
            *problem = ExportText::tr("cannot write %1: %2").arg(name, QString::fromStdString(ec.message()));
            return false;
        }
    }
    const QStringList old = dir.entryList({QStringLiteral("frame_*.png")}, QDir::Files);
    for (const QString &name : old) {
        const QRegularExpressionMatch m = pngFramePattern().match(name);
        if (m.hasMatch() && m.captured(1).toLongLong() > names.size())
            QFile::remove(dir.filePath(name));
    }
    return true;
}

ExportResult exportFrames(const ExportRequest &request, const SvgFace &face, const Timeline &timeline,
    Progress &progress, const std::atomic_bool *cancel)
{
    const QString out = request.outputPath;
    const QSize size = exportFrameSize(request);
    const VideoFormat format = videoFormatOf(request.format);
    const ExportBackground background = effectiveBackground(request);
    QColor drawnBackground = Qt::transparent;
    QImage backdrop;
    if (background.kind == ExportBackground::Kind::Colour)
        drawnBackground = background.colour;
    if (background.kind == ExportBackground::Kind::Photo) {
        QString error;
        backdrop = backgroundPicture(background.photoPath, size, &error);
        if (backdrop.isNull())
            return {ExportStatus::BadInput, error};
    }
    const FrameRenderer renderer(face, timeline, request.mouthShapes, size, drawnBackground, backdrop);
    const int first = std::min(renderer.frameCount() - 1, int(std::lround(request.start * renderer.frameRate())));
    const int count = exportFrameCount(request);

    AudioSource audio;
    if (videoFormatHasSound(format) && !request.silent) {
        QString problem;
        std::optional<AudioSource> sound = videoSound(request, timeline, &problem, cancel);
        if (isCancelled(cancel))
            return result(ExportStatus::Cancelled, out, QStringLiteral("cancelled"));
        if (!sound)
            return ExportResult {ExportStatus::BadInput, problem};
        audio = std::move(*sound);
        audio.offset -= first / renderer.frameRate(); // the export starts at frame `first`
    }
    VideoOptions options;
    // A GIF is transparent only when asked; under a photo its frames are opaque.
    options.background
        = background.kind == ExportBackground::Kind::Transparent ? QColor(Qt::transparent) : QColor(Qt::white);
    options.keepAlpha = background.kind == ExportBackground::Kind::Transparent;
    if (request.vp9Crf >= 0)
        options.vp9Crf = request.vp9Crf;
    if (format == VideoFormat::Gif) {
        // The palette must know the open mouth and shut eyes, which frame 0 may not show.
        Pose open = mouthPose(face.face(), request.mouthShapes, MouthShape::A);
        open.leftEyeOpen = open.rightEyeOpen = 0;
        options.paletteSamples << rasterizeSvg(face.svg(open), size, drawnBackground);
    }
    std::optional<TemporaryFolder> folder;
    QString path = out;
    if (format == VideoFormat::PngSequence) {
        folder.emplace(out);
        if (folder->path().isEmpty())
            return result(ExportStatus::Failed, out,
                ExportText::tr("cannot write: cannot create a folder in %1")
                    .arg(QDir::toNativeSeparators(QFileInfo(QDir::cleanPath(out)).absolutePath())));
        path = folder->path();
    }
    // Messages about the temporary folder name the target.
    const auto named = [&](const QString &error) {
        QString e = error;
        return folder ? e.replace(QDir::toNativeSeparators(path), QDir::toNativeSeparators(out)) : e;
    };

    QString error;
    VideoWriter writer;
    if (!writer.open(path, format, size, renderer.frameRate(), audio, &error, options))
        return {ExportStatus::Failed, named(error)};
    progress.stage(0, 0.98);
    FrameRenderOptions frameOptions;
    frameOptions.first = first;
    frameOptions.count = count;
    frameOptions.cancel = cancel;
    frameOptions.progress = [&](int delivered, int total) { progress(total > 0 ? double(delivered) / total : 1.0); };
    // The frames come from those an earlier try drew, or are drawn (and kept for the next try).
    KeptFrames *kept = request.keptFrames.get();
    int drawn = 0;
    bool rendered = true;
    if (kept && kept->holds(size, first, count)) {
        for (int i = 0; i < count && rendered; ++i) {
            rendered = !isCancelled(cancel) && writer.addFrame(kept->frame(i), &error);
            progress(double(i + 1) / count);
        }
    } else {
        if (kept)
            kept->restart(size, first, count);
        rendered = renderFrames(
            renderer,
            [&](int, const QImage &image) {
                ++drawn;
                if (kept)
                    kept->add(image);
                return writer.addFrame(image, &error);
            },
            frameOptions);
    }
    if (isCancelled(cancel)) {
        writer.cancel();
        return result(ExportStatus::Cancelled, out, QStringLiteral("cancelled"));
    }
    if (!rendered) {
        writer.cancel();
        return error.isEmpty() ? result(ExportStatus::Failed, out, ExportText::tr("rendering stopped"))
                               : ExportResult {ExportStatus::Failed, named(error)};
    }
    if (!writer.finish(&error))
        return {ExportStatus::Failed, named(error)};
    if (folder) {
        QString problem;
        if (!placeFrames(*folder, out, &problem))
            return result(ExportStatus::Failed, out, problem);
    }
    progress.finish();
    return {ExportStatus::Done, {}, drawn, 1};
}

} // namespace

QString animationFormatSuffix(AnimationFormat format)
{
    switch (format) {
    case AnimationFormat::SmilSvg: return QStringLiteral("svg");
    case AnimationFormat::HtmlPlayer: return QStringLiteral("html");
    case AnimationFormat::Mp4: return QStringLiteral("mp4");
    case AnimationFormat::Gif: return QStringLiteral("gif");
    case AnimationFormat::WebM: return QStringLiteral("webm");
    case AnimationFormat::Mov: return QStringLiteral("mov");
    case AnimationFormat::Apng: return QStringLiteral("apng");
    case AnimationFormat::WebP: return QStringLiteral("webp");
    case AnimationFormat::PngSequence: break;
    }
    return {};
}

std::optional<AnimationFormat> animationFormatForPath(const QString &path)
{
    if (path.endsWith(QLatin1Char('/')) || path.endsWith(QDir::separator()))
        return AnimationFormat::PngSequence;
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == u"htm")
        return AnimationFormat::HtmlPlayer;
    for (AnimationFormat format : kAllAnimationFormats) {
        if (!suffix.isEmpty() && suffix == animationFormatSuffix(format))
            return format;
    }
    return std::nullopt;
}

bool isRasterFormat(AnimationFormat format)
{
    return format != AnimationFormat::SmilSvg && format != AnimationFormat::HtmlPlayer;
}

bool animationFormatHasAlpha(AnimationFormat format)
{
    return isRasterFormat(format) && videoFormatHasAlpha(videoFormatOf(format));
}

bool animationFormatCanBeTransparent(AnimationFormat format)
{
    return format != AnimationFormat::Mp4;
}

bool animationFormatHasSound(AnimationFormat format)
{
    return !isRasterFormat(format) || videoFormatHasSound(videoFormatOf(format));
}

QString backgroundProblem(AnimationFormat format, const ExportBackground &background)
{
    const ExportBackground::Kind kind = background.kind;
    if (kind == ExportBackground::Kind::Transparent && !animationFormatCanBeTransparent(format))
        return ExportText::tr("MP4 cannot be transparent: choose WebM, MOV, WebP, APNG, GIF or PNG frames, or a "
                              "background colour or photo");
    if (!isRasterFormat(format) && (kind == ExportBackground::Kind::Colour || kind == ExportBackground::Kind::Photo))
        return ExportText::tr("SVG and HTML are drawn without a background; a background colour or photo needs a "
                              "video or picture format");
    if (kind == ExportBackground::Kind::Colour && !background.colour.isValid())
        return ExportText::tr("the background colour is not valid");
    return {};
}

ExportBackground effectiveBackground(const ExportRequest &request)
{
    if (request.background.kind != ExportBackground::Kind::Automatic)
        return request.background;
    if (!isRasterFormat(request.format) || animationFormatHasAlpha(request.format))
        return ExportBackground::transparent();
    return ExportBackground::ofColour(Qt::white);
}

ExportRequest exportRequestFor(const Project &project)
{
    ExportRequest r;
    r.face = project.face;
    r.style = project.style;
    r.timeline = project.timeline;
    r.mouthShapes = project.mouthShapes;
    r.layerFiles = project.layerPaths;
    return r;
}

QRectF exportFrame(const ExportRequest &request)
{
    SvgFace face(request.face, request.style);
    face.setFrame(request.framing == ExportFraming::Head ? headFrame(request.face) : QRectF());
    return face.frame();
}

QSize exportFrameSize(const ExportRequest &request)
{
    const QSizeF frame = exportFrame(request).size();
    const QSizeF base = frame.isEmpty() ? QSizeF(512, 512) : frame;
    // Automatic: the frame's own size, kept within 512-1280 pixels (the drawing is vector: a
    // small head is drawn larger, not blurred).
    const double side
        = request.size > 0 ? double(request.size) : std::clamp(std::max(base.width(), base.height()), 512.0, 1280.0);
    const QSize s = base.scaled(side, side, Qt::KeepAspectRatio).toSize();
    // Even, as encoders want.
    return QSize(std::max(2, s.width() & ~1), std::max(2, s.height() & ~1));
}

int exportFrameCount(const ExportRequest &request)
{
    const Timeline timeline = exportTimeline(request);
    const int all = std::max(1, timeline.frameCount());
    if (!isRasterFormat(request.format))
        return all;
    const double fps = timeline.frameRate() > 0 ? timeline.frameRate() : 25.0;
    const int first = std::clamp(int(std::lround(request.start * fps)), 0, all - 1);
    // Never longer than asked (a preset's limit is a maximum).
    const int wanted = request.duration > 0 ? std::max(1, int(std::floor(request.duration * fps + 1e-6))) : all;
    return std::min(wanted, all - first);
}

double exportDuration(const ExportRequest &request)
{
    const Timeline timeline = exportTimeline(request);
    return exportFrameCount(request) / (timeline.frameRate() > 0 ? timeline.frameRate() : 25.0);
}

ExportResult exportAnimation(
    const ExportRequest &request, const std::function<void(double)> &report, const std::atomic_bool *cancel)
{
    SvgFace face(request.face, request.style);
    face.setFrame(request.framing == ExportFraming::Head ? headFrame(request.face) : QRectF());
    if (std::optional<ExportResult> invalid = checkRequest(request, &face))
        return *invalid;
    if (isCancelled(cancel))
        return result(ExportStatus::Cancelled, request.outputPath, QStringLiteral("cancelled"));
    removeStaleParts(request.outputPath);
    Progress progress(report);
    progress(0.0);
    const Timeline timeline = exportTimeline(request);
    if (isRasterFormat(request.format))
        return exportFrames(request, face, timeline, progress, cancel);
    return exportDocument(request, face, timeline, progress, cancel);
}

} // namespace toonface
