#include "media/mediareader.h"
#include "testmain.h"
#include "track/clipsilence.h"
#include "track/mouthrange.h"
#include "track/neutralchoice.h"
#include "track/trackvideo.h"

#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>

using namespace toonface;

namespace {

const QString kVideoDir = QStringLiteral(TOONFACE_SHARED_DATA "/video");

double parting(const TrackedFrame &f)
{
    const auto &d = f.motion.displacementEs0;
    return d[pt::idx("8.2")].y() - d[pt::idx("8.9")].y();
}

} // namespace

class TestNeutralChoice : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // On the GRID clips (the lips apart before the sentence, shut after it): the frame chosen
    // is in a silence, its face found, and its lips part no more than frame 0's (the old
    // default) nor, but for the tracker's jitter, than any silent frame of the first seconds.
    void choosesAClosedMouthInASilence_data()
    {
        QTest::addColumn<QString>("clip");
        for (const char *name : {"bbaf2n.mpg", "lbax4n.mpg", "pwij3p.mpg", "id2_vcd_swwp2s.mpg"})
            QTest::newRow(name) << QString::fromLatin1(name);
    }

    void choosesAClosedMouthInASilence()
    {
        QFETCH(QString, clip);
        const QString path = kVideoDir + QLatin1Char('/') + clip;
        if (!QFileInfo::exists(path))
            QSKIP("the GRID clips of shared/data/video are absent");
        const NeutralChoice choice = chooseNeutralFrame(path);
        QVERIFY2(choice.error.isEmpty(), qPrintable(choice.error));
        QVERIFY(choice.found);
        QVERIFY(choice.silent);

        // The clip tracked from frame 0, its silence from its sound.
        const TrackResult track = trackVideo(path, TrackVideoOptions {});
        QVERIFY2(track.status == TrackStatus::Ok, qPrintable(track.error));
        QString error;
        const auto sound = readAudio(path, kSilenceSampleRate, &error);
        QVERIFY2(sound, qPrintable(error));
        const QVector<bool> silent = silentFrames(track.frames, *sound, kSilenceSampleRate, 1.0 / track.fps);
        QVERIFY(choice.frame < track.frames.size());
        QVERIFY2(silent[choice.frame], qPrintable(QString::number(choice.frame)));
        // The silent frames of the window searched.
        const int window = std::min(int(track.frames.size()), int(std::lround(kNeutralSearchS * track.fps)));
        double leastInSilence = parting(track.frames[0]);
        for (int i = 0; i < window; ++i) {
            if (silent[i])
                leastInSilence = std::min(leastInSilence, parting(track.frames[i]));
        }
        const double chosen = parting(track.frames[choice.frame]);
        qInfo("%s: frame %d (%.2f s), parting %.4f ES0 against frame 0's %.4f (least in the silences %.4f)",
            qPrintable(clip), choice.frame, choice.frame / track.fps, chosen, parting(track.frames[0]), leastInSilence);
        QVERIFY(chosen <= parting(track.frames[0]) + 1e-9);
        // Measured from another neutral the parting differs by the tracker's jitter only.
        QVERIFY2(chosen <= leastInSilence + 0.02, qPrintable(QString::number(chosen - leastInSilence)));
    }

    // A file that is not there, or not a video: the error names it and nothing is chosen.
    void aBadFileIsNamed()
    {
        QTemporaryDir dir;
        const QString missing = dir.filePath(QStringLiteral("gone.mp4"));
        NeutralChoice choice = chooseNeutralFrame(missing);
        QVERIFY(!choice.found);
        QVERIFY2(choice.error.contains(QStringLiteral("gone.mp4")), qPrintable(choice.error));
        const QString text = dir.filePath(QStringLiteral("notes.mp4"));
        QFile file(text);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("not a video at all");
        file.close();
        choice = chooseNeutralFrame(text);
        QVERIFY(!choice.found);
        QVERIFY2(choice.error.contains(QStringLiteral("notes.mp4")), qPrintable(choice.error));
    }
};

TOONFACE_TEST_MAIN(TestNeutralChoice)
#include "tst_neutralchoice.moc"
