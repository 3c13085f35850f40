#include "export/epubbook.h"

#include "anim/timeline.h"
#include "export/bookvideo.h"
#include "export/epubdocs.h"
#include "export/epubtext.h"
#include "export/epubzip.h"
#include "export/partfiles.h"
#include "export/smilexport.h"
#include "i18n/coretext.h"
#include "media/soundcopy.h"
#include "media/userfile.h"
#include "render/svgface.h"

#include <QBuffer>
#include <QCoreApplication>
#include <QCryptographicHash>
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QPainter>
#include <QStringDecoder>
#include <QSvgRenderer>
#include <QTemporaryDir>
#include <QUuid>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

namespace toonface {

namespace {

// The fastest a person reads aloud: a recording shorter than the text takes at this pace
// cannot hold it. Fast Mandarin newsreading runs near 6 syllables a second and fast English
// speech near 4 words; these leave room beyond both.
constexpr double kFastestSyllablesPerSecond = 9.0;
constexpr double kFastestWordsPerSecond = 6.0;
// The book's sound: speech keeps its sound below 12 kHz.
constexpr int kBookSampleRate = 24000;
constexpr qint64 kMaxTextBytes = 64ll << 20;
constexpr double kFaceFps = 25;
const QString kPackageDir = QStringLiteral("OEBPS/");

qint64 toMs(double seconds)
{
    return qint64(std::llround(seconds * 1000.0));
}

QString numbered(const char *prefix, int n, const char *suffix)
{
    return QStringLiteral("%1%2%3")
        .arg(QLatin1StringView(prefix))
        .arg(n, 5, 10, QLatin1Char('0'))
        .arg(QLatin1StringView(suffix));
}

// One sentence of the book as the speech sees it: every sentence is a line of the spoken text.
struct SpokenSentence
{
    int chapter = 0;
    int page = 0; // within the book
    bool heading = false;
    qsizetype offset = 0; // in SpokenBook::text
    qsizetype length = 0;
    int line = 1;
    int firstSyllable = -1; // in the script
    int syllableCount = 0;
};

struct SpokenBook
{
    QString text;
    QVector<SpokenSentence> sentences;
    QVector<int> chapterFirstSentence; // and one past the end at the back
    QVector<int> pageHeadingLevel;
    QVector<QString> chapterTitles;
    Script script;
};

SpokenBook layOut(const BookTextParse &parse)
{
    SpokenBook book;
    int page = 0;
    for (int c = 0; c < parse.chapters.size(); ++c) {
        book.chapterFirstSentence.append(int(book.sentences.size()));
        book.chapterTitles.append(parse.chapters[c].title);
        for (const BookPage &p : parse.chapters[c].pages) {
            book.pageHeadingLevel.append(p.headingLevel);
            auto add = [&](const BookSentence &s, bool heading) {
                book.sentences.append(SpokenSentence {c, page, heading, book.text.size(), s.text.size(), s.line});
                book.text += s.text + QLatin1Char('\n');
            };
            for (const BookSentence &s : p.heading)
                add(s, true);
            for (const BookSentence &s : p.sentences)
                add(s, false);
            ++page;
        }
    }
    book.chapterFirstSentence.append(int(book.sentences.size()));
    return book;
}

// Gives each sentence its syllables (by where they stand in the spoken text).
void assignSyllables(SpokenBook &book)
{
    int s = 0;
    for (int k = 0; k < book.script.syllables.size(); ++k) {
        const int position = book.script.syllables[k].position;
        while (s + 1 < book.sentences.size() && position >= book.sentences[s + 1].offset)
            ++s;
        if (book.sentences[s].firstSyllable < 0)
            book.sentences[s].firstSyllable = k;
        ++book.sentences[s].syllableCount;
    }
}

// The file line of the spoken text's `position`.
int lineAt(const SpokenBook &book, int position)
{
    int line = 1;
    for (const SpokenSentence &s : book.sentences) {
        if (s.offset > position)
            break;
        line = s.line;
    }
    return line;
}

// The output's hidden twin beside it (partfiles.h), removed unless the book is whole.
class PartFile
{
public:
    explicit PartFile(const QString &target)
    {
        const QFileInfo info(QDir::cleanPath(target));
        static std::atomic<int> serial = 0;
        for (int attempt = 0; attempt < 100 && m_path.isEmpty(); ++attempt) {
            const QString name = QStringLiteral("%1/.%2.%3-%4.part")
                                     .arg(info.absolutePath(), info.fileName())
                                     .arg(QCoreApplication::applicationPid())
                                     .arg(serial++);
            if (!QFileInfo::exists(name))
                m_path = name;
        }
    }
    ~PartFile()
    {
        if (!m_path.isEmpty())
            QFile::remove(m_path);
    }
    PartFile(const PartFile &) = delete;
    PartFile &operator=(const PartFile &) = delete;

