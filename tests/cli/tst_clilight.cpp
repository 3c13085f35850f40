// toonface-cli's launcher and light program (app/CMakeLists.txt): lipsync of a plain WAV
// recording runs without loading FFmpeg's codecs, OpenCV, dlib or Qt Gui (their loading alone
// took ~50 ms of every start), with the full program's output; every other command line is
// handed over to toonface-cli-full unchanged; a missing program is a clear error.
#include "speech/audio.h"
#include "speech/script.h"
#include "speech/tts.h"
#include "testmain.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>

using namespace toonface;

namespace {

struct Run
{
    int code = -1;
    QByteArray out;
    QByteArray err;
    QSet<QString> loaded; // shared libraries the dynamic loader opened (with LD_DEBUG=files)
};

Run run(const QString &program, const QStringList &args, bool traceLoading = false)
{
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    if (traceLoading)
        env.insert(QStringLiteral("LD_DEBUG"), QStringLiteral("files"));
    p.setProcessEnvironment(env);
    p.start(program, args);
    if (!p.waitForFinished(120000))
        return {};
    Run r {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, p.readAllStandardOutput(),
        p.readAllStandardError(), {}};
    // The loader's lines: "  1234:\tfile=libQt6Core.so.6 [0];  needed by ./toonface-cli [0]".
    static const QRegularExpression file(QStringLiteral("^\\s*\\d+:\\s+file=(\\S+) \\["));
    static const QRegularExpression loaderLine(QStringLiteral("^\\s*\\d+:"));
    QByteArrayList kept;
    for (const QByteArray &line : r.err.split('\n')) {
        const QString text = QString::fromLocal8Bit(line);
        if (const QRegularExpressionMatch m = file.match(text); m.hasMatch())
            r.loaded.insert(m.captured(1).section(QLatin1Char('/'), -1));
        else if (!loaderLine.match(text).hasMatch())
            kept << line;
    }
    if (traceLoading)
        r.err = kept.join('\n');
    return r;
}

// The libraries the light program must not load, by the start of their names.
const QStringList kHeavy = {QStringLiteral("libavcodec"), QStringLiteral("libavformat"), QStringLiteral("libopencv"),
    QStringLiteral("libdlib"), QStringLiteral("libQt6Gui"), QStringLiteral("libQt6Svg"), QStringLiteral("libx264"),
    QStringLiteral("libblas"), QStringLiteral("liblapack")};

QStringList heavyAmong(const QSet<QString> &loaded)
{
    QStringList found;
    for (const QString &name : loaded) {
        for (const QString &heavy : kHeavy) {
            if (name.startsWith(heavy))
                found << name;
        }
    }
    return found;
}

} // namespace

