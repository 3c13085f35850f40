#include "cli/faceinput.h"

#include "cli/command.h"
#include "detect/photocolours.h"
#include "i18n/coretext.h"
#include "io/facejson.h"
#include "io/imageio.h"
#include "io/project.h"
#include "render/svgface.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonParseError>

namespace toonface::cli {

namespace {

enum class InputKind { Photo, FaceJson, Project };

InputKind kindOf(const QString &path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == QLatin1StringView("toonface"))
        return InputKind::Project;
    if (suffix == QLatin1StringView("json"))
        return InputKind::FaceJson;
    return InputKind::Photo;
}

int detectionExitCode(DetectStatus status)
{
    switch (status) {
    case DetectStatus::Ok: return ExitOk;
    case DetectStatus::NoFace: return ExitNoFace;
    case DetectStatus::BadImage: return ExitBadInput;
    default: return ExitFailed;
    }
}

} // namespace

int loadFaceInput(const QString &path, const DetectOptions &options, FaceInput *out)
{
    QString error;
    switch (kindOf(path)) {
    case InputKind::Project: {
        const auto project = loadProject(path, &error);
        if (!project)
            return fail(ExitBadInput, error);
        out->face = project->face;
        out->style = project->style;
        out->hasProjectStyle = true;
        out->photoPath = project->photoPath;
        out->layerPaths = project->layerPaths;
        out->mouthShapes = project->mouthShapes;
        out->project = project;
        // A shared project may name any file; the user sees which ones lie outside its folder.
        if (const QStringList outside = filesOutsideFolder(*project, QFileInfo(path).absolutePath());
            !outside.isEmpty())
            warn(Cli::tr("%1 uses files outside its folder: %2").arg(path, outside.join(QStringLiteral("; "))));
        if (!out->photoPath.isEmpty() && QFileInfo::exists(out->photoPath))
            out->photo = loadPhoto(out->photoPath, &error);
        return ExitOk;
    }
    case InputKind::FaceJson: {
        QFile file(path);
        if (!file.open(QIODevice::ReadOnly))
            return fail(ExitBadInput, Cli::tr("cannot read %1: %2").arg(path, file.errorString()));
        QJsonParseError parseError;
        const QJsonDocument doc = QJsonDocument::fromJson(file.readAll(), &parseError);
        if (!doc.isObject())
            return fail(ExitBadInput,
                Cli::tr("%1: not a face JSON: %2 at offset %3")
                    .arg(path, parseError.errorString())
                    .arg(parseError.offset));
        QString imagePath;
        const auto face = faceFromJson(doc.object(), &error, &imagePath);
        if (!face)
            return fail(ExitBadInput, withProblem(path, error));
        out->face = *face;
        if (!imagePath.isEmpty()) {
            const QString resolved
                = QFileInfo(imagePath).isAbsolute() ? imagePath : QFileInfo(path).absoluteDir().filePath(imagePath);
            if (QFileInfo::exists(resolved)) {
                out->photoPath = resolved;
                out->photo = loadPhoto(resolved, &error);
            }
        }
        return ExitOk;
    }
    case InputKind::Photo: {
        out->photo = loadPhoto(path, &error);
        if (out->photo.isNull())
            return fail(ExitBadInput, error);
        out->photoPath = QFileInfo(path).absoluteFilePath();
        out->detection = detectFace(out->photo, options);
        if (out->detection.status != DetectStatus::Ok)
            return fail(detectionExitCode(out->detection.status), withProblem(path, out->detection.error));
        if (!out->detection.note.isEmpty())
            warn(Cli::tr("%1: the landmark method could not serve (%2); the points come from the classic method")
                     .arg(path, out->detection.note));
        if (out->detection.faceCount > 1)
            warn(Cli::tr("%1: %2 faces found; the largest, most central one is used")
                     .arg(path)
                     .arg(out->detection.faceCount));
        out->face = out->detection.face;
        return ExitOk;
    }
    }
    return ExitFailed;
}

int parseMethodOption(const QCommandLineParser &parser, const QCommandLineOption &method, DetectOptions *out)
{
    if (!detectionMethodFromName(parser.value(method), &out->method))
        return fail(ExitUsage, Cli::tr("unknown --method '%1' (auto, classic or landmarks)").arg(parser.value(method)));
    return ExitOk;
}

int parseEmotionOption(const QCommandLineParser &parser, const QCommandLineOption &emotion, Emotion *out)
{
    const auto expression = emotionFromName(parser.value(emotion));
    if (!expression)
        return fail(ExitUsage,
            Cli::tr("unknown --emotion '%1' (neutral, smile, sad, angry or surprise)").arg(parser.value(emotion)));
    *out = *expression;
    return ExitOk;
}

int parseStyleOption(const QCommandLineParser &parser, const QCommandLineOption &style, std::optional<Style> *out)
{
    if (!parser.isSet(style))
        return ExitOk;
    bool ok = false;
    *out = Style::preset(parser.value(style), &ok);
    if (!ok)
        return fail(ExitUsage,
            Cli::tr("unknown --style '%1' (%2)")
                .arg(parser.value(style), Style::presetNames().join(QStringLiteral(", "))));
    return ExitOk;
}

QCommandLineOption frameOption()
{
    return QCommandLineOption(QStringLiteral("frame"),
        Cli::tr("What the drawing shows: head (framed square around the head, the default) or photo (the "
                "photo's whole frame, to lay over the photo)."),
        QStringLiteral("head|photo"), QStringLiteral("head"));
}

int parseFrameOption(const QCommandLineParser &parser, const QCommandLineOption &frame, bool *wholePhoto)
{
    const QString value = parser.value(frame);
    if (value != QLatin1StringView("head") && value != QLatin1StringView("photo"))
        return fail(ExitUsage, Cli::tr("unknown --frame '%1' (head, photo)").arg(value));
    *wholePhoto = value == QLatin1StringView("photo");
    return ExitOk;
}

QRectF drawingFrame(const FaceModel &face, bool wholePhoto)
{
    return wholePhoto ? QRectF() : headFrame(face);
}

Style drawingStyle(const FaceInput &input, const std::optional<Style> &chosen)
{
    if (!chosen && input.hasProjectStyle)
        return input.style;
    Style style = chosen.value_or(Style::preset(QStringLiteral("normal")));
    if (!input.photo.isNull())
        sampleColours(input.photo, input.face, &style);
    return style;
}

} // namespace toonface::cli
