#include "export/exportpreset.h"

#include "export/keptframes.h"
#include "i18n/coretext.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace toonface {

namespace {

// VP9's crf: the first try, and the last (its lowest quality).
constexpr int kFirstCrf = 30;
constexpr int kLastCrf = 63;

QString kilobytes(qint64 bytes)
{
    return QString::number(double(bytes) / 1024.0, 'f', bytes < 10 * 1024 ? 1 : 0);
}

QString seconds(double s)
{
    return QString::number(s, 'f', 2).remove(QRegularExpression(QStringLiteral("\\.?0+$")));
}

// A hidden name beside `target` for one try, in the pattern removeStaleParts() knows.
QString attemptPath(const QString &target, int attempt)
{
    const QFileInfo info(QDir::cleanPath(target));
    return QStringLiteral("%1/.%2.%3-%4.part")
        .arg(info.absolutePath(), info.fileName())
        .arg(QCoreApplication::applicationPid())
        .arg(900000 + attempt);
}

} // namespace

const QVector<ExportPreset> &exportPresets()
{
    static const QVector<ExportPreset> presets = {
        {QStringLiteral("telegram-sticker"), AnimationFormat::WebM, 512, 3.0, 256 * 1024, 30, false},
        {QStringLiteral("emoji"), AnimationFormat::WebM, 100, 3.0, 64 * 1024, 30, false},
        {QStringLiteral("slide-overlay"), AnimationFormat::WebM, 1080, 0, 0, 0, true},
    };
    return presets;
}

std::optional<ExportPreset> exportPresetNamed(const QString &name)
{
    for (const ExportPreset &p : exportPresets()) {
        if (p.name == name)
            return p;
    }
    return std::nullopt;
}

QStringList exportPresetNames()
{
    QStringList names;
    for (const ExportPreset &p : exportPresets())
        names << p.name;
    return names;
}

ExportRequest withPreset(ExportRequest request, const ExportPreset &preset)
{
    request.format = preset.format;
    request.size = preset.side;
    request.framing = ExportFraming::Head;
    const double timelineFps = request.fps > 0 ? request.fps : request.timeline.frameRate();
    if (preset.maxFps > 0 && (timelineFps <= 0 || timelineFps > preset.maxFps))
        request.fps = preset.maxFps;
    if (!preset.sound)
        request.silent = true;
    if (request.background.kind == ExportBackground::Kind::Automatic)
        request.background = ExportBackground::transparent();
    return request;
}

QString presetProblem(const ExportRequest &request, const ExportPreset &preset)
{
    const std::optional<AnimationFormat> byName = animationFormatForPath(request.outputPath);
    if (byName && *byName != preset.format)
        return ExportText::tr("the %1 preset writes %2: name the output .%3")
            .arg(preset.name, animationFormatSuffix(preset.format).toUpper(), animationFormatSuffix(preset.format));
    if (preset.maxSeconds > 0) {
        const double length = exportDuration(request);
        // Half a frame of slack: a 3 s clip at 25 fps is 75 frames.
        const double fps = request.fps > 0 ? request.fps : request.timeline.frameRate();
        if (length > preset.maxSeconds + 0.5 / std::max(1.0, fps))
            return ExportText::tr("the clip is %1 s long, the %2 preset allows %3 s (%4 s too long): export a "
                                  "stretch of at most %3 s")
                .arg(seconds(length), preset.name, seconds(preset.maxSeconds), seconds(length - preset.maxSeconds));
    }
    return {};
}

ExportResult exportWithPreset(const ExportRequest &base, const ExportPreset &preset,
    const std::function<void(double)> &progress, const std::atomic_bool *cancel)
{
    ExportRequest request = withPreset(base, preset);
    const QString out = request.outputPath;
    if (out.isEmpty())
        return {ExportStatus::BadInput, ExportText::tr("no output file given")};
    if (const QString problem = presetProblem(request, preset); !problem.isEmpty())
        return {ExportStatus::OverLimit, withProblem(QDir::toNativeSeparators(out), problem)};
    if (preset.maxBytes <= 0)
        return exportAnimation(request, progress, cancel);

    // Each try is written under a hidden name and measured; the one that fits replaces the target.
    // The frames are drawn once, by the first try, and kept: later tries only encode them again.
    int crf = request.vp9Crf >= 0 ? request.vp9Crf : kFirstCrf;
    request.keptFrames = std::make_shared<KeptFrames>();
    double done = 0;
    int framesDrawn = 0;
    for (int attempt = 0;; ++attempt) {
        const QString path = attemptPath(out, attempt);
        ExportRequest tryRequest = request;
        tryRequest.outputPath = path;
        tryRequest.vp9Crf = crf;
        // The first try (drawing and encoding) fills half the bar, each later one (encoding
        // only) half of what is left.
        const double from = done;
        const double to = done + (1.0 - done) / 2;
        const ExportResult r = exportAnimation(
            tryRequest,
            [&](double f) {
                if (progress)
                    progress(from + (to - from) * f);
            },
            cancel);
        done = to;
        framesDrawn += r.framesDrawn;
        if (!r.ok()) {
            QFile::remove(path);
            ExportResult named = r;
            named.error.replace(QDir::toNativeSeparators(path), QDir::toNativeSeparators(out));
            return named;
        }
        const qint64 bytes = QFileInfo(path).size();
        if (bytes <= preset.maxBytes) {
            if (QFileInfo::exists(out))
                QFile::setPermissions(path, QFile::permissions(out));
            std::error_code ec;
            std::filesystem::rename(
                QFile::encodeName(path).toStdString(), QFile::encodeName(QDir::cleanPath(out)).toStdString(), ec);
            if (ec) {
                QFile::remove(path);
                return {ExportStatus::Failed,
                    withProblem(QDir::toNativeSeparators(out),
                        ExportText::tr("cannot write: %1").arg(QString::fromStdString(ec.message())))};
            }
            if (progress)
                progress(1.0);
            return {ExportStatus::Done, {}, framesDrawn, attempt + 1};
        }
        QFile::remove(path);
        if (crf >= kLastCrf)
            return {ExportStatus::OverLimit,
                withProblem(QDir::toNativeSeparators(out),
                    ExportText::tr("at the lowest quality the file is %1 KB, the %2 preset allows %3 KB (%4 KB "
                                   "over): export a shorter stretch or a lower frame rate")
                        .arg(kilobytes(bytes), preset.name, kilobytes(preset.maxBytes),
                            kilobytes(bytes - preset.maxBytes))),
                framesDrawn, attempt + 1};
        // VP9's files roughly halve every 6 steps of crf: aim just under the limit.
        const double over = std::log2(double(bytes) / double(preset.maxBytes));
        crf = std::min(kLastCrf, crf + std::max(2, int(std::ceil(6.0 * over)) + 1));
    }
}

} // namespace toonface
