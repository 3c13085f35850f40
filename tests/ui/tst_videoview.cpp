#include "numberedclip.h"
#include "testmain.h"
#include "uifixture.h"
#include "videofixture.h"

#include "capture/framedecoder.h"
#include "capture/videoview.h"
#include "document/document.h"
#include "media/mediareader.h"
#include "playback/playhead.h"
#include "views/previewview.h"
#include "window/studio.h"

#include <QAction>
#include <QDockWidget>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QSignalSpy>
#include <QTabBar>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace toonface;
using namespace toonface::videofixture;

namespace {

constexpr int kFrames = 20;
constexpr double kOffset = 0.4;

void setClip(Document &doc, std::optional<VideoClip> clip)
{
    Animation a = doc.animation();
    a.timeline.setVideo(std::move(clip));
    doc.changeAnimation(a, QStringLiteral("clip"));
}

// The title of the front tab of the window's tab group holding the Video dock (empty: none).
QString frontTab(const QMainWindow &window)
{
    for (const QTabBar *bar : window.findChildren<QTabBar *>()) {
        for (int i = 0; i < bar->count(); ++i) {
            if (bar->tabText(i) == QStringLiteral("Video"))
                return bar->tabText(bar->currentIndex());
        }
    }
    return {};
}

// The time in the middle of clip frame `index`.
double timeOf(int index)
{
    return kOffset + (index + 0.5) / kFps;
}

} // namespace

class TestVideoView : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    QString m_grey;

    bool waitShown(VideoView &view, int index)
    {
        return QTest::qWaitFor([&] { return view.shownFrame() == index && !view.decoder()->isBusy(); }, 20000);
    }

