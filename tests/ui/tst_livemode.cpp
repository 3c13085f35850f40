#include "capture/framepane.h"
#include "capture/livesession.h"
#include "capture/livetake.h"
#include "capture/livewindow.h"
#include "capture/microphone.h"
#include "document/document.h"
#include "face/fapu.h"
#include "face/pointtable.h"
#include "media/mediareader.h"
#include "playback/playhead.h"
#include "testmain.h"
#include "track/clocksource.h"
#include "track/trackaccuracy.h"
#include "track/videofilesource.h"
#include "uifixture.h"

#include <QComboBox>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QPainter>
#include <QPushButton>
#include <QSet>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QThread>
#include <QUndoStack>
#include <QtTest>

#include <cmath>
#include <thread>

using namespace toonface;

namespace {

const QString kClip = QStringLiteral(TOONFACE_SHARED_DATA "/video/bbaf2n.mpg");

std::unique_ptr<VideoFileSource> pacedClip(QString *error)
{
    auto source = std::make_unique<VideoFileSource>();
    VideoFileSource::Options options;
    options.paced = true;
    if (!source->open(kClip, options, error))
        return nullptr;
    return source;
}

Audio clipSound()
{
    QString error;
    std::optional<QVector<float>> samples = readAudio(kClip, kSpeechSampleRate, &error);
    return samples ? Audio {*samples, kSpeechSampleRate} : Audio {};
}

// The gap the pose opens between the lips (8.2 below 8.9), pixels.
double poseMouthGap(const Pose &pose)
{
    return pose.offset[pt::idx("8.2")].y() - pose.offset[pt::idx("8.9")].y();
}

} // namespace

class TestLiveMode : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void clipDrivesTheCartoon();
    void latestPictureWinsWhenTheGuiStalls();
    void soundDrivesTheMouth();
    void recordPutsTheTakeOnTheTimelineAsOneStep();
    void restPoseAndNoFaceAreSaid();
    void clockSourceKeepsTime();
    void heardOnlyVoiceDrivesTheMouth();
    void microphoneOnlyWithoutMicrophoneSaysSo();
    void mouthChoicesDoNotSayCamera();
    void cartoonWaitsAtRestBeforeASource();
    void opensBesideTheMainWindow();
};

void TestLiveMode::initTestCase()
{
    fixture::isolateSettings();
    if (!QFileInfo::exists(kClip))
        QSKIP("the GRID clips of shared/data/video are absent");
}

void TestLiveMode::clipDrivesTheCartoon()
{
    Document document;
    fixture::fill(document);
    LiveSession session(&document);
    session.setImageSize(QSize(320, 320));
    QString error;
    std::unique_ptr<VideoFileSource> source = pacedClip(&error);
    QVERIFY2(source, qPrintable(error));
    const int frames = source->frameCount();
    QSignalSpy finished(&session, &LiveSession::finished);
    QVector<double> tracked, shown;
    QSet<int> indices;
    connect(&session, &LiveSession::frameReady, this, [&] {
        const LiveFrame &f = session.current();
        QCOMPARE(f.cartoon.size(), QSize(320, 320));
        QVERIFY(!f.source.isNull());
        QVERIFY(!indices.contains(f.index)); // each picture once, in order
        indices.insert(f.index);
        if (f.hasTrack && !f.tracked.lost) {
            tracked.append(f.tracked.motion.mouthOpenEs0);
            shown.append(poseMouthGap(f.pose));
        }
        // With TOONFACE_SCREENSHOTS set, every fifth frame beside its cartoon, to look at.
        const QString dir = qEnvironmentVariable("TOONFACE_SCREENSHOTS");
        if (!dir.isEmpty() && f.index % 5 == 0) {
            QImage pair(f.source.width() + f.cartoon.width(), std::max(f.source.height(), f.cartoon.height()),
                QImage::Format_RGB32);
            pair.fill(Qt::white);
            QPainter painter(&pair);
            painter.drawImage(0, 0, f.source);
            painter.drawImage(f.source.width(), 0, f.cartoon);
            painter.end();
            pair.save(QDir(dir).filePath(QStringLiteral("live-%1.png").arg(f.index, 3, 10, QLatin1Char('0'))));
        }
    });
    session.start(std::move(source));
    QVERIFY(session.isRunning());
    QVERIFY(finished.wait(20000));
    QVERIFY(!session.isRunning());
    QVERIFY2(finished.first().at(0).toString().isEmpty(), qPrintable(finished.first().at(0).toString()));
    QVERIFY(session.hasRestPose());

    const LiveFigures f = session.figures();
    qInfo("%d frames in the clip, %d delivered, %d drawn, %d shown, %d replaced, %d lost", frames, f.delivered,
        f.rendered, f.shown, f.replaced, f.lost);
    // A paced source drops only the frames it was late for (few, unless the machine is loaded).
    QVERIFY(f.delivered > frames / 4);
    QCOMPARE(f.rendered, f.delivered);
    // Every picture drawn was shown or replaced by a newer one: none waits in a queue.
    QCOMPARE(f.shown + f.replaced, f.rendered);
    QCOMPARE(f.readyMs.size(), f.rendered);
    QCOMPARE(f.shownMs.size(), f.shown);
    QVERIFY(tracked.size() >= 10);
    // The cartoon's lips part as the speaker's do.
    const auto [low, high] = std::minmax_element(shown.cbegin(), shown.cend());
    const double es0 = document.face().fapu().es0;
    QVERIFY2(*high - *low > 0.05 * es0, qPrintable(QStringLiteral("%1 px").arg(*high - *low)));
    const double r = pearson(tracked, shown);
    qInfo("tracked mouth opening vs the cartoon's: r = %.3f over %lld frames", r, qlonglong(tracked.size()));
    QVERIFY(r > 0.9);
}

