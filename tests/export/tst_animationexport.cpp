#include "animationfixture.h"
#include "testmain.h"

#include "export/animationexport.h"
#include "io/project.h"
#include "media/mediareader.h"
#include "render/style.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <atomic>

using namespace toonface;

namespace {

// A short talking timeline: 1.6 s at 10 fps (16 frames), with the sound of a tone when given.
Timeline shortTimeline(const QString &audioPath = {})
{
    Timeline t;
    t.setFrameRate(10);
    t.addMouthCues({{0.1, 0.4, MouthShape::A}, {0.4, 0.7, MouthShape::O}, {0.8, 1.2, MouthShape::I}});
    t.addBlink({0.5, 0.15});
    t.addEmotionClip({0.2, 1.4, Emotion::Smile, 0.8, 0.3, 0.3});
    t.setAudioClips({AudioClip {audioPath, 0.0, 1.6}});
    return t;
}

ExportRequest request(AnimationFormat format, const QString &out, const QString &audioPath = {})
{
    ExportRequest r;
    r.format = format;
    r.outputPath = out;
    r.size = 96;
    r.face = test::animationFace();
    r.style = Style::preset(QStringLiteral("normal"));
    r.timeline = shortTimeline(audioPath);
    return r;
}

QString outputName(AnimationFormat format)
{
    return format == AnimationFormat::PngSequence ? QStringLiteral("frames/")
                                                  : QStringLiteral("out.") + animationFormatSuffix(format);
}

// Everything in `dir`, hidden entries included.
QStringList entries(const QString &dir)
{
    return QDir(dir).entryList(QDir::AllEntries | QDir::Hidden | QDir::System | QDir::NoDotAndDotDot, QDir::Name);
}

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace

class TestAnimationExport : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    QString m_tone;

    QString newFolder(const QString &name)
    {
        const QString path = m_dir.filePath(name);
        QDir(path).removeRecursively();
        QDir().mkpath(path);
        return path;
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_tone = m_dir.filePath(QStringLiteral("tone.wav"));
        QVERIFY(test::writeToneWav(m_tone, 1.6));
    }

    void formatsFromPaths()
    {
        QCOMPARE(animationFormatForPath(QStringLiteral("a/b.SVG")), AnimationFormat::SmilSvg);
        QCOMPARE(animationFormatForPath(QStringLiteral("b.htm")), AnimationFormat::HtmlPlayer);
        QCOMPARE(animationFormatForPath(QStringLiteral("b.html")), AnimationFormat::HtmlPlayer);
        QCOMPARE(animationFormatForPath(QStringLiteral("b.mp4")), AnimationFormat::Mp4);
        QCOMPARE(animationFormatForPath(QStringLiteral("b.gif")), AnimationFormat::Gif);
        QCOMPARE(animationFormatForPath(QStringLiteral("frames/")), AnimationFormat::PngSequence);
        QCOMPARE(animationFormatForPath(QStringLiteral("b.txt")), std::nullopt);
        QCOMPARE(animationFormatForPath(QStringLiteral("b")), std::nullopt);
        for (AnimationFormat f : kAllAnimationFormats) {
            if (f != AnimationFormat::PngSequence)
                QCOMPARE(animationFormatForPath(QStringLiteral("x.") + animationFormatSuffix(f)), f);
        }
    }

    // A project's animation, its sound included, becomes a request.
    void requestFromAProject()
    {
        Project project;
        project.face = test::animationFace();
        project.style = Style::preset(QStringLiteral("cute"));
        project.timeline = shortTimeline(m_tone);
        project.mouthShapes = MouthShapeSet();
        project.layerPaths = {QStringLiteral("/layers/hat.svg")};
        const ExportRequest r = exportRequestFor(project);
        QCOMPARE(r.face, project.face);
        QCOMPARE(r.style, project.style);
        QCOMPARE(r.timeline, project.timeline);
        QCOMPARE(r.mouthShapes, project.mouthShapes);
        QCOMPARE(r.layerFiles, project.layerPaths);
        QVERIFY(r.audioPath.isEmpty()); // the timeline's clip is the sound
        QCOMPARE(r.outputPath, QString());
        const QString out = QDir(newFolder(QStringLiteral("project"))).filePath(QStringLiteral("p.mp4"));
        ExportRequest withOutput = r;
        withOutput.outputPath = out;
        withOutput.layerFiles.clear();
        withOutput.size = 64;
        const ExportResult result = exportAnimation(withOutput);
        QVERIFY2(result.ok(), qPrintable(result.error));
        QString error;
        const std::optional<MediaInfo> info = probeMedia(out, &error);
        QVERIFY2(info, qPrintable(error));
        QVERIFY(info->hasAudio);
    }

