#include "cli/command.h"
#include "cli/videotrack.h"

#include <QJsonDocument>
#include <QTextStream>

namespace toonface::cli {

namespace {

int runTrack(const Command &self, const QStringList &args)
{
    QCommandLineParser parser;
    const VideoTrackOptions trackOptions;
    trackOptions.addTo(parser);
    const QCommandLineOption output(QStringList {QStringLiteral("o"), QStringLiteral("output")},
        Cli::tr("Write the track JSON here (default: stdout)."), QStringLiteral("TRACK.json"));
    parser.addOption(output);
    parser.addPositionalArgument(QStringLiteral("VIDEO"), Cli::tr("The video of a speaking face."));
    bool helped = false;
    if (!parseArguments(parser, self, args, &helped))
        return ExitUsage;
    if (helped)
        return ExitOk;
    if (parser.positionalArguments().size() != 1)
        return fail(ExitUsage, Cli::tr("track takes one VIDEO (usage: toonface-cli %1)").arg(self.usage));
    TrackVideoOptions options;
    if (const int code = trackOptions.read(parser, &options); code != ExitOk)
        return code;
    TrackResult track;
    if (const int code = trackClip(parser.positionalArguments().constFirst(), options, &track); code != ExitOk)
        return code;
    const QByteArray json = QJsonDocument(trackToJson(track)).toJson(QJsonDocument::Compact);
    // On a terminal the compact line ends with a newline; the file holds the JSON alone.
    return writeOutput(parser, output, parser.isSet(output) ? json : json + '\n');
}

const CommandRegistrar registrar({QStringLiteral("track"),
    QString::fromUtf8(QT_TRANSLATE_NOOP("toonface::cli::Cli",
        "Track the face of a video frame by frame and write its motion as JSON (toonface.track/1).")),
    QStringLiteral(
        "track VIDEO [--method auto|classic|landmarks] [--neutral-frame N|auto] [--snap-mouth] [-o TRACK.json]"),
    runTrack});

} // namespace

} // namespace toonface::cli