void TestLiveMode::latestPictureWinsWhenTheGuiStalls()
{
    Document document;
    fixture::fill(document);
    LiveSession session(&document);
    session.setImageSize(QSize(160, 160));
    QString error;
    std::unique_ptr<VideoFileSource> source = pacedClip(&error);
    QVERIFY2(source, qPrintable(error));
    QSignalSpy ready(&session, &LiveSession::frameReady);
    session.start(std::move(source));
    QVERIFY(ready.wait(10000));
    // The GUI thread stalls for 600 ms: the worker goes on drawing.
    const int before = session.figures().rendered;
    QThread::msleep(600);
    session.stop(); // no more pictures: what waits for the GUI is what the stall left
    const LiveFigures stalled = session.figures();
    QVERIFY(stalled.rendered >= before + 5);
    // One event-loop turn then shows the newest picture once; the others were replaced.
    QCoreApplication::processEvents();
    const LiveFigures after = session.figures();
    QCOMPARE(after.shown, stalled.shown + 1);
    QCOMPARE(after.replaced, stalled.replaced);
    QVERIFY(stalled.replaced >= stalled.rendered - before - 1);
    QCOMPARE(after.shown + after.replaced, after.rendered);
    QCOMPARE(session.current().index, after.newestIndex); // the newest picture, not the oldest waiting
    QCoreApplication::processEvents();
    QCOMPARE(session.figures().shown, after.shown); // nothing else was queued
    QVERIFY(!session.isRunning());
}

void TestLiveMode::soundDrivesTheMouth()
{
    Document document;
    fixture::fill(document);
    LiveSession session(&document);
    session.setImageSize(QSize(160, 160));
    session.setMouthMode(LiveMouth::Microphone);
    const Audio sound = clipSound();
    if (sound.isEmpty())
        QSKIP("the clip's sound cannot be read");
    QString error;
    std::unique_ptr<VideoFileSource> source = pacedClip(&error);
    QVERIFY2(source, qPrintable(error));
    QSignalSpy finished(&session, &LiveSession::finished);
    int open = 0, shut = 0, total = 0;
    connect(&session, &LiveSession::frameReady, this, [&] {
        const LiveFrame &f = session.current();
        ++total;
        QVERIFY(f.soundDrivesMouth);
        // The mouth holds the sound's shape at its weight, as a mouth key would.
        const std::array<QPointF, 4> d = document.mouthShapes().displacements(f.sound.shape, document.face());
        QCOMPARE(f.pose.offset[pt::idx("8.2")], d[1] * f.sound.weight);
        if (f.sound.shape == MouthShape::M)
            ++shut;
        else
            ++open;
    });
    session.start(std::move(source), sound);
    QVERIFY(finished.wait(20000));
    qInfo("sound-driven mouth: %d open, %d shut of %d frames", open, shut, total);
    QVERIFY(open > total / 4); // GRID speakers talk for most of the clip
    QVERIFY(shut > 0); // the clip starts and ends in silence
}

