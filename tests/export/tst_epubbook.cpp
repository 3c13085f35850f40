// The read-aloud EPUB 3 book: its text's chapters, pages and sentences; the archive; the package
// document, navigation and Media Overlays; the overlay's times against the speech's; bad input;
// and epubcheck's verdict.

#include "export/bookvideo.h"
#include "export/epubbook.h"
#include "export/epubtext.h"
#include "export/epubzip.h"
#include "face/averageface.h"
#include "media/mediareader.h"
#include "shareddata.h"
#include "speech/audio.h"
#include "speech/lipsync.h"
#include "testmain.h"
#include "xmltree.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <map>

using namespace toonface;
using toonface::test::Node;

namespace {

QString writeText(const QTemporaryDir &dir, const QString &name, const QString &text)
{
    const QString path = dir.filePath(name);
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        return {};
    f.write(text.toUtf8());
    return path;
}

BookRequest request(const QString &text, const QString &out)
{
    BookRequest r;
    r.textPath = text;
    r.outputPath = out;
    r.face = averageFace(QRectF(106, 130, 300, 330), QSize(512, 512));
    r.style = Style::preset(QStringLiteral("normal"));
    r.author = QStringLiteral("A. Writer");
    r.modified = QDateTime(QDate(2026, 1, 2), QTime(3, 4, 5), Qt::UTC);
    return r;
}

// The book read back: its entries by name, in order.
struct Book
{
    std::vector<ZipEntry> entries;
    QByteArray raw;
    QByteArray entry(const QString &name) const
    {
        for (const ZipEntry &e : entries) {
            if (e.name == name)
                return e.data;
        }
        return {};
    }
    bool has(const QString &name) const
    {
        return std::any_of(entries.cbegin(), entries.cend(), [&](const ZipEntry &e) { return e.name == name; });
    }
};

Book readBook(const QString &path)
{
    Book b;
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return b;
    b.raw = f.readAll();
    QString error;
    b.entries = readZip(b.raw, &error);
    return b;
}

Node xml(const QByteArray &data)
{
    Node root;
    QString error;
    if (!test::parseXml(data, &root, &error))
        qWarning("%s", qPrintable(error));
    return root;
}

qint64 clipMs(const QString &value)
{
    static const QRegularExpression re(QStringLiteral("^(\\d+)\\.(\\d{3})s$"));
    const QRegularExpressionMatch m = re.match(value);
    return m.hasMatch() ? m.captured(1).toLongLong() * 1000 + m.captured(2).toLongLong() : -1;
}

qint64 clockMs(const QString &value)
{
    static const QRegularExpression re(QStringLiteral("^(\\d+):(\\d\\d):(\\d\\d)\\.(\\d{3})$"));
    const QRegularExpressionMatch m = re.match(value);
    return m.hasMatch()
        ? ((m.captured(1).toLongLong() * 60 + m.captured(2).toLongLong()) * 60 + m.captured(3).toLongLong()) * 1000
            + m.captured(4).toLongLong()
        : -1;
}

struct Clip
{
    QString text; // page#id
    QString audio;
    qint64 begin = 0, end = 0;
};

// The leaf clips of an overlay in order.
QVector<Clip> clipsOf(const Node &smil)
{
    QVector<Clip> clips;
    for (const Node *par : test::elementsNamed(smil, QStringLiteral("par"))) {
        Clip c;
        for (const Node &child : par->children) {
            if (child.name == QLatin1StringView("text"))
                c.text = child.attribute(QStringLiteral("src"));
            if (child.name == QLatin1StringView("audio")) {
                c.audio = child.attribute(QStringLiteral("src"));
                c.begin = clipMs(child.attribute(QStringLiteral("clipBegin")));
                c.end = clipMs(child.attribute(QStringLiteral("clipEnd")));
            }
        }
        clips.append(c);
    }
    return clips;
}

QString epubcheckJar()
{
    for (const QString &p : {QStringLiteral("/usr/share/java/epubcheck.jar")}) {
        if (QFileInfo::exists(p))
            return p;
    }
    return {};
}

// epubcheck's report on `path`; empty when it found nothing to say.
QString epubcheckProblems(const QString &path)
{
    QProcess p;
    p.setProcessChannelMode(QProcess::MergedChannels);
    // A short run of a large program: the quick compiler only and the serial collector halve
    // its CPU time (8.1 -> 3.9 CPU-s on a small book, the verdict the same), which the suite
    // spends seven times.
    p.start(QStringLiteral("java"),
        {QStringLiteral("-XX:TieredStopAtLevel=1"), QStringLiteral("-XX:+UseSerialGC"), QStringLiteral("-jar"),
            epubcheckJar(), path});
    if (!p.waitForFinished(300000))
        return QStringLiteral("epubcheck did not finish");
    const QString out = QString::fromUtf8(p.readAll());
    return p.exitCode() == 0 && out.contains(QLatin1StringView("No errors or warnings detected")) ? QString() : out;
}

const QString kEnglish = QStringLiteral(
    "# The Fox\n\nA quick brown fox jumps over the lazy dog. The dog sleeps!\n\nWhy does the fox run? It is "
    "late.\n\n## Night\n\nThe moon rises over the hill.\n\n# The Dog\n\nThe dog wakes up and barks.\n");
const QString kChinese
    = QStringLiteral("# 第一章\n\n你好。我是一本書。\n\n今天天氣很好！我們去公園吧。\n\n# 第二章\n\n再見。\n");

} // namespace

