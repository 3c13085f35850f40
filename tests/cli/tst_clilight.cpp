// The light toonface-cli (app/toonface-cli-light.cpp): lipsync of a plain WAV recording runs
// without loading FFmpeg's codecs, OpenCV, dlib or Qt Gui (their loading alone took ~50 ms of
// every start), with the full program's output; every other command line is handed over to
// toonface-cli-full unchanged; a missing toonface-cli-full is a clear error.
#include "speech/audio.h"
#include "speech/script.h"
#include "speech/tts.h"

#include <QFile>
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
    QByteArrayList kept;
    for (const QByteArray &line : r.err.split('\n')) {
        const QRegularExpressionMatch m = file.match(QString::fromLocal8Bit(line));
        if (m.hasMatch())
            r.loaded.insert(m.captured(1).section(QLatin1Char('/'), -1));
        else if (!line.contains(": "))
            kept << line;
        else if (!QRegularExpression(QStringLiteral("^\\s*\\d+:")).match(QString::fromLocal8Bit(line)).hasMatch())
            kept << line;
    }
    if (traceLoading)
        r.err = kept.join('\n').trimmed();
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
        QTest::newRow("lipsync no script") << QStringList {QStringLiteral("lipsync"), QStringLiteral("--audio"),
            QStringLiteral("/nonexistent.wav")};
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

    // Without toonface-cli-full beside it or in its installed place, the light program still
    // runs what it can and says which file is missing for the rest.
    void missingFullProgramIsAClearError()
    {
        const QString alone = m_dir.filePath(QStringLiteral("alone/bin/toonface-cli"));
        QVERIFY(QDir().mkpath(QFileInfo(alone).path()));
        QVERIFY(QFile::copy(QStringLiteral(TOONFACE_CLI_PATH), alone));
        const Run version = run(alone, {QStringLiteral("--version")});
        QCOMPARE(version.code, 1);
        QVERIFY2(version.err.contains("toonface-cli-full") && version.err.contains("installation is incomplete"),
            version.err.constData());
        QVERIFY2(version.err.startsWith("toonface-cli: error: ") && version.err.count('\n') == 1, version.err.constData());
        const Run lipsync = run(alone, lipsyncArgs(m_wav));
        QVERIFY2(lipsync.code == 0, lipsync.err.constData());
        QVERIFY(lipsync.out.contains("\"mouthCues\""));
    }
};

QTEST_GUILESS_MAIN(TestCliLight)
#include "tst_clilight.moc"
