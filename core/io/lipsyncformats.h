#pragma once

#include "anim/timeline.h"
#include "face/mouthshape.h"

#include <QByteArray>
#include <QHash>
#include <QString>
#include <QStringList>
#include <QVector>

#include <array>
#include <optional>

namespace toonface {

// How Toonface's nine mouth shapes are named in another program's shape set, in both
// directions, plus the names that mean "rest" (silence: no cue). A plain value type: start
// from a default table and override single entries with the setters.
//
// rhubarb() — Rhubarb Lip Sync's shapes, matched case-sensitively:
//
//   ours  exported as  Rhubarb's meaning                      imported back as
//   m     A            closed lips (P B M)                     m
//   f     G            upper teeth on the lower lip (F V)      f
//   h     B            slightly open, clenched teeth           i   (not bijective)
//   a     D            wide open (AA)                          a
//   i     B            slightly open, clenched teeth (EE)      i
//   u     F            puckered (OO, W)                        u
//   e     C            open (EH, AE)                           e
//   o     E            slightly rounded (AO, ER)               o
//   n     H            tongue raised (L)                       n
//   rest  X            idle                                    rest
//
//   It is a bijection between {m f a i u e o n} and {A G D B F C E H} (and rest ↔ X); h has no
//   letter of its own and comes back as i. Toonface's own lowercase names (the CLI's TSV)
//   import as themselves.
//
// prestonBlair() — Preston Blair's phoneme set as Papagayo and Moho name it, matched
// case-insensitively:
//
//   ours  exported as       imported back as
//   m     MBP               m
//   f     FV                f
//   h     etc               h
//   a     AI                a
//   i     E                 i
//   u     U                 u
//   e     E                 i   (not bijective)
//   o     O                 o
//   n     L                 n
//   rest  rest              rest
//   (WQ)                    u   (import only)
//
//   It is a bijection between {m f h a i u o n} and {MBP FV etc AI E U O L} (and rest ↔ rest);
//   e has no phoneme of its own and comes back as i; WQ imports as u.
class ShapeMapping
{
public:
    static ShapeMapping rhubarb();
    static ShapeMapping prestonBlair();

    // The name `shape` is written as.
    QString exportName(MouthShape shape) const { return m_export[int(shape)]; }
    void setExportName(MouthShape shape, const QString &name) { m_export[int(shape)] = name; }

    // The name written for silence; it also imports as rest.
    QString restName() const { return m_rest; }
    void setRestName(const QString &name);

    enum class Match { Shape, Rest, Unknown };
    // What an external name stands for; *shape is set when the result is Match::Shape.
    Match importName(const QString &name, MouthShape *shape) const;
    // Makes `name` import as `shape`, or as rest when `shape` is nullopt.
    void setImportShape(const QString &name, std::optional<MouthShape> shape);

    bool isCaseSensitive() const { return m_caseSensitive; }
    // Every name that imports (as a shape or as rest), sorted.
    QStringList importNames() const;

    bool operator==(const ShapeMapping &) const = default;

private:
    ShapeMapping() = default;
    QString key(const QString &name) const { return m_caseSensitive ? name : name.toLower(); }

    std::array<QString, kMouthShapeCount> m_export;
    QHash<QString, std::optional<MouthShape>> m_import; // key(name) -> shape, or nullopt for rest
    QString m_rest;
    bool m_caseSensitive = true;
};

// The mouth track as another lip-sync program writes it. Cues are sorted, do not overlap and
// have end > start; the time between cues is silence.
struct LipSyncTrack
{
    QVector<MouthCue> cues;
    // The recording the cues belong to, as the file names it (may be empty or relative).
    QString soundFile;
    // Seconds the track covers; 0 when unknown (then it ends with the last cue).
    double duration = 0;

    bool operator==(const LipSyncTrack &) const = default;
};

enum class LipSyncFormat {
    RhubarbTsv, // .tsv: "start<TAB>shape" lines; a cue lasts until the next line
    RhubarbJson, // .json: {"metadata": {soundFile, duration}, "mouthCues": [{start, end, value}]}
    Papagayo, // .pgo: "lipsync version 1", voices / phrases / words / phonemes, in frames
    MohoSwitch, // .dat: "MohoSwitch1", then "frame shape" lines with 1-based frames
};

// By the file name's extension (.tsv .json .pgo .dat, any case); nullopt for others.
std::optional<LipSyncFormat> lipSyncFormatForPath(const QString &path);
QString lipSyncFormatName(LipSyncFormat format);

struct LipSyncOptions
{
    // The shape names; when unset, rhubarb() for the Rhubarb formats and prestonBlair() for
    // Papagayo and Moho.
    std::optional<ShapeMapping> mapping;
    // Frames per second of the frame-based formats (Moho; Papagayo writes it rounded to an
    // integer, as Papagayo stores it, and reads it from the file). A last cue that a file
    // leaves open (a final line that is not rest) lasts one frame at this rate.
    double fps = 25;
};

// The file's text. Times are kept exactly in JSON, to the millisecond in TSV and on the frame
// grid in Papagayo and Moho (each cue's start and end rounded to the nearest frame; a cue that
// rounds to no frame is left out). Silence between cues, and before the first cue, is written
// as the mapping's rest name; a track's duration beyond its last cue is kept in JSON and
// Papagayo. Papagayo gets one voice whose phrases are the runs of cues without silence, one
// word (named by our shape name) per cue.
// requires: options.fps > 0; the cues as LipSyncTrack describes.
QByteArray writeLipSync(const LipSyncTrack &track, LipSyncFormat format, const LipSyncOptions &options = {});

// Parses a file's text. A rest name ends the cue before it and starts none. Equal consecutive
// names stay separate cues. Of a Papagayo file the first voice is read. The JSON form also
// accepts `shape` for `value` (Toonface's lip-sync JSON).
// On failure returns nullopt and sets *error to "<fileName>: line <n>: <problem>" (JSON
// syntax errors give the line too; a well-formed JSON document with a bad field gives its
// path instead, e.g. "<fileName>: mouthCues[3].value: unknown shape 'Q'").
std::optional<LipSyncTrack> parseLipSync(const QByteArray &data, LipSyncFormat format, const QString &fileName,
    const LipSyncOptions &options, QString *error);

// Atomic save (QSaveFile); on failure *error is "<path>: <problem>".
bool saveLipSync(const LipSyncTrack &track, const QString &path, LipSyncFormat format, const LipSyncOptions &options,
    QString *error);
// Reads the file; the format, when not given, follows the extension.
std::optional<LipSyncTrack> loadLipSync(
    const QString &path, std::optional<LipSyncFormat> format, const LipSyncOptions &options, QString *error);

} // namespace toonface