    void frameSizes()
    {
        ExportRequest r = request(AnimationFormat::Mp4, QStringLiteral("x.mp4"));
        r.framing = ExportFraming::Photo; // the 512x512 photo
        r.size = 0;
        QCOMPARE(exportFrameSize(r), QSize(512, 512));
        r.size = 300;
        QCOMPARE(exportFrameSize(r), QSize(300, 300));
        r.face.setImageSize(QSize(800, 450));
        r.size = 720;
        QCOMPARE(exportFrameSize(r), QSize(720, 404)); // 405 rounded down to even
        r.size = 0;
        QCOMPARE(exportFrameSize(r), QSize(800, 450));
        r.face.setImageSize(QSize(3000, 2000));
        QCOMPARE(exportFrameSize(r).width(), 1280); // automatic stays within 512-1280
        r.fps = 20;
        QCOMPARE(exportFrameCount(r), 32);
    }

    void eachFormat_data()
    {
        QTest::addColumn<AnimationFormat>("format");
        for (AnimationFormat f : kAllAnimationFormats)
            QTest::newRow(qPrintable(outputName(f))) << f;
    }

    // Each format is produced whole, with its sound where it has one, and nothing else is left
    // in the folder.
    void eachFormat()
    {
        QFETCH(AnimationFormat, format);
        const QString dir = newFolder(QStringLiteral("each"));
        const QString out = QDir(dir).filePath(outputName(format));
        const ExportRequest r = request(format, out, m_tone);
        QVector<double> reported;
        const ExportResult result = exportAnimation(r, [&](double f) { reported.append(f); });
        QVERIFY2(result.ok(), qPrintable(result.error));
        QVERIFY(!reported.isEmpty());
        QCOMPARE(reported.first(), 0.0);
        QCOMPARE(reported.last(), 1.0);
        QVERIFY(std::is_sorted(reported.cbegin(), reported.cend()));
        QCOMPARE(entries(dir), QStringList {QDir::cleanPath(outputName(format))});

        const int frames = exportFrameCount(r);
        QCOMPARE(frames, 16);
        const QSize size = exportFrameSize(r);
        QCOMPARE(std::max(size.width(), size.height()), 96);
        QString error;
        switch (format) {
        case AnimationFormat::SmilSvg: {
            const QByteArray svg = readAll(out);
            QVERIFY(svg.startsWith("<?xml"));
            QVERIFY(svg.contains("<animate "));
            QVERIFY(svg.contains("data:audio/"));
            break;
        }
        case AnimationFormat::HtmlPlayer: {
            const QByteArray html = readAll(out);
            QVERIFY(html.contains("<svg"));
            QVERIFY(html.contains("<audio"));
            break;
        }
        case AnimationFormat::WebP: { // FFmpeg 5.1 reads no animated WebP (tst_transparentexport decodes it)
            const QByteArray webp = readAll(out);
            QVERIFY(webp.startsWith("RIFF") && webp.mid(8, 4) == "WEBP");
            QVERIFY(webp.contains("ANIM") && webp.contains("ANMF"));
            break;
        }
        case AnimationFormat::Mp4:
        case AnimationFormat::Gif:
        case AnimationFormat::PngSequence:
        case AnimationFormat::WebM:
        case AnimationFormat::Mov:
        case AnimationFormat::Apng: {
            const std::optional<MediaInfo> info = probeMedia(out, &error);
            QVERIFY2(info, qPrintable(error));
            QCOMPARE(info->frameCount, frames);
            QCOMPARE(QSize(info->width, info->height), size);
            QCOMPARE(info->hasAudio, animationFormatHasSound(format));
            if (animationFormatHasSound(format)) {
                QCOMPARE(info->fps, 10.0);
                QVERIFY2(
                    std::abs(info->audioDurationS - 1.6) < 0.05, qPrintable(QString::number(info->audioDurationS)));
            }
            break;
        }
        }
    }

