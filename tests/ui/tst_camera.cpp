#include "capture/camerafeed.h"
#include "capture/cameraframesource.h"
#include "capture/capturedialog.h"
#include "capture/framepane.h"
#include "capture/livewindow.h"
#include "document/document.h"
#include "testmain.h"
#include "uifixture.h"

#include <QCamera>
#include <QMediaDevices>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QVideoFrame>
#include <QVideoFrameFormat>
#include <QVideoSink>
#include <QtTest>

#include <thread>

using namespace toonface;

namespace {

// A camera frame made by hand, as a sink delivers them: BGRX, one colour, a marker pixel.
QVideoFrame cameraFrame(QSize size, QColor colour)
{
    QVideoFrame frame(QVideoFrameFormat(size, QVideoFrameFormat::Format_BGRX8888));
    if (!frame.map(QVideoFrame::WriteOnly))
        return {};
    for (int y = 0; y < size.height(); ++y) {
        uchar *line = frame.bits(0) + qsizetype(y) * frame.bytesPerLine(0);
        for (int x = 0; x < size.width(); ++x) {
            const bool marker = x == 1 && y == 2;
            line[4 * x + 0] = uchar(marker ? 255 : colour.blue());
            line[4 * x + 1] = uchar(marker ? 255 : colour.green());
            line[4 * x + 2] = uchar(marker ? 255 : colour.red());
            line[4 * x + 3] = 255;
        }
    }
    frame.unmap();
    return frame;
}

bool noCamera()
{
    return QMediaDevices::videoInputs().isEmpty();
}

} // namespace

class TestCamera : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { fixture::isolateSettings(); }
    void sourceConvertsCameraFrames();
    void sourceKeepsOnlyTheNewestFrame();
    void sourceWaitsAndStops();
    void sourceFollowsASink();
    void sourceFailureEndsTheReader();
    void feedWithoutCameraSaysSo();
    void dialogWithoutCameraSaysSoAndShowsNoTestPattern();
    void dialogSnapshotBecomesAPhoto();
    void liveWindowWithoutCameraSaysSo();
};

void TestCamera::sourceConvertsCameraFrames()
{
    CameraFrameSource source;
    QVERIFY(!source.push(QVideoFrame())); // invalid: skipped
    QVERIFY(source.push(cameraFrame(QSize(64, 48), QColor(200, 100, 50))));
    const std::optional<VideoFrame> frame = source.next();
    QVERIFY(frame);
    QCOMPARE(frame->image.size(), QSize(64, 48));
    QCOMPARE(frame->image.format(), QImage::Format_RGB32);
    QCOMPARE(QColor(frame->image.pixel(10, 10)), QColor(200, 100, 50));
    QCOMPARE(QColor(frame->image.pixel(1, 2)), QColor(255, 255, 255));
    QCOMPARE(frame->index, 0);
    QVERIFY(frame->time >= 0);
    QCOMPARE(source.frameSize(), QSize(64, 48));
    QVERIFY(source.lastArrival() >= 0 && source.lastArrival() <= source.now());
}

void TestCamera::sourceKeepsOnlyTheNewestFrame()
{
    CameraFrameSource source;
    source.push(cameraFrame(QSize(8, 8), Qt::red));
    source.push(cameraFrame(QSize(8, 8), Qt::green));
    source.push(cameraFrame(QSize(8, 8), Qt::blue));
    QCOMPARE(source.pushedFrames(), 3);
    QCOMPARE(source.replacedFrames(), 2);
    const std::optional<VideoFrame> frame = source.next();
    QVERIFY(frame);
    QCOMPARE(QColor(frame->image.pixel(4, 4)), QColor(Qt::blue));
    QCOMPARE(frame->index, 2);
}

void TestCamera::sourceWaitsAndStops()
{
    CameraFrameSource source;
    std::optional<VideoFrame> got;
    std::thread reader([&] { got = source.next(); });
    QThread::msleep(50);
    source.push(QImage(QSize(4, 4), QImage::Format_ARGB32), 1.5);
    reader.join();
    QVERIFY(got);
    QCOMPARE(got->time, 1.5);
    QCOMPARE(got->image.format(), QImage::Format_RGB32);

    bool ended = false;
    std::thread waiting([&] { ended = !source.next().has_value(); });
    QThread::msleep(50);
    source.stop();
    waiting.join();
    QVERIFY(ended);
    source.push(QImage(QSize(4, 4), QImage::Format_RGB32)); // after stop: ignored
    QVERIFY(!source.next());
    QVERIFY(source.error().isEmpty());
}

