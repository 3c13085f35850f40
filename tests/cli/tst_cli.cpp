#include "face/averageface.h"
#include "face/emotion.h"
#include "face/fapu.h"
#include "face/pose.h"
#include "io/project.h"
#include "media/mediareader.h"
#include "render/svgface.h"
#include "testmain.h"

#include "testphotos.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <QXmlStreamReader>

#include <memory>
#include <vector>

#include <sys/stat.h>

using namespace toonface;

namespace {

const QString kPortrait = QStringLiteral("/usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg");

struct Run
{
    int code = -1;
    QByteArray out;
    QByteArray err;
};

Run cli(const QStringList &args, const QProcessEnvironment &env = QProcessEnvironment::systemEnvironment())
{
    QProcess p;
    p.setProcessEnvironment(env);
    p.start(QStringLiteral(TOONFACE_CLI_PATH), args);
    if (!p.waitForFinished(120000))
        return {};
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, p.readAllStandardOutput(),
        p.readAllStandardError()};
}

// The contract's error format: exactly one line "toonface-cli: error: ...".
bool isOneErrorLine(const QByteArray &err)
{
    static const QRegularExpression re(QStringLiteral("^toonface-cli: error: [^\\n]+\\n$"));
    return re.match(QString::fromUtf8(err)).hasMatch();
}

bool isWellFormedSvg(const QString &path, QString *viewBox)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return false;
    QXmlStreamReader xml(&f);
    bool sawSvg = false;
    while (!xml.atEnd()) {
        if (xml.readNext() == QXmlStreamReader::StartElement && !sawSvg) {
            sawSvg = xml.name() == QLatin1StringView("svg");
            *viewBox = xml.attributes().value(QLatin1StringView("viewBox")).toString();
        }
    }
    return sawSvg && !xml.hasError();
}

} // namespace

class TestCli : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    QString path(const QString &name) const { return m_dir.filePath(name); }
    // A project holding an average face, saved as `name`; its path, or empty if it could not be saved.
    QString faceProject(const QString &name) const
    {
        Project project;
        project.face = averageFace(QRectF(60, 80, 200, 240), QSize(320, 400));
        QString error;
        return saveProject(project, path(name), &error) ? path(name) : QString();
    }
    void requirePortrait()
    {
        if (!QFile::exists(kPortrait))
            QSKIP("grace_hopper.jpg is not installed (package python-matplotlib-data)");
    }

