#include "face/averageface.h"
#include "io/project.h"
#include "speech/audio.h"
#include "testmain.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <csignal>
#include <limits>

#ifdef Q_OS_LINUX
#include <linux/capability.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

using namespace toonface;

namespace {

const QString kData = QStringLiteral(TOONFACE_TEST_DATA "/io");

// A project in which every field differs from its default, with doubles that have no short
// decimal form, so that a lossy write shows.
Project richProject(const QString &dir)
{
    Project p;
    p.photoPath = dir + QStringLiteral("/photos/face.jpg");
    p.face = averageFace(QRectF(101.3, 150.7, 203.1, 241.9), QSize(640, 800));
    p.face.setPoint(12, QPointF(1.0 / 3.0, 2.0 / 7.0 + 100), true);
    p.face.setPoint(40, QPointF(123.456789012345678, 0.1 + 0.2), true);
    p.face.setHandPlaced(71, true);

    p.style.name = QStringLiteral("cute");
    p.style.cornerCutDepth = 3;
    p.style.cute = true;
    p.style.eyebrows = EyebrowVariant::Bezier;
    p.style.nose = NoseVariant::Tip;
    p.style.components.insert(QStringLiteral("hair"), {QColor(0x33, 0x22, 0x1a), QColor(), 0.0, true});
    p.style.components.insert(QStringLiteral("face"), {QColor(242, 201, 160), QColor(90, 59, 34), 1.0 / 3.0, true});
    p.style.components.insert(QStringLiteral("eyeballs"), {QColor(26, 26, 26, 204), QColor(1, 2, 3, 4), 0.75, false});
    p.style.components.insert(QStringLiteral("ears"), {QColor(), QColor(), 0, false});

    MouthShapePreset a = MouthShapeSet::defaultPreset(MouthShape::A);
    a.offsets[Down].dy = {0.95, 0.01, -0.2, 1.0 / 7.0};
    a.offsets[Left].dx = {0.001, 1.0 / 9.0, 0.3, -2.5};
    a.cornersAtLipMiddle = true;
    p.mouthShapes.setPreset(MouthShape::A, a);
    MouthShapePreset n = MouthShapeSet::defaultPreset(MouthShape::N);
    n.cornersFromPrevious = false;
    p.mouthShapes.setPreset(MouthShape::N, n);

    p.layerPaths
        = {dir + QStringLiteral("/layers/hat.svg"), QDir::cleanPath(dir + QStringLiteral("/../elsewhere/glasses.svg"))};

    // Every track of the timeline, with numbers that need all their digits.
    Timeline timeline;
    timeline.setFrameRate(29.97);
    for (int i = 0; i < 5; ++i)
        timeline.addMouthKey(MouthKey {i / 12.0 + 1e-9, MouthShape::A, 0.75, 1 / 24.0});
    timeline.addEmotionClip(EmotionClip {0.5, 2.25, Emotion::Smile, 0.6, 0.2, 0.4});
    timeline.addBlink(BlinkEvent {1.1, 0.17});
    timeline.addGazeKey(GazeKey {0.3, QPointF(0.05, -0.02)});
    timeline.addHeadKey(HeadKey {0.7, 3.5, QPointF(0.01, 0.02), 1.05});
    // Two recordings, the second trimmed, each with its script.
    AudioClip voice {dir + QStringLiteral("/audio/voice.wav"), 0.125 + 1e-9, 12.345678901234567};
    voice.script = QStringLiteral("你好，世界 — \"hello\"\n第二行");
    voice.language = QStringLiteral("cmn");
    AudioClip reply {dir + QStringLiteral("/audio/reply.wav"), 13.0, 4.5};
    reply.trimIn = 0.25;
    reply.trimOut = 1.0 / 3;
    reply.script = QStringLiteral("Fine, thanks");
    reply.language = QStringLiteral("en");
    timeline.setAudioClips({reply, voice});
    timeline.setVideo(VideoClip {dir + QStringLiteral("/video/talk.mpg"), 0.5 + 1e-9, 2.999999999, 29.97});
    p.timeline = timeline;

    LipsyncSyllable ni {QStringLiteral("你"), QStringLiteral("ni"), 3, 0.1, 0.35, 0.9, {}};
    ni.shapes = {{MouthShape::I, 0.1}};
    LipsyncSyllable hao {QStringLiteral("好"), QStringLiteral("hao"), 3, 0.35, 0.7 + 1e-12, 0.5, {}};
    hao.shapes = {{MouthShape::A, 0.35}, {MouthShape::U, 0.35 + 0.8095 * 0.35}};
    p.syllables = {ni, hao};

    return p;
}

QByteArray readAll(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return f.readAll();
}

bool writeFile(const QString &path, const QByteArray &bytes)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

QStringList entries(const QString &dir)
{
    return QDir(dir).entryList(QDir::AllEntries | QDir::Hidden | QDir::System | QDir::NoDotAndDotDot, QDir::Name);
}

#ifdef Q_OS_LINUX
// Root writes into read-only directories regardless of their mode. Dropping CAP_DAC_OVERRIDE
// from this thread's effective set (it stays permitted, so it can be raised again) makes the
// mode count, as it does for a normal user.
class DacOverrideDropped
{
public:
    DacOverrideDropped()
    {
        __user_cap_header_struct header {_LINUX_CAPABILITY_VERSION_3, 0};
        if (syscall(SYS_capget, &header, m_saved) != 0)
            return;
        __user_cap_data_struct reduced[2] = {m_saved[0], m_saved[1]};
        reduced[0].effective &= ~(1u << CAP_DAC_OVERRIDE);
        m_active = syscall(SYS_capset, &header, reduced) == 0;
    }
    ~DacOverrideDropped()
    {
        if (!m_active)
            return;
        __user_cap_header_struct header {_LINUX_CAPABILITY_VERSION_3, 0};
        syscall(SYS_capset, &header, m_saved);
    }

private:
    __user_cap_data_struct m_saved[2] {};
    bool m_active = false;
};
#endif

} // namespace

