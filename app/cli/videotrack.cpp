#include "cli/videotrack.h"

#include "cli/command.h"
#include "media/mediareader.h"
#include "track/neutralchoice.h"

#include <QFileInfo>

namespace toonface::cli {

int VideoTrackOptions::read(const QCommandLineParser &parser, TrackVideoOptions *out) const
{
    if (!detectionMethodFromName(parser.value(method), &out->tracker.method))
        return fail(ExitUsage, Cli::tr("unknown --method '%1' (auto, classic or landmarks)").arg(parser.value(method)));
    if (parser.value(neutralFrame) == QLatin1StringView("auto")) {
        out->neutralFrame = kChooseNeutralFrame;
    } else {
        bool ok = false;
        out->neutralFrame = parser.value(neutralFrame).toInt(&ok);
        if (!ok || out->neutralFrame < 0)
            return fail(ExitUsage,
                Cli::tr("--neutral-frame takes a frame number from 0 or auto, not '%1'")
                    .arg(parser.value(neutralFrame)));
    }
    out->tracker.snapMouth = parser.isSet(snapMouth);
    return ExitOk;
}

int trackClip(const QString &path, const TrackVideoOptions &chosen, TrackResult *out)
{
    TrackVideoOptions options = chosen;
    if (options.neutralFrame == kChooseNeutralFrame) {
        progress(Cli::tr("looking for a frame at rest in %1").arg(QFileInfo(path).fileName()));
        const NeutralChoice choice = chooseNeutralFrame(path, interruption());
        if (interruption()->load())
            return fail(ExitInterrupted, Cli::tr("%1: interrupted; nothing was written").arg(path));
        options.neutralFrame = choice.found ? choice.frame : 0;
        if (choice.found)
            note(choice.silent
                    ? Cli::tr("%1: neutral frame %2 (mouth closed, eyes open, in a silence; --neutral-frame N names "
                              "another)")
                          .arg(path)
                          .arg(choice.frame)
                    : Cli::tr("%1: neutral frame %2 (mouth closed, eyes open; --neutral-frame N names another)")
                          .arg(path)
                          .arg(choice.frame));
    }
    int lastPercent = -1;
    *out = trackVideo(path, options, [&](int done, int total) {
        const int percent = total > 0 ? std::min(100, done * 100 / total) : -1;
        if (percent >= 0 && percent / 10 != lastPercent / 10)
            progress(Cli::tr("tracking %1: %2 %").arg(QFileInfo(path).fileName()).arg(percent));
        lastPercent = percent;
    });
    switch (out->status) {
    case TrackStatus::Ok: break;
    case TrackStatus::NoFace:
        // A copy cut short decodes to a smear of grey, where no face can be found.
        if (const QString damage = mediaDamage(path); !damage.isEmpty())
            return fail(ExitBadInput, damage);
        return fail(ExitNoFace, out->error);
    case TrackStatus::ModelMissing: return fail(ExitFailed, out->error);
    case TrackStatus::Cancelled: return fail(ExitFailed, out->error);
    case TrackStatus::BadVideo: return fail(ExitBadInput, out->error);
    }
    for (const QString &w : std::as_const(out->warnings))
        warn(w);
    return ExitOk;
}

bool looksLikeVideo(const QString &path)
{
    static const QStringList suffixes
        = {QStringLiteral("mp4"), QStringLiteral("m4v"), QStringLiteral("mov"), QStringLiteral("mpg"),
            QStringLiteral("mpeg"), QStringLiteral("avi"), QStringLiteral("mkv"), QStringLiteral("webm"),
            QStringLiteral("ogv"), QStringLiteral("wmv"), QStringLiteral("flv"), QStringLiteral("ts")};
    return suffixes.contains(QFileInfo(path).suffix().toLower());
}

} // namespace toonface::cli
