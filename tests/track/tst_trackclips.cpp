#include "export/videoencoder.h"
#include "talkingface.h"
#include "testmain.h"
#include "track/trackaccuracy.h"
#include "track/trackvideo.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QTemporaryDir>
#include <QTest>

using namespace toonface;

namespace {

// A portrait without glasses, so that painted lids read as shut eyes.
const QString kPortrait = QStringLiteral("/usr/lib/python3/dist-packages/skimage/data/astronaut.png");
const QString kVideoDir = QStringLiteral(TOONFACE_SHARED_DATA "/video");

QString writeClip(const QString &path, const QVector<QImage> &frames)
{
    VideoWriter writer;
    QString error;
    if (!writer.open(path, VideoFormat::Mp4, frames.first().size(), 25, AudioSource {}, &error))
        return error;
    for (const QImage &f : frames) {
        if (!writer.addFrame(f, &error))
            return error;
    }
    return writer.finish(&error) ? QString() : error;
}

} // namespace

class TestTrackClips : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void gridClipsFollowTheReference_data()
    {
        QTest::addColumn<QString>("clip");
        for (const char *name : {"bbaf2n.mpg", "lbax4n.mpg", "pwij3p.mpg", "id2_vcd_swwp2s.mpg"})
            QTest::newRow(name) << QString::fromLatin1(name);
    }

    void gridClipsFollowTheReference()
    {
        QFETCH(QString, clip);
        const QString path = kVideoDir + QLatin1Char('/') + clip;
        if (!QFileInfo::exists(path))
            QSKIP("the GRID clips of shared/data/video are absent");
        QString error;
        const auto reference = referenceSignals(path, &error);
        QVERIFY2(reference, qPrintable(error));

        TrackVideoOptions options;
        options.tracker.method = DetectionMethod::Landmarks;
        const TrackResult track = trackVideo(path, options);
        QVERIFY2(track.status == TrackStatus::Ok, qPrintable(track.error));
        QCOMPARE(track.method, QStringLiteral("landmarks"));
        QCOMPARE(track.frames.size(), reference->times.size());
        QVERIFY(track.hasAudio);
        for (const TrackedFrame &f : track.frames)
            QVERIFY(!f.lost);
        const TrackAccuracy a = compareSignals(trackedSignals(track), *reference, track.fps);
        qInfo("%s landmarks: mouth r = %.3f, eyes r = %.3f, blinks %d of %d (%d extra)", qPrintable(clip),
            a.mouthCorrelation, a.eyeCorrelation, a.blinksFound, a.referenceBlinks, a.extraBlinks);
        QVERIFY2(a.mouthCorrelation >= 0.9, qPrintable(QString::number(a.mouthCorrelation)));
        QCOMPARE(a.blinksFound, a.referenceBlinks);

        // The classic method (thesis ch. 6): every clip's face is found by it, the blinks with no
        // extra one, the mouth's opening follows the reference, less closely than the landmarks
        // (0.76-0.83 on the four clips).
        options.tracker.method = DetectionMethod::Classic;
        const TrackResult classic = trackVideo(path, options);
        QVERIFY2(classic.status == TrackStatus::Ok, qPrintable(classic.error));
        const TrackAccuracy c = compareSignals(trackedSignals(classic), *reference, classic.fps);
        qInfo("%s classic: mouth r = %.3f, eyes r = %.3f, blinks %d of %d (%d extra)", qPrintable(clip),
            c.mouthCorrelation, c.eyeCorrelation, c.blinksFound, c.referenceBlinks, c.extraBlinks);
        QCOMPARE(classic.frames.size(), track.frames.size());
        QVERIFY2(c.mouthCorrelation >= 0.65, qPrintable(QString::number(c.mouthCorrelation)));
        QCOMPARE(c.blinksFound, c.referenceBlinks);
        QCOMPARE(c.extraBlinks, 0);
    }

    void trackJsonHasTheContract()
    {
        const QString path = kVideoDir + QStringLiteral("/bbaf2n.mpg");
        if (!QFileInfo::exists(path))
            QSKIP("the GRID clips of shared/data/video are absent");
        TrackVideoOptions options;
        options.neutralFrame = 5;
        int calls = 0, lastDone = 0, total = 0;
        const TrackResult track = trackVideo(path, options, [&](int done, int all) {
            ++calls;
            lastDone = done;
            total = all;
        });
        QVERIFY2(track.status == TrackStatus::Ok, qPrintable(track.error));
        QCOMPARE(lastDone, int(track.frames.size()));
        QVERIFY(calls >= 70);
        QVERIFY(total > 0);
        QCOMPARE(track.frames.first().index, 0); // every frame from the first, the neutral being 5
        const QJsonObject json = trackToJson(track);
        QCOMPARE(json.value(QStringLiteral("format")).toString(), QStringLiteral("toonface.track/1"));
        QCOMPARE(json.value(QStringLiteral("neutralFrame")).toInt(), 5);
        QCOMPARE(json.value(QStringLiteral("video")).toObject().value(QStringLiteral("width")).toInt(), 360);
        QCOMPARE(json.value(QStringLiteral("neutral")).toObject().value(QStringLiteral("format")).toString(),
            QStringLiteral("toonface.face/1"));
        const QJsonArray frames = json.value(QStringLiteral("frames")).toArray();
        QCOMPARE(frames.size(), track.frames.size());
        const QJsonObject f = frames[5].toObject();
        QVERIFY(f.contains(QStringLiteral("time")) && f.contains(QStringLiteral("lost"))
            && f.contains(QStringLiteral("confidence")));
        QStringList ids;
        for (const QJsonValue &p : f.value(QStringLiteral("points")).toArray())
            ids << p.toObject().value(QStringLiteral("id")).toString();
        for (const char *id : {"8.1", "8.2", "8.3", "8.4", "8.9", "8.10", "2.2", "2.3", "3.1", "3.2", "3.3", "3.4",
                 "3.5", "3.6", "4.1", "4.2", "4.3", "4.4", "4.5", "4.6"})
            QVERIFY2(ids.contains(QString::fromLatin1(id)), id);
        // At the neutral frame itself nothing has moved (up to the filter's memory).
        const QJsonArray d = f.value(QStringLiteral("displacements")).toObject().value(QStringLiteral("8.2")).toArray();
        QVERIFY(std::abs(d[1].toDouble()) < 0.05);
    }

    void clipWithoutAFaceIsNoFace()
    {
        QTemporaryDir dir;
        QVector<QImage> frames;
        for (int i = 0; i < 10; ++i) {
            QImage image(160, 120, QImage::Format_RGB32);
            image.fill(QColor(100 + 5 * i, 120, 140));
            frames.append(image);
        }
        const QString path = dir.filePath(QStringLiteral("wall.mp4"));
        const QString written = writeClip(path, frames);
        QVERIFY2(written.isEmpty(), qPrintable(written));
        const TrackResult track = trackVideo(path, {});
        QCOMPARE(int(track.status), int(TrackStatus::NoFace));
        QVERIFY2(track.error.startsWith(path + QStringLiteral(": frame 0: ")), qPrintable(track.error));

        TrackVideoOptions late;
        late.neutralFrame = 40;
        const TrackResult past = trackVideo(path, late);
        QCOMPARE(int(past.status), int(TrackStatus::BadVideo));
        QVERIFY2(past.error.contains(QStringLiteral("past the video's end")), qPrintable(past.error));
    }

    void silentClipOfADrawnFaceTracksAndCancels()
    {
        if (!QFileInfo::exists(kPortrait))
            QSKIP("astronaut.png is not installed (package python3-skimage)");
        const testing::TalkingFace talking(QImage(kPortrait).scaled(320, 320));
        QVERIFY(talking.isValid());
        QVector<QImage> frames;
        for (int i = 0; i < 30; ++i)
            frames.append(talking.frame(i >= 10 && i < 16 ? 1.0 : 0.0, i == 22 || i == 23 ? 0.0 : 1.0));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("drawn.mp4"));
        const QString written = writeClip(path, frames);
        QVERIFY2(written.isEmpty(), qPrintable(written));
        const TrackResult track = trackVideo(path, {});
        QVERIFY2(track.status == TrackStatus::Ok, qPrintable(track.error));
        QVERIFY(!track.hasAudio);
        QCOMPARE(track.frames.size(), 30);
        QVERIFY(track.frames[13].motion.mouthOpenEs0 > track.frames[5].motion.mouthOpenEs0 + 0.1);

        std::atomic_bool cancel {true};
        const TrackResult cancelled = trackVideo(path, {}, {}, &cancel);
        QCOMPARE(int(cancelled.status), int(TrackStatus::Cancelled));
        QVERIFY(cancelled.frames.isEmpty());
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestTrackClips)
#include "tst_trackclips.moc"
