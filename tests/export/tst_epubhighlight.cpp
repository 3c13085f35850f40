// The read-aloud book in a browser: headless Chromium plays a book's Media Overlays in real time
// through a minimal overlay player (tests/data/export/overlayplayer.html) and the highlight it
// logs follows the overlay's clips, in the audio's own clock.

#include "chromium.h"
#include "export/epubbook.h"
#include "export/epubzip.h"
#include "face/averageface.h"
#include "testmain.h"
#include "xmltree.h"

#include <QDeadlineTimer>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <QUrl>

#include <map>
#include <optional>

using namespace toonface;
using toonface::test::Node;

namespace {

// How late, in the audio's clock, a highlight may switch after its clip has begun. The player
// polls the audio every 5 ms; on the shared 2-core machine, timers were seen firing up to a few
// tens of ms late. 0.15 s is still within the first word of a sentence (a syllable lasts about
// 0.2 s), so a highlight that late is on the sentence being spoken; one that followed the wrong
// clip, a missed seek or a page's stale audio is off by a sentence (0.5 s and more).
constexpr double kLateSwitch = 0.15;
// A seek into the MP3 lands where it was asked, to the decoder's rounding.
constexpr double kSeek = 0.005;

// One <par> of an overlay: its page, its text element and its audio clip.
struct Par
{
    QString page; // as the package document's manifest gives it
    QString id;
    QString audio;
    double begin = 0, end = 0;
};

// The clock values the book writes ("12.345s").
double seconds(const QString &v)
{
    return v.endsWith(QLatin1Char('s')) ? v.chopped(1).toDouble() : -1;
}

// What the browser logged: the lines the player wrote to the console ("tf-hl ...").
QStringList playerLines(const QByteArray &stderrText)
{
    static const QRegularExpression re(QStringLiteral("\"tf-hl ([^\"]*)\""));
    QStringList lines;
    for (auto it = re.globalMatch(QString::fromUtf8(stderrText)); it.hasNext();)
        lines.append(it.next().captured(1));
    return lines;
}

} // namespace

class TestEpubHighlight : public QObject
{
    Q_OBJECT

    QString m_chromium;

    // Runs the player page in headless Chromium until it logs "done" or `limit` ms pass; returns
    // what Chromium wrote on stderr (nullopt when it cannot start, `m_startFailure` set).
    std::optional<QByteArray> play(const QString &page, int limit)
    {
        QTemporaryDir profile;
        QProcess chromium;
        chromium.setProcessChannelMode(QProcess::SeparateChannels);
        // Real time: --virtual-time-budget would stop the media clock. file:// throughout (the
        // player reads the package with XMLHttpRequest, and an HTTP server without byte ranges
        // breaks seeking in the MP3). The console goes to stderr.
        chromium.start(m_chromium,
            {QStringLiteral("--headless"), QStringLiteral("--no-sandbox"), QStringLiteral("--disable-gpu"),
                QStringLiteral("--no-first-run"), QStringLiteral("--disable-background-networking"),
                QStringLiteral("--disable-component-update"), QStringLiteral("--disable-sync"),
                QStringLiteral("--autoplay-policy=no-user-gesture-required"),
                QStringLiteral("--allow-file-access-from-files"), QStringLiteral("--enable-logging=stderr"),
                QStringLiteral("--v=0"), QStringLiteral("--user-data-dir=") + profile.path(),
                QUrl::fromLocalFile(page).toString()});
        if (!chromium.waitForStarted(20000)) {
            m_startFailure = chromium.errorString();
            return std::nullopt;
        }
        QByteArray err;
        QDeadlineTimer deadline(limit);
        static const QRegularExpression done(QStringLiteral("\"tf-hl done "));
        while (!deadline.hasExpired() && chromium.state() == QProcess::Running) {
            chromium.waitForReadyRead(200);
            err += chromium.readAllStandardError();
            chromium.readAllStandardOutput();
            if (done.match(QString::fromUtf8(err)).hasMatch())
                break;
        }
        if (deadline.hasExpired())
            qWarning("the player did not finish in %d ms", limit);
        // Closed (its helpers with it) before its profile folder goes.
        chromium.terminate();
        if (!chromium.waitForFinished(10000)) {
            chromium.kill();
            chromium.waitForFinished(10000);
        }
        return err + chromium.readAllStandardError();
    }
    QString m_startFailure;

private Q_SLOTS:
    void initTestCase()
    {
        m_chromium = test::chromiumPath();
        if (m_chromium.isEmpty())
            QSKIP("Chromium is not installed (Debian package chromium): no browser to play the book in");
    }