    const QString &path() const { return m_path; }
    bool moveTo(const QString &target, QString *problem)
    {
        std::error_code ec;
        std::filesystem::rename(QFile::encodeName(m_path).toStdString(), QFile::encodeName(target).toStdString(), ec);
        if (ec) {
            *problem = QString::fromStdString(ec.message());
            return false;
        }
        m_path.clear();
        return true;
    }

private:
    QString m_path;
};

QByteArray coverPng(const BookRequest &request, QString *error)
{
    SvgFace face(request.face, request.style);
    for (const QString &layer : request.layerFiles) {
        if (!face.addLayerFile(layer, error))
            return {};
    }
    const QRectF frame = headFrame(request.face);
    face.setFrame(frame);
    QSvgRenderer renderer(face.svg());
    const int side = 1200;
    QImage image(side, int(std::lround(side * frame.height() / std::max(1.0, frame.width()))), QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    renderer.render(&painter);
    painter.end();
    QByteArray png;
    QBuffer buffer(&png);
    buffer.open(QIODevice::WriteOnly);
    image.save(&buffer, "PNG");
    return png;
}

// The sound of `audio` as MP3 in `dir` (a core media type of EPUB, which every reading system
// plays; FFmpeg encodes it several times faster than AAC); its path, or empty with *error.
QString encodedSound(const QTemporaryDir &dir, const QString &name, const Audio &audio, QString *error)
{
    const QString path = dir.filePath(name);
    return writeAudio(path, audio, error) ? path : QString();
}

class BookWriter
{
public:
    BookWriter(const BookRequest &request, SpokenBook &book, EpubZip &zip, BookResult &result)
        : m_request(request)
        , m_book(book)
        , m_zip(zip)
        , m_result(result)
    { }

    // Lays out the sentences of chapter `c` on the clips of `audioHref` between beginMs and endMs,
    // draws its pages and writes them. `progress` gets the fraction of the chapter's pages done.
    bool writeChapter(int c, const QString &audioHref, qint64 beginMs, qint64 endMs,
        const std::function<void(double)> &progress, const std::atomic_bool *cancel);

    QVector<epub::ManifestItem> manifest;
    QStringList spine;
    QVector<epub::NavEntry> nav;
    // The pages' videos (BookFaceMedia::Video), or null: the face is an animated SVG.
    PageVideoWriter *videos = nullptr;

private:
    bool fail(BookStatus status, const QString &error)
    {
        m_result.status = status;
        m_result.error = error;
        return false;
    }
    bool writePage(int page, int first, int last, const QVector<epub::PageSentence> &sentences,
        const QString &audioHref, const std::atomic_bool *cancel);

    const BookRequest &m_request;
    SpokenBook &m_book;
    EpubZip &m_zip;
    BookResult &m_result;
};

bool BookWriter::writeChapter(int c, const QString &audioHref, qint64 beginMs, qint64 endMs,
    const std::function<void(double)> &progress, const std::atomic_bool *cancel)
{
    const int first = m_book.chapterFirstSentence[c];
    const int end = m_book.chapterFirstSentence[c + 1];
    const QVector<LipsyncSyllable> &syllables = m_result.syllables;
    // Each sentence begins where its first syllable does (the chapter's first at the chapter's
    // start); one without syllables begins where the next one does.
    QVector<qint64> begins(end - first, -1);
    for (int i = first; i < end; ++i) {
        const SpokenSentence &s = m_book.sentences[i];
        if (i == first)
            begins[0] = beginMs;
        else if (s.firstSyllable >= 0)
            begins[i - first] = toMs(syllables[s.firstSyllable].start);
    }
    qint64 next = endMs;
    for (int i = end - 1; i >= first; --i) {
        if (begins[i - first] < 0)
            begins[i - first] = next;
        next = begins[i - first];
    }
    for (int i = 1; i < begins.size(); ++i)
        begins[i] = std::clamp(begins[i], begins[i - 1], endMs);

    QVector<epub::PageSentence> laidOut;
    for (int i = first; i < end; ++i) {
        const SpokenSentence &s = m_book.sentences[i];
        epub::PageSentence ps;
        const QString id = QStringLiteral("tf-s%1").arg(i + 1);
        const qint64 sentenceEnd = i + 1 < end ? begins[i + 1 - first] : endMs;
        ps.clip = {id, begins[i - first], sentenceEnd};
        const QString text = m_book.text.mid(s.offset, s.length);
        qsizetype at = 0;
        qint64 pieceBegin = ps.clip.beginMs;
        for (int k = 0; k < s.syllableCount; ++k) {
            const ScriptSyllable &syl = m_book.script.syllables[s.firstSyllable + k];
            const qsizetype pos = std::clamp(qsizetype(syl.position) - s.offset, at, text.size());
            if (pos > at)
                ps.pieces.append({text.mid(at, pos - at), {}});
            const qint64 nextBegin = k + 1 < s.syllableCount
                ? std::clamp(toMs(syllables[s.firstSyllable + k + 1].start), pieceBegin, sentenceEnd)
                : sentenceEnd;
            ps.pieces.append(
                {text.mid(pos, syl.length), {QStringLiteral("%1-%2").arg(id).arg(k + 1), pieceBegin, nextBegin}});
            pieceBegin = nextBegin;
            at = std::min(text.size(), pos + syl.length);
        }
        if (at < text.size())
            ps.pieces.append({text.mid(at), {}});
        laidOut.append(ps);
    }

    for (int i = first; i < end;) {
        int j = i;
        while (j < end && m_book.sentences[j].page == m_book.sentences[i].page)
            ++j;
        if (!writePage(m_book.sentences[i].page, i, j, laidOut.mid(i - first, j - i), audioHref, cancel))
            return false;
        if (i == first) {
            const QString title = m_book.chapterTitles[c].isEmpty() ? m_request.title : m_book.chapterTitles[c];
            nav.append({title, manifest[manifest.size() - 2].href,
                std::max(1, m_book.pageHeadingLevel[m_book.sentences[i].page])});
        }
        if (progress)
            progress(double(j - first) / std::max(1, end - first));
        i = j;
    }
    m_result.chapters += 1;
    return true;
}

bool BookWriter::writePage(int page, int first, int last, const QVector<epub::PageSentence> &sentences,
    const QString &audioHref, const std::atomic_bool *cancel)
{
    const qint64 beginMs = sentences.first().clip.beginMs;
    const qint64 endMs = sentences.last().clip.endMs;
    const double duration = std::max(0.04, double(endMs - beginMs) / 1000.0);
    const double shift = double(beginMs) / 1000.0;

    // The face's timeline: the page's syllables from the page's start.
    QVector<LipsyncSyllable> spoken;
    for (int i = first; i < last; ++i) {
        const SpokenSentence &s = m_book.sentences[i];
        for (int k = 0; k < s.syllableCount; ++k) {
            LipsyncSyllable syl = m_result.syllables[s.firstSyllable + k];
            syl.start -= shift;
            syl.end -= shift;
            for (ShapeKey &key : syl.shapes)
                key.start -= shift;
            spoken.append(syl);
        }
    }
    Timeline timeline;
    timeline.setFrameRate(kFaceFps);
    timeline.addMouthCues(mouthCues(spoken, duration));
    timeline.generateBlinks(quint32(page) * 2654435761u, duration);

    const QString pageName = numbered("p", page + 1, ".xhtml");
    epub::PageDocument doc;
    QString error;
    if (videos) {
        ExportStatus status = ExportStatus::Failed;
        const QString video = videos->write(timeline, beginMs, endMs, cancel, &status, &error);
        if (status == ExportStatus::Cancelled)
            return fail(BookStatus::Cancelled, withProblem(m_request.outputPath, QStringLiteral("cancelled")));
        const QString href = numbered("video/p", page + 1, ".mp4");
        if (video.isEmpty() || !m_zip.addFile(kPackageDir + href, video))
            return fail(BookStatus::Failed, video.isEmpty() ? error : m_zip.errorString());
        manifest.append({numbered("video-p", page + 1, ""), href, QStringLiteral("video/mp4"), {}, {}});
        doc.faceVideoHref = QStringLiteral("../") + href;
        doc.posterHref = QStringLiteral("../images/cover.png");
        doc.videoWidth = PageVideoWriter::frameSize().width();
        doc.videoHeight = PageVideoWriter::frameSize().height();
    } else {
        AnimationExportOptions options;
        options.audio = ExportAudio::None;
        options.frame = headFrame(m_request.face);
        options.layerFiles = m_request.layerFiles;
        options.cancel = cancel;
        const std::optional<SmilElement> face
            = exportSmilElement(m_request.face, m_request.style, timeline, m_request.mouthShapes, options, &error);
        if (isCancelled(cancel))
            return fail(BookStatus::Cancelled, withProblem(m_request.outputPath, QStringLiteral("cancelled")));
        if (!face)
            return fail(BookStatus::BadInput, error);
        doc.faceSvg = face->svg;
    }

    doc.language = m_result.language;
    const int chapter = m_book.sentences[first].chapter;
    doc.title = m_book.chapterTitles[chapter].isEmpty() ? m_request.title : m_book.chapterTitles[chapter];
    doc.headingLevel = m_book.sentences[first].heading ? m_book.pageHeadingLevel[page] : 0;
    doc.sentences = sentences;
    doc.stylesheetHref = QStringLiteral("../book.css");

    const QString overlayName = numbered("p", page + 1, ".smil");
    const QString pageId = numbered("p", page + 1, "");
    const QString overlayId = numbered("mo", page + 1, "");
    const bool bySyllable = m_request.highlight == BookHighlight::Syllable;
    if (!m_zip.add(kPackageDir + QStringLiteral("text/") + pageName, epub::pageXhtml(doc), true)
        || !m_zip.add(kPackageDir + QStringLiteral("smil/") + overlayName,
            epub::overlaySmil(
                doc, QStringLiteral("../text/") + pageName, QStringLiteral("../") + audioHref, bySyllable),
            true))
        return fail(BookStatus::Failed, m_zip.errorString());
    manifest.append({pageId, QStringLiteral("text/") + pageName, QStringLiteral("application/xhtml+xml"),
        videos ? QString() : QStringLiteral("svg"), overlayId});
    manifest.append({overlayId, QStringLiteral("smil/") + overlayName, QStringLiteral("application/smil+xml"), {}, {},
        endMs - beginMs});
    spine.append(pageId);
    for (int i = first; i < last; ++i) {
        const epub::PageSentence &s = sentences[i - first];
        const SpokenSentence &spokenSentence = m_book.sentences[i];
        m_result.sentences.append({QStringLiteral("text/") + pageName, s.clip.id, audioHref,
            spokenSentence.syllableCount > 0 ? spokenSentence.firstSyllable : -1, s.clip.beginMs, s.clip.endMs});
    }
    m_result.pages += 1;
    return true;
}

BookResult failed(BookStatus status, const QString &error)
{
    BookResult r;
    r.status = status;
    r.error = error;
    return r;
}

} // namespace

QStringList bookLanguages()
{
    return {QStringLiteral("zh-Hant"), QStringLiteral("zh-Hans"), QStringLiteral("en")};
}

BookResult exportBook(const BookRequest &request, const BookProgressFn &progress, const std::atomic_bool *cancel)
{
    auto report = [&progress](double fraction, const QString &stage) {
        if (progress)
            progress(std::clamp(fraction, 0.0, 1.0), stage);
    };
    const QString out = request.outputPath;
    const auto cancelled
        = [&out]() { return failed(BookStatus::Cancelled, withProblem(out, QStringLiteral("cancelled"))); };

    // The text.
    QString problem;
    const std::optional<QByteArray> bytes = readUserFile(request.textPath, kMaxTextBytes, &problem);
    if (!bytes)
        return failed(BookStatus::BadInput, withProblem(request.textPath, problem));
    QStringDecoder utf8(QStringDecoder::Utf8);
    const QString text = utf8(*bytes);
    if (utf8.hasError())
        return failed(BookStatus::BadInput, withProblem(request.textPath, ExportText::tr("is not UTF-8 text")));
    const QString suffix = QFileInfo(request.textPath).suffix().toLower();
    const bool markdown = suffix == QLatin1StringView("md") || suffix == QLatin1StringView("markdown");
    const BookTextParse parse = parseBookText(text, markdown, request.textPath);
    if (!parse.ok())
        return failed(BookStatus::BadInput, parse.error);

    Language language = Language::Auto;
    if (request.language.startsWith(QLatin1StringView("zh")) && bookLanguages().contains(request.language))
        language = Language::Mandarin;
    else if (request.language == QLatin1StringView("en"))
        language = Language::English;
    else if (!request.language.isEmpty())
        return failed(BookStatus::BadInput,
            ExportText::tr("unknown book language '%1' (%2)")
                .arg(request.language, bookLanguages().join(QStringLiteral(", "))));

    SpokenBook book = layOut(parse);
    const ScriptParse script = parseScript(book.text, language);
    if (!script.ok()) {
        const ScriptProblem &p = script.problems.isEmpty() ? ScriptProblem {} : script.problems.first();
        return failed(BookStatus::BadInput,
            script.problems.isEmpty()
                ? withProblem(request.textPath, script.error)
                : withProblem(ExportText::tr("%1, line %2").arg(request.textPath).arg(lineAt(book, p.position)),
                    ExportText::tr("'%1' cannot be read aloud: %2").arg(p.text, p.reason)));
    }
    book.script = script.script;
    assignSyllables(book);

    BookResult result;
    result.language = !request.language.isEmpty()   ? request.language
        : book.script.language == Language::English ? QStringLiteral("en")
                                                    : QStringLiteral("zh");
    BookRequest meta = request;
    if (meta.title.isEmpty())
        meta.title = !parse.chapters.first().title.isEmpty() ? parse.chapters.first().title
                                                             : QFileInfo(request.textPath).completeBaseName();

    QTemporaryDir temporary;
    if (!temporary.isValid())
        return failed(BookStatus::Failed,
            withProblem(out, ExportText::tr("no room for temporary files: %1").arg(temporary.errorString())));

    // The recording: checked against the text's length, re-encoded for the book, aligned.
    QString recordingFile;
    if (!request.audioPath.isEmpty()) {
        if (const QString irregular = irregularFileProblem(request.audioPath); !irregular.isEmpty())
            return failed(BookStatus::BadInput, withProblem(request.audioPath, irregular));
        // Re-encoded a block at a time: an hour-long recording is never held whole.
        recordingFile = temporary.filePath(QStringLiteral("book.mp3"));
        const SoundCopy copied = copySound(
            request.audioPath, recordingFile, kBookSampleRate,
            [&](double f) { report(0.1 * f, ExportText::tr("reading the recording")); }, cancel);
        if (copied.status == SoundCopyStatus::Cancelled)
            return cancelled();
        if (!copied.ok())
            return failed(
                copied.status == SoundCopyStatus::BadInput ? BookStatus::BadInput : BookStatus::Failed, copied.error);
        const double seconds = copied.seconds;
        const bool english = book.script.language == Language::English;
        const double fastest = english ? kFastestWordsPerSecond : kFastestSyllablesPerSecond;
        const qsizetype units = book.script.syllables.size();
        if (seconds * fastest < double(units))
            return failed(BookStatus::BadInput,
                withProblem(request.audioPath,
                    (english ? ExportText::tr(
                         "the recording (%1 s) is shorter than the text: its %2 words need at least "
                         "%3 s even read fast (%4 a second)")
                             : ExportText::tr("the recording (%1 s) is shorter than the text: its %2 syllables need at "
                                              "least %3 s even read fast (%4 a second)"))
                        .arg(seconds, 0, 'f', 1)
                        .arg(units)
                        .arg(double(units) / fastest, 0, 'f', 1)
                        .arg(fastest)));
        if (isCancelled(cancel))
            return cancelled();
        report(0.1, ExportText::tr("aligning the recording with the text"));
        const LipsyncOutcome aligned = lipsyncRecording(
            request.audioPath, book.script, request.textPath,
            [&](double f, const QString &stage) { report(0.1 + 0.4 * f, stage); }, cancel);
        if (aligned.status == LipsyncStatus::Cancelled)
            return cancelled();
        if (!aligned.ok())
            return failed(aligned.status == LipsyncStatus::CannotAlign ? BookStatus::CannotAlign : BookStatus::BadInput,
                aligned.error);
        if (aligned.result.syllables.size() != book.script.syllables.size())
            return failed(BookStatus::CannotAlign,
                ExportText::tr("%1 and %2 could not be aligned: syllables were lost")
                    .arg(request.audioPath, request.textPath));
        result.syllables = aligned.result.syllables;
        result.duration = aligned.result.duration;
    }

    // The archive: the mimetype first and stored, as OCF asks.
    removeStaleParts(out);
    PartFile part(out);
    if (part.path().isEmpty())
        return failed(BookStatus::Failed, withProblem(out, ExportText::tr("cannot write beside it")));
    const QDateTime now = QDateTime::currentDateTimeUtc();
    const QDateTime modified = request.modified.isValid() ? request.modified : now.addMSecs(-now.time().msec());
    EpubZip zip(part.path(), modified);
    QString coverError;
    const QByteArray cover = coverPng(request, &coverError);
    if (cover.isEmpty())
        return failed(BookStatus::BadInput,
            coverError.isEmpty() ? withProblem(out, ExportText::tr("cannot draw the cover")) : coverError);
    zip.add(QStringLiteral("mimetype"), QByteArrayLiteral("application/epub+zip"), false);
    zip.add(QStringLiteral("META-INF/container.xml"), epub::containerXml(kPackageDir + QStringLiteral("package.opf")),
        true);
    zip.add(kPackageDir + QStringLiteral("book.css"), epub::stylesheet(), true);
    zip.add(kPackageDir + QStringLiteral("images/cover.png"), cover, false);
    zip.add(kPackageDir + QStringLiteral("cover.xhtml"),
        epub::coverXhtml(
            result.language, meta.title, meta.author, QStringLiteral("images/cover.png"), QStringLiteral("book.css")),
        true);
    if (!recordingFile.isEmpty())
        zip.addFile(kPackageDir + QStringLiteral("audio/book.mp3"), recordingFile);
    if (!zip.isOpen())
        return failed(BookStatus::Failed, zip.errorString());

    BookWriter writer(meta, book, zip, result);
    std::optional<PageVideoWriter> videos;
    if (request.faceMedia == BookFaceMedia::Video) {
        videos.emplace(meta, temporary.path());
        writer.videos = &*videos;
        // The pages' videos are cut from the recording as the book reads it.
        if (!recordingFile.isEmpty() && !videos->openSound(recordingFile, &problem))
            return failed(BookStatus::Failed, problem);
    }
    if (!recordingFile.isEmpty() && !videos)
        QFile::remove(recordingFile);
    writer.manifest = {
        {QStringLiteral("nav"), QStringLiteral("nav.xhtml"), QStringLiteral("application/xhtml+xml"),
            QStringLiteral("nav"), {}},
        {QStringLiteral("css"), QStringLiteral("book.css"), QStringLiteral("text/css"), {}, {}},
        {QStringLiteral("cover-image"), QStringLiteral("images/cover.png"), QStringLiteral("image/png"),
            QStringLiteral("cover-image"), {}},
        {QStringLiteral("cover"), QStringLiteral("cover.xhtml"), QStringLiteral("application/xhtml+xml"), {}, {}},
    };
    writer.spine = {QStringLiteral("cover")};
    if (!recordingFile.isEmpty())
        writer.manifest.append(
            {QStringLiteral("audio"), QStringLiteral("audio/book.mp3"), QStringLiteral("audio/mpeg"), {}, {}});

    // Chapter by chapter: spoken (by the voice), drawn and written before the next one.
    const int chapters = int(book.chapterTitles.size());
    const double total = std::max<qsizetype>(1, book.script.syllables.size());
    const qint64 recordingMs = toMs(result.duration);
    for (int c = 0; c < chapters; ++c) {
        const int firstSentence = book.chapterFirstSentence[c];
        const int endSentence = book.chapterFirstSentence[c + 1];
        int firstSyllable = -1, syllableEnd = -1;
        for (int i = firstSentence; i < endSentence; ++i) {
            const SpokenSentence &s = book.sentences[i];
            if (s.syllableCount > 0) {
                firstSyllable = firstSyllable < 0 ? s.firstSyllable : firstSyllable;
                syllableEnd = s.firstSyllable + s.syllableCount;
            }
        }
        const double from = firstSyllable < 0 ? 0.0 : firstSyllable / total;
        const double to = syllableEnd < 0 ? from : syllableEnd / total;
        QString audioHref;
        qint64 beginMs = 0, endMs = 0;
        if (!recordingFile.isEmpty()) {
            // The recording's stretch from this chapter's first syllable to the next one's.
            audioHref = QStringLiteral("audio/book.mp3");
            beginMs = c == 0 || firstSyllable < 0 ? 0 : toMs(result.syllables[firstSyllable].start);
            endMs = recordingMs;
            for (int n = c + 1; n < chapters && endMs == recordingMs; ++n) {
                for (int i = book.chapterFirstSentence[n]; i < book.chapterFirstSentence[n + 1]; ++i) {
                    if (book.sentences[i].syllableCount > 0) {
                        endMs = toMs(result.syllables[book.sentences[i].firstSyllable].start);
                        break;
                    }
                }
            }
            const auto pages
                = [&](double f) { report(0.5 + 0.5 * (from + (to - from) * f), ExportText::tr("drawing the pages")); };
            if (!writer.writeChapter(c, audioHref, beginMs, std::max(beginMs, endMs), pages, cancel))
                return failed(result.status, result.error);
            continue;
        }
        // The voice reads the chapter into its own file.
        Script chapterScript;
        chapterScript.language = book.script.language;
        if (firstSyllable >= 0)
            chapterScript.syllables = book.script.syllables.mid(firstSyllable, syllableEnd - firstSyllable);
        report(from, ExportText::tr("reading chapter %1 of %2 aloud").arg(c + 1).arg(chapters));
        const TtsResult spoken = synthesize(
            chapterScript, request.voice,
            [&](double f, const QString &) {
                report(from + (to - from) * 0.6 * f,
                    ExportText::tr("reading chapter %1 of %2 aloud").arg(c + 1).arg(chapters));
            },
            cancel);
        if (isCancelled(cancel))
            return cancelled();
        if (!spoken.ok())
            return failed(BookStatus::BadInput, withProblem(request.textPath, spoken.error));
        const LipsyncResult timed = lipsyncResult(chapterScript, spoken);
        if (timed.syllables.size() != chapterScript.syllables.size())
            return failed(BookStatus::Failed,
                withProblem(request.textPath, ExportText::tr("the voice lost syllables of chapter %1").arg(c + 1)));
        result.syllables += timed.syllables;
        result.duration += timed.duration;
        audioHref = numbered("audio/c", c + 1, ".mp3");
        const QString file = encodedSound(temporary, QStringLiteral("chapter.mp3"), spoken.audio, &problem);
        if (file.isEmpty())
            return failed(BookStatus::Failed, problem);
        if (!zip.addFile(kPackageDir + audioHref, file))
            return failed(BookStatus::Failed, zip.errorString());
        writer.manifest.append({numbered("audio-c", c + 1, ""), audioHref, QStringLiteral("audio/mpeg"), {}, {}});
        // The chapter's pages' videos are cut from its sound as the book reads it.
        if (videos && !videos->openSound(file, &problem))
            return failed(BookStatus::Failed, problem);
        const auto pages
            = [&](double f) { report(from + (to - from) * (0.6 + 0.4 * f), ExportText::tr("drawing the pages")); };
        if (!writer.writeChapter(c, audioHref, 0, toMs(timed.duration), pages, cancel))
            return failed(result.status, result.error);
        QFile::remove(file);
    }

    // The navigation and the package document, now that every page is known.
    zip.add(kPackageDir + QStringLiteral("nav.xhtml"), epub::navXhtml(result.language, meta.title, writer.nav), true);
    const QByteArray hash
        = QCryptographicHash::hash(*bytes + meta.title.toUtf8() + meta.author.toUtf8(), QCryptographicHash::Sha1);
    epub::PackageMetadata package {QStringLiteral("urn:uuid:")
            + QUuid::createUuidV5(QUuid(QStringLiteral("{6ba7b811-9dad-11d1-80b4-00c04fd430c8}")), hash)
                  .toString(QUuid::WithoutBraces),
        meta.title, meta.author, result.language, modified};
    zip.add(
        kPackageDir + QStringLiteral("package.opf"), epub::packageOpf(package, writer.manifest, writer.spine), true);
    if (isCancelled(cancel))
        return cancelled();
    if (!zip.finish())
        return failed(BookStatus::Failed, zip.errorString());
    if (!part.moveTo(out, &problem))
        return failed(BookStatus::Failed, withProblem(out, ExportText::tr("cannot write: %1").arg(problem)));
    report(1, ExportText::tr("done"));
    result.status = BookStatus::Done;
    return result;
}

} // namespace toonface