    // The MP4 as an independent reader sees it.
    void mp4ReadByFfprobe()
    {
        const QString ffprobe = QStandardPaths::findExecutable(QStringLiteral("ffprobe"));
        if (ffprobe.isEmpty())
            QSKIP("ffprobe is not installed");
        const QString out = QDir(newFolder(QStringLiteral("ffprobe"))).filePath(QStringLiteral("talk.mp4"));
        const ExportRequest r = request(AnimationFormat::Mp4, out, m_tone);
        const ExportResult result = exportAnimation(r);
        QVERIFY2(result.ok(), qPrintable(result.error));
        QProcess p;
        p.start(ffprobe,
            {QStringLiteral("-v"), QStringLiteral("error"), QStringLiteral("-count_frames"),
                QStringLiteral("-show_entries"), QStringLiteral("stream=codec_type,nb_read_frames"),
                QStringLiteral("-of"), QStringLiteral("csv=p=0"), out});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 0);
        const QStringList lines
            = QString::fromUtf8(p.readAllStandardOutput()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QStringList streams;
        for (const QString &line : lines)
            streams << line.trimmed();
        QVERIFY2(streams.contains(QStringLiteral("video,%1").arg(exportFrameCount(r))), qPrintable(streams.join(u'|')));
        QVERIFY2(std::any_of(streams.cbegin(), streams.cend(), [](const QString &s) { return s.startsWith(u"audio"); }),
            qPrintable(streams.join(u'|')));
    }

    void cancelLeavesNothing_data()
    {
        QTest::addColumn<AnimationFormat>("format");
        QTest::addColumn<double>("at"); // the fraction at which cancel is pressed; -1: before it starts
        for (AnimationFormat f : kAllAnimationFormats) {
            for (double at : {-1.0, 0.0, 0.5, 0.9, 0.95}) {
                QTest::newRow(qPrintable(QStringLiteral("%1 at %2").arg(outputName(f)).arg(at))) << f << at;
            }
        }
    }

    // Cancelled before, during and at the end of the work, an export leaves no file, no
    // temporary file and no folder; a file it would have replaced stays as it was.
    void cancelLeavesNothing()
    {
        QFETCH(AnimationFormat, format);
        QFETCH(double, at);
        const QString dir = newFolder(QStringLiteral("cancel"));
        const QString out = QDir(dir).filePath(outputName(format));
        std::atomic_bool cancel = at < 0;
        const ExportResult result = exportAnimation(
            request(format, out, m_tone),
            [&](double f) {
                if (f >= at)
                    cancel = true;
            },
            &cancel);
        QCOMPARE(result.status, ExportStatus::Cancelled);
        QVERIFY2(result.error.contains(QDir::toNativeSeparators(out)), qPrintable(result.error));
        QVERIFY(result.error.endsWith(QStringLiteral("cancelled")));
        QCOMPARE(entries(dir), QStringList());

        // Over an earlier export: it is kept.
        if (format == AnimationFormat::PngSequence)
            return;
        QFile old(out);
        QVERIFY(old.open(QIODevice::WriteOnly));
        old.write("an earlier export");
        old.close();
        cancel = at < 0;
        QCOMPARE(exportAnimation(
                     request(format, out),
                     [&](double f) {
                         if (f >= at)
                             cancel = true;
                     },
                     &cancel)
                     .status,
            ExportStatus::Cancelled);
        QCOMPARE(readAll(out), QByteArray("an earlier export"));
        QCOMPARE(entries(dir), QStringList {QFileInfo(out).fileName()});
    }

    void pngSequenceIntoAnExistingFolder()
    {
        const QString dir = newFolder(QStringLiteral("png-existing"));
        // An earlier, longer sequence and a file of the user's.
        for (int i = 1; i <= 20; ++i)
            QFile(QDir(dir).filePath(QStringLiteral("frame_%1.png").arg(i, 5, 10, QLatin1Char('0'))))
                .open(QIODevice::WriteOnly);
        QFile notes(QDir(dir).filePath(QStringLiteral("notes.txt")));
        QVERIFY(notes.open(QIODevice::WriteOnly));
        notes.close();
        std::atomic_bool cancel = false;
        ExportRequest r = request(AnimationFormat::PngSequence, dir + QLatin1Char('/'));
        QCOMPARE(exportAnimation(
                     r, [&](double f) { cancel = f > 0.5; }, &cancel)
                     .status,
            ExportStatus::Cancelled);
        QCOMPARE(entries(dir).size(), 21); // untouched, and no temporary folder beside it
        QCOMPARE(entries(m_dir.path()).filter(QStringLiteral(".part")), QStringList());
        const ExportResult result = exportAnimation(r);
        QVERIFY2(result.ok(), qPrintable(result.error));
        QStringList expected;
        for (int i = 1; i <= 16; ++i)
            expected << QStringLiteral("frame_%1.png").arg(i, 5, 10, QLatin1Char('0'));
        expected << QStringLiteral("notes.txt");
        QCOMPARE(entries(dir), expected);
        QVERIFY(!QImage(QDir(dir).filePath(QStringLiteral("frame_00016.png"))).isNull());
    }

    void failureSaysWhyAndLeavesNothing_data()
    {
        QTest::addColumn<AnimationFormat>("format");
        for (AnimationFormat f : kAllAnimationFormats)
            QTest::newRow(qPrintable(outputName(f))) << f;
    }

