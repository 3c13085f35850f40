#pragma once

#include <QCoreApplication>
#include <QStringList>

namespace toonface {

// The contexts of core's user-visible messages (errors of the files it reads and writes,
// detection and export problems) in the translations (resources/translations), one per area:
// `ProjectText::tr("...")`. Developer logs, file contents and JSON keys stay untranslated.
struct ProjectText // projects and the JSON files inside them (face, timeline, layers, syllables)
{
    Q_DECLARE_TR_FUNCTIONS(toonface::ProjectFile)
};
struct ImageText // photos and SVG layers
{
    Q_DECLARE_TR_FUNCTIONS(toonface::ImageFile)
};
struct SoundText // sound files read and written
{
    Q_DECLARE_TR_FUNCTIONS(toonface::SoundFile)
};
struct VideoText // video files read, and face tracking through them
{
    Q_DECLARE_TR_FUNCTIONS(toonface::VideoFile)
};
struct MediaText // FFmpeg's most common errors, in audio and video files alike
{
    Q_DECLARE_TR_FUNCTIONS(toonface::Media)
};
struct ScriptText // scripts, speech synthesis, alignment, the pinyin dictionaries
{
    Q_DECLARE_TR_FUNCTIONS(toonface::Script)
};
struct LipSyncText // lip-sync files of other programs (Rhubarb, Papagayo, Moho, TextGrid)
{
    Q_DECLARE_TR_FUNCTIONS(toonface::LipSyncFile)
};
struct ExportText // animation export: SVG, HTML, MP4, GIF, PNG frames
{
    Q_DECLARE_TR_FUNCTIONS(toonface::Export)
};
struct DetectText // face detection, its models and caches
{
    Q_DECLARE_TR_FUNCTIONS(toonface::Detector)
};

// "WHERE: problem", a file's or a field's name and what is wrong with it, joined as the language
// writes it (a full-width colon in Chinese).
inline QString withProblem(const QString &where, const QString &problem)
{
    return QCoreApplication::translate("toonface::Problem", "%1: %2").arg(where, problem);
}

// Two sentences one after the other: a space between them in English, none in Chinese.
inline QString joinSentences(const QString &first, const QString &second)
{
    return QCoreApplication::translate("toonface::Problem", "%1 %2", "two sentences one after the other")
        .arg(first, second);
}

// Reasons given one after the other ("a; b"; a full-width semicolon in Chinese).
inline QString joinReasons(const QStringList &reasons)
{
    return reasons.join(QCoreApplication::translate("toonface::Problem", "; ", "between two reasons"));
}

} // namespace toonface