class TestEpubBook : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // The archive: the mimetype first, stored, at the start (OCF); other entries deflated or
    // stored, read back whole.
    void zipArchive()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("a.zip"));
        const QByteArray text = QByteArray("<p>hello</p>\n").repeated(200);
        const QString file = writeText(dir, QStringLiteral("blob.bin"), QStringLiteral("binary\x01 data"));
        {
            EpubZip zip(path, QDateTime(QDate(2026, 3, 4), QTime(5, 6, 8), Qt::UTC));
            QVERIFY(zip.add(QStringLiteral("mimetype"), "application/epub+zip", false));
            QVERIFY(zip.add(QStringLiteral("OEBPS/text/页.xhtml"), text, true));
            QVERIFY(zip.addFile(QStringLiteral("OEBPS/audio/a.m4a"), file));
            QVERIFY(zip.finish());
        }
        const Book b = readBook(path);
        QCOMPARE(b.raw.mid(30, 8), QByteArray("mimetype"));
        QCOMPARE(b.raw.mid(38, 20), QByteArray("application/epub+zip"));
        QCOMPARE(int(b.raw[8]), 0); // stored
        QCOMPARE(b.entries.size(), size_t(3));
        QCOMPARE(b.entries[0].name, QStringLiteral("mimetype"));
        QCOMPARE(b.entries[1].name, QStringLiteral("OEBPS/text/页.xhtml"));
        QCOMPARE(b.entries[1].method, quint16(8));
        QCOMPARE(b.entries[1].data, text);
        QVERIFY(b.raw.size() < text.size()); // deflated
        QCOMPARE(b.entries[2].method, quint16(0));
        QCOMPARE(b.entries[2].data, QByteArray("binary\x01 data"));
        // unzip agrees, when it is installed.
        const QString unzip = QStandardPaths::findExecutable(QStringLiteral("unzip"));
        if (!unzip.isEmpty()) {
            QProcess p;
            p.start(unzip, {QStringLiteral("-tq"), path});
            QVERIFY(p.waitForFinished(30000));
            QCOMPARE(p.exitCode(), 0);
        }
    }

    // Chapters at headings, a page per paragraph, sentences at their end marks; Markdown's
    // marks gone, its code left out.
    void textLayout()
    {
        const QString md = QStringLiteral(
            "Before any heading. Still before.\n\n# One *big* chapter\n\nFirst line of a paragraph\nwrapped here. "
            "\"Quoted end!\" Then e.g. 3.14 stays.\n\n```\ncode();\n```\n\n- An **item** with a "
            "[link](http://x.org).\n\n## Sub\n\n中文第一句。第二句！\n第三句\n");
        const BookTextParse parse = parseBookText(md, true, QStringLiteral("x.md"));
        QVERIFY2(parse.ok(), qPrintable(parse.error));
        QCOMPARE(parse.chapters.size(), 3);
        QCOMPARE(parse.chapters[0].title, QString());
        QCOMPARE(parse.chapters[0].pages[0].sentences.size(), 2);
        QCOMPARE(parse.chapters[1].title, QStringLiteral("One big chapter"));
        QCOMPARE(parse.chapters[1].pages.size(), 2);
        const BookPage &first = parse.chapters[1].pages[0];
        QCOMPARE(first.headingLevel, 1);
        QCOMPARE(first.heading.first().text, QStringLiteral("One big chapter"));
        QStringList sentences;
        for (const BookSentence &s : first.sentences)
            sentences << s.text;
        QCOMPARE(sentences,
            QStringList({QStringLiteral("First line of a paragraph wrapped here."), QStringLiteral("\"Quoted end!\""),
                QStringLiteral("Then e.g."), QStringLiteral("3.14 stays.")}));
        QCOMPARE(first.sentences[1].line, 6);
        QCOMPARE(parse.chapters[1].pages[1].sentences.first().text, QStringLiteral("An item with a link."));
        QCOMPARE(parse.chapters[2].pages[0].headingLevel, 2);
        QStringList chinese;
        for (const BookSentence &s : parse.chapters[2].pages[0].sentences)
            chinese << s.text;
        QCOMPARE(chinese,
            QStringList({QStringLiteral("中文第一句。"), QStringLiteral("第二句！"), QStringLiteral("第三句")}));
        // Without blank lines every line is a paragraph.
        const BookTextParse lines = parseBookText(QStringLiteral("一行。\n二行。\n"), false, QStringLiteral("x.txt"));
        QCOMPARE(lines.chapters.size(), 1);
        QCOMPARE(lines.chapters[0].pages.size(), 2);
    }

    void badText_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("problem");
        QTest::newRow("empty") << "e.txt"
                               << ""
                               << "empty";
        QTest::newRow("blank") << "b.txt"
                               << "\n  \n\n"
                               << "empty";
        QTest::newRow("headings only") << "h.md"
                                       << "# One\n\n## Two\n"
                                       << "no sentence ends";
        QTest::newRow("no sentence end") << "n.txt"
                                         << "hello there\nand more words\n"
                                         << "no sentence ends";
        QTest::newRow("unspeakable") << "u.txt"
                                     << "Hello. ⓧⓨⓩ ☃☃.\n"
                                     << "line 1";
    }

    // Bad text: a clear error naming the file, and no book (nor a part of one).
    void badText()
    {
        QFETCH(QString, name);
        QFETCH(QString, text);
        QFETCH(QString, problem);
        QTemporaryDir dir;
        const QString out = dir.filePath(QStringLiteral("book.epub"));
        const BookResult r = exportBook(request(writeText(dir, name, text), out));
        QCOMPARE(r.status, BookStatus::BadInput);
        QVERIFY2(r.error.contains(name) && r.error.contains(problem), qPrintable(r.error));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList {name});
    }

    // A recording far shorter than the text is refused before it is aligned.
    void recordingShorterThanText()
    {
        QTemporaryDir dir;
        const ScriptParse script = parseScript(QStringLiteral("short words."), Language::English);
        const TtsResult spoken = synthesize(script.script);
        QVERIFY2(spoken.ok(), qPrintable(spoken.error));
        const QString wav = dir.filePath(QStringLiteral("short.wav"));
        QString error;
        QVERIFY(writeAudio(wav, spoken.audio, &error));
        const QString text = writeText(dir, QStringLiteral("long.txt"),
            QStringLiteral("These many words cannot all fit into a recording that lasts for under a second. ")
                .repeated(4));
        BookRequest req = request(text, dir.filePath(QStringLiteral("book.epub")));
        req.audioPath = wav;
        const BookResult r = exportBook(req);
        QCOMPARE(r.status, BookStatus::BadInput);
        QVERIFY2(
            r.error.contains(wav) && r.error.contains(QLatin1StringView("shorter than the text")), qPrintable(r.error));
        QVERIFY(!QFileInfo::exists(req.outputPath));
    }

    void spokenBook_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("language");
        QTest::addColumn<bool>("bySyllable");
        QTest::newRow("english") << kEnglish << "en" << false;
        QTest::newRow("english by word") << kEnglish << "en" << true;
        QTest::newRow("chinese") << kChinese << "zh-Hant" << false;
        QTest::newRow("chinese by character") << kChinese << "zh-Hans" << true;
    }

    // A book read by the voice: the package document, the navigation, a page and an overlay per
    // paragraph, the overlays' clips tiling each chapter's sound from its syllables' times.
    void spokenBook()
    {
        QFETCH(QString, text);
        QFETCH(QString, language);
        QFETCH(bool, bySyllable);
        QTemporaryDir dir;
        BookRequest req
            = request(writeText(dir, QStringLiteral("story.md"), text), dir.filePath(QStringLiteral("b.epub")));
        req.language = language;
        req.highlight = bySyllable ? BookHighlight::Syllable : BookHighlight::Sentence;
        QVector<double> fractions;
        const BookResult r = exportBook(req, [&](double f, const QString &) { fractions.append(f); });
        QVERIFY2(r.ok(), qPrintable(r.error));
        QVERIFY(!fractions.isEmpty() && fractions.last() == 1.0);
        QVERIFY(std::is_sorted(fractions.cbegin(), fractions.cend()));
        const Book b = readBook(req.outputPath);
        QVERIFY(!b.entries.empty());
        QCOMPARE(b.entries.front().name, QStringLiteral("mimetype"));
        QCOMPARE(b.entries.front().method, quint16(0));

        // Container -> package document.
        const Node container = xml(b.entry(QStringLiteral("META-INF/container.xml")));
        const QString opfPath = test::elementsNamed(container, QStringLiteral("rootfile"))
                                    .value(0)
                                    ->attribute(QStringLiteral("full-path"));
        const QString base = opfPath.left(opfPath.lastIndexOf(QLatin1Char('/')) + 1);
        const Node opf = xml(b.entry(opfPath));
        QCOMPARE(opf.attribute(QStringLiteral("version")), QStringLiteral("3.0"));
        QCOMPARE(test::elementsNamed(opf, QStringLiteral("dc:language")).size(), 1);
        QCOMPARE(test::elementsNamed(opf, QStringLiteral("dc:title")).size(), 1);
        QCOMPARE(test::elementsNamed(opf, QStringLiteral("dc:creator")).size(), 1);
        QVERIFY(b.entry(opfPath).contains("<dc:language>" + language.toUtf8() + "</dc:language>"));
        QVERIFY(b.entry(opfPath).contains("<dc:creator id=\"tf-author\">A. Writer</dc:creator>"));
        QVERIFY(b.entry(opfPath).contains("<dc:title>" + text.section(QLatin1Char('\n'), 0, 0).mid(2).toUtf8()));
        QVERIFY(b.entry(opfPath).contains("2026-01-02T03:04:05Z"));

        std::map<QString, const Node *> items;
        for (const Node *item : test::elementsNamed(opf, QStringLiteral("item"))) {
            items[item->attribute(QStringLiteral("id"))] = item;
            QVERIFY2(b.has(base + item->attribute(QStringLiteral("href"))),
                qPrintable(item->attribute(QStringLiteral("href"))));
        }
        QVERIFY(items.count(QStringLiteral("cover-image")));
        QCOMPARE(items[QStringLiteral("cover-image")]->attribute(QStringLiteral("properties")),
            QStringLiteral("cover-image"));
        QVERIFY(b.entry(base + QStringLiteral("images/cover.png")).startsWith("\x89PNG"));

        // media:duration of each overlay and their sum.
        std::map<QString, qint64> durations;
        qint64 total = -1;
        const QString opfText = QString::fromUtf8(b.entry(opfPath));
        const QRegularExpression durationRe(
            QStringLiteral("<meta property=\"media:duration\"( refines=\"#([^\"]+)\")?>([^<]+)</meta>"));
        for (auto it = durationRe.globalMatch(opfText); it.hasNext();) {
            const QRegularExpressionMatch m = it.next();
            if (m.captured(2).isEmpty())
                total = clockMs(m.captured(3));
            else
                durations[m.captured(2)] = clockMs(m.captured(3));
        }
        qint64 sum = 0;
        for (const auto &[id, ms] : durations)
            sum += ms;
        QCOMPARE(total, sum);
        // The sound's length, each audio file's rounded to the millisecond.
        QVERIFY2(std::abs(double(total) - r.duration * 1000) <= 0.5 * r.chapters,
            qPrintable(QStringLiteral("%1 ms of overlays, %2 s of sound").arg(total).arg(r.duration)));

        // The spine's pages: each with its overlay, whose clips tile its stretch of the sound.
        const QList<const Node *> spine = test::elementsNamed(opf, QStringLiteral("itemref"));
        QCOMPARE(spine.size(), r.pages + 1); // the cover first
        std::map<QString, qint64> audioEnd; // how far each audio file has been read
        int sentenceIndex = 0;
        for (const Node *ref : spine.mid(1)) {
            const Node *page = items[ref->attribute(QStringLiteral("idref"))];
            QCOMPARE(page->attribute(QStringLiteral("properties")), QStringLiteral("svg"));
            const QString overlayId = page->attribute(QStringLiteral("media-overlay"));
            QVERIFY(items.count(overlayId));
            const QString pageHref = page->attribute(QStringLiteral("href"));
            const QByteArray pageData = b.entry(base + pageHref);
            const Node pageXml = xml(pageData);
            QCOMPARE(test::elementsNamed(pageXml, QStringLiteral("svg")).size(), 1);
            QVERIFY(!test::elementsNamed(pageXml, QStringLiteral("animate")).isEmpty());
            const QString smilHref = items[overlayId]->attribute(QStringLiteral("href"));
            const QVector<Clip> clips = clipsOf(xml(b.entry(base + smilHref)));
            QVERIFY(!clips.isEmpty());
            qint64 overlay = 0;
            for (const Clip &c : clips) {
                const QString audio = QDir::cleanPath(QFileInfo(smilHref).path() + QLatin1Char('/') + c.audio);
                QVERIFY2(b.has(base + audio), qPrintable(audio));
                QCOMPARE(c.begin, audioEnd[audio]); // no gap, no overlap
                QVERIFY(c.end > c.begin);
                audioEnd[audio] = c.end;
                overlay += c.end - c.begin;
                // The text it highlights is in the page.
                const QString fragment = c.text.section(QLatin1Char('#'), 1);
                QVERIFY(c.text.startsWith(QStringLiteral("../") + pageHref + QLatin1Char('#')));
                QVERIFY2(test::findId(pageXml, fragment), qPrintable(fragment));
            }
            QCOMPARE(overlay, durations[overlayId]);
            // The face moves for as long as the page is read.
            QVERIFY(pageData.contains("dur=\"" + QByteArray::number(double(overlay) / 1000.0, 'g', 10)));
            // Sentences: each begins at its first syllable (the first of a file at 0).
            for (; sentenceIndex < r.sentences.size() && r.sentences[sentenceIndex].page == pageHref; ++sentenceIndex) {
                const BookSentenceTiming &s = r.sentences[sentenceIndex];
                QVERIFY(test::findId(pageXml, s.id));
                QVERIFY(s.firstSyllable >= 0);
                const qint64 start = std::llround(r.syllables[s.firstSyllable].start * 1000);
                QVERIFY2(s.beginMs == start || s.beginMs == 0,
                    qPrintable(QStringLiteral("%1: %2 vs %3").arg(s.id).arg(s.beginMs).arg(start)));
                if (!bySyllable) {
                    const auto clip = std::find_if(clips.cbegin(), clips.cend(),
                        [&](const Clip &c) { return c.text.endsWith(QLatin1Char('#') + s.id); });
                    QVERIFY(clip != clips.cend());
                    QCOMPARE(clip->begin, s.beginMs);
                    QCOMPARE(clip->end, s.endMs);
                }
            }
        }
        QCOMPARE(sentenceIndex, r.sentences.size());
        // Every audio file is read to its end: the clips sum to the sound.
        qint64 read = 0;
        for (const auto &[audio, end] : audioEnd)
            read += end;
        QCOMPARE(read, total);
        // Each audio file decodes to the length its overlays give it (the encoder's frames round it up).
        for (const auto &[audio, end] : audioEnd) {
            const QString copy = dir.filePath(QStringLiteral("sound.mp3"));
            QFile f(copy);
            QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
            f.write(b.entry(base + audio));
            f.close();
            const AudioResult sound = loadAudio(copy);
            QVERIFY2(sound.ok(), qPrintable(sound.error));
            QVERIFY2(std::abs(sound.audio.duration() * 1000 - double(end)) < 70,
                qPrintable(
                    QStringLiteral("%1: %2 s decoded, %3 ms read").arg(audio).arg(sound.audio.duration()).arg(end)));
        }

        // The navigation: one entry per chapter heading, nested by level, each on its first page.
        const Node nav = xml(b.entry(base + QStringLiteral("nav.xhtml")));
        const QList<const Node *> links = test::elementsNamed(nav, QStringLiteral("a"));
        QCOMPARE(links.size(), r.chapters);
        QCOMPARE(r.chapters, int(text.count(QRegularExpression(QStringLiteral("(^|\\n)#")))));
        for (const Node *a : links)
            QVERIFY(b.has(base + a->attribute(QStringLiteral("href"))));
        if (text.contains(QLatin1StringView("## Night")))
            QCOMPARE(test::elementsNamed(nav, QStringLiteral("ol")).size(), 2);
    }

    // A recording of the shared data, made into a book by toonface-cli: every clip of the
    // overlay (one per syllable here) begins at the syllable's start as `toonface-cli lipsync`
    // aligns it, to the millisecond both write, and the clips sum to the recording. Each in a
    // process of its own: alignments made one after another in one process differ slightly.
    void recordedBook_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("text"); // the transcript with its sentences ended; empty: the .txt
        for (const char *name : {"BAC009S0002W0122", "BAC009S0002W0123", "NST_ID001"})
            QTest::newRow(name) << QString::fromLatin1(name) << QString();
        QTest::newRow("p2fa_test1") << QStringLiteral("p2fa_test1")
                                    << QStringLiteral("你更喜欢老鹰还是鹦鹉？我更喜欢鹦鹉。");
    }

    void recordedBook()
    {
        QFETCH(QString, name);
        QFETCH(QString, text);
        const QDir speech(QDir(testing::sharedDataDir()).filePath(QStringLiteral("speech")));
        const QString wav = speech.filePath(name + QStringLiteral(".wav"));
        QFile transcript(speech.filePath(name + QStringLiteral(".txt")));
        if (!QFileInfo::exists(wav) || !transcript.open(QIODevice::ReadOnly))
            QSKIP("the shared speech data is not here (../shared/data/speech)");
        // The transcripts have no sentence end: a book's text ends its sentence.
        if (text.isEmpty())
            text = QString::fromUtf8(transcript.readAll()).simplified() + QStringLiteral("。");
        QTemporaryDir dir;
        const QString textPath = writeText(dir, QStringLiteral("t.txt"), text + QStringLiteral("\n"));
        const QString out = dir.filePath(QStringLiteral("r.epub"));
        QProcess book;
        book.start(QStringLiteral(TOONFACE_CLI_PATH),
            {QStringLiteral("book"), textPath, QStringLiteral("--audio"), wav, QStringLiteral("--lang"),
                QStringLiteral("zh-Hans"), QStringLiteral("--highlight"), QStringLiteral("syllable"),
                QStringLiteral("-o"), out});
        QVERIFY(book.waitForFinished(120000));
        QVERIFY2(book.exitCode() == 0, book.readAllStandardError().constData());
        QProcess lipsync;
        lipsync.start(QStringLiteral(TOONFACE_CLI_PATH),
            {QStringLiteral("lipsync"), QStringLiteral("--audio"), wav, QStringLiteral("--script"), textPath});
        QVERIFY(lipsync.waitForFinished(120000));
        QCOMPARE(lipsync.exitCode(), 0);
        const QJsonObject aligned = QJsonDocument::fromJson(lipsync.readAllStandardOutput()).object();
        const QJsonArray syllables = aligned.value(QStringLiteral("syllables")).toArray();
        const auto ms = [](const QJsonValue &v) { return qint64(std::llround(v.toDouble() * 1000)); };

        const Book b = readBook(out);
        QVector<Clip> clips;
        for (const ZipEntry &e : b.entries) {
            if (e.name.endsWith(QLatin1StringView(".smil")))
                clips += clipsOf(xml(e.data));
        }
        QCOMPARE(clips.size(), syllables.size());
        QCOMPARE(clips.first().begin, 0);
        for (int k = 1; k < clips.size(); ++k) {
            QCOMPARE(clips[k].begin, ms(syllables[k].toObject().value(QStringLiteral("start"))));
            QCOMPARE(clips[k - 1].end, clips[k].begin);
        }
        QCOMPARE(clips.last().end, ms(aligned.value(QStringLiteral("duration"))));
        // A sentence's highlight (its <seq>) starts with its first syllable.
        if (text.contains(QStringLiteral("？"))) {
            const Node smil = xml(b.entry(QStringLiteral("OEBPS/smil/p00001.smil")));
            QCOMPARE(test::elementsNamed(smil, QStringLiteral("seq")).size(), 2);
        }

        if (epubcheckJar().isEmpty() || QStandardPaths::findExecutable(QStringLiteral("java")).isEmpty())
            return;
        const QString problems = epubcheckProblems(out);
        QVERIFY2(problems.isEmpty(), qPrintable(problems));
    }

    // The recording reaches the book whole, re-encoded a block at a time with progress, and a
    // cancel while it is read leaves nothing.
    void recordingStreamsIntoTheBook()
    {
        QTemporaryDir dir;
        const QString text = writeText(dir, QStringLiteral("story.md"), kEnglish);
        QString spokenText;
        for (const QString &line : kEnglish.split(QLatin1Char('\n'))) {
            if (!line.trimmed().isEmpty())
                spokenText += (line.startsWith(QLatin1Char('#')) ? line.mid(line.indexOf(QLatin1Char(' ')) + 1) : line)
                    + QLatin1Char('\n');
        }
        const ScriptParse script = parseScript(spokenText, Language::English);
        const TtsResult spoken = synthesize(script.script);
        QVERIFY2(spoken.ok(), qPrintable(spoken.error));
        const QString wav = dir.filePath(QStringLiteral("reading.wav"));
        QString error;
        QVERIFY2(writeAudio(wav, spoken.audio, &error), qPrintable(error));

        BookRequest req = request(text, dir.filePath(QStringLiteral("r.epub")));
        req.audioPath = wav;
        std::atomic_bool cancel = false;
        const BookResult stopped = exportBook(
            req,
            [&](double, const QString &stage) {
                if (stage == QLatin1StringView("reading the recording"))
                    cancel = true;
            },
            &cancel);
        QCOMPARE(stopped.status, BookStatus::Cancelled);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden),
            (QStringList {QStringLiteral("reading.wav"), QStringLiteral("story.md")}));

        QVector<double> reading;
        const BookResult r = exportBook(req, [&](double f, const QString &stage) {
            if (stage == QLatin1StringView("reading the recording"))
                reading.append(f);
        });
        QVERIFY2(r.ok(), qPrintable(r.error));
        QVERIFY(!reading.isEmpty() && std::is_sorted(reading.begin(), reading.end()));
        const QString mp3 = dir.filePath(QStringLiteral("book.mp3"));
        QFile f(mp3);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(readBook(req.outputPath).entry(QStringLiteral("OEBPS/audio/book.mp3")));
        f.close();
        const std::optional<MediaInfo> info = probeMedia(mp3, &error);
        QVERIFY2(info, qPrintable(error));
        QCOMPARE(info->audioCodec, QStringLiteral("mp3"));
        QCOMPARE(info->audioSampleRate, 24000);
        QVERIFY2(std::abs(info->audioDurationS - spoken.audio.duration()) < 0.1,
            qPrintable(QStringLiteral("%1 s of %2 s").arg(info->audioDurationS).arg(spoken.audio.duration())));
    }

    // The face as a video per page (for reading systems without media overlays): each page shows
    // its video, which the package lists as video/mp4 and which holds the face (H.264) reading
    // the page (AAC) for as long as the page's overlay reads it; epubcheck finds nothing to say.
    void videoFaceBook()
    {
        QTemporaryDir dir;
        BookRequest req
            = request(writeText(dir, QStringLiteral("story.md"), kEnglish), dir.filePath(QStringLiteral("v.epub")));
        req.faceMedia = BookFaceMedia::Video;
        const BookResult r = exportBook(req);
        QVERIFY2(r.ok(), qPrintable(r.error));
        const Book b = readBook(req.outputPath);
        const Node opf = xml(b.entry(QStringLiteral("OEBPS/package.opf")));
        std::map<QString, const Node *> items;
        for (const Node *item : test::elementsNamed(opf, QStringLiteral("item")))
            items[item->attribute(QStringLiteral("href"))] = item;
        const QRegularExpression videoRe(QStringLiteral("<video src=\"../(video/p\\d{5}\\.mp4)\""));
        int pages = 0;
        for (const Node *ref : test::elementsNamed(opf, QStringLiteral("itemref"))) {
            const Node *page = nullptr;
            for (const auto &[href, item] : items) {
                if (item->attribute(QStringLiteral("id")) == ref->attribute(QStringLiteral("idref")))
                    page = item;
            }
            QVERIFY(page);
            const QString pageHref = page->attribute(QStringLiteral("href"));
            if (!pageHref.startsWith(QLatin1StringView("text/")))
                continue; // the cover
            ++pages;
            QCOMPARE(page->attribute(QStringLiteral("properties")), QString()); // no SVG in it
            const QByteArray pageData = b.entry(QStringLiteral("OEBPS/") + pageHref);
            const Node pageXml = xml(pageData);
            QCOMPARE(test::elementsNamed(pageXml, QStringLiteral("svg")).size(), 0);
            QCOMPARE(test::elementsNamed(pageXml, QStringLiteral("video")).size(), 1);
            const QRegularExpressionMatch m = videoRe.match(QString::fromUtf8(pageData));
            QVERIFY2(m.hasMatch(), pageData.constData());
            const QString videoHref = m.captured(1);
            QVERIFY(items.count(videoHref));
            QCOMPARE(items[videoHref]->attribute(QStringLiteral("media-type")), QStringLiteral("video/mp4"));

            qint64 overlayMs = 0;
            for (const auto &[href, item] : items) {
                if (item->attribute(QStringLiteral("id")) == page->attribute(QStringLiteral("media-overlay"))) {
                    for (const Clip &c : clipsOf(xml(b.entry(QStringLiteral("OEBPS/") + href))))
                        overlayMs += c.end - c.begin;
                }
            }
            QVERIFY(overlayMs > 0);
            const QString video = dir.filePath(QStringLiteral("page.mp4"));
            QFile f(video);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(b.entry(QStringLiteral("OEBPS/") + videoHref));
            f.close();
            QString error;
            const std::optional<MediaInfo> info = probeMedia(video, &error);
            QVERIFY2(info, qPrintable(error));
            QCOMPARE(info->videoCodec, QStringLiteral("h264"));
            QCOMPARE(QSize(info->width, info->height), QSize(320, 320));
            QVERIFY(info->hasAudio);
            // Within a frame of the pages' video; the sound is cut or padded to the video's
            // length, give or take the AAC encoder's first and last frames (1024 samples at 48 kHz each).
            const double frameMs = 1000.0 / PageVideoWriter::frameRate();
            QCOMPARE(info->fps, PageVideoWriter::frameRate());
            QVERIFY2(std::abs(info->videoDurationS * 1000 - double(overlayMs)) <= frameMs + 1,
                qPrintable(QStringLiteral("%1: %2 s of video, %3 ms read")
                               .arg(videoHref)
                               .arg(info->videoDurationS)
                               .arg(overlayMs)));
            QVERIFY2(std::abs(info->audioDurationS * 1000 - double(overlayMs)) <= frameMs + 45,
                qPrintable(QStringLiteral("%1: %2 s of sound, %3 ms read")
                               .arg(videoHref)
                               .arg(info->audioDurationS)
                               .arg(overlayMs)));
        }
        QCOMPARE(pages, r.pages);

        if (epubcheckJar().isEmpty() || QStandardPaths::findExecutable(QStringLiteral("java")).isEmpty())
            return;
        const QString problems = epubcheckProblems(req.outputPath);
        QVERIFY2(problems.isEmpty(), qPrintable(problems));
    }

    // Cancelled: nothing is written, not even a hidden part.
    void cancelled()
    {
        QTemporaryDir dir;
        const QString text = writeText(dir, QStringLiteral("story.md"), kEnglish);
        std::atomic_bool cancel = false;
        const BookResult r = exportBook(
            request(text, dir.filePath(QStringLiteral("c.epub"))),
            [&](double f, const QString &) {
                if (f > 0.3)
                    cancel = true;
            },
            &cancel);
        QCOMPARE(r.status, BookStatus::Cancelled);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList {QStringLiteral("story.md")});
    }

    // epubcheck (the Debian package) finds nothing to report on books read by the voice.
    void epubcheckPasses_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<bool>("bySyllable");
        QTest::newRow("english") << kEnglish << false;
        QTest::newRow("chinese by character") << kChinese << true;
        // About ten minutes at the voice's 175 words a minute, in chapters of ten paragraphs.
        const QStringList words = QStringLiteral(
            "the little fox sees an old dog by the river and the garden keeps a story for every morning light")
                                      .split(QLatin1Char(' '));
        QString ten;
        for (int n = 0; n < 1750; ++n) {
            if (n % 300 == 0)
                ten += QStringLiteral("\n\n# Chapter %1\n\n").arg(n / 300 + 1);
            else if (n % 30 == 0)
                ten += QStringLiteral("\n\n");
            ten += words[(n * 7 + n / 19) % words.size()] + (n % 10 == 9 ? QStringLiteral(". ") : QStringLiteral(" "));
        }
        QTest::newRow("ten minutes") << ten + QStringLiteral("The end.") << false;
    }

    void epubcheckPasses()
    {
        QFETCH(QString, text);
        QFETCH(bool, bySyllable);
        if (epubcheckJar().isEmpty() || QStandardPaths::findExecutable(QStringLiteral("java")).isEmpty())
            QSKIP("epubcheck is not installed (packaging/install-deps.sh installs it)");
        QTemporaryDir dir;
        BookRequest req = request(writeText(dir, QStringLiteral("s.md"), text), dir.filePath(QStringLiteral("s.epub")));
        req.highlight = bySyllable ? BookHighlight::Syllable : BookHighlight::Sentence;
        const BookResult r = exportBook(req);
        QVERIFY2(r.ok(), qPrintable(r.error));
        const QString problems = epubcheckProblems(req.outputPath);
        QVERIFY2(problems.isEmpty(), qPrintable(problems));
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestEpubBook)
#include "tst_epubbook.moc"
