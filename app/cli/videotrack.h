#pragma once

#include "track/trackvideo.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QString>

namespace toonface::cli {

// The options `track` and `animate --video` share: --method, --neutral-frame, --snap-mouth.
struct VideoTrackOptions
{
    QCommandLineOption method {QStringLiteral("method"),
        QStringLiteral("Tracking method: auto, classic (thesis ch. 6) or landmarks."),
        QStringLiteral("auto|classic|landmarks"), QStringLiteral("auto")};
    QCommandLineOption neutralFrame {QStringLiteral("neutral-frame"),
        QStringLiteral("The frame (from 0) whose face is the neutral one, or auto: a frame at rest in the clip's "
                       "first seconds, chosen as the editor's Import Video chooses it (default auto)."),
        QStringLiteral("N|auto"), QStringLiteral("auto")};
    QCommandLineOption snapMouth {QStringLiteral("snap-mouth"),
        QStringLiteral("Snap the tracked mouth to the nearest of the nine mouth shapes (else continuous).")};

    void addTo(QCommandLineParser &parser) const { parser.addOptions({method, neutralFrame, snapMouth}); }
    // Reads the options into *out; on a bad value prints the error and returns ExitUsage.
    int read(const QCommandLineParser &parser, TrackVideoOptions *out) const;
};

// TrackVideoOptions::neutralFrame when --neutral-frame is auto: trackClip() chooses the frame.
inline constexpr int kChooseNeutralFrame = -1;

// Tracks `path` with progress lines on stderr. With options.neutralFrame kChooseNeutralFrame the
// neutral frame is chosen first (track/neutralchoice.h) and named on stderr; where no face is
// found in the clip's first seconds, frame 0 is tracked, whose error names what is wrong.
// Returns ExitOk (warnings printed), or prints the error and returns the contract's code:
// 3 unreadable video, 4 no face on the neutral frame, 130 interrupted.
int trackClip(const QString &path, const TrackVideoOptions &options, TrackResult *out);

// Whether `path` names a video by its suffix (mp4, mpg, mov, avi, mkv, webm, ...).
bool looksLikeVideo(const QString &path);

} // namespace toonface::cli
