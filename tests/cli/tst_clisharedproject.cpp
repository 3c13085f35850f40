#include "animationfixture.h"
#include "testmain.h"

#include "face/mouthshape.h"
#include "io/project.h"
#include "render/style.h"

#include <QDir>
#include <QDirIterator>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>
#include <QUrl>
#include <QXmlStreamReader>

#include <csignal>

#include <sys/stat.h>

using namespace toonface;

namespace {

const QByteArray kSecret = "-----BEGIN OPENSSH PRIVATE KEY-----\nb3BlbnNzaC1rZXktdjEAAAAABG5vbmUAAAAE\n";

struct Run
{
    int code = -1;
    QByteArray err;
    qint64 ms = 0;
};

Run cli(const QStringList &args)
{
    QProcess p;
    QElapsedTimer timer;
    timer.start();
    p.start(QStringLiteral(TOONFACE_CLI_PATH), args);
    if (!p.waitForFinished(60000)) {
        p.kill();
        p.waitForFinished();
        return {};
    }
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, p.readAllStandardError(), timer.elapsed()};
}

bool writeFile(const QString &path, const QByteArray &content)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(content) == content.size();
}

// Whether any file below `dir` holds `needle` (as it is, or in base64 at any of the three
// alignments).
QString fileHolding(const QString &dir, const QByteArray &needle)
{
    QList<QByteArray> forms = {needle};
    for (int shift = 0; shift < 3; ++shift)
        forms << needle.mid(shift).toBase64().left((needle.size() - shift) / 3 * 4 - 4);
    for (QDirIterator it(dir, QDir::Files | QDir::Hidden, QDirIterator::Subdirectories); it.hasNext();) {
        const QString path = it.next();
        if (path.endsWith(QLatin1StringView("id_rsa")))
            continue;
        QFile f(path);
        if (!f.open(QIODevice::ReadOnly))
            continue;
        const QByteArray content = f.readAll();
        for (const QByteArray &form : forms) {
            if (content.contains(form))
                return path;
        }
    }
    return {};
}

} // namespace