    void failureSaysWhyAndLeavesNothing()
    {
        QFETCH(AnimationFormat, format);
        const QString dir = newFolder(QStringLiteral("fail"));
        // A folder that does not exist.
        const QString missing = QDir(dir).filePath(QStringLiteral("no/such/") + outputName(format));
        ExportResult result = exportAnimation(request(format, missing, m_tone));
        QCOMPARE(result.status, ExportStatus::Failed);
        QVERIFY2(result.error.startsWith(QDir::toNativeSeparators(missing) + QStringLiteral(": ")),
            qPrintable(result.error));
        QVERIFY2(result.error.contains(QStringLiteral("does not exist")), qPrintable(result.error));
        QCOMPARE(entries(dir), QStringList());

        // A "folder" that is a file: nothing can be written in it.
        const QString file = QDir(dir).filePath(QStringLiteral("plain"));
        QFile f(file);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.close();
        const QString inFile = file + QLatin1Char('/') + outputName(format);
        result = exportAnimation(request(format, inFile, m_tone));
        QCOMPARE(result.status, ExportStatus::Failed);
        QVERIFY2(result.error.contains(QDir::toNativeSeparators(inFile)), qPrintable(result.error));
        QCOMPARE(entries(dir), QStringList {QStringLiteral("plain")});

        // The target is the other kind: a folder for a file, a file for a PNG sequence.
        const QString other = QDir(dir).filePath(QStringLiteral("other"));
        if (format == AnimationFormat::PngSequence) {
            QFile o(other);
            QVERIFY(o.open(QIODevice::WriteOnly));
        } else {
            QVERIFY(QDir().mkdir(other));
        }
        result = exportAnimation(
            request(format, format == AnimationFormat::PngSequence ? other + QLatin1Char('/') : other, m_tone));
        QCOMPARE(result.status, ExportStatus::Failed);
        QVERIFY2(result.error.contains(QStringLiteral("other")), qPrintable(result.error));
        QCOMPARE(entries(dir), (QStringList {QStringLiteral("other"), QStringLiteral("plain")}));
    }

    void badInputNamesTheFile()
    {
        const QString dir = newFolder(QStringLiteral("bad"));
        ExportRequest r = request(AnimationFormat::Mp4, QDir(dir).filePath(QStringLiteral("a.mp4")));
        r.layerFiles << QDir(dir).filePath(QStringLiteral("missing-hat.svg"));
        ExportResult result = exportAnimation(r);
        QCOMPARE(result.status, ExportStatus::BadInput);
        QVERIFY2(result.error.contains(QStringLiteral("missing-hat.svg")), qPrintable(result.error));

        r = request(AnimationFormat::SmilSvg, QDir(dir).filePath(QStringLiteral("a.svg")),
            QDir(dir).filePath(QStringLiteral("gone.wav")));
        result = exportAnimation(r);
        QCOMPARE(result.status, ExportStatus::BadInput);
        QVERIFY2(result.error.contains(QStringLiteral("gone.wav")), qPrintable(result.error));

        r = request(AnimationFormat::Gif, QDir(dir).filePath(QStringLiteral("a.gif")));
        r.size = 5;
        result = exportAnimation(r);
        QCOMPARE(result.status, ExportStatus::BadInput);
        QVERIFY2(result.error.contains(QStringLiteral("a.gif")) && result.error.contains(QStringLiteral("size 5")),
            qPrintable(result.error));
        r.size = 0;
        r.fps = 500;
        QCOMPARE(exportAnimation(r).status, ExportStatus::BadInput);
        r.fps = 0;
        r.outputPath.clear();
        QCOMPARE(exportAnimation(r).status, ExportStatus::BadInput);
        QCOMPARE(entries(dir), QStringList());
    }

    // The request's rate and framing reach the output.
    void rateAndFraming()
    {
        const QString dir = newFolder(QStringLiteral("rate"));
        ExportRequest r = request(AnimationFormat::Gif, QDir(dir).filePath(QStringLiteral("r.gif")));
        r.fps = 5;
        r.framing = ExportFraming::Photo;
        r.face.setImageSize(QSize(512, 256));
        const ExportResult result = exportAnimation(r);
        QVERIFY2(result.ok(), qPrintable(result.error));
        QString error;
        const std::optional<MediaInfo> info = probeMedia(r.outputPath, &error);
        QVERIFY2(info, qPrintable(error));
        QCOMPARE(info->frameCount, 8); // 1.6 s at 5 fps
        QCOMPARE(QSize(info->width, info->height), QSize(96, 48));
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestAnimationExport)
#include "tst_animationexport.moc"
