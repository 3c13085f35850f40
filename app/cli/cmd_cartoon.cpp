#include "cli/command.h"
#include "cli/faceinput.h"
#include "export/cartoonfile.h"
#include "face/emotion.h"
#include "face/pose.h"
#include "render/svgface.h"

#include <QFileInfo>

namespace toonface::cli {

namespace {

int runCartoon(const Command &self, const QStringList &args)
{
    QCommandLineParser parser;
    const QCommandLineOption output(QStringList {QStringLiteral("o"), QStringLiteral("output")},
        Cli::tr("The cartoon SVG to write."), QStringLiteral("OUT.svg"));
    const QCommandLineOption png(
        QStringLiteral("png"), Cli::tr("Also rasterize to this PNG."), QStringLiteral("OUT.png"));
    const QCommandLineOption size(QStringLiteral("size"), Cli::tr("The PNG's longer side in pixels (default 512)."),
        QStringLiteral("N"), QStringLiteral("512"));
    const QCommandLineOption style(QStringLiteral("style"),
        Cli::tr("Drawing style: %1.").arg(Style::presetNames().join(QStringLiteral(", "))), QStringLiteral("NAME"));
    const QCommandLineOption emotion(QStringLiteral("emotion"),
        Cli::tr("Expression: neutral, smile, sad, angry or surprise (default: the face as photographed)."),
        QStringLiteral("NAME"), QStringLiteral("neutral"));
    const QCommandLineOption method(QStringLiteral("method"),
        Cli::tr("Detection method for a photo: auto, classic or landmarks."), QStringLiteral("auto|classic|landmarks"),
        QStringLiteral("auto"));
    const QCommandLineOption caricature(QStringLiteral("caricature"),
        Cli::tr("How much to exaggerate what makes the face its own: 0 (exact) to 1 (default: the style's)."),
        QStringLiteral("F"));
    const QCommandLineOption frame = frameOption();
    parser.addOptions({output, png, size, style, emotion, method, frame, caricature});
    parser.addPositionalArgument(QStringLiteral("INPUT"), Cli::tr("A photo, a face JSON or a project."));
    bool helped = false;
    if (!parseArguments(parser, self, args, &helped))
        return ExitUsage;
    if (helped)
        return ExitOk;
    if (parser.positionalArguments().size() != 1)
        return fail(ExitUsage, Cli::tr("cartoon takes one input (usage: toonface-cli %1)").arg(self.usage));
    if (!parser.isSet(output))
        return fail(ExitUsage, Cli::tr("cartoon needs -o OUT.svg"));
    bool sizeOk = false;
    const int pngSize = parser.value(size).toInt(&sizeOk);
    if (!sizeOk || pngSize < 16 || pngSize > 8192)
        return fail(
            ExitUsage, Cli::tr("--size takes a whole number from 16 to 8192, not '%1'").arg(parser.value(size)));
    double caricatureFactor = -1;
    if (parser.isSet(caricature)) {
        bool ok = false;
        caricatureFactor = parser.value(caricature).toDouble(&ok);
        if (!ok || caricatureFactor < 0 || caricatureFactor > kMaxCaricature)
            return fail(
                ExitUsage, Cli::tr("--caricature takes a number from 0 to 1, not '%1'").arg(parser.value(caricature)));
    }
    Emotion expression = Emotion::Neutral;
    std::optional<Style> chosenStyle;
    DetectOptions options;
    if (const int code = parseEmotionOption(parser, emotion, &expression); code != ExitOk)
        return code;
    if (const int code = parseStyleOption(parser, style, &chosenStyle); code != ExitOk)
        return code;
    bool wholePhoto = false;
    if (const int code = parseFrameOption(parser, frame, &wholePhoto); code != ExitOk)
        return code;
    if (const int code = parseMethodOption(parser, method, &options); code != ExitOk)
        return code;

    FaceInput input;
    if (const int code = loadFaceInput(parser.positionalArguments().constFirst(), options, &input); code != ExitOk)
        return code;
    Style drawStyle = drawingStyle(input, chosenStyle);
    if (caricatureFactor >= 0)
        drawStyle.caricature = caricatureFactor;

    SvgFace face(input.face, drawStyle);
    face.setFrame(drawingFrame(input.face, wholePhoto));
    for (const QString &layer : std::as_const(input.layerPaths)) {
        QString error;
        if (!face.addLayerFile(layer, &error))
            return fail(ExitBadInput, error);
    }
    // An emotion is drawn as the animation draws it where nothing is said (lips at rest); with
    // none asked for, the face is as photographed.
    const Pose pose = parser.isSet(emotion) ? stillEmotionPose(input.face, expression, 1.0) : Pose();
    const QByteArray svg = face.svg(pose);
    QString error;
    if (!writeFileAtomically(parser.value(output), svg, &error))
        return fail(ExitFailed, error);
    if (parser.isSet(png)) {
        const QSize target = face.frame().size().scaled(pngSize, pngSize, Qt::KeepAspectRatio).toSize();
        if (!writeCartoonFile(svg, target, parser.value(png), &error, "png"))
            return fail(ExitFailed, error);
    }
    return ExitOk;
}

const CommandRegistrar registrar({QStringLiteral("cartoon"),
    QString::fromUtf8(QT_TRANSLATE_NOOP(
        "toonface::cli::Cli", "Draw the cartoon face of a photo, a face JSON or a project as SVG (and PNG).")),
    QStringLiteral(
        "cartoon IMAGE|FACE.json|PROJECT.toonface -o OUT.svg [--png OUT.png [--size N]] [--frame head|photo] "
        "[--style NAME] [--emotion NAME] [--caricature F]"),
    runCartoon, true});

} // namespace

} // namespace toonface::cli
