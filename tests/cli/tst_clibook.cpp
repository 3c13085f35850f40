// toonface-cli book: the contract's exit codes, the error line naming the file, and no book
// (nor a hidden part of one) left behind on bad input.

#include "face/averageface.h"
#include "io/project.h"
#include "speech/audio.h"
#include "testmain.h"
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <csignal>

using namespace toonface;

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

// A long recording that is not silent: a warbling tone of `minutes`.
QString writeLongRecording(const QTemporaryDir &dir, double minutes)
{
    Audio a;
    a.sampleRate = 16000;
    a.samples.resize(qsizetype(minutes * 60 * a.sampleRate));
    for (qsizetype i = 0; i < a.samples.size(); ++i) {
        const double t = double(i) / a.sampleRate;
        a.samples[i] = float(0.3 * std::sin(2 * M_PI * (200 + 50 * std::sin(t)) * t));
    }
    const QString path = dir.filePath(QStringLiteral("long.wav"));
    QString error;
    return writeAudio(path, a, &error) ? path : QString();
}

// Runs the CLI with progress lines on, interrupts it (SIGINT) at its first progress line that
// contains `stage`, and returns its exit code and stderr.
Run interruptedAt(const QStringList &args, const QByteArray &stage)
{
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("TOONFACE_PROGRESS"), QStringLiteral("1"));
    p.setProcessEnvironment(env);
    p.setReadChannel(QProcess::StandardError); // what waitForReadyRead() waits for
    p.start(QStringLiteral(TOONFACE_CLI_PATH), args);
    if (!p.waitForStarted())
        return {};
    QByteArray err;
    while (!err.contains(stage) && p.state() == QProcess::Running && p.waitForReadyRead(60000))
        err += p.readAllStandardError();
    if (p.state() == QProcess::Running)
        ::kill(pid_t(p.processId()), SIGINT);
    if (!p.waitForFinished(60000))
        return {};
    err += p.readAllStandardError();
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, QString::fromUtf8(err)};
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
        QTest::newRow("bad face-as") << QStringList {QStringLiteral("--say"), QStringLiteral("--face-as"),
            QStringLiteral("gif"), QStringLiteral("-o"), QStringLiteral("b.epub")};
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

    // A long --audio shows its progress as it is read (a line when the stage begins), and Ctrl+C
    // stops it there: exit 130, no book and no hidden part of one.
    void interruptedWhileReadingTheRecording()
    {
        QTemporaryDir dir;
        const QString wav = writeLongRecording(dir, 10);
        QVERIFY(!wav.isEmpty());
        const QString textPath = writeText(dir, QStringLiteral("t.txt"), QStringLiteral("Hello there."));
        const QString out = dir.filePath(QStringLiteral("b.epub"));
        const Run run = interruptedAt(
            {QStringLiteral("book"), textPath, QStringLiteral("--audio"), wav, QStringLiteral("-o"), out},
            "reading the recording: ");
        QCOMPARE(run.code, 130);
        QVERIFY2(run.err.contains(u"reading the recording: 0 %") && run.err.contains(u"interrupted")
                && !run.err.contains(u"align"),
            qPrintable(run.err));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden),
            QStringList({QStringLiteral("long.wav"), QStringLiteral("t.txt")}));
    }

    // animate --audio aligns a long recording with progress lines, and Ctrl+C stops it.
    void animateInterruptedWhileAligning()
    {
        QTemporaryDir dir;
        const QString wav = writeLongRecording(dir, 10);
        QVERIFY(!wav.isEmpty());
        const QString script = writeText(dir, QStringLiteral("s.txt"), QStringLiteral("Hello there. ").repeated(200));
        Project face;
        face.face = averageFace(QRectF(106, 130, 300, 330), QSize(512, 512));
        const QString project = dir.filePath(QStringLiteral("face.toonface"));
        QVERIFY(saveProject(face, project, nullptr));
        const QString out = dir.filePath(QStringLiteral("a.mp4"));
        const Run run = interruptedAt({QStringLiteral("animate"), project, QStringLiteral("--audio"), wav,
                                          QStringLiteral("--script"), script, QStringLiteral("-o"), out},
            " %");
        QCOMPARE(run.code, 130);
        QVERIFY2(run.err.contains(u"interrupted"), qPrintable(run.err));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden),
            QStringList({QStringLiteral("face.toonface"), QStringLiteral("long.wav"), QStringLiteral("s.txt")}));
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