// A project from a stranger does no harm when its receiver exports it: no file that is not
// decoded media reaches the export, no layer reaches outside the page, and a device, a pipe,
// a deep tree or a damaged layer gives a clear error (exit 3) instead of a hang or a crash.
class TestCliSharedProject : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_home;

    // A project in m_home/shared/NAME.toonface with the animation timeline, its sound `audio`
    // (relative to the project's folder when not absolute), and the given layers.
    QString project(const QString &name, const QString &audio, const QStringList &layerFiles = {},
        const QVector<StyleLayer> &inlineLayers = {})
    {
        const QString dir = m_home.filePath(QStringLiteral("shared"));
        QDir().mkpath(dir);
        Project p;
        p.face = test::animationFace();
        p.timeline = test::animationTimeline();
        p.timeline.setAudioClips({});
        if (!audio.isEmpty())
            p.timeline.setAudioClips({AudioClip {QDir(dir).absoluteFilePath(audio), 0.0, 10.0}});
        p.layerPaths = layerFiles;
        p.style.layers = inlineLayers;
        const QString path = QDir(dir).filePath(name + QStringLiteral(".toonface"));
        QString error;
        if (!saveProject(p, path, &error))
            qWarning("%s", qPrintable(error));
        return path;
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(QFileInfo::exists(QStringLiteral(TOONFACE_CLI_PATH)));
        QVERIFY(writeFile(m_home.filePath(QStringLiteral("id_rsa")), kSecret));
    }

    // The sound named by the project is the user's private key: refused by name, for every
    // output, and not one byte of it in any file written.
    void privateFileAsSoundRefused_data()
    {
        QTest::addColumn<QString>("suffix");
        for (const char *s : {"svg", "html", "mp4"})
            QTest::newRow(s) << QString::fromLatin1(s);
    }
    void privateFileAsSoundRefused()
    {
        QFETCH(QString, suffix);
        const QString proj = project(QStringLiteral("key"), QStringLiteral("../id_rsa"));
        const QString out = m_home.filePath(QStringLiteral("out/export.") + suffix);
        QDir().mkpath(QFileInfo(out).absolutePath());
        const Run r = cli({QStringLiteral("animate"), proj, QStringLiteral("-o"), out});
        QCOMPARE(r.code, 3);
        QVERIFY2(r.err.contains("id_rsa") && r.err.contains("toonface-cli: error: "), r.err.constData());
        QVERIFY2(r.err.contains("not a readable sound or video file"), r.err.constData());
        // The receiver is told the project reaches outside its folder.
        QVERIFY2(r.err.contains("outside its folder") && r.err.contains("id_rsa"), r.err.constData());
        QVERIFY(!QFileInfo::exists(out));
        const QString holder = fileHolding(m_home.path(), kSecret);
        QVERIFY2(holder.isEmpty(), qPrintable(holder));
    }

    // Devices, pipes and folders named as sound or layers are refused at once, never read.
    void devicesAndPipesRefused_data()
    {
        QTest::addColumn<QString>("sound");
        QTest::addColumn<QString>("layer");
        QTest::addColumn<QString>("named");
        const QString fifo = m_home.filePath(QStringLiteral("pipe"));
        if (!QFileInfo::exists(fifo))
            QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
        QTest::newRow("sound /dev/zero") << QStringLiteral("/dev/zero") << QString() << QStringLiteral("/dev/zero");
        QTest::newRow("sound fifo") << fifo << QString() << fifo;
        QTest::newRow("sound folder") << m_home.path() << QString() << m_home.path();
        QTest::newRow("layer /dev/zero") << QString() << QStringLiteral("/dev/zero") << QStringLiteral("/dev/zero");
        QTest::newRow("layer fifo") << QString() << fifo << fifo;
    }
    void devicesAndPipesRefused()
    {
        QFETCH(QString, sound);
        QFETCH(QString, layer);
        QFETCH(QString, named);
        const QString proj
            = project(QStringLiteral("device"), sound, layer.isEmpty() ? QStringList() : QStringList {layer});
        const QString out = m_home.filePath(QStringLiteral("device.html"));
        const Run r = cli({QStringLiteral("animate"), proj, QStringLiteral("-o"), out});
        QCOMPARE(r.code, 3);
        QVERIFY2(r.err.contains(named.toUtf8()) && !r.err.contains("does not exist"), r.err.constData());
        QVERIFY(!QFileInfo::exists(out));
        qInfo("refused in %lld ms", r.ms);
    }

    // A control character in a path the project names (an escape sequence that would redraw
    // the terminal) is printed as \xNN, never raw.
    void controlCharactersPrintedEscaped()
    {
        const QString proj = project(QStringLiteral("escape"),
            QStringLiteral("a\x1b[2J\x07"
                           "b.wav"));
        const Run r
            = cli({QStringLiteral("animate"), proj, QStringLiteral("-o"), m_home.filePath(QStringLiteral("e.svg"))});
        QCOMPARE(r.code, 3);
        QVERIFY2(!r.err.contains('\x1b') && !r.err.contains('\x07'), r.err.toPercentEncoding().constData());
        QVERIFY2(r.err.contains("a\\x1b[2J\\x07b.wav"), r.err.constData());
    }

    // An export stopped with Ctrl+C (SIGINT) or by the system (SIGTERM) says so (exit 130) and
    // leaves neither the output nor a hidden part file behind.
    void interruptedExportLeavesNothing_data()
    {
        QTest::addColumn<int>("signal");
        QTest::newRow("SIGINT") << int(SIGINT);
        QTest::newRow("SIGTERM") << int(SIGTERM);
    }
    void interruptedExportLeavesNothing()
    {
        QFETCH(int, signal);
        const QString dir = m_home.filePath(QStringLiteral("interrupted"));
        QDir().mkpath(dir);
        Project p;
        p.face = test::animationFace();
        QVector<MouthKey> keys;
        for (int i = 0; i < 600; ++i)
            keys.append(MouthKey {i * 0.1, kAllMouthShapes[size_t(i) % kAllMouthShapes.size()], 1.0, std::nullopt});
        p.timeline.setMouthKeys(keys);
        const QString proj = QDir(dir).filePath(QStringLiteral("long.toonface"));
        QVERIFY(saveProject(p, proj, nullptr));
        const QString out = QDir(dir).filePath(QStringLiteral("long.mp4"));
        QProcess process;
        process.start(QStringLiteral(TOONFACE_CLI_PATH), {QStringLiteral("animate"), proj, QStringLiteral("-o"), out});
        QVERIFY(process.waitForStarted());
        // Once frames are being written.
        auto partFiles = [&] { return QDir(dir).entryList({QStringLiteral("*.part")}, QDir::Files | QDir::Hidden); };
        QTRY_VERIFY_WITH_TIMEOUT(!partFiles().isEmpty() || process.state() == QProcess::NotRunning, 60000);
        QVERIFY2(process.state() != QProcess::NotRunning, process.readAllStandardError().constData());
        QCOMPARE(::kill(pid_t(process.processId()), signal), 0);
        QVERIFY(process.waitForFinished(30000));
        QCOMPARE(process.exitStatus(), QProcess::NormalExit);
        QCOMPARE(process.exitCode(), 130);
        const QByteArray err = process.readAllStandardError();
        QVERIFY2(err.contains("interrupted"), err.constData());
        QVERIFY(!QFileInfo::exists(out));
        QCOMPARE(partFiles(), QStringList());
    }

    // A layer file of 100,000 nested groups is refused by name (it crashed the SMIL writer); a
    // layer with the SVG 1.1 DOCTYPE and &nbsp; exports as well-formed SVG.
    void layerFiles()
    {
        QByteArray deep = "<svg xmlns=\"http://www.w3.org/2000/svg\">";
        for (int i = 0; i < 100000; ++i)
            deep += "<g>";
        for (int i = 0; i < 100000; ++i)
            deep += "</g>";
        deep += "</svg>";
        const QString deepFile = m_home.filePath(QStringLiteral("shared/deep.svg"));
        QVERIFY(writeFile(deepFile, deep));
        Run r = cli({QStringLiteral("animate"), project(QStringLiteral("deep"), QString(), {deepFile}),
            QStringLiteral("-o"), m_home.filePath(QStringLiteral("deep.svg"))});
        QCOMPARE(r.code, 3);
        QVERIFY2(r.err.contains("deep.svg") && r.err.contains("nested"), r.err.constData());

        const QString svg11 = m_home.filePath(QStringLiteral("shared/svg11.svg"));
        QVERIFY(writeFile(svg11,
            "<?xml version=\"1.0\"?>\n<!DOCTYPE svg PUBLIC \"-//W3C//DTD SVG 1.1//EN\" "
            "\"http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd\">\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
            "viewBox=\"0 0 10 10\"><text>a&nbsp;b</text><rect width=\"4\" height=\"4\" fill=\"#0a0\"/></svg>"));
        const QString out = m_home.filePath(QStringLiteral("svg11.svg"));
        r = cli({QStringLiteral("animate"), project(QStringLiteral("svg11"), QString(), {svg11}), QStringLiteral("-o"),
            out});
        QVERIFY2(r.code == 0, r.err.constData());
        QFile f(out);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QXmlStreamReader reader(f.readAll());
        while (!reader.atEnd())
            reader.readNext();
        QVERIFY2(!reader.hasError(), qPrintable(reader.errorString()));
    }

    // A project whose layers try every way out of the page: exported as SVG and HTML and opened
    // in Chromium while a server listens on the loopback address the layers name, the pages
    // make no request and stay where they are.
    void pagesMakeNoRequest()
    {
        QString chromium = QStandardPaths::findExecutable(QStringLiteral("chromium"));
        if (chromium.isEmpty())
            QSKIP("Chromium is not installed (Debian package chromium): the pages cannot be opened");
        QTcpServer server;
        QVERIFY(server.listen(QHostAddress::LocalHost));
        int requests = 0;
        QByteArray firstRequest;
        connect(&server, &QTcpServer::newConnection, this, [&] {
            while (QTcpSocket *s = server.nextPendingConnection()) {
                ++requests;
                s->waitForReadyRead(500);
                if (firstRequest.isEmpty())
                    firstRequest = s->readAll();
                s->close();
            }
        });
        const QByteArray at = "http://127.0.0.1:" + QByteArray::number(server.serverPort());
        const QByteArray hostile = "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:h=\"http://www.w3.org/1999/xhtml\" "
                                   "viewBox=\"0 0 10 10\">"
                                   "<style>@\\69mport '"
            + at + "/a.css'; rect{fill:\\75 rl(" + at
            + "/b)}</style>"
              "<rect width=\"5\" height=\"5\" style=\"fill:image-set('"
            + at
            + "/c.png' 1x)\"/>"
              "<p/><img srcset=\""
            + at + "/d.png 1x\"/><video poster=\"" + at
            + "/e.png\"/>"
              "<link rel=\"preload\" as=\"image\" imagesrcset=\""
            + at
            + "/f.png 1x\"/>"
              "<meta http-equiv=\"refresh\" content=\"0;url="
            + at
            + "/g\"/>"
              "<h:img srcset=\""
            + at
            + "/h.png 1x\"/>"
              "<h:meta http-equiv=\"refresh\" content=\"0;url="
            + at
            + "/i\"/>"
              "<image href=\""
            + at + "/j.png\" width=\"1\" height=\"1\"/></svg>";
        StyleLayer layer;
        layer.name = QStringLiteral("hostile.svg");
        layer.svg = hostile;
        // The project is written by hand, as an attacker would, not through the cleaning reader.
        const QString proj = project(QStringLiteral("hostile"), QString());
        QFile file(proj);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QJsonObject json = QJsonDocument::fromJson(file.readAll()).object();
        file.close();
        QJsonObject style = json.value(QStringLiteral("style")).toObject();
        style.insert(QStringLiteral("layers"),
            QJsonArray {QJsonObject {{QStringLiteral("name"), layer.name},
                {QStringLiteral("svg"), QString::fromUtf8(hostile)}, {QStringLiteral("x"), 0}, {QStringLiteral("y"), 0},
                {QStringLiteral("width"), 2}, {QStringLiteral("front"), true}, {QStringLiteral("visible"), true}}});
        json.insert(QStringLiteral("style"), style);
        QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
        file.write(QJsonDocument(json).toJson());
        file.close();
        // The project as read holds only the cleaned layer.
        QString error;
        const std::optional<Project> loaded = loadProject(proj, &error);
        QVERIFY2(loaded && loaded->style.layers.size() == 1, qPrintable(error));
        QVERIFY(!loaded->style.layers.first().svg.contains("127.0.0.1"));

        auto openInChromium = [&](const QString &page) {
            QTemporaryDir profile;
            QProcess browser;
            browser.start(chromium,
                {QStringLiteral("--headless"), QStringLiteral("--no-sandbox"), QStringLiteral("--disable-gpu"),
                    QStringLiteral("--disable-quic"), QStringLiteral("--no-first-run"),
                    QStringLiteral("--disable-background-networking"), QStringLiteral("--disable-component-update"),
                    QStringLiteral("--disable-sync"), QStringLiteral("--user-data-dir=") + profile.path(),
                    QStringLiteral("--virtual-time-budget=3000"), QStringLiteral("--dump-dom"),
                    QUrl::fromLocalFile(page).toString()});
            if (!browser.waitForStarted(20000))
                return QByteArray();
            // The event loop runs meanwhile, so the server takes any connection.
            QElapsedTimer waited;
            waited.start();
            while (browser.state() != QProcess::NotRunning && waited.elapsed() < 90000)
                QTest::qWait(50);
            if (browser.state() != QProcess::NotRunning) {
                browser.kill();
                browser.waitForFinished();
            }
            QTest::qWait(200);
            return browser.readAllStandardOutput();
        };
        for (const char *suffix : {"svg", "html"}) {
            const QString out = m_home.filePath(QStringLiteral("hostile.") + QLatin1StringView(suffix));
            const Run r = cli({QStringLiteral("animate"), proj, QStringLiteral("-o"), out});
            QVERIFY2(r.code == 0, r.err.constData());
            QFile exported(out);
            QVERIFY(exported.open(QIODevice::ReadOnly));
            QVERIFY(!exported.readAll().contains("127.0.0.1"));
            const QByteArray dom = openInChromium(out);
            QVERIFY2(requests == 0, firstRequest.constData());
            // Still the exported page, not one it was sent to.
            QVERIFY2(dom.contains(QByteArrayLiteral("face")), dom.left(400).constData());
        }
        // The harness sees what it is meant to: the layer as it came, opened on its own, does
        // reach the server.
        const QString raw = m_home.filePath(QStringLiteral("raw-layer.svg"));
        QVERIFY(writeFile(raw, hostile));
        openInChromium(raw);
        QVERIFY2(requests > 0, "the unclean layer made no request: the server would not have seen one either");
    }
};

TOONFACE_TEST_MAIN(TestCliSharedProject)
#include "tst_clisharedproject.moc"