private Q_SLOTS:
    void helpAndVersion()
    {
        Run r = cli({QStringLiteral("--help")});
        QCOMPARE(r.code, 0);
        QVERIFY(r.out.contains("detect IMAGE"));
        QVERIFY(r.out.contains("cartoon IMAGE|FACE.json|PROJECT.toonface"));
        r = cli({QStringLiteral("--version")});
        QCOMPARE(r.code, 0);
        QVERIFY(r.out.startsWith("toonface-cli "));
        r = cli({QStringLiteral("cartoon"), QStringLiteral("--help")});
        QCOMPARE(r.code, 0);
        QVERIFY(r.out.contains("--emotion"));
    }

    void usageErrors_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("no command") << QStringList {};
        QTest::newRow("unknown command") << QStringList {QStringLiteral("paint")};
        QTest::newRow("detect without image") << QStringList {QStringLiteral("detect")};
        QTest::newRow("detect two images")
            << QStringList {QStringLiteral("detect"), QStringLiteral("a.jpg"), QStringLiteral("b.jpg")};
        QTest::newRow("unknown option") << QStringList {
            QStringLiteral("detect"), QStringLiteral("--colour"), QStringLiteral("a.jpg")};
        QTest::newRow("bad method") << QStringList {
            QStringLiteral("detect"), QStringLiteral("a.jpg"), QStringLiteral("--method"), QStringLiteral("magic")};
        QTest::newRow("cartoon without -o") << QStringList {QStringLiteral("cartoon"), QStringLiteral("a.jpg")};
        QTest::newRow("bad emotion") << QStringList {QStringLiteral("cartoon"), QStringLiteral("a.jpg"),
            QStringLiteral("-o"), QStringLiteral("x.svg"), QStringLiteral("--emotion"), QStringLiteral("bored")};
        QTest::newRow("bad caricature") << QStringList {QStringLiteral("cartoon"), QStringLiteral("a.jpg"),
            QStringLiteral("-o"), QStringLiteral("x.svg"), QStringLiteral("--caricature"), QStringLiteral("3")};
        QTest::newRow("bad style") << QStringList {QStringLiteral("cartoon"), QStringLiteral("a.jpg"),
            QStringLiteral("-o"), QStringLiteral("x.svg"), QStringLiteral("--style"), QStringLiteral("cubist")};
        QTest::newRow("bad size") << QStringList {QStringLiteral("cartoon"), QStringLiteral("a.jpg"),
            QStringLiteral("-o"), QStringLiteral("x.svg"), QStringLiteral("--size"), QStringLiteral("huge")};
    }

    void usageErrors()
    {
        QFETCH(QStringList, args);
        const Run r = cli(args);
        QCOMPARE(r.code, 2);
        QVERIFY2(isOneErrorLine(r.err), r.err.constData());
    }

    void unreadableInputs_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QByteArray>("content"); // empty = do not create
        QTest::newRow("missing") << QStringLiteral("missing.jpg") << QByteArray();
        QTest::newRow("not an image") << QStringLiteral("notes.jpg") << QByteArray("just some words\n");
        QTest::newRow("empty") << QStringLiteral("empty.png") << QByteArray("\0", 0);
        QTest::newRow("bad face json") << QStringLiteral("face.json")
                                       << QByteArray("{\"format\": \"toonface.face/1\", \"points\": 3}");
        QTest::newRow("not json") << QStringLiteral("face2.json") << QByteArray("{points");
        QTest::newRow("bad project") << QStringLiteral("p.toonface")
                                     << QByteArray("{\"format\": \"toonface.project\", \"version\": 1}");
    }

    void unreadableInputs()
    {
        QFETCH(QString, file);
        QFETCH(QByteArray, content);
        const QString p = path(file);
        if (qstrcmp(QTest::currentDataTag(), "missing") != 0) {
            QFile f(p);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(content);
        }
        for (const QString &cmd : {QStringLiteral("detect"), QStringLiteral("cartoon")}) {
            if (cmd == QLatin1StringView("detect") && !file.endsWith(QLatin1StringView(".jpg"))
                && !file.endsWith(QLatin1StringView(".png")))
                continue;
            const Run r = cli({cmd, p, QStringLiteral("-o"), path(QStringLiteral("out.svg"))});
            QCOMPARE(r.code, 3);
            QVERIFY2(isOneErrorLine(r.err), r.err.constData());
            QVERIFY2(r.err.contains(file.toUtf8()), "the error names the file");
        }
    }

    void truncatedPhoto()
    {
        requirePortrait();
        QFile in(kPortrait);
        QVERIFY(in.open(QIODevice::ReadOnly));
        const QByteArray all = in.readAll();
        QFile out(path(QStringLiteral("truncated.jpg")));
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(all.left(all.size() / 3));
        out.close();
        const Run r = cli({QStringLiteral("detect"), out.fileName()});
        QCOMPARE(r.code, 3);
        QVERIFY2(isOneErrorLine(r.err), r.err.constData());
        QVERIFY(r.err.contains("truncated.jpg"));
    }

    // A photo of two people: the larger face is used, and the count said on stderr.
    void twoFacesAreCounted()
    {
        requirePortrait();
        const QImage one(kPortrait);
        const QImage both = testing::twoPeople(one);
        const QString photo = path(QStringLiteral("two people.png"));
        QVERIFY(both.save(photo));
        const Run r = cli({QStringLiteral("detect"), photo, QStringLiteral("-o"), path(QStringLiteral("two.json"))});
        QCOMPARE(r.code, 0);
        QVERIFY2(
            r.err.contains("two people.png: 2 faces found; the largest, most central one is used"), r.err.constData());
        QFile json(path(QStringLiteral("two.json")));
        QVERIFY(json.open(QIODevice::ReadOnly));
        const QJsonObject face = QJsonDocument::fromJson(json.readAll()).object();
        QCOMPARE(face.value(QStringLiteral("faceCount")).toInt(), 2);
        QVERIFY(face.value(QStringLiteral("faceBox")).toObject().value(QStringLiteral("x")).toDouble() < one.width());

        // --face picks the other one: the smaller portrait's face, right of the first.
        const QJsonObject box = face.value(QStringLiteral("faceBox")).toObject();
        const QPointF centre(
            box.value(QStringLiteral("x")).toDouble() + box.value(QStringLiteral("width")).toDouble() / 2,
            box.value(QStringLiteral("y")).toDouble() + box.value(QStringLiteral("height")).toDouble() / 2);
        const QPointF other = QPointF(one.width(), 0) + centre * 0.85;
        const Run picked = cli({QStringLiteral("detect"), photo, QStringLiteral("--face"),
            QStringLiteral("%1,%2").arg(other.x()).arg(other.y()), QStringLiteral("-o"),
            path(QStringLiteral("other.json"))});
        QCOMPARE(picked.code, 0);
        QFile otherJson(path(QStringLiteral("other.json")));
        QVERIFY(otherJson.open(QIODevice::ReadOnly));
        const QJsonObject otherBox
            = QJsonDocument::fromJson(otherJson.readAll()).object().value(QStringLiteral("faceBox")).toObject();
        QVERIFY(otherBox.value(QStringLiteral("x")).toDouble() > one.width());

        const Run bad = cli({QStringLiteral("detect"), photo, QStringLiteral("--face"), QStringLiteral("left")});
        QCOMPARE(bad.code, 2);
        QVERIFY2(bad.err.contains("--face wants a point X,Y"), bad.err.constData());
    }

    void noFace()
    {
        QImage blank(640, 480, QImage::Format_RGB32);
        blank.fill(QColor(200, 210, 220));
        const QString p = path(QStringLiteral("blank.png"));
        QVERIFY(blank.save(p));
        Run r = cli({QStringLiteral("detect"), p});
        QCOMPARE(r.code, 4);
        QVERIFY2(isOneErrorLine(r.err), r.err.constData());
        r = cli({QStringLiteral("cartoon"), p, QStringLiteral("-o"), path(QStringLiteral("blank.svg"))});
        QCOMPARE(r.code, 4);
        QVERIFY(!QFile::exists(path(QStringLiteral("blank.svg"))));
    }

    // The classic method does not call a dark pair without a face around it a face: "no face"
    // (exit 4) with the failed check in one line naming the file.
    void classicRefusesPairWithoutFace()
    {
        const QImage wall = testing::darkPairOnAWall();
        const QString p = path(QStringLiteral("two-blobs.png"));
        QVERIFY(wall.save(p));
        const Run r = cli({QStringLiteral("detect"), p, QStringLiteral("--method"), QStringLiteral("classic")});
        QCOMPARE(r.code, 4);
        QVERIFY2(isOneErrorLine(r.err), r.err.constData());
        QVERIFY(r.err.contains("two-blobs.png"));
        QVERIFY2(r.err.contains("no face around it"), r.err.constData());
        QVERIFY(r.out.isEmpty());
    }

    // Without the landmark model, auto falls back to the thesis' pipeline: the portrait still
    // gets its points, the JSON says which method placed them, stderr warns why.
    void detectFallsBackToClassic()
    {
        requirePortrait();
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("TOONFACE_LANDMARK_MODEL"), QStringLiteral("/nonexistent/landmarks.dat"));
        const Run r = cli({QStringLiteral("detect"), kPortrait}, env);
        QCOMPARE(r.code, 0);
        const QJsonObject face = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(face.value(QStringLiteral("method")).toString(), QStringLiteral("classic"));
        QCOMPARE(face.value(QStringLiteral("points")).toArray().size(), 72);
        QVERIFY(r.err.startsWith("toonface-cli: warning: "));
        QVERIFY(r.err.contains("/nonexistent/landmarks.dat"));
        const Run strict
            = cli({QStringLiteral("detect"), kPortrait, QStringLiteral("--method"), QStringLiteral("landmarks")}, env);
        QCOMPARE(strict.code, 1); // an installation problem, not the input's
        QVERIFY(isOneErrorLine(strict.err));
    }

    void detectPortrait()
    {
        requirePortrait();
        const Run r = cli({QStringLiteral("detect"), kPortrait});
        QCOMPARE(r.code, 0);
        QVERIFY2(r.err.isEmpty(), r.err.constData());
        const QJsonObject json = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(json.value(QLatin1StringView("format")).toString(), QStringLiteral("toonface.face/1"));
        const QJsonArray points = json.value(QLatin1StringView("points")).toArray();
        QCOMPARE(points.size(), 72);
        QCOMPARE(points.first().toObject().value(QLatin1StringView("id")).toString(), QStringLiteral("h.1"));
        QCOMPARE(points.last().toObject().value(QLatin1StringView("id")).toString(), QStringLiteral("2.3"));
        // What the person looks like (tst_appearancejson checks the object's schema).
        const QJsonObject look = json.value(QLatin1StringView("appearance")).toObject();
        QVERIFY(look.value(QLatin1StringView("skin")).toString().startsWith(QLatin1Char('#')));
        QVERIFY(look.value(QLatin1StringView("confidence")).isObject());
        for (const auto &v : points) {
            const QJsonObject o = v.toObject();
            for (const char *key : {"id", "x", "y", "group", "control"})
                QVERIFY2(o.contains(QLatin1StringView(key)), key);
        }
        const QJsonObject image = json.value(QLatin1StringView("image")).toObject();
        QCOMPARE(image.value(QLatin1StringView("width")).toInt(), 512);
        QCOMPARE(image.value(QLatin1StringView("height")).toInt(), 600);
        QVERIFY(json.value(QLatin1StringView("fapu")).toObject().value(QLatin1StringView("ES0")).toDouble() > 50);
        QVERIFY(json.value(QLatin1StringView("timingMs")).toObject().contains(QLatin1StringView("total")));
        QVERIFY(!json.value(QLatin1StringView("method")).toString().isEmpty());

        const QString facePath = path(QStringLiteral("hopper.json"));
        const Run saved = cli({QStringLiteral("detect"), kPortrait, QStringLiteral("-o"), facePath});
        QCOMPARE(saved.code, 0);
        QVERIFY(saved.out.isEmpty());
        QVERIFY(QFile::exists(facePath));
    }

    void cartoonFromEveryInput()
    {
        requirePortrait();
        // From the photo, with a PNG.
        const QString svg = path(QStringLiteral("hopper.svg"));
        const QString png = path(QStringLiteral("hopper.png"));
        Run r = cli({QStringLiteral("cartoon"), kPortrait, QStringLiteral("-o"), svg, QStringLiteral("--png"), png,
            QStringLiteral("--size"), QStringLiteral("300")});
        QCOMPARE(r.code, 0);
        QString viewBox;
        QVERIFY(isWellFormedSvg(svg, &viewBox));
        // Framed square around the head, which holds the detected face box.
        const QStringList box = viewBox.split(QLatin1Char(' '));
        QCOMPARE(box.size(), 4);
        const QRectF frame(box[0].toDouble(), box[1].toDouble(), box[2].toDouble(), box[3].toDouble());
        QCOMPARE(frame.width(), frame.height());
        const QImage image(png);
        QCOMPARE(image.size(), QSize(300, 300));
        const QString detected = path(QStringLiteral("hopper-face.json"));
        QCOMPARE(cli({QStringLiteral("detect"), kPortrait, QStringLiteral("-o"), detected}).code, 0);
        QFile faceFile(detected);
        QVERIFY(faceFile.open(QIODevice::ReadOnly));
        const QJsonObject faceBox
            = QJsonDocument::fromJson(faceFile.readAll()).object().value(QStringLiteral("faceBox")).toObject();
        const QRectF detectedBox(faceBox.value(QStringLiteral("x")).toDouble(),
            faceBox.value(QStringLiteral("y")).toDouble(), faceBox.value(QStringLiteral("width")).toDouble(),
            faceBox.value(QStringLiteral("height")).toDouble());
        QVERIFY2(frame.contains(detectedBox), qPrintable(viewBox));
        QVERIFY(frame.width() < 3 * std::max(detectedBox.width(), detectedBox.height())); // the head, not the photo
        // The photo's frame on request, so the drawing lies over the photo.
        const QString whole = path(QStringLiteral("hopper-photo.svg"));
        QCOMPARE(cli({QStringLiteral("cartoon"), kPortrait, QStringLiteral("-o"), whole, QStringLiteral("--frame"),
                         QStringLiteral("photo")})
                     .code,
            0);
        QVERIFY(isWellFormedSvg(whole, &viewBox));
        QCOMPARE(viewBox, QStringLiteral("0 0 512 600"));
        const Run bad = cli({QStringLiteral("cartoon"), kPortrait, QStringLiteral("-o"), whole,
            QStringLiteral("--frame"), QStringLiteral("torso")});
        QCOMPARE(bad.code, 2);
        QVERIFY(bad.err.contains("--frame"));

        // From the face JSON.
        const QString facePath = path(QStringLiteral("face-for-cartoon.json"));
        QCOMPARE(cli({QStringLiteral("detect"), kPortrait, QStringLiteral("-o"), facePath}).code, 0);
        const QString svg2 = path(QStringLiteral("from-json.svg"));
        r = cli({QStringLiteral("cartoon"), facePath, QStringLiteral("-o"), svg2});
        QCOMPARE(r.code, 0);
        QVERIFY(isWellFormedSvg(svg2, &viewBox));

        // An emotion changes the drawing; a style too.
        const QString smile = path(QStringLiteral("smile.svg"));
        QCOMPARE(cli({QStringLiteral("cartoon"), facePath, QStringLiteral("-o"), smile, QStringLiteral("--emotion"),
                         QStringLiteral("smile")})
                     .code,
            0);
        QFile a(svg2), b(smile);
        QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
        QVERIFY(a.readAll() != b.readAll());
        const QString cute = path(QStringLiteral("cute.svg"));
        QCOMPARE(cli({QStringLiteral("cartoon"), facePath, QStringLiteral("-o"), cute, QStringLiteral("--style"),
                         QStringLiteral("cute")})
                     .code,
            0);
    }

    // An emotion's cartoon is the animation's frame of it where nothing is said (the lips at
    // rest, shut); with none asked for, the face is drawn as photographed (here lips apart).
    void cartoonEmotionIsItsRestFrame()
    {
        Project project;
        project.face = averageFace(QRectF(60, 80, 200, 240), QSize(320, 400));
        const double es0 = project.face.fapu().es0;
        for (const char *id : {"8.2", "2.3", "2.1"})
            project.face.setPoint(pt::idx(id), project.face.point(id) + QPointF(0, 0.12 * es0), false);
        project.style.name = QStringLiteral("normal");
        const QString projectPath = path(QStringLiteral("apart.toonface"));
        QString error;
        QVERIFY2(saveProject(project, projectPath, &error), qPrintable(error));
        const std::optional<Project> loaded = loadProject(projectPath, &error);
        QVERIFY2(loaded, qPrintable(error));
        SvgFace drawn(loaded->face, loaded->style);
        drawn.setFrame(headFrame(loaded->face));
        auto read = [](const QString &file) {
            QFile f(file);
            return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
        };
        const QString plain = path(QStringLiteral("apart.svg"));
        QCOMPARE(cli({QStringLiteral("cartoon"), projectPath, QStringLiteral("-o"), plain}).code, 0);
        QCOMPARE(read(plain), drawn.svg(Pose()));
        for (Emotion e : kAllEmotions) {
            const QString out = path(emotionName(e) + QStringLiteral(".svg"));
            QCOMPARE(cli({QStringLiteral("cartoon"), projectPath, QStringLiteral("-o"), out,
                             QStringLiteral("--emotion"), emotionName(e)})
                         .code,
                0);
            QCOMPARE(read(out), drawn.svg(stillEmotionPose(loaded->face, e, 1.0)));
        }
        QVERIFY(read(path(QStringLiteral("neutral.svg"))) != read(plain));
    }

    void cartoonFromProject()
    {
        Project project;
        project.face = averageFace(QRectF(60, 80, 200, 240), QSize(320, 400));
        project.style.name = QStringLiteral("normal");
        const QString projectPath = path(QStringLiteral("mine.toonface"));
        QString error;
        QVERIFY2(saveProject(project, projectPath, &error), qPrintable(error));
        const QString svg = path(QStringLiteral("project.svg"));
        const Run r = cli({QStringLiteral("cartoon"), projectPath, QStringLiteral("-o"), svg});
        QCOMPARE(r.code, 0);
        QString viewBox;
        QVERIFY(isWellFormedSvg(svg, &viewBox));
        const QRectF frame = headFrame(project.face);
        QCOMPARE(viewBox,
            QStringLiteral("%1 %2 %3 %4").arg(frame.x()).arg(frame.y()).arg(frame.width()).arg(frame.height()));
        QVERIFY(frame.contains(project.face.bounds()));
    }

    void animateUsageErrors_data()
    {
        QTest::addColumn<QStringList>("args");
        const QString in = QStringLiteral("face.toonface");
        QTest::newRow("no output") << QStringList {
            QStringLiteral("animate"), in, QStringLiteral("--say"), QStringLiteral("ni3 hao3")};
        QTest::newRow("no speech for a photo") << QStringList {
            QStringLiteral("animate"), QStringLiteral("face.png"), QStringLiteral("-o"), QStringLiteral("a.svg")};
        QTest::newRow("two speeches") << QStringList {QStringLiteral("animate"), in, QStringLiteral("--say"),
            QStringLiteral("ni3"), QStringLiteral("--audio"), QStringLiteral("a.wav"), QStringLiteral("--script"),
            QStringLiteral("s.txt"), QStringLiteral("-o"), QStringLiteral("a.svg")};
        QTest::newRow("audio without script") << QStringList {QStringLiteral("animate"), in, QStringLiteral("--audio"),
            QStringLiteral("a.wav"), QStringLiteral("-o"), QStringLiteral("a.svg")};
        QTest::newRow("unknown output type") << QStringList {QStringLiteral("animate"), in, QStringLiteral("--say"),
            QStringLiteral("ni3"), QStringLiteral("-o"), QStringLiteral("a.avi")};
        QTest::newRow("bad fps") << QStringList {QStringLiteral("animate"), in, QStringLiteral("--say"),
            QStringLiteral("ni3"), QStringLiteral("--fps"), QStringLiteral("0"), QStringLiteral("-o"),
            QStringLiteral("a.svg")};
        QTest::newRow("video and text") << QStringList {QStringLiteral("animate"), in, QStringLiteral("--video"),
            QStringLiteral("clip.mpg"), QStringLiteral("--say"), QStringLiteral("ni3"), QStringLiteral("-o"),
            QStringLiteral("a.svg")};
    }

    void animateUsageErrors()
    {
        QFETCH(QStringList, args);
        const Run r = cli(args);
        QCOMPARE(r.code, 2);
        QVERIFY2(isOneErrorLine(r.err), r.err.constData());
    }

    // The main job: a face talks from text alone, as SMIL SVG, HTML and MP4 with sound.
    void animateSaysText()
    {
        const QString projectPath = faceProject(QStringLiteral("talker.toonface"));
        QVERIFY(!projectPath.isEmpty());
        QString error;

        const QString svg = path(QStringLiteral("talk.svg"));
        const QString saved = path(QStringLiteral("talk-project.toonface"));
        Run r = cli({QStringLiteral("animate"), projectPath, QStringLiteral("--say"),
            QStringLiteral("ni3 hao3, shi4 jie4"), QStringLiteral("--emotion"), QStringLiteral("smile"),
            QStringLiteral("--project"), saved, QStringLiteral("-o"), svg});
        QCOMPARE(r.code, 0);
        QString viewBox;
        QVERIFY(isWellFormedSvg(svg, &viewBox));
        QFile svgFile(svg);
        QVERIFY(svgFile.open(QIODevice::ReadOnly));
        const QByteArray content = svgFile.readAll();
        QVERIFY(content.contains("<animate "));
        QVERIFY(content.contains("data:audio/"));
        QVERIFY2(QFile::exists(path(QStringLiteral("talk.wav"))), "the spoken recording is kept beside the output");
        const auto reloaded = loadProject(saved, &error);
        QVERIFY2(reloaded, qPrintable(error));
        QVERIFY(!reloaded->timeline.mouthKeys().isEmpty());
        QCOMPARE(reloaded->syllables.size(), 4);
        QCOMPARE(reloaded->syllables[1].pinyin, QStringLiteral("hao"));
        QCOMPARE(reloaded->timeline.audioClips().first().script, QStringLiteral("ni3 hao3, shi4 jie4"));
        QCOMPARE(reloaded->audioPath(), QFileInfo(path(QStringLiteral("talk.wav"))).absoluteFilePath());

        // The saved project plays its own timeline: the same frames as the animation it came from.
        const QString replay = path(QStringLiteral("replay.svg"));
        r = cli({QStringLiteral("animate"), saved, QStringLiteral("-o"), replay});
        QCOMPARE(r.code, 0);
        QFile replayFile(replay);
        QVERIFY(replayFile.open(QIODevice::ReadOnly));
        QCOMPARE(replayFile.readAll(), content);
        // A project without an animation says so.
        r = cli({QStringLiteral("animate"), projectPath, QStringLiteral("-o"), path(QStringLiteral("none.svg"))});
        QCOMPARE(r.code, 3);
        QVERIFY2(r.err.contains("no animation") && r.err.contains("talker.toonface"), r.err.constData());

        const QString html = path(QStringLiteral("talk.html"));
        QCOMPARE(cli({QStringLiteral("animate"), saved, QStringLiteral("--say"), QStringLiteral("ni3 hao3"),
                         QStringLiteral("-o"), html})
                     .code,
            0);
        QFile htmlFile(html);
        QVERIFY(htmlFile.open(QIODevice::ReadOnly));
        QVERIFY(htmlFile.readAll().contains("<audio"));

        const QString mp4 = path(QStringLiteral("talk.mp4"));
        r = cli({QStringLiteral("animate"), projectPath, QStringLiteral("--say"), QStringLiteral("ni3 hao3"),
            QStringLiteral("--fps"), QStringLiteral("20"), QStringLiteral("-o"), mp4});
        QCOMPARE(r.code, 0);
        const auto info = probeMedia(mp4, &error);
        QVERIFY2(info, qPrintable(error));
        QVERIFY(info->hasAudio);
        QCOMPARE(info->fps, 20.0);
        QVERIFY(info->audioDurationS > 0.3);
        QVERIFY2(std::abs(info->frameCount / 20.0 - info->audioDurationS) < 0.1, "frames span the sound");
    }

    void animateCannotAlign()
    {
        const QString projectPath = faceProject(QStringLiteral("aligner.toonface"));
        QVERIFY(!projectPath.isEmpty());
        QString error;
        // One spoken syllable against a script of forty.
        const QString wav = path(QStringLiteral("one.wav"));
        QCOMPARE(cli({QStringLiteral("say"), QStringLiteral("hao3"), QStringLiteral("-o"), wav}).code, 0);
        const QString script = path(QStringLiteral("long.txt"));
        QFile f(script);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(
            QStringLiteral("我们今天一起去公园散步然后回家吃饭我们今天一起去公园散步然后回家吃饭我们今天一起去公园散步")
                .toUtf8());
        f.close();
        Run r = cli({QStringLiteral("animate"), projectPath, QStringLiteral("--audio"), wav, QStringLiteral("--script"),
            script, QStringLiteral("-o"), path(QStringLiteral("x.svg"))});
        QCOMPARE(r.code, 5);
        QVERIFY2(isOneErrorLine(r.err), r.err.constData());
        r = cli({QStringLiteral("animate"), projectPath, QStringLiteral("--audio"), path(QStringLiteral("nope.wav")),
            QStringLiteral("--script"), script, QStringLiteral("-o"), path(QStringLiteral("x.svg"))});
        QCOMPARE(r.code, 3);
        QVERIFY(r.err.contains("nope.wav"));
    }

    // A script given through a pipe (`--script <(echo ...)`) is read once: aligned, and kept
    // whole in the saved project.
    void animateScriptFromAPipe()
    {
        const QString projectPath = faceProject(QStringLiteral("piped.toonface"));
        QVERIFY(!projectPath.isEmpty());
        QString error;
        const QString wav = path(QStringLiteral("piped.wav"));
        QCOMPARE(cli({QStringLiteral("say"), QStringLiteral("ni3 hao3 shi4 jie4"), QStringLiteral("-o"), wav}).code, 0);
        const QString fifo = path(QStringLiteral("script.fifo"));
        QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
        QProcess writer; // the shell's side of the pipe
        writer.start(QStringLiteral("/bin/sh"),
            {QStringLiteral("-c"), QStringLiteral("printf '%s\\n' 'ni3 hao3 shi4 jie4' > \"$0\""), fifo});
        QVERIFY(writer.waitForStarted());
        const QString saved = path(QStringLiteral("piped-out.toonface"));
        const Run r
            = cli({QStringLiteral("animate"), projectPath, QStringLiteral("--audio"), wav, QStringLiteral("--script"),
                fifo, QStringLiteral("--project"), saved, QStringLiteral("-o"), path(QStringLiteral("piped.svg"))});
        QVERIFY(writer.waitForFinished(10000));
        QCOMPARE(r.code, 0);
        const auto reloaded = loadProject(saved, &error);
        QVERIFY2(reloaded, qPrintable(error));
        QCOMPARE(reloaded->timeline.audioClips().first().script, QStringLiteral("ni3 hao3 shi4 jie4"));
        QCOMPARE(reloaded->syllables.size(), 4);
    }

    // The landmark model's cache: written by the first detecting run, used by the next ones,
    // made again when damaged; the points the same every time.
    void detectUsesTheModelCache()
    {
        requirePortrait();
        const QString cacheDir = path(QStringLiteral("model-cache"));
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("TOONFACE_CACHE_DIR"), cacheDir);
        auto pointsOf = [](const Run &r) {
            return QJsonDocument::fromJson(r.out).object().value(QLatin1StringView("points")).toArray();
        };
        const Run first = cli({QStringLiteral("detect"), kPortrait}, env);
        QCOMPARE(first.code, 0);
        // The model's cache and the face detector's.
        QCOMPARE(QDir(cacheDir).entryList(QDir::Files).size(), 2);
        QCOMPARE(QDir(cacheDir).entryList({QStringLiteral("*.detector-cache")}, QDir::Files).size(), 1);
        const QStringList files = QDir(cacheDir).entryList({QStringLiteral("*.landmarks-cache")}, QDir::Files);
        QCOMPARE(files.size(), 1);
        const QString cacheFile = QDir(cacheDir).filePath(files.first());
        const qint64 size = QFileInfo(cacheFile).size();
        const QDateTime written = QFileInfo(cacheFile).lastModified();

        const Run second = cli({QStringLiteral("detect"), kPortrait}, env);
        QCOMPARE(second.code, 0);
        QCOMPARE(pointsOf(second), pointsOf(first));
        QCOMPARE(QFileInfo(cacheFile).lastModified(), written);

        QFile damaged(cacheFile);
        QVERIFY(damaged.resize(size / 3));
        const Run third = cli({QStringLiteral("detect"), kPortrait}, env);
        QCOMPARE(third.code, 0);
        QVERIFY2(third.err.isEmpty(), third.err.constData());
        QCOMPARE(pointsOf(third), pointsOf(first));
        QCOMPARE(QFileInfo(cacheFile).size(), size);
        QCOMPARE(QDir(cacheDir).entryList(QDir::Files).size(), 2);

        // Several processes at once with no cache yet: each finds the face, one cache is left.
        const QString freshDir = path(QStringLiteral("model-cache-concurrent"));
        env.insert(QStringLiteral("TOONFACE_CACHE_DIR"), freshDir);
        std::vector<std::unique_ptr<QProcess>> runs;
        for (int i = 0; i < 3; ++i) {
            runs.push_back(std::make_unique<QProcess>());
            runs.back()->setProcessEnvironment(env);
            runs.back()->start(QStringLiteral(TOONFACE_CLI_PATH), {QStringLiteral("detect"), kPortrait});
        }
        for (auto &p : runs) {
            QVERIFY(p->waitForFinished(120000));
            QCOMPARE(p->exitCode(), 0);
            const QJsonArray points = QJsonDocument::fromJson(p->readAllStandardOutput())
                                          .object()
                                          .value(QLatin1StringView("points"))
                                          .toArray();
            QCOMPARE(points, pointsOf(first));
        }
        QCOMPARE(QDir(freshDir).entryList(QDir::Files | QDir::Hidden).size(), 2);
        const QStringList left = QDir(freshDir).entryList({QStringLiteral("*.landmarks-cache")}, QDir::Files);
        QCOMPARE(left.size(), 1);
        QCOMPARE(QFileInfo(QDir(freshDir).filePath(left.first())).size(), size);
    }

    // Runs that cannot use the landmark model do not start loading it.
    void noModelWorkWithoutLandmarks()
    {
        requirePortrait();
        const QString cacheDir = path(QStringLiteral("untouched-cache"));
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("TOONFACE_CACHE_DIR"), cacheDir);
        const QString projectPath = faceProject(QStringLiteral("no-model.toonface"));
        QVERIFY(!projectPath.isEmpty());
        QString error;
        QCOMPARE(
            cli({QStringLiteral("cartoon"), projectPath, QStringLiteral("-o"), path(QStringLiteral("nm.svg"))}, env)
                .code,
            0);
        QCOMPARE(cli({QStringLiteral("detect"), QStringLiteral("--help")}, env).code, 0);
        cli({QStringLiteral("detect"), kPortrait, QStringLiteral("--method"), QStringLiteral("classic")}, env);
        QVERIFY(!QFileInfo::exists(cacheDir));
    }

    void unwritableOutput()
    {
        const QString projectPath = faceProject(QStringLiteral("w.toonface"));
        QVERIFY(!projectPath.isEmpty());
        QString error;
        const Run r = cli({QStringLiteral("cartoon"), projectPath, QStringLiteral("-o"),
            path(QStringLiteral("no/such/dir/out.svg"))});
        QCOMPARE(r.code, 1);
        QVERIFY2(isOneErrorLine(r.err), r.err.constData());
        QVERIFY(r.err.contains("out.svg"));
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestCli)
#include "tst_cli.moc"