void TestLiveMode::recordPutsTheTakeOnTheTimelineAsOneStep()
{
    QTemporaryDir dir;
    Document document;
    fixture::fill(document, dir.filePath(QStringLiteral("portrait.png")));
    Playhead playhead;
    playhead.setTime(1.0);
    LiveWindow window(&document, &playhead);
    window.setLooping(false);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.startClip(kClip));
    QTRY_VERIFY_WITH_TIMEOUT(window.session()->hasRestPose() && window.session()->current().hasTrack, 10000);
    QVERIFY(!window.cartoonPane()->image().isNull());
    QVERIFY(!window.sourcePane()->box().isEmpty());
    // The clip again from its start (the rest pose kept), so that the take fits in it.
    QVERIFY(window.startClip(kClip));
    QVERIFY(window.session()->hasRestPose());
    const Animation before = document.animation();
    const int steps = document.undoStack()->count();

    QTest::mouseClick(window.recordButton(), Qt::LeftButton);
    QVERIFY(window.session()->isRecording());
    QTest::qWait(1200);
    QTest::mouseClick(window.recordButton(), Qt::LeftButton);
    QVERIFY(!window.session()->isRecording());
    QCOMPARE(document.undoStack()->count(), steps + 1);
    QVERIFY2(window.statusText().startsWith(QStringLiteral("Recorded")), qPrintable(window.statusText()));

    const Timeline &t = document.timeline();
    QVERIFY(t.poseKeys().size() >= 8);
    QVERIFY(t.headKeys().size() == t.poseKeys().size());
    QVERIFY(t.gazeKeys().size() == t.poseKeys().size());
    QCOMPARE(t.poseKeys().first().time, 1.0);
    QVERIFY(t.poseKeys().last().time > 1.8 && t.poseKeys().last().time < 2.6);
    QVERIFY(t.poseKeys().first().offsetsEs0.contains(QStringLiteral("8.2"))); // the camera drove the mouth
    // The clip's sound over the take, beside the project's photo, starting at the playhead.
    QVERIFY(!t.audioClips().isEmpty());
    QCOMPARE(t.audioClips().first().offset, 1.0);
    QVERIFY(t.audioClips().first().path.startsWith(QFileInfo(dir.path()).absoluteFilePath()));
    QVERIFY(QFileInfo::exists(t.audioClips().first().path));
    QVERIFY(std::abs(t.audioClips().first().duration - (t.poseKeys().last().time - 1.0)) < 0.2);

    document.undoStack()->undo();
    QCOMPARE(document.animation(), before);
    document.undoStack()->redo();
    QVERIFY(document.timeline().poseKeys().size() >= 8);
    window.close();
}

void TestLiveMode::restPoseAndNoFaceAreSaid()
{
    Document document;
    fixture::fill(document);
    LiveSession session(&document);
    QSignalSpy status(&session, &LiveSession::status);
    QString error;
    std::unique_ptr<VideoFileSource> source = pacedClip(&error);
    QVERIFY2(source, qPrintable(error));
    session.start(std::move(source));
    QTRY_VERIFY_WITH_TIMEOUT(session.hasRestPose(), 10000);
    QTRY_VERIFY(!status.isEmpty());
    QVERIFY(status.last().at(0).toString().startsWith(QStringLiteral("Rest pose set")));
    session.stop();

    // A blank "camera": no face for the rest pose, said; the cartoon still shows (at rest).
    status.clear();
    struct Blank : FrameSource
    {
        int n = 0;
        std::optional<VideoFrame> next() override
        {
            if (n >= 10)
                return std::nullopt;
            QThread::msleep(20);
            QImage image(QSize(320, 240), QImage::Format_RGB32);
            image.fill(Qt::gray);
            return VideoFrame {image, n * 0.04, n++};
        }
        double frameRate() const override { return 25; }
        QSize frameSize() const override { return {320, 240}; }
    };
    QSignalSpy finished(&session, &LiveSession::finished);
    session.start(std::make_unique<Blank>());
    QVERIFY(finished.wait(10000));
    QVERIFY(!session.hasRestPose());
    QVERIFY(!status.isEmpty());
    QVERIFY2(status.first().at(0).toString().startsWith(QStringLiteral("No face for the rest pose")),
        qPrintable(status.first().at(0).toString()));
    QVERIFY(!session.current().hasTrack);
    QVERIFY(!session.current().cartoon.isNull());
    QCOMPARE(session.current().pose, Pose {});
}

