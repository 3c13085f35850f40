#pragma once

#include "export/animationexport.h"
#include "export/epubbook.h"

#include <QSize>
#include <QString>

#include <atomic>
#include <memory>

namespace toonface {

namespace av {
class AudioFeed;
}
class SvgFace;
struct Pose;

// The talking face of a read-aloud book's pages as videos (BookFaceMedia::Video): for each page
// an MP4 (H.264 + AAC) of the face reading the page aloud, its sound the page's stretch of the
// book's own sound, for reading systems that play video but neither media overlays nor SVG
// animation. The pages' sound is cut from one sound file read forward once, so a book of an
// hour decodes its sound once, not once a page.
//
// Made for a book page, not a film: a small head at half the film rate, each distinct pose
// drawn once and its picture reused while the face holds it (pauses, held mouth shapes, eyes
// open), distinct poses drawn on every core.
//
// Not thread-safe: one book's writer, used from the thread that makes the book.
class PageVideoWriter
{
public:
    // Temporary files go in `folder`.
    PageVideoWriter(const BookRequest &request, const QString &folder);
    ~PageVideoWriter();
    PageVideoWriter(const PageVideoWriter &) = delete;
    PageVideoWriter &operator=(const PageVideoWriter &) = delete;

    // The frames' size: a square head frame, small enough that a book's worth of pages draws
    // in a fraction of its reading time on two cores.
    static QSize frameSize();
    // Frames a second of the pages' videos.
    static double frameRate();

    // Starts cutting pages from `soundPath` (the book's MP3, or a chapter's) at its start.
    bool openSound(const QString &soundPath, QString *error);

    // Writes the video of a page: `timeline` from the page's start, with the sound of
    // [beginMs, endMs) of the open sound (pages come in the sound's order). Its path (a
    // temporary file, replaced by the next page's), or empty with *status and *error set
    // (Cancelled when *cancel became true).
    QString write(const Timeline &timeline, qint64 beginMs, qint64 endMs, const std::atomic_bool *cancel,
        ExportStatus *status, QString *error);

    // Frames written into the videos so far, and how many of them were drawn (the others
    // reused the picture of the same pose).
    qint64 framesWritten() const { return m_written; }
    qint64 framesDrawn() const { return m_drawn; }

private:
    struct Pictures; // the pictures of recent poses

    bool readSound(qint64 beginMs, qint64 endMs, QVector<float> *samples, QString *error);

    const BookRequest &m_request;
    QString m_folder;
    std::unique_ptr<av::AudioFeed> m_feed;
    qint64 m_at = 0; // samples of the open sound read so far
    std::unique_ptr<SvgFace> m_face;
    std::unique_ptr<Pictures> m_pictures;
    qint64 m_written = 0;
    qint64 m_drawn = 0;
};

// `pose` rounded to `step` pixels (offsets and head translation; the lids and the head's
// turn and scale to steps as fine): poses that round alike draw alike at a scale where `step`
// is below what a pixel shows.
Pose roundedPose(const Pose &pose, double step);

} // namespace toonface