    void highlightFollowsTheVoice_data()
    {
        QTest::addColumn<bool>("byWord");
        QTest::newRow("sentences") << false;
        QTest::newRow("words") << true;
    }

    // A book of two pages read by the built-in voice (one chapter: both pages' clips are in one
    // MP3, so page 2 seeks into it). Every <par> of the overlays is highlighted, in order, with
    // the package's active class (which the book's style sheet colours), each switch within
    // kLateSwitch of its clipBegin in the audio's clock; page 2 starts where its first clip does.
    void highlightFollowsTheVoice()
    {
        QFETCH(bool, byWord);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString text = dir.filePath(QStringLiteral("story.md"));
        {
            QFile f(text);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("# Story\n\nThe fox runs. The dog sleeps.\n\nThe moon rises. It is late.\n");
        }
        BookRequest req;
        req.textPath = text;
        req.outputPath = dir.filePath(QStringLiteral("story.epub"));
        req.face = averageFace(QRectF(106, 130, 300, 330), QSize(512, 512));
        req.style = Style::preset(QStringLiteral("normal"));
        req.highlight = byWord ? BookHighlight::Syllable : BookHighlight::Sentence;
        const BookResult r = exportBook(req);
        QVERIFY2(r.ok(), qPrintable(r.error));
        QCOMPARE(r.pages, 2);

        // Unpacked beside the player.
        QFile epub(req.outputPath);
        QVERIFY(epub.open(QIODevice::ReadOnly));
        QString error;
        const std::vector<ZipEntry> entries = readZip(epub.readAll(), &error);
        QVERIFY2(!entries.empty(), qPrintable(error));
        const QDir book(dir.filePath(QStringLiteral("book")));
        QByteArray opfData, opfPath;
        std::map<QString, QByteArray> files;
        for (const ZipEntry &e : entries) {
            QVERIFY(QDir().mkpath(QFileInfo(book.filePath(e.name)).path()));
            QFile f(book.filePath(e.name));
            QVERIFY(f.open(QIODevice::WriteOnly) && f.write(e.data) == e.data.size());
            files[e.name] = e.data;
            if (e.name.endsWith(QLatin1StringView(".opf")))
                opfPath = e.name.toUtf8();
        }
        const QString player = book.filePath(QStringLiteral("overlayplayer.html"));
        QVERIFY(QFile::copy(QStringLiteral(TOONFACE_TEST_DATA "/export/overlayplayer.html"), player));

        // What the package says: the active class, and the spine's overlays' clips in order.
        const QString opfText = QString::fromUtf8(files[QString::fromUtf8(opfPath)]);
        static const QRegularExpression activeRe(
            QStringLiteral("<meta property=\"media:active-class\">([^<]+)</meta>"));
        const QString active = activeRe.match(opfText).captured(1);
        QVERIFY(!active.isEmpty());
        const QString base = QString::fromUtf8(opfPath).section(QLatin1Char('/'), 0, -2) + QLatin1Char('/');
        Node opf;
        QVERIFY(test::parseXml(opfText.toUtf8(), &opf, &error));
        std::map<QString, const Node *> items;
        for (const Node *item : test::elementsNamed(opf, QStringLiteral("item")))
            items[item->attribute(QStringLiteral("id"))] = item;
        QVector<Par> pars;
        QStringList pages;
        for (const Node *ref : test::elementsNamed(opf, QStringLiteral("itemref"))) {
            const Node *item = items[ref->attribute(QStringLiteral("idref"))];
            const QString overlay = item->attribute(QStringLiteral("media-overlay"));
            if (overlay.isEmpty())
                continue;
            pages.append(item->attribute(QStringLiteral("href")));
            const QString smilHref = items[overlay]->attribute(QStringLiteral("href"));
            Node smil;
            QVERIFY(test::parseXml(files[base + smilHref], &smil, &error));
            for (const Node *par : test::elementsNamed(smil, QStringLiteral("par"))) {
                Par p;
                p.page = pages.last();
                for (const Node &c : par->children) {
                    if (c.name == QLatin1StringView("text"))
                        p.id = c.attribute(QStringLiteral("src")).section(QLatin1Char('#'), 1);
                    if (c.name == QLatin1StringView("audio")) {
                        p.audio = c.attribute(QStringLiteral("src"));
                        p.begin = seconds(c.attribute(QStringLiteral("clipBegin")));
                        p.end = seconds(c.attribute(QStringLiteral("clipEnd")));
                    }
                }
                QVERIFY(!p.id.isEmpty() && p.begin >= 0 && p.end > p.begin);
                pars.append(p);
            }
        }
        QCOMPARE(pages.size(), 2);
        const auto firstOfPage2
            = std::find_if(pars.cbegin(), pars.cend(), [&](const Par &p) { return p.page == pages[1]; });
        QVERIFY(firstOfPage2 != pars.cend());
        // Page 2 reads on in the file page 1 began: the player has to seek into it.
        QCOMPARE(firstOfPage2->audio, pars.first().audio);
        QVERIFY(firstOfPage2->begin > 0.5);

        // Played: the sound's length and a margin for the browser's start, under load.
        const double last = pars.last().end;
        QElapsedTimer wall;
        wall.start();
        const std::optional<QByteArray> err = play(player, int(last * 1000) + 45000);
        if (!err && !m_startFailure.isEmpty())
            QSKIP(qPrintable(QStringLiteral("Chromium cannot start: %1").arg(m_startFailure)));
        QVERIFY(err);
        const QStringList lines = playerLines(*err);
        qInfo("%lld ms to play %.3f s of overlay", qlonglong(wall.elapsed()), last);
        QVERIFY2(!lines.isEmpty(), err->right(2000).constData());
        for (const QString &l : lines)
            QVERIFY2(!l.startsWith(QLatin1StringView("error")), qPrintable(l));
        QVERIFY2(lines.last().startsWith(QLatin1StringView("done ")), qPrintable(lines.join(QLatin1Char('\n'))));
        QCOMPARE(lines.first(), QStringLiteral("class ") + active);
        // The file played to the last clip's end.
        QVERIFY2(lines.last().section(QLatin1Char(' '), 1).toDouble() >= last - kSeek, qPrintable(lines.last()));

        QVector<QStringList> switches, seeks;
        for (const QString &l : lines) {
            const QStringList f = l.split(QLatin1Char(' '));
            if (f[0] == QLatin1StringView("on"))
                switches.append(f);
            else if (f[0] == QLatin1StringView("seek"))
                seeks.append(f);
        }
        // Each page begins with a seek, page 2's into the middle of the file, at its first clip.
        QCOMPARE(seeks.size(), 2);
        QCOMPARE(seeks[0][1], pages[0]);
        QVERIFY(std::abs(seeks[0][2].toDouble() - pars.first().begin) <= kSeek);
        QCOMPARE(seeks[1][1], pages[1]);
        QVERIFY2(std::abs(seeks[1][2].toDouble() - firstOfPage2->begin) <= kSeek,
            qPrintable(QStringLiteral("page 2 sought to %1 s, its clip begins at %2 s")
                           .arg(seeks[1][2])
                           .arg(firstOfPage2->begin)));

        // Every clip's text lit, in order, while its clip plays.
        QCOMPARE(switches.size(), pars.size());
        double latest = 0;
        for (qsizetype i = 0; i < pars.size(); ++i) {
            const QStringList &s = switches[i]; // on PAGE ID TIME CLASS BACKGROUND
            const Par &p = pars[i];
            QCOMPARE(s.size(), 6);
            QCOMPARE(s[1], p.page);
            QCOMPARE(s[2], p.id);
            const double t = s[3].toDouble();
            const double late = t - p.begin;
            latest = std::max(latest, late);
            QVERIFY2(late >= -kSeek && late <= kLateSwitch,
                qPrintable(
                    QStringLiteral("%1 lit at %2 s, its clip is %3-%4 s").arg(p.id).arg(t).arg(p.begin).arg(p.end)));
            QVERIFY(t < p.end);
            QVERIFY2(s[4].split(QLatin1Char(',')).contains(active), qPrintable(s[4]));
            // The book's style sheet colours the active class: the reader sees it.
            QVERIFY2(s[5] != QLatin1StringView("rgba(0,0,0,0)"), qPrintable(s[5]));
        }
        qInfo("%lld clips highlighted; the latest switch %.1f ms after its clipBegin (audio clock)",
            qlonglong(pars.size()), latest * 1000);
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestEpubHighlight)
#include "tst_epubhighlight.moc"