class TestCliLight : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    QString m_wav, m_flac, m_script;

    QStringList lipsyncArgs(const QString &audio) const
    {
        return {QStringLiteral("lipsync"), QStringLiteral("--audio"), audio, QStringLiteral("--script"), m_script};
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        const QString text = QStringLiteral("你好，今天天气很好。");
        const TtsResult spoken = synthesize(parseScript(text, Language::Mandarin).script);
        QVERIFY2(spoken.ok(), qPrintable(spoken.error));
        QString error;
        m_wav = m_dir.filePath(QStringLiteral("speech.wav"));
        m_flac = m_dir.filePath(QStringLiteral("speech.flac"));
        QVERIFY2(writeAudio(m_wav, spoken.audio, &error), qPrintable(error));
        QVERIFY2(writeAudio(m_flac, spoken.audio, &error), qPrintable(error));
        m_script = m_dir.filePath(QStringLiteral("speech.txt"));
        QFile f(m_script);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(text.toUtf8());
    }

    // lipsync of a WAV recording with a character script: none of the heavy libraries is
    // loaded, and the result is the full program's, byte for byte.
    void lipsyncOfWavStaysLight()
    {
        const Run light = run(QStringLiteral(TOONFACE_CLI_PATH), lipsyncArgs(m_wav), true);
        QVERIFY2(light.code == 0, light.err.constData());
        QVERIFY2(light.loaded.contains(QStringLiteral("libQt6Core.so.6")), "the loader's trace was not read");
        QVERIFY2(heavyAmong(light.loaded).isEmpty(), qPrintable(heavyAmong(light.loaded).join(QLatin1Char(' '))));
        QVERIFY(light.out.contains("\"mouthCues\""));
        const Run full = run(QStringLiteral(TOONFACE_CLI_FULL_PATH), lipsyncArgs(m_wav));
        QCOMPARE(full.code, 0);
        QCOMPARE(light.out, full.out);
    }

    // A recording FFmpeg must decode is handed to the full program, with the same result.
    void otherFormatsGoToTheFullProgram()
    {
        const Run light = run(QStringLiteral(TOONFACE_CLI_PATH), lipsyncArgs(m_flac), true);
        QVERIFY2(light.code == 0, light.err.constData());
        QVERIFY(!heavyAmong(light.loaded).isEmpty());
        const Run full = run(QStringLiteral(TOONFACE_CLI_FULL_PATH), lipsyncArgs(m_flac));
        QCOMPARE(light.out, full.out);
        // The light program checks the launcher's choice with the command's own parser.
        const QString lightProgram
            = QFileInfo(QStringLiteral(TOONFACE_CLI_FULL_PATH)).dir().filePath(QStringLiteral("toonface-cli-light"));
        const Run direct = run(lightProgram, lipsyncArgs(m_flac), true);
        QVERIFY2(direct.code == 0, direct.err.constData());
        QVERIFY(!heavyAmong(direct.loaded).isEmpty());
        QCOMPARE(direct.out, full.out);
    }

    // Every other command line, good or bad, gives what the full program gives.
    void otherCommandLinesAreHandedOver_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("help") << QStringList {QStringLiteral("--help")};
        QTest::newRow("version") << QStringList {QStringLiteral("--version")};
        QTest::newRow("none") << QStringList {};
        QTest::newRow("unknown") << QStringList {QStringLiteral("frobnicate")};
        QTest::newRow("say help") << QStringList {QStringLiteral("say"), QStringLiteral("--help")};
        QTest::newRow("lipsync help") << QStringList {QStringLiteral("lipsync"), QStringLiteral("--help")};
        QTest::newRow("lipsync no script")
            << QStringList {QStringLiteral("lipsync"), QStringLiteral("--audio"), QStringLiteral("/nonexistent.wav")};
        QTest::newRow("lipsync missing file") << QStringList {QStringLiteral("lipsync"), QStringLiteral("--audio"),
            QStringLiteral("/nonexistent.wav"), QStringLiteral("--script"), QStringLiteral("/nonexistent.txt")};
    }

    void otherCommandLinesAreHandedOver()
    {
        QFETCH(QStringList, args);
        const Run light = run(QStringLiteral(TOONFACE_CLI_PATH), args);
        const Run full = run(QStringLiteral(TOONFACE_CLI_FULL_PATH), args);
        QCOMPARE(light.code, full.code);
        QCOMPARE(light.out, full.out);
        QCOMPARE(light.err, full.err);
    }

    // The launcher (toonface-cli) loads no library but the C++ runtime; without the program
    // it hands over to it says which file is missing. The light program runs without the full
    // one, and says which file is missing for what it hands over.
    void missingProgramsAreAClearError()
    {
        const QString bin = m_dir.filePath(QStringLiteral("alone/bin"));
        QVERIFY(QDir().mkpath(bin));
        const QString launcher = bin + QStringLiteral("/toonface-cli");
        QVERIFY(QFile::copy(QStringLiteral(TOONFACE_CLI_PATH), launcher));
        auto isOneError = [](const Run &r, const char *missing) {
            return r.code == 1 && r.out.isEmpty() && r.err.startsWith("toonface-cli: error: cannot find ")
                && r.err.count('\n') == 1 && r.err.contains(missing) && r.err.contains("installation is incomplete");
        };
        const Run version = run(launcher, {QStringLiteral("--version")}, true);
        QVERIFY2(isOneError(version, "/toonface-cli-full"), version.err.constData());
        QVERIFY2(!version.loaded.contains(QStringLiteral("libQt6Core.so.6")), "the launcher loaded Qt");
        QVERIFY2(version.loaded.contains(QStringLiteral("libc.so.6")), "the loader's trace was not read");
        const Run lipsync = run(launcher, lipsyncArgs(m_wav));
        QVERIFY2(isOneError(lipsync, "/toonface-cli-light"), lipsync.err.constData());

        QVERIFY(QFile::copy(
            QFileInfo(QStringLiteral(TOONFACE_CLI_FULL_PATH)).dir().filePath(QStringLiteral("toonface-cli-light")),
            bin + QStringLiteral("/toonface-cli-light")));
        const Run light = run(launcher, lipsyncArgs(m_wav));
        QVERIFY2(light.code == 0, light.err.constData());
        QVERIFY(light.out.contains("\"mouthCues\""));
        const Run help = run(launcher,
            {QStringLiteral("lipsync"), QStringLiteral("--audio"), m_flac, QStringLiteral("--script"), m_script});
        QVERIFY2(isOneError(help, "/toonface-cli-full"), help.err.constData());
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestCliLight)
#include "tst_clilight.moc"