void TestCamera::sourceFollowsASink()
{
    CameraFrameSource source;
    QVideoSink sink;
    source.attach(&sink);
    sink.setVideoFrame(cameraFrame(QSize(16, 12), QColor(10, 20, 30)));
    QCOMPARE(source.pushedFrames(), 1);
    const std::optional<VideoFrame> frame = source.next();
    QVERIFY(frame);
    QCOMPARE(QColor(frame->image.pixel(5, 5)), QColor(10, 20, 30));
    source.detach();
    sink.setVideoFrame(cameraFrame(QSize(16, 12), QColor(40, 50, 60)));
    QCOMPARE(source.pushedFrames(), 1);
}

void TestCamera::sourceFailureEndsTheReader()
{
    CameraFrameSource source;
    bool ended = false;
    std::thread reader([&] { ended = !source.next().has_value(); });
    QThread::msleep(30);
    source.fail(QStringLiteral("The camera “Test” was disconnected."));
    reader.join();
    QVERIFY(ended);
    QCOMPARE(source.error(), QStringLiteral("The camera “Test” was disconnected."));
}

void TestCamera::feedWithoutCameraSaysSo()
{
    if (!noCamera())
        QSKIP("this machine has a camera");
    CameraFeed feed;
    QVERIFY(CameraFeed::cameras().isEmpty());
    QString error;
    QVERIFY(!feed.start(QString(), &error));
    QCOMPARE(error, CameraFeed::noCameraMessage());
    QVERIFY(error.contains(QStringLiteral("No camera")));
    QVERIFY(!feed.isActive());
    QVERIFY(feed.findChildren<QCamera *>().isEmpty());
}

void TestCamera::dialogWithoutCameraSaysSoAndShowsNoTestPattern()
{
    if (!noCamera())
        QSKIP("this machine has a camera");
    Document document;
    fixture::fill(document);
    CaptureDialog dialog(&document);
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    QTest::qWait(200);
    QVERIFY(!dialog.hasCamera());
    QVERIFY(dialog.messageText().contains(QStringLiteral("No camera")));
    QCOMPARE(dialog.view()->caption(), QStringLiteral("No camera"));
    QVERIFY(dialog.view()->image().isNull()); // nothing shown: no test pattern
    QVERIFY(!dialog.takeButton()->isEnabled());
    QVERIFY(dialog.findChildren<QCamera *>().isEmpty());
    // Taking a photo anyway (a shortcut) says why not, and writes nothing.
    dialog.takePhoto(0);
    QVERIFY(dialog.savedPath().isEmpty());
    QVERIFY(dialog.messageText().contains(QStringLiteral("No camera")));
    QVERIFY(dialog.isVisible());
}

void TestCamera::dialogSnapshotBecomesAPhoto()
{
    QTemporaryDir dir;
    Document document;
    fixture::fill(document, dir.filePath(QStringLiteral("portrait.png")));
    CaptureDialog dialog(&document);
    QSignalSpy taken(&dialog, &CaptureDialog::photoTaken);
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    // A frame as the camera would show it: the fixture's drawn head.
    const QImage picture = fixture::photo();
    dialog.showFrame(picture);
    QVERIFY(dialog.takeButton()->isEnabled());
    QCOMPARE(dialog.view()->image(), picture);
    dialog.takePhoto(1);
    QCOMPARE(dialog.view()->caption(), QStringLiteral("1"));
    QTRY_COMPARE_WITH_TIMEOUT(taken.count(), 1, 3000);
    const QString path = taken.first().at(0).toString();
    QCOMPARE(path, dialog.savedPath());
    QCOMPARE(QFileInfo(path).absolutePath(), QFileInfo(dir.path()).absoluteFilePath());
    QVERIFY(path.endsWith(QStringLiteral("portrait-camera.png")));
    QImage saved(path);
    QCOMPARE(saved.size(), picture.size());
    QCOMPARE(saved.convertToFormat(QImage::Format_RGB32), picture.convertToFormat(QImage::Format_RGB32));
    QCOMPARE(dialog.result(), int(QDialog::Accepted));
}

void TestCamera::liveWindowWithoutCameraSaysSo()
{
    if (!noCamera())
        QSKIP("this machine has a camera");
    Document document;
    fixture::fill(document);
    LiveWindow window(&document, nullptr);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.statusText().contains(QStringLiteral("No camera")));
    QVERIFY(!window.startCamera(QString()));
    QVERIFY(window.statusText().contains(QStringLiteral("No camera")));
    QCOMPARE(window.sourcePane()->caption(), QStringLiteral("No camera"));
    QVERIFY(window.sourcePane()->image().isNull());
    QVERIFY(!window.recordButton()->isEnabled());
    QVERIFY(window.findChildren<QCamera *>().isEmpty());
}

TOONFACE_TEST_MAIN(TestCamera)
#include "tst_camera.moc"