class TestProject : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void roundTripIsLossless()
    {
        QTemporaryDir tmp;
        QVERIFY(tmp.isValid());
        const Project original = richProject(tmp.path());
        const QString file = tmp.filePath(QStringLiteral("a.toonface"));
        QString error;
        QVERIFY2(saveProject(original, file, &error), qPrintable(error));
        const std::optional<Project> loaded = loadProject(file, &error);
        QVERIFY2(loaded, qPrintable(error));

        // Field by field first, so that a failure says which one.
        QCOMPARE(loaded->photoPath, original.photoPath);
        QCOMPARE(loaded->face.imageSize(), original.face.imageSize());
        for (int i = 0; i < kPointCount; ++i) {
            QCOMPARE(loaded->face.point(i).x(), original.face.point(i).x());
            QCOMPARE(loaded->face.point(i).y(), original.face.point(i).y());
            QCOMPARE(loaded->face.isHandPlaced(i), original.face.isHandPlaced(i));
        }
        QCOMPARE(loaded->face.handPlacedCount(), 3);
        QCOMPARE(loaded->style.components.keys(), original.style.components.keys());
        for (const QString &name : original.style.components.keys()) {
            const ComponentStyle &a = loaded->style.components[name];
            const ComponentStyle &b = original.style.components[name];
            QCOMPARE(a.fill, b.fill);
            QCOMPARE(a.stroke, b.stroke);
            QCOMPARE(a.strokeWidth, b.strokeWidth);
            QCOMPARE(a.visible, b.visible);
        }
        QVERIFY(loaded->style == original.style);
        for (MouthShape s : kAllMouthShapes)
            QVERIFY2(loaded->mouthShapes.preset(s) == original.mouthShapes.preset(s), qPrintable(mouthShapeName(s)));
        QVERIFY(!loaded->mouthShapes.isDefault(MouthShape::A));
        QCOMPARE(loaded->layerPaths, original.layerPaths);
        QCOMPARE(loaded->timeline, original.timeline);
        QCOMPARE(loaded->syllables, original.syllables);
        QCOMPARE(loaded->audioPath(), original.audioPath());
        QCOMPARE(loaded->timeline.audioClips().size(), 2);
        QCOMPARE(loaded->timeline.audioClips()[1].trimOut, 1.0 / 3);
        QCOMPARE(loaded->timeline.audioClips()[1].script, QStringLiteral("Fine, thanks"));
        QVERIFY(*loaded == original);
    }

    void defaultProjectRoundTrips()
    {
        QTemporaryDir tmp;
        const QString file = tmp.filePath(QStringLiteral("empty.toonface"));
        QString error;
        QVERIFY2(saveProject(Project(), file, &error), qPrintable(error));
        const auto loaded = loadProject(file, &error);
        QVERIFY2(loaded, qPrintable(error));
        QVERIFY(!loaded->face.imageSize().isValid());
        QVERIFY(loaded->photoPath.isEmpty());
        QVERIFY(*loaded == Project());
    }

    // Presets are saved as they are: a project made with any preset loads back equal.
    void everyStylePresetRoundTrips()
    {
        QTemporaryDir tmp;
        for (const QString &name : Style::presetNames()) {
            Project project;
            project.style = Style::preset(name);
            const QString file = tmp.filePath(name + QStringLiteral(".toonface"));
            QString error;
            QVERIFY2(saveProject(project, file, &error), qPrintable(error));
            const auto loaded = loadProject(file, &error);
            QVERIFY2(loaded, qPrintable(error));
            QVERIFY2(loaded->style == project.style, qPrintable(name));
        }
    }

    void fileLayout()
    {
        QTemporaryDir tmp;
        const QString file = tmp.filePath(QStringLiteral("a.toonface"));
        QString error;
        QVERIFY2(saveProject(richProject(tmp.path()), file, &error), qPrintable(error));
        const QJsonObject json = QJsonDocument::fromJson(readAll(file)).object();
        QCOMPARE(json.value(QStringLiteral("format")).toString(), QStringLiteral("toonface.project"));
        QCOMPARE(json.value(QStringLiteral("version")).toInt(), kProjectVersion);
        // Paths on disk are relative to the project file.
        QCOMPARE(json.value(QStringLiteral("photo")).toString(), QStringLiteral("photos/face.jpg"));
        QCOMPARE(json.value(QStringLiteral("layers")).toArray().at(0).toString(), QStringLiteral("layers/hat.svg"));
        QCOMPARE(json.value(QStringLiteral("layers")).toArray().at(1).toString(),
            QStringLiteral("../elsewhere/glasses.svg"));
        const QJsonArray clips
            = json.value(QStringLiteral("timeline")).toObject().value(QStringLiteral("audio")).toArray();
        QCOMPARE(clips.size(), 2);
        QCOMPARE(clips.at(0).toObject().value(QStringLiteral("path")).toString(), QStringLiteral("audio/voice.wav"));
        QCOMPARE(clips.at(1).toObject().value(QStringLiteral("path")).toString(), QStringLiteral("audio/reply.wav"));
        const QJsonObject video
            = json.value(QStringLiteral("timeline")).toObject().value(QStringLiteral("video")).toObject();
        QCOMPARE(video.value(QStringLiteral("path")).toString(), QStringLiteral("video/talk.mpg"));
        QCOMPARE(video.value(QStringLiteral("fps")).toDouble(), 29.97);
        // Points in face-model order with their flags.
        const QJsonArray points = json.value(QStringLiteral("points")).toArray();
        QCOMPARE(points.size(), kPointCount);
        for (int i = 0; i < kPointCount; ++i)
            QCOMPARE(points.at(i).toObject().value(QStringLiteral("id")).toString(), pointId(i));
        QCOMPARE(points.at(12).toObject().value(QStringLiteral("handPlaced")).toBool(), true);
        QCOMPARE(points.at(13).toObject().value(QStringLiteral("handPlaced")).toBool(), false);
        // Colours: #rrggbb when opaque, #aarrggbb otherwise, "none" for no colour.
        const QJsonObject components
            = json.value(QStringLiteral("style")).toObject().value(QStringLiteral("components")).toObject();
        const QJsonObject hair = components.value(QStringLiteral("hair")).toObject();
        QCOMPARE(hair.value(QStringLiteral("fill")).toString(), QStringLiteral("#33221a"));
        QCOMPARE(hair.value(QStringLiteral("stroke")).toString(), QStringLiteral("none"));
        QCOMPARE(components.value(QStringLiteral("eyeballs")).toObject().value(QStringLiteral("fill")).toString(),
            QStringLiteral("#cc1a1a1a"));
        // All nine mouth shapes by name.
        const QJsonObject shapes = json.value(QStringLiteral("mouthShapes")).toObject();
        QCOMPARE(shapes.size(), kMouthShapeCount);
        for (MouthShape s : kAllMouthShapes)
            QVERIFY(shapes.contains(mouthShapeName(s)));
        const QJsonObject aDn = shapes.value(QStringLiteral("a")).toObject().value(QStringLiteral("dn")).toObject();
        QCOMPARE(aDn.value(QStringLiteral("dy")).toObject().value(QStringLiteral("mns")).toDouble(), 0.95);
    }

    void movedProjectResolvesPathsAgainstItsNewFolder()
    {
        QTemporaryDir a;
        QTemporaryDir b;
        const QString oldFile = a.filePath(QStringLiteral("talk.toonface"));
        const Project original = richProject(a.path());
        QVERIFY(writeFile(original.photoPath, QByteArrayLiteral("not really a photo")));
        QString error;
        QVERIFY2(saveProject(original, oldFile, &error), qPrintable(error));

        // The user moves the project together with its photo folder.
        const QString newFile = b.filePath(QStringLiteral("talk.toonface"));
        QVERIFY(QFile::copy(oldFile, newFile));
        QVERIFY(writeFile(b.filePath(QStringLiteral("photos/face.jpg")), readAll(original.photoPath)));

        const auto loaded = loadProject(newFile, &error);
        QVERIFY2(loaded, qPrintable(error));
        QCOMPARE(loaded->photoPath, QDir::cleanPath(b.filePath(QStringLiteral("photos/face.jpg"))));
        QVERIFY(QFileInfo::exists(loaded->photoPath));
        QCOMPARE(loaded->audioPath(), QDir::cleanPath(b.filePath(QStringLiteral("audio/voice.wav"))));
        QVERIFY(loaded->timeline.video());
        QCOMPARE(loaded->timeline.video()->path, QDir::cleanPath(b.filePath(QStringLiteral("video/talk.mpg"))));
        QCOMPARE(loaded->timeline.video()->offset, original.timeline.video()->offset);
        QCOMPARE(loaded->layerPaths.at(1), QDir::cleanPath(b.path() + QStringLiteral("/../elsewhere/glasses.svg")));
        QVERIFY(loaded->face == original.face);
    }

    void relativeFileNameResolvesAgainstItsFolder()
    {
        QTemporaryDir tmp;
        const Project original = richProject(tmp.path());
        const QString saved = QDir::currentPath();
        QVERIFY(QDir::setCurrent(tmp.path()));
        QString error;
        const bool ok = saveProject(original, QStringLiteral("rel.toonface"), &error);
        const auto loaded = loadProject(QStringLiteral("rel.toonface"), &error);
        QDir::setCurrent(saved);
        QVERIFY2(ok, qPrintable(error));
        QVERIFY2(loaded, qPrintable(error));
        QCOMPARE(loaded->photoPath, original.photoPath);
    }

    void versionOneFixtureLoads()
    {
        const QString file = kData + QStringLiteral("/v1/project.toonface");
        QString error;
        const auto p = loadProject(file, &error);
        QVERIFY2(p, qPrintable(error));
        QCOMPARE(p->photoPath, QDir::cleanPath(kData + QStringLiteral("/v1/photo.png")));
        QCOMPARE(p->face.imageSize(), QSize(640, 800));
        QCOMPARE(p->face.point(pt::idx("h.2")), QPointF(123.25, 147.5));
        QCOMPARE(p->face.handPlacedCount(), 2);
        QVERIFY(p->face.isHandPlaced(12));
        QVERIFY(p->face.isHandPlaced(40));
        QCOMPARE(p->style.components.size(), 3);
        QCOMPARE(p->style.components.value(QStringLiteral("face")).fill, QColor(0xf2, 0xc9, 0xa0));
        QVERIFY(!p->style.components.value(QStringLiteral("hair")).stroke.isValid());
        QVERIFY(!p->style.components.value(QStringLiteral("eyeballs")).stroke.isValid()); // absent = none
        QCOMPARE(p->style.components.value(QStringLiteral("eyeballs")).fill, QColor(0x1a, 0x1a, 0x1a, 0xcc));
        // The file holds face-model.md's defaults except a's lower lip (0.95 MNS0 instead of 0.8).
        for (MouthShape s : kAllMouthShapes) {
            if (s != MouthShape::A)
                QVERIFY2(p->mouthShapes.isDefault(s), qPrintable(mouthShapeName(s)));
        }
        QCOMPARE(p->mouthShapes.preset(MouthShape::A).offsets[Down].dy.mns, 0.95);
        QCOMPARE(p->layerPaths, QStringList {QDir::cleanPath(kData + QStringLiteral("/v1/layers/hat.svg"))});
        QCOMPARE(p->timeline.mouthKeys().size(), 2);
        QCOMPARE(p->timeline.mouthKeys()[1].time, 0.4);
        QCOMPARE(p->timeline.mouthKeys()[1].shape, MouthShape::A);
        QCOMPARE(p->audioPath(), QDir::cleanPath(kData + QStringLiteral("/v1/voice.wav")));
        QVERIFY(p->syllables.isEmpty()); // a file from before syllables were saved
        // Its one sound is a track of one clip, with the file's script.
        QCOMPARE(p->timeline.audioClips().size(), 1);
        const AudioClip &clip = p->timeline.audioClips().first();
        QCOMPARE(clip.offset, 0.25);
        QCOMPARE(clip.trimIn, 0.0);
        QCOMPARE(clip.trimOut, 0.0);
        QCOMPARE(clip.script, QStringLiteral("ni hao"));
        QCOMPARE(clip.language, QStringLiteral("cmn"));
        QVERIFY(!p->timeline.video()); // a file from before Import Video
        // Saved again, it is written in the new form and loads the same.
        QTemporaryDir dir;
        const QString again = dir.filePath(QStringLiteral("again.toonface"));
        QVERIFY2(saveProject(*p, again, &error), qPrintable(error));
        const QJsonObject json = QJsonDocument::fromJson(readAll(again)).object();
        QCOMPARE(json.value(QStringLiteral("version")).toInt(), 2);
        QVERIFY(json.value(QStringLiteral("timeline")).toObject().value(QStringLiteral("audio")).isArray());
        QVERIFY(!json.contains(QStringLiteral("script")));
        const auto reloaded = loadProject(again, &error);
        QVERIFY2(reloaded, qPrintable(error));
        QCOMPARE(reloaded->timeline.audioClips(), p->timeline.audioClips());
    }

    // A version-1 sound of unknown length gets its file's length when the file is there.
    void versionOneSoundGetsItsLength()
    {
        QTemporaryDir dir;
        const QString file = dir.filePath(QStringLiteral("project.toonface"));
        QVERIFY(QFile::copy(kData + QStringLiteral("/v1/project.toonface"), file));
        Audio tone;
        tone.samples.resize(qsizetype(1.5 * tone.sampleRate));
        for (qsizetype i = 0; i < tone.samples.size(); ++i)
            tone.samples[i] = float(0.3 * std::sin(0.1 * double(i)));
        QString error;
        QVERIFY2(writeAudio(dir.filePath(QStringLiteral("voice.wav")), tone, &error), qPrintable(error));
        const auto p = loadProject(file, &error);
        QVERIFY2(p, qPrintable(error));
        QCOMPARE(p->timeline.audioClips().size(), 1);
        QVERIFY2(std::abs(p->timeline.audioClips().first().duration - 1.5) < 0.01,
            qPrintable(QString::number(p->timeline.audioClips().first().duration)));
        QCOMPARE(p->timeline.audioClips().first().end(), 1.75); // from its offset, 0.25 s
    }

    void malformedProjects_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("expected");
        auto row = [](const char *file, const char *expected) {
            QTest::newRow(file) << QString::fromLatin1(file) << QString::fromUtf8(expected);
        };
        row("missing-points.toonface", "points: expected an array, it is missing");
        row("point12-x-string.toonface", "points[12].x: expected a number, found the string \"12.5\"");
        row("point3-y-null.toonface", "points[3].y: expected a number, found null");
        row("point0-x-nan-string.toonface", "points[0].x: expected a number, found the string \"NaN\"");
        row("point7-x-huge.toonface", "points[7].x: expected a number between -10000000 and 10000000, found 1e+300");
        row("point-x-1e999.toonface", "not a Toonface project: illegal number at offset");
        row("point2-handplaced-string.toonface", "points[2].handPlaced: expected true or false");
        row("wrong-id-order.toonface", "points[5].id: expected \"h.6\"");
        row("71-points.toonface", "points: expected 72 points, found 71");
        row("bad-colour.toonface", "style.components.hair.fill: expected a colour like #rrggbb");
        row("bad-colour-digits.toonface", "style.components.face.stroke: expected a colour like #rrggbb");
        row("negative-stroke.toonface", "style.components.face.strokeWidth: expected a width of 0 or more");
        row("bad-eyebrows.toonface", "style.eyebrows: expected one of \"polyline\", \"bezier\", \"thick\"");
        row("corner-cut-depth.toonface", "style.cornerCutDepth: expected an integer from 0 to 8, found 50");
        row("unknown-mouth-shape.toonface", "mouthShapes.x: unknown mouth shape");
        row("missing-mouth-shape.toonface", "mouthShapes.o: expected an object, it is missing");
        row("mouth-term-missing.toonface", "mouthShapes.a.dn.dy.mns: expected a number, it is missing");
        row("mouth-flag-number.toonface", "mouthShapes.n.cornersFromPrevious: expected true or false, found 1");
        row("layer-empty.toonface", "layers[1]: expected a file path");
        row("timeline-array.toonface", "timeline: expected an object, found an array");
        row("timeline-mouth-shape.toonface", "timeline.mouth[1].shape");
        // Times are capped at the longest timeline kept (Timeline::kMaxSeconds, four hours).
        row("timeline-key-1e308.toonface", "timeline.mouth[1].time: 1e+308 s is beyond the longest timeline");
        row("timeline-clip-10h.toonface", "timeline.emotion[0].end: 36001 s is beyond the longest timeline");
        row("syllable-end-before-start.toonface", "script.syllables[0].end: expected a time after the start");
        row("audio-offset-string.toonface", "audio.offset: expected a number");
        row("script-language.toonface", "script.language: expected \"cmn\", \"en\" or \"\"");
        row("image-size-negative.toonface", "imageSize.width: expected an integer from 0 to 1000000, found -640");
        row("newer-version.toonface", "made by a newer Toonface (project version 3; this version reads up to 2)");
        row("version-string.toonface", "version: expected a version number (1 or more), found the string \"1\"");
        row("version-zero.toonface", "version: expected a version number (1 or more), found 0");
        row("wrong-format.toonface",
            "not a Toonface project (format: expected \"toonface.project\", found the string \"toonface.face/1\")");
        row("missing-format.toonface", "not a Toonface project (it has no \"format\" field)");
        row("top-level-array.toonface", "not a Toonface project (expected a JSON object");
        row("not-json.toonface", "not a Toonface project: illegal value at offset");
        row("empty.toonface", "the file is empty");
        row("truncated.toonface", "not a Toonface project: ");
    }

    void malformedProjects()
    {
        QFETCH(QString, file);
        QFETCH(QString, expected);
        const QString path = kData + QStringLiteral("/bad/") + file;
        QVERIFY(QFileInfo::exists(path));
        QString error;
        const auto project = loadProject(path, &error);
        QVERIFY(!project);
        QVERIFY2(error.startsWith(path + QStringLiteral(": ")), qPrintable(error));
        QVERIFY2(error.contains(expected), qPrintable(error));
        QVERIFY2(!error.contains(QLatin1Char('\n')), qPrintable(error));
    }

    void truncatedFileReportsTheOffset()
    {
        const QString path = kData + QStringLiteral("/bad/truncated.toonface");
        QString error;
        QVERIFY(!loadProject(path, &error));
        const QByteArray bytes = readAll(path);
        const QString where = QStringLiteral(" at offset %1 (line %2, column %3)")
                                  .arg(bytes.size())
                                  .arg(bytes.count('\n') + 1)
                                  .arg(bytes.size() - bytes.lastIndexOf('\n'));
        QVERIFY2(error.endsWith(where), qPrintable(error));
    }

    void everyTruncationIsRefused()
    {
        QTemporaryDir tmp;
        const QString good = tmp.filePath(QStringLiteral("good.toonface"));
        QString error;
        QVERIFY2(saveProject(richProject(tmp.path()), good, &error), qPrintable(error));
        const QByteArray bytes = readAll(good);
        const QString cut = tmp.filePath(QStringLiteral("cut.toonface"));
        // The last byte is the trailing newline: cutting it still leaves a complete document.
        for (qsizetype n = 0; n < bytes.size() - 1; n += 61) {
            QVERIFY(writeFile(cut, bytes.left(n)));
            QVERIFY2(!loadProject(cut, &error), qPrintable(QString::number(n)));
            QVERIFY2(error.startsWith(cut + QStringLiteral(": ")), qPrintable(error));
        }
    }

    void corruptedBytesNeverCrash()
    {
        QTemporaryDir tmp;
        const QString good = tmp.filePath(QStringLiteral("good.toonface"));
        QString error;
        QVERIFY2(saveProject(richProject(tmp.path()), good, &error), qPrintable(error));
        const QByteArray bytes = readAll(good);
        const QString bad = tmp.filePath(QStringLiteral("bad.toonface"));
        quint32 state = 12345;
        auto next = [&state] { return state = state * 1664525u + 1013904223u; };
        int refused = 0;
        for (int round = 0; round < 300; ++round) {
            QByteArray mutated = bytes;
            for (int k = 0; k < 3; ++k)
                mutated[qsizetype(next() % quint32(mutated.size()))] = char(next() >> 24);
            QVERIFY(writeFile(bad, mutated));
            if (!loadProject(bad, &error)) {
                ++refused;
                QVERIFY2(error.startsWith(bad + QStringLiteral(": ")), qPrintable(error));
            }
        }
        QVERIFY(refused > 0);
    }

    void missingFile()
    {
        QTemporaryDir tmp;
        const QString path = tmp.filePath(QStringLiteral("nowhere.toonface"));
        QString error;
        QVERIFY(!loadProject(path, &error));
        QCOMPARE(error, path + QStringLiteral(": no such file"));
        QVERIFY(!loadProject(tmp.path(), &error));
        QVERIFY2(error.startsWith(tmp.path() + QStringLiteral(": is a folder")), qPrintable(error));
    }

    void projectFromJsonReportsPathWithoutFile()
    {
        QTemporaryDir tmp;
        QJsonObject json = projectToJson(richProject(tmp.path()), tmp.path());
        QJsonObject style = json.value(QStringLiteral("style")).toObject();
        style.insert(QStringLiteral("cute"), QStringLiteral("very"));
        json.insert(QStringLiteral("style"), style);
        QString error;
        QVERIFY(!projectFromJson(json, tmp.path(), &error));
        QCOMPARE(error, QStringLiteral("style.cute: expected true or false, found the string \"very\""));
    }

    void saveOverwritesAndLeavesNoTemporaryFiles()
    {
        QTemporaryDir tmp;
        const QString file = tmp.filePath(QStringLiteral("a.toonface"));
        Project p = richProject(tmp.path());
        QString error;
        QVERIFY2(saveProject(p, file, &error), qPrintable(error));
        p.syllables.first().text = QStringLiteral("changed");
        QVERIFY2(saveProject(p, file, &error), qPrintable(error));
        QCOMPARE(loadProject(file, &error)->syllables.first().text, QStringLiteral("changed"));
        QCOMPARE(entries(tmp.path()), QStringList {QStringLiteral("a.toonface")});
    }

    void saveRefusesNonFiniteValues()
    {
        QTemporaryDir tmp;
        const QString file = tmp.filePath(QStringLiteral("a.toonface"));
        Project p = richProject(tmp.path());
        QString error;
        QVERIFY2(saveProject(p, file, &error), qPrintable(error));
        const QByteArray before = readAll(file);
        p.face.setPoint(3, QPointF(std::numeric_limits<double>::quiet_NaN(), 1));
        QVERIFY(!saveProject(p, file, &error));
        QVERIFY2(error.startsWith(file + QStringLiteral(": not saved")), qPrintable(error));
        QVERIFY2(error.contains(QStringLiteral("points[3].x")), qPrintable(error));
        QCOMPARE(readAll(file), before);
    }

    void saveIntoReadOnlyFolderKeepsTheOldFile()
    {
#ifndef Q_OS_LINUX
        QSKIP("folder permissions are tested on Linux");
#else
        QTemporaryDir tmp;
        const QString dir = tmp.filePath(QStringLiteral("ro"));
        QVERIFY(QDir().mkpath(dir));
        const QString file = dir + QStringLiteral("/a.toonface");
        Project p = richProject(tmp.path());
        QString error;
        QVERIFY2(saveProject(p, file, &error), qPrintable(error));
        const QByteArray before = readAll(file);
        const QStringList filesBefore = entries(dir);

        QVERIFY(QFile::setPermissions(dir,
            QFile::ReadOwner | QFile::ExeOwner | QFile::ReadGroup | QFile::ExeGroup | QFile::ReadOther
                | QFile::ExeOther));
        bool saved = false;
        bool folderWritable = false;
        {
            DacOverrideDropped unprivileged;
            QFile probe(dir + QStringLiteral("/probe"));
            folderWritable = probe.open(QIODevice::WriteOnly);
            if (folderWritable)
                probe.remove();
            else {
                p.syllables.first().text = QStringLiteral("a new script");
                saved = saveProject(p, file, &error);
            }
        }
        QFile::setPermissions(dir, QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
        if (folderWritable)
            QSKIP("this process can write into read-only folders (privileged, and capabilities could not be dropped)");

        QVERIFY(!saved);
        QVERIFY2(error.startsWith(file + QStringLiteral(": cannot save: ")), qPrintable(error));
        // A reason the user can act on, never Qt's "Unknown error".
        QVERIFY2(!error.contains(QStringLiteral("Unknown error")), qPrintable(error));
        QVERIFY2(error.size() > file.size() + QStringLiteral(": cannot save: ").size() + 4, qPrintable(error));
        QCOMPARE(readAll(file), before);
        QCOMPARE(entries(dir), filesBefore);
#endif
    }

    void failedWriteKeepsTheOldFile()
    {
#ifndef Q_OS_LINUX
        QSKIP("the file size limit is set with setrlimit on Linux");
#else
        // A write that fails halfway (here: the file size limit; in life: a full disk).
        QTemporaryDir tmp;
        const QString file = tmp.filePath(QStringLiteral("a.toonface"));
        QVERIFY(writeFile(file, QByteArrayLiteral("{\"the\": \"old project\"}\n")));
        const QByteArray before = readAll(file);

        rlimit saved {};
        QCOMPARE(getrlimit(RLIMIT_FSIZE, &saved), 0);
        rlimit small = saved;
        small.rlim_cur = 4096;
        const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
        QCOMPARE(setrlimit(RLIMIT_FSIZE, &small), 0);
        QString error;
        const bool ok = saveProject(richProject(tmp.path()), file, &error);
        setrlimit(RLIMIT_FSIZE, &saved);
        std::signal(SIGXFSZ, oldHandler);

        QVERIFY(!ok);
        QVERIFY2(error.startsWith(file + QStringLiteral(": cannot save: ")), qPrintable(error));
        QCOMPARE(readAll(file), before);
        QCOMPARE(entries(tmp.path()), QStringList {QStringLiteral("a.toonface")});
#endif
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestProject)
#include "tst_project.moc"