// ClockSource: frames without pictures numbered by their time; a late reader skips to the frame
// due; stop() ends a waiting next() at once.
void TestLiveMode::clockSourceKeepsTime()
{
    ClockSource clock(50);
    QCOMPARE(clock.frameRate(), 50.0);
    std::optional<VideoFrame> f = clock.next();
    QVERIFY(f && f->image.isNull());
    QCOMPARE(f->index, 0);
    QCOMPARE(f->time, 0.0);
    f = clock.next();
    QVERIFY(f);
    QCOMPARE(f->index, 1);
    QCOMPARE(f->time, 0.02);
    QThread::msleep(200);
    f = clock.next();
    QVERIFY(f);
    QVERIFY2(f->index >= 10, qPrintable(QString::number(f->index))); // at least 200 ms in
    QCOMPARE(f->time, f->index / 50.0);

    ClockSource slow(0.1); // a frame every 10 s: next() waits
    QVERIFY(slow.next()); // the first at once
    std::optional<VideoFrame> waited {VideoFrame {}};
    std::thread reader([&] { waited = slow.next(); });
    QThread::msleep(50);
    slow.stop();
    reader.join();
    QVERIFY(!waited);
    QVERIFY(!slow.next());
}

// Live mode with no camera: the voice alone drives the cartoon's mouth (the face at rest), and a
// take of it puts mouth keys and the sound on the timeline, keeping the motion already there.
void TestLiveMode::heardOnlyVoiceDrivesTheMouth()
{
    const Audio sound = clipSound();
    if (sound.isEmpty())
        QSKIP("the clip's sound cannot be read");
    QTemporaryDir dir;
    Document document;
    fixture::fill(document, dir.filePath(QStringLiteral("portrait.png")));
    {
        Animation a = document.animation();
        a.timeline.addHeadKey({0.5, 4.0, {}, 1.0});
        a.timeline.addHeadKey({3.0, -4.0, {}, 1.0});
        document.changeAnimation(a, QStringLiteral("head"));
    }
    const QVector<HeadKey> heads = document.timeline().headKeys();
    LiveSession session(&document);
    session.setImageSize(QSize(160, 160));
    int open = 0, shut = 0, total = 0;
    connect(&session, &LiveSession::frameReady, this, [&] {
        const LiveFrame &f = session.current();
        ++total;
        QVERIFY(f.soundDrivesMouth);
        QVERIFY(!f.hasTrack);
        QVERIFY(!f.cartoon.isNull());
        const std::array<QPointF, 4> d = document.mouthShapes().displacements(f.sound.shape, document.face());
        QCOMPARE(f.pose.offset[pt::idx("8.2")], d[1] * f.sound.weight);
        (f.sound.shape == MouthShape::M ? shut : open) += 1;
    });
    session.start(std::make_unique<ClockSource>(30));
    session.startRecording();
    // The voice as a microphone hears it: 20 ms at a time, in real time.
    const int chunk = sound.sampleRate / 50;
    QElapsedTimer clock;
    clock.start();
    for (qsizetype at = 0; at < sound.samples.size(); at += chunk) {
        session.pushAudio(
            sound.samples.constData() + at, std::min<qsizetype>(chunk, sound.samples.size() - at), sound.sampleRate);
        while (clock.elapsed() < (at + chunk) * 1000 / sound.sampleRate)
            QTest::qWait(5);
    }
    const LiveTake take = session.stopRecording();
    session.stop();
    qInfo("heard-only mouth: %d open, %d shut of %d frames", open, shut, total);
    QVERIFY(open > total / 4);
    QVERIFY(shut > 0);
    QVERIFY(take.frames.isEmpty());
    QCOMPARE(take.mouthMode, LiveMouth::Microphone);
    QVERIFY2(std::abs(take.duration - sound.duration()) < 0.5, qPrintable(QString::number(take.duration)));
    QVERIFY(std::abs(take.audio.duration() - sound.duration()) < 0.1);
    QVERIFY(!take.mouth.isEmpty());

    const int steps = document.undoStack()->count();
    QString message;
    QVERIFY2(commitTake(&document, take, 1.0, dir.filePath(QStringLiteral("take.wav")), &message), qPrintable(message));
    QCOMPARE(document.undoStack()->count(), steps + 1);
    QVERIFY2(message.startsWith(QStringLiteral("Recorded")) && message.contains(QStringLiteral("microphone")),
        qPrintable(message));
    const Timeline &t = document.timeline();
    QCOMPARE(t.headKeys(), heads); // the motion there is kept
    QVERIFY(t.poseKeys().isEmpty());
    QVERIFY(t.mouthKeys().size() >= 4);
    int opened = 0;
    for (const MouthKey &k : t.mouthKeys()) {
        QVERIFY(k.time >= 1.0 - 1e-9 && k.time <= 1.0 + take.duration + 1e-9);
        opened += k.shape != MouthShape::M ? 1 : 0;
    }
    QVERIFY(opened >= 2);
    QVERIFY(!t.audioClips().isEmpty());
    QCOMPARE(t.audioClips().first().offset, 1.0);
    QVERIFY(QFileInfo::exists(t.audioClips().first().path));
}

