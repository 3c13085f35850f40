#pragma once

#include "face/facemodel.h"
#include "face/mouthshape.h"
#include "render/style.h"
#include "speech/lipsync.h"
#include "speech/tts.h"

#include <QDateTime>
#include <QString>
#include <QStringList>
#include <QVector>

#include <atomic>
#include <functional>

namespace toonface {

// What a reading system highlights while it reads: each sentence, or each syllable (a Chinese
// character; an English word) within its sentence (a nested <seq epub:textref> per sentence).
enum class BookHighlight { Sentence, Syllable };

// How the talking face moves on the pages.
enum class BookFaceMedia {
    // A SMIL-animated SVG inline, timed from the page's first sentence: reading systems that
    // animate SVG move it as the overlay reads.
    Svg,
    // A video (MP4: H.264 and AAC) per page of the face reading the page aloud with its sound,
    // for reading systems without media overlays or SVG animation: the reader presses play.
    Video,
};

// Everything a read-aloud book needs, by value (run it on any thread).
struct BookRequest
{
    // The text: plain UTF-8, or Markdown when it ends in .md or .markdown (see parseBookText).
    QString textPath;
    // The recording of the whole text, headings included, in reading order; empty: the
    // built-in voice reads it, chapter by chapter.
    QString audioPath;
    TtsOptions voice;
    // "zh-Hant", "zh-Hans" or "en"; empty: Chinese ("zh") or English as the text reads.
    QString language;
    QString title; // empty: the first heading, else the file's name
    QString author; // may be empty

    // The talking face on every page, and on the cover.
    FaceModel face;
    Style style;
    MouthShapeSet mouthShapes;
    QStringList layerFiles;

    BookHighlight highlight = BookHighlight::Sentence;
    BookFaceMedia faceMedia = BookFaceMedia::Svg;
    QString outputPath; // BOOK.epub
    QDateTime modified; // dcterms:modified and the archive's times; invalid: now
};

// The languages a book's text may be given in (--lang).
QStringList bookLanguages();

enum class BookStatus {
    Done,
    Cancelled, // nothing was written
    BadInput, // the text, the recording or a layer cannot make a book (empty text, no sentence
              // end, a recording shorter than the text, an unreadable file)
    CannotAlign, // the recording and the text do not match
    Failed, // the book cannot be written
};

// When one sentence is read: its element in its page and its clip of the audio file, in whole
// milliseconds. Every clip starts where the aligner (or the voice) starts the sentence's first
// syllable, rounded to the millisecond, except the first of an audio file, which starts at 0;
// it ends where the next one starts (the pause after a sentence is part of it) or at the end of
// the file, so a chapter's clips play its sound without a gap.
struct BookSentenceTiming
{
    QString page; // "text/p00001.xhtml", relative to the package document
    QString id; // the sentence's element id
    QString audio; // "audio/book.mp3", relative to the package document
    int firstSyllable = -1; // index in BookResult::syllables; -1 for a sentence without any
    qint64 beginMs = 0;
    qint64 endMs = 0;
};

struct BookResult
{
    BookStatus status = BookStatus::Failed;
    QString error; // names the file and the problem
    QString language; // the book's dc:language
    int chapters = 0;
    int pages = 0;
    double duration = 0; // seconds of sound in the book, all its audio files
    // Every syllable of the text in reading order, times in its audio file (the recording's
    // for --audio, its chapter's for the built-in voice).
    QVector<LipsyncSyllable> syllables;
    QVector<BookSentenceTiming> sentences;
    bool ok() const { return status == BookStatus::Done; }
};

// Called on the calling thread with the fraction done (0..1) and what is being done.
using BookProgressFn = std::function<void(double fraction, const QString &stage)>;

// Makes the EPUB 3 book of `request`: a cover (the cartoon), a navigation document with a
// chapter per heading, and a page per paragraph with the talking face (request.faceMedia: a
// SMIL-animated SVG inline, or a video of the page read aloud) beside the text, whose sentences
// a Media Overlay ties to the sound (MP3: the recording re-encoded, or the voice's chapters).
// Long texts stream: the recording is re-encoded a block at a time and each chapter is spoken,
// drawn and written into the archive before the next one. The book appears only when it is whole: it is written beside
// the target under a hidden name and renamed at the end; a failed or cancelled export leaves nothing.
BookResult exportBook(
    const BookRequest &request, const BookProgressFn &progress = {}, const std::atomic_bool *cancel = nullptr);

} // namespace toonface
