#pragma once

#include "anim/timeline.h"
#include "face/facemodel.h"
#include "face/mouthshape.h"
#include "render/style.h"
#include "speech/lipsync.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <QVector>

#include <optional>

namespace toonface {

// A Toonface project (.toonface): versioned JSON {format: "toonface.project", version: 1, ...}.
// On disk the photo, audio and layer paths are relative to the project file; in memory they
// are absolute.
//
// Version 2 holds: photo, imageSize {width, height} (absent when unknown), points
// [{id, x, y, handPlaced}] in face-model.md order, style {name, cornerCutDepth, cute, eyebrows,
// nose, components {name: {fill, stroke, strokeWidth, visible}}, layers [{name, svg, x, y, width,
// front, visible}] (io/layersjson.h: the user's SVG layers held inline)}, mouthShapes {m, f, h, a, i, u,
// e, o, n: {up, dn, lf, rt: {dx, dy: {mns, mw, lowerLip, px}}, cornersAtLipMiddle,
// cornersFromPrevious}}, layers [path], timeline {...} (Timeline::toJson: its `audio` is the
// audio track, each clip with its path relative to the project, its script and language),
// syllables [...] (syllablesToJson: every clip's syllables, at timeline times).
// Version 1 held one sound: `audio` {path, offset} beside `timeline.audio` {path, offset,
// duration} (`audio` won when the two disagreed: older files kept the timeline's path absolute)
// and `script` {text, language, syllables}; it loads as an audio track of that one clip with
// that script (a file with only `audio` gets a clip of unknown duration, 0; loadProject gives it
// its file's length when the file can be read).
// The timeline's video clip (Import Video) is written relative to the project too.
// Colours are "#rrggbb", "#aarrggbb" or "none" (8 bits a channel: an in-memory colour
// round-trips when it is an 8-bit RGB colour). Numbers are written in their shortest exact
// form, so a save and a load give back an equal Project.
struct Project
{
    QString photoPath;
    FaceModel face;
    Style style;
    MouthShapeSet mouthShapes;
    QStringList layerPaths; // extra SVG layers
    Timeline timeline; // its audioClips() are the project's recordings
    QVector<LipsyncSyllable> syllables; // every clip's script's syllables at their aligned times

    // The first recording's file (absolute), or empty.
    QString audioPath() const
    {
        return timeline.audioClips().isEmpty() ? QString() : timeline.audioClips().first().path;
    }

    bool operator==(const Project &) const = default;
};

inline constexpr int kProjectVersion = 2;

// Writes atomically (QSaveFile): a failed save leaves the old file intact and no temporary
// file behind. Refuses (error "<file>: not saved: ...") a project that loadProject would reject,
// such as one with a non-finite coordinate.
bool saveProject(const Project &project, const QString &path, QString *error);

// Validates every field; on failure returns nullopt with *error = "<file>: <json path>: <problem>",
// e.g. "a.toonface: points[12].x: expected a number". A newer version is refused by name.
std::optional<Project> loadProject(const QString &path, QString *error);

// The files `project` names (photo, sound, video, layers) that lie outside `projectDir`, the
// folder of its project file, each as "what: path" ("sound: /home/me/.ssh/id_rsa"). Such paths
// are allowed (people keep their media elsewhere) but a project from someone else that names
// them is shown to its user before anything reads them into an export.
QStringList filesOutsideFolder(const Project &project, const QString &projectDir);

QJsonObject projectToJson(const Project &project, const QString &projectDir);
std::optional<Project> projectFromJson(const QJsonObject &json, const QString &projectDir, QString *error);

} // namespace toonface
