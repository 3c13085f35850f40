#include "media/mediareader.h"
#include "testmain.h"
#include "track/clipsilence.h"
#include "track/trackvideo.h"

#include <QFile>
#include <QFileInfo>
#include <QTest>

#include <cmath>

using namespace toonface;

namespace {

const QString kVideoDir = QStringLiteral(TOONFACE_SHARED_DATA "/video");
constexpr double kFps = 25.0;

QVector<TrackedFrame> framesAt(int count, double fps)
{
    QVector<TrackedFrame> frames;
    for (int i = 0; i < count; ++i) {
        TrackedFrame f;
        f.index = i;
        f.time = i / fps;
        frames.append(f);
    }
    return frames;
}

} // namespace

class TestClipSilence : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // Silence is found from the sound's level against the clip's own loud level: the lips'
    // lead before the voice and their closing after it are speech, and so is a short gap (a
    // stop's closure); a quiet room is silence, however loud the room is for its microphone.
    void findsTheSilenceFromTheClipsOwnSound_data()
    {
        QTest::addColumn<double>("voiceDb");
        QTest::addColumn<double>("roomDb");
        QTest::newRow("a loud voice in a quiet room") << -18.0 << -55.0;
        QTest::newRow("a quiet voice in a humming room") << -35.0 << -66.0;
        QTest::newRow("the gain turned up") << -8.0 << -40.0;
    }

    void findsTheSilenceFromTheClipsOwnSound()
    {
        QFETCH(double, voiceDb);
        QFETCH(double, roomDb);
        constexpr int rate = 16000;
        // 4 s: the room for 1 s, a voice from 1 s to 3 s with a 0.08 s gap at 2 s, the room.
        QVector<float> sound(4 * rate);
        const double voice = std::pow(10.0, voiceDb / 20.0) * std::sqrt(2.0);
        const double room = std::pow(10.0, roomDb / 20.0) * std::sqrt(2.0);
        for (qsizetype i = 0; i < sound.size(); ++i) {
            const double t = double(i) / rate;
            const bool speaking = t >= 1.0 && t < 3.0 && !(t >= 2.0 && t < 2.08);
            sound[i] = float((speaking ? voice : room) * std::sin(2 * M_PI * (speaking ? 180.0 : 60.0) * t));
        }
        const QVector<TrackedFrame> frames = framesAt(100, kFps);
        const QVector<bool> silent = silentFrames(frames, sound, rate, 1.0 / kFps);
        QCOMPARE(silent.size(), frames.size());
        const int lead = int(std::lround(kLipLeadS * kFps));
        const int close = int(std::lround(kLipCloseS * kFps));
        for (int i = 0; i < 100; ++i) {
            const bool expected = i < 25 - lead || i >= 75 + close;
            QVERIFY2(silent[i] == expected, qPrintable(QStringLiteral("frame %1").arg(i)));
        }
        // No sound: nothing is silent.
        QCOMPARE(silentFrames(frames, {}, rate, 1.0 / kFps), QVector<bool>(100, false));
        // A steady sound (music, a fan) shows no voice to tell from the room: nothing is
        // silent; digital silence is silent throughout.
        QVector<float> steady(sound.size());
        for (qsizetype i = 0; i < steady.size(); ++i)
            steady[i] = float(voice * std::sin(2 * M_PI * 180.0 * double(i) / rate));
        QCOMPARE(silentFrames(frames, steady, rate, 1.0 / kFps), QVector<bool>(100, false));
        QCOMPARE(silentFrames(frames, QVector<float>(sound.size(), 0.0f), rate, 1.0 / kFps), QVector<bool>(100, true));
    }

    // The GRID clip with word times (swwp2s.align, 1/25000 s): the silence found before and
    // after the sentence ends and starts within two frames of the marked `sil`.
    void matchesTheMarkedSilenceOfAGridClip()
    {
        const QString path = kVideoDir + QStringLiteral("/id2_vcd_swwp2s.mpg");
        QFile align(kVideoDir + QStringLiteral("/swwp2s.align"));
        if (!QFileInfo::exists(path) || !align.open(QIODevice::ReadOnly))
            QSKIP("the GRID clips of shared/data/video are absent");
        QList<QStringList> words;
        for (const QByteArray &line : align.readAll().split('\n')) {
            const QStringList cells = QString::fromUtf8(line).simplified().split(QLatin1Char(' '), Qt::SkipEmptyParts);
            if (cells.size() == 3)
                words.append(cells);
        }
        QVERIFY(words.size() > 2);
        QCOMPARE(words.first()[2], QStringLiteral("sil"));
        QCOMPARE(words.last()[2], QStringLiteral("sil"));
        const double speechFrom = words.first()[1].toDouble() / 25000.0;
        const double silenceFrom = words.last()[0].toDouble() / 25000.0;

        const TrackResult track = trackVideo(path, TrackVideoOptions {});
        QVERIFY2(track.status == TrackStatus::Ok, qPrintable(track.error));
        QString error;
        const auto sound = readAudio(path, kSilenceSampleRate, &error);
        QVERIFY2(sound, qPrintable(error));
        const QVector<bool> silent = silentFrames(track.frames, *sound, kSilenceSampleRate, 1.0 / track.fps);
        const qsizetype first = silent.indexOf(false);
        const qsizetype last = silent.lastIndexOf(false);
        QVERIFY(first > 0 && last + 1 < silent.size());
        qInfo("speech from frame %lld (marked %.2f), silence from %lld (marked %.2f)", qlonglong(first),
            speechFrom * track.fps, qlonglong(last + 1), silenceFrom * track.fps);
        QVERIFY2(std::abs(first - speechFrom * track.fps) <= 2.0, qPrintable(QString::number(first)));
        QVERIFY2(std::abs(last + 1 - silenceFrom * track.fps) <= 2.0, qPrintable(QString::number(last + 1)));
        // Inside the sentence no pause is long enough to close the mouth.
        for (qsizetype i = first; i <= last; ++i)
            QVERIFY2(!silent[i], qPrintable(QString::number(i)));
    }
};

TOONFACE_TEST_MAIN(TestClipSilence)
#include "tst_clipsilence.moc"