// "Microphone only" on a machine with no microphone: the window says so and nothing starts.
void TestLiveMode::microphoneOnlyWithoutMicrophoneSaysSo()
{
    if (Microphone::isPresent())
        QSKIP("this machine has a microphone (tst_microphone covers the source with one)");
    Document document;
    fixture::fill(document);
    Playhead playhead;
    LiveWindow window(&document, &playhead);
    QVERIFY(!window.startMicrophoneOnly());
    QCOMPARE(window.statusText(), Microphone::noMicrophoneMessage());
    QVERIFY(!window.session()->isRunning());
}

// The mouth's choices speak of the picture, not of a camera: the source is as often a video file.
void TestLiveMode::mouthChoicesDoNotSayCamera()
{
    Document document;
    fixture::fill(document);
    Playhead playhead;
    LiveWindow window(&document, &playhead);
    auto *mouth = window.findChild<QComboBox *>(QStringLiteral("liveMouth"));
    QVERIFY(mouth);
    QCOMPARE(mouth->count(), 3);
    for (int i = 0; i < mouth->count(); ++i)
        QVERIFY2(!mouth->itemText(i).contains(QStringLiteral("camera"), Qt::CaseInsensitive),
            qPrintable(mouth->itemText(i)));
    QVERIFY(!mouth->toolTip().contains(QStringLiteral("camera"), Qt::CaseInsensitive));
}

// Before any source runs, the cartoon is there at rest (it was a blank card), and without a face
// the card says what to do.
void TestLiveMode::cartoonWaitsAtRestBeforeASource()
{
    Document document;
    fixture::fill(document);
    Playhead playhead;
    LiveWindow window(&document, &playhead);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(!window.session()->isRunning());
    const QImage rest = window.cartoonPane()->image();
    QVERIFY(!rest.isNull());
    // A drawing, not an empty card: more than one colour.
    QSet<QRgb> colours;
    for (int y = 0; y < rest.height(); y += 7)
        for (int x = 0; x < rest.width(); x += 7)
            colours.insert(rest.pixel(x, y));
    QVERIFY2(colours.size() > 8, qPrintable(QString::number(colours.size())));

    Document empty;
    LiveWindow nothing(&empty, &playhead);
    QVERIFY(nothing.cartoonPane()->image().isNull());
    QVERIFY(!nothing.cartoonPane()->caption().isEmpty());
}

// Live Mode opens as its own window beside the main window when the screen has room, and
// otherwise at the screen's right edge: never centred over the main window's photo, never off
// the screen.
void TestLiveMode::opensBesideTheMainWindow()
{
    const QRect screen(0, 0, 1920, 1080);
    const QSize wanted(960, 640);
    // Room on the right of a main window on the left half.
    QRect place = LiveWindow::placement(QRect(0, 30, 900, 800), wanted, screen);
    QCOMPARE(place, QRect(QPoint(900, 30), wanted));
    // Room only on the left.
    place = LiveWindow::placement(QRect(960, 0, 960, 1000), wanted, screen);
    QCOMPARE(place, QRect(QPoint(0, 0), wanted));
    // A maximised main window on a laptop screen: at the right edge, inside the screen, shrunk
    // to it, its left edge right of the main window's centre-left photo.
    const QRect laptop(0, 0, 1280, 720);
    place = LiveWindow::placement(laptop, wanted, laptop);
    QVERIFY(laptop.contains(place));
    QCOMPARE(place.right(), laptop.right());
    QVERIFY(place.left() >= laptop.width() / 4);
    // A small screen: the window shrinks to fit.
    place = LiveWindow::placement(QRect(0, 0, 800, 500), wanted, QRect(0, 0, 800, 500));
    QCOMPARE(place, QRect(0, 0, 800, 500));
    // A main window low on the screen: the live window still fits above the bottom.
    place = LiveWindow::placement(QRect(0, 900, 900, 100), wanted, screen);
    QCOMPARE(place.bottom(), screen.bottom());
}

TOONFACE_TEST_MAIN(TestLiveMode)
#include "tst_livemode.moc"
