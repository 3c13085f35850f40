// toonface-cli book: the contract's exit codes, the error line naming the file, and no book
// (nor a hidden part of one) left behind on bad input.

#include "testmain.h"
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

namespace {

struct Run
{
    int code = -1;
    QString err;
};

Run cli(const QStringList &args)
{
    QProcess p;
    p.start(QStringLiteral(TOONFACE_CLI_PATH), args);
    if (!p.waitForFinished(180000))
        return {};
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, QString::fromUtf8(p.readAllStandardError())};
}

QString writeText(const QTemporaryDir &dir, const QString &name, const QString &text)
{
    QFile f(dir.filePath(name));
    if (!f.open(QIODevice::WriteOnly))
        return {};
    f.write(text.toUtf8());
    return f.fileName();
}

} // namespace

class TestCliBook : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void badInput_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("problem");
        QTest::newRow("empty") << ""
                               << "empty";
        QTest::newRow("no sentence end") << "some words\nand more words\n"
                                         << "no sentence ends";
        QTest::newRow("recording shorter than the text")
            << QStringLiteral("This text goes on and on, far longer than the one second it was given. ").repeated(5)
            << "shorter than the text";
    }

    void badInput()
    {
        QFETCH(QString, text);
        QFETCH(QString, problem);
        QTemporaryDir dir;
        const QString wav = dir.filePath(QStringLiteral("short.wav"));
        QCOMPARE(cli({QStringLiteral("say"), QStringLiteral("Hello."), QStringLiteral("-o"), wav}).code, 0);
        const QString textPath = writeText(dir, QStringLiteral("story.txt"), text);
        const QString out = dir.filePath(QStringLiteral("story.epub"));
        const Run run
            = cli({QStringLiteral("book"), textPath, QStringLiteral("--audio"), wav, QStringLiteral("-o"), out});
        QCOMPARE(run.code, 3);
        QVERIFY2(run.err.startsWith(QLatin1StringView("toonface-cli: error: ")) && run.err.contains(problem)
                && run.err.count(QLatin1Char('\n')) == 1,
            qPrintable(run.err));
        QVERIFY2(run.err.contains(problem == QLatin1StringView("shorter than the text") ? wav : textPath),
            qPrintable(run.err));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden),
            QStringList({QStringLiteral("short.wav"), QStringLiteral("story.txt")}));
    }

    void usage_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("no source") << QStringList {QStringLiteral("-o"), QStringLiteral("b.epub")};
        QTest::newRow("both sources") << QStringList {QStringLiteral("--say"), QStringLiteral("--audio"),
            QStringLiteral("a.wav"), QStringLiteral("-o"), QStringLiteral("b.epub")};
        QTest::newRow("not .epub") << QStringList {
            QStringLiteral("--say"), QStringLiteral("-o"), QStringLiteral("b.zip")};
        QTest::newRow("bad language") << QStringList {QStringLiteral("--say"), QStringLiteral("--lang"),
            QStringLiteral("fr"), QStringLiteral("-o"), QStringLiteral("b.epub")};
        QTest::newRow("bad highlight") << QStringList {QStringLiteral("--say"), QStringLiteral("--highlight"),
            QStringLiteral("word"), QStringLiteral("-o"), QStringLiteral("b.epub")};
    }

    void usage()
    {
        QFETCH(QStringList, args);
        QTemporaryDir dir;
        const QString textPath = writeText(dir, QStringLiteral("t.txt"), QStringLiteral("Hello there."));
        const Run run = cli(QStringList {QStringLiteral("book"), textPath} + args);
        QCOMPARE(run.code, 2);
        QVERIFY(run.err.startsWith(QLatin1StringView("toonface-cli: error: ")));
    }

    // A Markdown text read by the voice, with a title, an author and a language.
    void spoken()
    {
        QTemporaryDir dir;
        const QString textPath = writeText(
            dir, QStringLiteral("t.md"), QStringLiteral("# 開始\n\n你好。今天天氣很好！\n\n# 結束\n\n再見。\n"));
        const QString out = dir.filePath(QStringLiteral("b.epub"));
        const Run run = cli({QStringLiteral("book"), textPath, QStringLiteral("--say"), QStringLiteral("--lang"),
            QStringLiteral("zh-Hant"), QStringLiteral("--title"), QStringLiteral("天氣"), QStringLiteral("--author"),
            QStringLiteral("王小明"), QStringLiteral("-o"), out});
        QVERIFY2(run.code == 0, qPrintable(run.err));
        QFile book(out);
        QVERIFY(book.open(QIODevice::ReadOnly));
        QVERIFY(book.read(58).endsWith("mimetypeapplication/epub+zip"));
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestCliBook)
#include "tst_clibook.moc"
