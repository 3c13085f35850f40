#pragma once

#include <QByteArray>
#include <QDateTime>
#include <QString>
#include <QVector>

// The XML documents of a read-aloud EPUB 3 book: the container, the package document, the
// navigation document, the cover, the pages (XHTML with the talking face inline) and their
// Media Overlays (SMIL). Plain functions of their arguments; epubbook.cpp assembles them.
namespace toonface::epub {

// The class reading systems give the text being read (media:active-class).
inline constexpr const char *kActiveClass = "-epub-media-overlay-active";

// A stretch of text read aloud: its element id in the page and its clip of the recording, in
// whole milliseconds of the audio file.
struct ReadClip
{
    QString id;
    qint64 beginMs = 0;
    qint64 endMs = 0;
};

// A sentence of a page: its text cut into pieces, each a syllable (or English word) with its
// own id and clip, or the text between them (id empty).
struct PageSentence
{
    ReadClip clip; // the whole sentence
    struct Piece
    {
        QString text;
        ReadClip clip; // id empty: text between syllables
    };
    QVector<Piece> pieces;
};

struct PageDocument
{
    QString language; // BCP 47
    QString title; // of the chapter
    int headingLevel = 0; // the first sentence is the chapter's heading when > 0
    QVector<PageSentence> sentences;
    QByteArray faceSvg; // the <svg> element of the talking face
    // Or, when not empty, the face's video of the page reading itself aloud (relative to the
    // page), shown with controls at its size over `posterHref` until it is played; the poster
    // stands in for it where video does not play.
    QString faceVideoHref;
    QString posterHref;
    int videoWidth = 0;
    int videoHeight = 0;
    QString stylesheetHref; // relative to the page
};

// Pages are written in the folder "text/", their overlays in "smil/", sound in "audio/".
QByteArray pageXhtml(const PageDocument &page);

// The overlay of `pageHref` (as seen from the overlay), reading `audioHref`: one <par> per
// sentence, or with `bySyllable` one <seq epub:textref> per sentence holding a <par> per
// syllable.
QByteArray overlaySmil(const PageDocument &page, const QString &pageHref, const QString &audioHref, bool bySyllable);

QByteArray containerXml(const QString &packagePath);
QByteArray stylesheet();
QByteArray coverXhtml(const QString &language, const QString &title, const QString &author, const QString &imageHref,
    const QString &stylesheetHref);

struct NavEntry
{
    QString title;
    QString href;
    int level = 1; // heading level; deeper levels nest under the one before
};
QByteArray navXhtml(const QString &language, const QString &title, const QVector<NavEntry> &entries);

struct ManifestItem
{
    QString id;
    QString href;
    QString mediaType;
    QString properties;
    QString mediaOverlay; // id of the overlay item
    qint64 overlayMs = -1; // for an overlay: its media:duration
};

struct PackageMetadata
{
    QString identifier; // urn:uuid:...
    QString title;
    QString author; // may be empty
    QString language;
    QDateTime modified;
};

// The package document: metadata (with each overlay's media:duration and their sum), the
// manifest and the spine (`spine`: item ids in reading order).
QByteArray packageOpf(const PackageMetadata &meta, const QVector<ManifestItem> &manifest, const QStringList &spine);

// "h:mm:ss.mmm", the clock value of media:duration.
QString clockValue(qint64 ms);
// "12.345s", the clip times of an overlay.
QString clipValue(qint64 ms);

} // namespace toonface::epub
