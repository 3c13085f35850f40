#include "cli/command.h"
#include "cli/faceinput.h"
#include "detect/appearance.h"
#include "detect/photocolours.h"
#include "io/appearancejson.h"
#include "io/facejson.h"
#include "render/style.h"

#include <QDir>
#include <QJsonDocument>
#include <QTextStream>

#include <cmath>

namespace toonface::cli {

namespace {

int runDetect(const Command &self, const QStringList &args)
{
    QCommandLineParser parser;
    const QCommandLineOption method(QStringLiteral("method"), Cli::tr("Detection method: auto, classic or landmarks."),
        QStringLiteral("auto|classic|landmarks"), QStringLiteral("auto"));
    const QCommandLineOption output(QStringList {QStringLiteral("o"), QStringLiteral("output")},
        Cli::tr("Write the face JSON here (default: stdout)."), QStringLiteral("FACE.json"));
    const QCommandLineOption debugDir(QStringLiteral("debug-dir"),
        Cli::tr("Write intermediate images of the detection here."), QStringLiteral("DIR"));
    const QCommandLineOption faceAt(QStringLiteral("face"),
        Cli::tr("With several faces, use the one at this point of the photo (pixels) instead of the largest, "
                "most central one."),
        QStringLiteral("X,Y"));
    parser.addOptions({method, output, debugDir, faceAt});
    parser.addPositionalArgument(QStringLiteral("IMAGE"), Cli::tr("The photo."));
    bool helped = false;
    if (!parseArguments(parser, self, args, &helped))
        return ExitUsage;
    if (helped)
        return ExitOk;
    if (parser.positionalArguments().size() != 1)
        return fail(ExitUsage, Cli::tr("detect takes one IMAGE (usage: toonface-cli %1)").arg(self.usage));

    DetectOptions options;
    if (const int code = parseMethodOption(parser, method, &options); code != ExitOk)
        return code;
    if (parser.isSet(faceAt)) {
        const QStringList xy = parser.value(faceAt).split(QLatin1Char(','));
        bool okX = false, okY = false;
        const double x = xy.size() == 2 ? xy[0].trimmed().toDouble(&okX) : 0;
        const double y = xy.size() == 2 ? xy[1].trimmed().toDouble(&okY) : 0;
        if (!okX || !okY || !std::isfinite(x) || !std::isfinite(y))
            return fail(
                ExitUsage, Cli::tr("--face wants a point X,Y in photo pixels, not '%1'").arg(parser.value(faceAt)));
        options.faceAt = QPointF(x, y);
    }
    if (parser.isSet(debugDir)) {
        options.debugDir = parser.value(debugDir);
        if (!QDir().mkpath(options.debugDir))
            return fail(ExitFailed, Cli::tr("cannot create the debug folder %1").arg(options.debugDir));
    }
    const QString image = parser.positionalArguments().constFirst();
    FaceInput input;
    if (const int code = loadFaceInput(image, options, &input); code != ExitOk)
        return code;
    QJsonObject face = faceToJson(input.face, input.photoPath, &input.detection);
    // What the person looks like and wears, as the cartoon will draw it.
    if (!input.photo.isNull()) {
        Style style = Style::preset(QStringLiteral("normal"));
        AppearanceFindings findings;
        sampleColours(input.photo, input.face, &style, &findings);
        face.insert(QStringLiteral("appearance"), appearanceToJson(style, findings));
    }
    const QByteArray json = QJsonDocument(face).toJson(QJsonDocument::Indented);
    return writeOutput(parser, output, json);
}

const CommandRegistrar registrar({QStringLiteral("detect"),
    QString::fromUtf8(QT_TRANSLATE_NOOP(
        "toonface::cli::Cli", "Find the face in a photo and write its 72 points as JSON (toonface.face/1).")),
    QStringLiteral("detect IMAGE [--method auto|classic|landmarks] [-o FACE.json] [--debug-dir DIR] [--face X,Y]"),
    runDetect, true});

} // namespace

} // namespace toonface::cli