private Q_SLOTS:
    void initTestCase()
    {
        fixture::isolateSettings();
        QVERIFY(m_dir.isValid());
        m_grey = m_dir.filePath(QStringLiteral("grey.mp4"));
        QCOMPARE(writeGreyClip(m_grey, kFrames), QString());
    }

    void showsTheFrameAtThePlayhead()
    {
        Document doc;
        fixture::fill(doc);
        Playhead playhead;
        VideoView view(&doc, &playhead);
        view.resize(320, 240);
        view.show();
        QCOMPARE(view.wantedFrame(), -1);
        QVERIFY(view.text().contains(QStringLiteral("Import Video")));

        setClip(doc, VideoClip {m_grey, kOffset, kFrames / kFps, kFps});
        // Before the clip starts: a line says when it does.
        QCOMPARE(view.wantedFrame(), -1);
        QVERIFY2(view.text().contains(QStringLiteral("0.40")), qPrintable(view.text()));

        QString error;
        for (int index : {0, 7, 8, 19, 3}) {
            playhead.setTime(timeOf(index));
            QCOMPARE(view.wantedFrame(), index);
            QVERIFY2(waitShown(view, index), qPrintable(QString::number(index)));
            const std::optional<QImage> expected = readVideoFrame(m_grey, index, &error);
            QVERIFY2(expected, qPrintable(error));
            QVERIFY2(meanDifference(view.image(), *expected) < 1.0, qPrintable(QString::number(index)));
        }
        // Frame boundaries: the frame that starts at a time is the one shown from then on.
        playhead.setTime(kOffset + 5 / kFps);
        QCOMPARE(view.wantedFrame(), 5);
        playhead.setTime(kOffset + 5 / kFps - 0.001);
        QCOMPARE(view.wantedFrame(), 4);
        // After its end.
        playhead.setTime(kOffset + kFrames / kFps + 0.01);
        QCOMPARE(view.wantedFrame(), -1);
        QVERIFY2(view.text().contains(QStringLiteral("ended")), qPrintable(view.text()));
        QCOMPARE(view.shownFrame(), -1);
        // Back to a frame decoded just before: shown at once from what was kept.
        playhead.setTime(timeOf(3));
        QVERIFY(waitShown(view, 3));
    }

    // Playback faster than decoding: the frames passed over are dropped, never queued, and the
    // view ends on the frame of the playhead.
    void latestRequestWins()
    {
        Document doc;
        fixture::fill(doc);
        Playhead playhead;
        VideoView view(&doc, &playhead);
        view.show();
        setClip(doc, VideoClip {m_grey, 0.0, kFrames / kFps, kFps});
        QVERIFY(waitShown(view, 0));
        QSignalSpy shown(&view, &VideoView::frameShown);
        // Twenty playhead moves with no event processed between them (a stalled GUI thread).
        for (int i = 1; i < kFrames; ++i)
            playhead.setTime((i + 0.5) / kFps);
        QVERIFY(waitShown(view, kFrames - 1));
        // At most the one decode that was under way and the newest.
        QVERIFY2(shown.size() <= 2, qPrintable(QString::number(shown.size())));
        QVERIFY(view.decoder()->droppedRequests() >= kFrames - 3);
        QString error;
        QVERIFY(meanDifference(view.image(), *readVideoFrame(m_grey, kFrames - 1, &error)) < 1.0);

        // Stepping forward frame by frame (playback at the clip's rate) shows every frame in order.
        playhead.setTime(0.5 / kFps);
        QVERIFY(waitShown(view, 0));
        shown.clear();
        for (int i = 1; i < kFrames; ++i) {
            playhead.setTime((i + 0.5) / kFps);
            QVERIFY(waitShown(view, i));
        }
        QCOMPARE(shown.size(), kFrames - 1);
        for (int i = 0; i < shown.size(); ++i)
            QCOMPARE(shown[i][0].toInt(), i + 1);
    }

    // In a long clip a jump back or far ahead costs at most a key-frame interval of decoding
    // (it seeks), not the clip from its start; playing on still costs a frame a frame.
    void jumpsInALongClipSeek()
    {
        const QString path = m_dir.filePath(QStringLiteral("numbered.mp4"));
        const int frames = 3000; // two minutes at 25 fps
        QCOMPARE(numberedclip::write(path, frames, kFps), QString());
        FrameDecoder decoder;
        QString error;
        QVERIFY2(decoder.open(path, &error), qPrintable(error));
        QSignalSpy ready(&decoder, &FrameDecoder::frameReady);
        QSignalSpy failed(&decoder, &FrameDecoder::failed);
        int decodedBefore = 0;
        const auto show = [&](int index, int mostDecoded) {
            ready.clear();
            decodedBefore = decoder.framesDecoded();
            decoder.request(index);
            if (!QTest::qWaitFor([&] { return !ready.isEmpty() || !failed.isEmpty(); }, 20000) || !failed.isEmpty())
                return QStringLiteral("frame %1 not shown").arg(index);
            const int shown = numberedclip::indexOf(ready.first().at(1).value<QImage>());
            const int cost = decoder.framesDecoded() - decodedBefore;
            if (ready.first().at(0).toInt() != index || shown != index || cost > mostDecoded)
                return QStringLiteral("asked %1, got %2 showing %3, %4 frames decoded")
                    .arg(index)
                    .arg(ready.first().at(0).toInt())
                    .arg(shown)
                    .arg(cost);
            return QString();
        };
        const int keyInterval = int(2 * kFps);
        QCOMPARE(show(10, 11), QString());
        QCOMPARE(show(11, 1), QString()); // playing on
        QCOMPARE(show(2800, keyInterval + 1), QString()); // far ahead
        QCOMPARE(show(2801, 1), QString());
        QCOMPARE(show(150, keyInterval + 1), QString()); // back
        QCOMPARE(show(frames - 1, keyInterval + 1), QString()); // the last
        QCOMPARE(show(0, 1), QString()); // the first
        QCOMPARE(show(40, 41), QString()); // a little ahead: read on
    }

    void unreadableClipSaysSo()
    {
        Document doc;
        fixture::fill(doc);
        Playhead playhead;
        VideoView view(&doc, &playhead);
        const QString missing = m_dir.filePath(QStringLiteral("moved-away.mp4"));
        setClip(doc, VideoClip {missing, 0.0, 1.0, kFps});
        QVERIFY2(view.text().contains(missing), qPrintable(view.text()));
        QCOMPARE(view.wantedFrame(), -1);
        playhead.setTime(0.5);
        QCOMPARE(view.shownFrame(), -1);
    }

    // The dock shows itself when a clip is imported and hides when it goes (undo).
    void dockFollowsTheProject()
    {
        Document doc;
        fixture::fill(doc);
        Playhead playhead;
        QMainWindow window;
        auto *dock = new VideoDock(&doc, &playhead, &window);
        window.addDockWidget(Qt::RightDockWidgetArea, dock);
        window.show();
        QVERIFY(dock->isHidden());
        setClip(doc, VideoClip {m_grey, 0.0, kFrames / kFps, kFps});
        QVERIFY(!dock->isHidden());
        QVERIFY(waitShown(*dock->view(), 0));
        // Closed by the user, it decodes nothing while the playhead moves; shown again, it
        // catches up with the playhead.
        dock->close();
        QSignalSpy shown(dock->view(), &VideoView::frameShown);
        playhead.setTime(timeOf(9) - kOffset);
        QTest::qWait(100);
        QVERIFY(shown.isEmpty());
        QVERIFY(!dock->view()->decoder()->isBusy());
        dock->show();
        QVERIFY(waitShown(*dock->view(), 9));
        doc.undoStack()->undo();
        QVERIFY(dock->isHidden());
        doc.undoStack()->redo();
        QVERIFY(!dock->isHidden());
    }

    // The studio offers Import Video in the Animation menu and the dock's toggle in View.
    void studioWiresTheVideo()
    {
        Document doc;
        fixture::fill(doc);
        QMainWindow window;
        QMenu *view = window.menuBar()->addMenu(QStringLiteral("&View"));
        Studio studio(&doc, &window);
        PreviewView preview(&doc, studio.playhead());
        window.setCentralWidget(&preview);
        auto *appearance = new QDockWidget(QStringLiteral("Appearance"), &window);
        window.addDockWidget(Qt::RightDockWidgetArea, appearance);
        studio.install(&preview, nullptr);
        window.show();
        QVERIFY(studio.importVideoAction());
        QVERIFY(studio.animationMenu()->actions().contains(studio.importVideoAction()));
        QVERIFY(studio.importVideoAction()->isEnabled());
        VideoDock *dock = studio.videoDock();
        QVERIFY(dock);
        QVERIFY(view->actions().contains(dock->toggleViewAction()));
        QVERIFY(dock->isHidden());
        setClip(doc, VideoClip {m_grey, 0.0, kFrames / kFps, kFps});
        QVERIFY(!dock->isHidden());
        // A tab with the docks on the right, not a column that squeezes the photo and cartoon.
        QVERIFY(window.tabifiedDockWidgets(dock).contains(appearance));
        // It follows the studio's playhead.
        studio.playhead()->setTime(timeOf(6) - kOffset);
        QVERIFY(waitShown(*dock->view(), 6));
        window.setCentralWidget(nullptr);
        preview.setParent(nullptr);
    }

    // A project with a clip opened while the Appearance tab is in front (as the window's saved
    // state has it): the Video tab comes to the front, else nothing says the project has a clip.
    void reopenedProjectShowsTheVideoTab()
    {
        Document doc;
        fixture::fill(doc, m_dir.filePath(QStringLiteral("photo.png")));
        setClip(doc, VideoClip {m_grey, 0.0, kFrames / kFps, kFps});
        const QString file = m_dir.filePath(QStringLiteral("reopened.toonface"));
        QString error;
        QVERIFY2(doc.save(file, &error), qPrintable(error));
        setClip(doc, std::nullopt);

        QMainWindow window;
        window.menuBar()->addMenu(QStringLiteral("&View"));
        Studio studio(&doc, &window);
        PreviewView preview(&doc, studio.playhead());
        window.setCentralWidget(&preview);
        auto *appearance = new QDockWidget(QStringLiteral("Appearance"), &window);
        appearance->setObjectName(QStringLiteral("appearanceDock"));
        window.addDockWidget(Qt::RightDockWidgetArea, appearance);
        studio.install(&preview, nullptr);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        VideoDock *dock = studio.videoDock();
        // The window's saved state brings the dock back before the project opens, its tab
        // behind Appearance's as the user left it.
        dock->show();
        appearance->raise();
        QCOMPARE(frontTab(window), QStringLiteral("Appearance"));

        QVERIFY2(doc.load(file, &error), qPrintable(error));
        QVERIFY(doc.timeline().video());
        QVERIFY(!dock->isHidden());
        QCOMPARE(frontTab(window), QStringLiteral("Video"));
        QTRY_VERIFY(!dock->visibleRegion().isEmpty());
        window.setCentralWidget(nullptr);
        preview.setParent(nullptr);
    }

    // The project remembers the clip, relative to the project file.
    void projectKeepsTheClip()
    {
        Document doc;
        fixture::fill(doc, m_dir.filePath(QStringLiteral("photo.png")));
        setClip(doc, VideoClip {m_grey, 1.25, kFrames / kFps, kFps});
        const QString file = m_dir.filePath(QStringLiteral("project.toonface"));
        QString error;
        QVERIFY2(doc.save(file, &error), qPrintable(error));
        Document loaded;
        QVERIFY2(loaded.load(file, &error), qPrintable(error));
        QVERIFY(loaded.timeline().video());
        QCOMPARE(*loaded.timeline().video(), *doc.timeline().video());
    }
};

TOONFACE_TEST_MAIN(TestVideoView)
#include "tst_videoview.moc"
