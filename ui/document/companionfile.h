#pragma once

#include <QString>

namespace toonface {

class Document;

// A new file to keep beside the document: in the project's folder (else the photo's, else the
// user's `fallback` folder, else home), named "<project or photo name>-<tag>.<extension>", or
// "...-<tag>-2.<extension>" and so on when that exists. Used for the files a project refers to
// (spoken sound, recorded takes, camera snapshots).
QString companionFile(const Document &document, const QString &tag, const QString &extension, const QString &fallback);

// Where an export of the document is offered by default: "<project or photo name>.<extension>"
// (or "<untitledName>.<extension>") in the same folder as companionFile()'s, so a photo opened
// from a folder the user cannot write to (the system's sample pictures, a read-only card) does
// not make the export fail. An existing file is not avoided: exporting again replaces it.
QString exportFile(
    const Document &document, const QString &extension, const QString &untitledName, const QString &fallback);

} // namespace toonface
