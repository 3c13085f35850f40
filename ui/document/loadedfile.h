#pragma once

#include "io/project.h"

#include <QImage>
#include <QString>

namespace toonface {

// What opening a file yields: a project with its photo, or a photo with a fresh project
// around it (no face yet). Built off the GUI thread by loadFile(), applied on it by
// Document::open().
struct LoadedFile
{
    QString path; // absolute path of the opened file
    bool isProject = false;
    Project project; // for a photo: photoPath set, the "normal" style preset
    QImage photo;
    QString error; // non-empty: the file could not be opened, and why (names the file)
    QString photoWarning; // a project whose photo could not be read: why
    QStringList outsideFiles; // the files a project names outside its folder (filesOutsideFolder)

    bool ok() const { return error.isEmpty(); }
};

// True for a .toonface project path (by suffix); every other file is treated as a photo.
bool isProjectPath(const QString &path);

// Reads a project (and its photo) or a photo. Thread-safe: touches no shared state, so it
// runs in QtConcurrent::run. Never throws; failures come back in LoadedFile::error.
LoadedFile loadFile(const QString &path);

} // namespace toonface
