#include "playbackfixture.h"
#include "testmain.h"
#include "uifixture.h"

#include "anim/timelineevaluator.h"
#include "playback/playbackcontroller.h"
#include "playback/playhead.h"
#include "render/svgface.h"
#include "views/previewview.h"

#include <QElapsedTimer>
#include <QHBoxLayout>
#include <QUndoStack>
#include <QtTest>

using namespace toonface;

// The animated preview: the pose at the playhead, drawn on time or dropped, never queued.
class TestPreviewPlayback : public QObject
{
    Q_OBJECT

    Document *m_doc = nullptr;
    Playhead *m_playhead = nullptr;
    QWidget *m_window = nullptr;
    PreviewView *m_preview = nullptr;

    // What the preview must show at `t`: the evaluator's pose drawn by SvgFace in its frame.
    QByteArray expectedSvg(double t) const
    {
        SvgFace face(m_doc->face(), m_doc->style());
        face.setFrame(m_preview->frame());
        return face.svg(TimelineEvaluator(m_doc->timeline(), m_doc->face(), m_doc->mouthShapes()).evaluate(t));
    }

private Q_SLOTS:
    void init()
    {
        m_doc = new Document;
        fixture::fill(*m_doc);
        fixture::setTimeline(*m_doc, fixture::talkingTimeline(4.0));
        m_playhead = new Playhead;
        m_window = new QWidget;
        auto *layout = new QHBoxLayout(m_window);
        m_preview = new PreviewView(m_doc, m_playhead);
        layout->addWidget(m_preview);
        m_window->resize(400, 460);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window));
        m_preview->image();
    }

    void cleanup()
    {
        delete m_window;
        delete m_playhead;
        delete m_doc;
    }

    void showsThePoseAtThePlayhead()
    {
        QCOMPARE(m_preview->svg(), expectedSvg(0));
        const QImage atStart = m_preview->image();
        m_playhead->setTime(0.3); // an 'o' is sounding
        QCOMPARE(m_preview->svg(), expectedSvg(0.3));
        QVERIFY(m_preview->svg() != expectedSvg(0));
        QVERIFY(m_preview->image() != atStart);
        m_playhead->setTime(0);
        QCOMPARE(m_preview->image(), atStart);
    }

    void playheadMovesDrawWithoutRebuildingTheScene()
    {
        const int rebuilds = m_preview->rebuildCount();
        const int drawn = m_preview->renderer()->renderedFrames();
        for (int i = 1; i <= 10; ++i)
            m_playhead->setTime(i * 0.04);
        QCOMPARE(m_preview->renderer()->renderedFrames(), drawn); // coalesced: nothing yet
        QTRY_COMPARE(m_preview->renderer()->renderedFrames(), drawn + 1);
        QTRY_VERIFY(!m_preview->renderer()->isBusy());
        QCOMPARE(m_preview->renderer()->current().time, 0.4);
        QCOMPARE(m_preview->rebuildCount(), rebuilds);

        // The scene is rebuilt for what it is drawn from, not for the file state.
        m_doc->undoStack()->setClean();
        m_preview->svg();
        QCOMPARE(m_preview->rebuildCount(), rebuilds);
        Timeline timeline = m_doc->timeline();
        timeline.addEmotionClip(EmotionClip {0, 4, Emotion::Smile, 1.0, 0.2, 0.2});
        fixture::setTimeline(*m_doc, timeline);
        QCOMPARE(m_preview->svg(), expectedSvg(0.4)); // smiling now
        QCOMPARE(m_preview->rebuildCount(), rebuilds + 1);
        MouthShapeSet shapes = m_doc->mouthShapes();
        m_doc->changeMouthShapes(shapes, QStringLiteral("same shapes")); // no change: nothing pushed
        m_preview->svg();
        QCOMPARE(m_preview->rebuildCount(), rebuilds + 1);
    }

    // A frame's work that cannot fit a frame goes to a worker: the playhead keeps its pace, the
    // picture shows the newest frame each time the worker is free, and the frames passed
    // meanwhile are dropped rather than drawn late.
    void lateFramesAreDroppedNotQueued()
    {
        constexpr int kCostMs = 150;
        PreviewRenderer *renderer = m_preview->renderer();
        renderer->setExtraRenderCost(kCostMs);
        m_playhead->setTime(0.04);
        m_preview->svg(); // a frame at the slow cost, so the renderer knows it
        QVERIFY(renderer->averageRenderMs() > renderer->renderBudgetMs());
        const int drawnBefore = renderer->renderedFrames();
        const int backgroundBefore = renderer->backgroundFrames();

        PlaybackController controller(m_doc, m_playhead);
        QElapsedTimer elapsed;
        elapsed.start();
        controller.play();
        QTest::qWait(1200);
        controller.pause();
        const double seconds = elapsed.nsecsElapsed() / 1e9;

        // The GUI thread was never held by a frame: the playhead advanced nearly every frame
        // (drawing each on the GUI thread would have allowed one per 150 ms).
        QVERIFY2(controller.framesPlayed() >= int(seconds * 25 * 0.6),
            qPrintable(QStringLiteral("%1 frames in %2 s").arg(controller.framesPlayed()).arg(seconds)));
        const int drawn = renderer->renderedFrames() - drawnBefore;
        QVERIFY(renderer->backgroundFrames() - backgroundBefore >= 2);
        QVERIFY(renderer->droppedFrames() > 0);
        // One job in flight: never more pictures than the worker could draw one after another.
        QVERIFY2(drawn <= int(seconds * 1000 / kCostMs) + 2, qPrintable(QString::number(drawn)));
        QVERIFY(drawn + renderer->droppedFrames() <= controller.framesPlayed() + 2);

        // After the playback the worker finishes at most one job more, and then shows the
        // playhead's last frame, not an older one left in a queue.
        QTRY_VERIFY_WITH_TIMEOUT(!renderer->isBusy() && renderer->current().time == m_playhead->time(), 3000);
        QCOMPARE(m_preview->svg(), expectedSvg(m_playhead->time()));
    }

    void noFaceShowsNoPicture()
    {
        Project empty;
        m_doc->reset(empty, fixture::photo(), {}, false);
        QVERIFY(m_preview->svg().isEmpty());
        m_playhead->setTime(1.0);
        QVERIFY(m_preview->svg().isEmpty());
        QVERIFY(!m_preview->image().isNull());
    }
};

TOONFACE_TEST_MAIN(TestPreviewPlayback)
#include "tst_previewplayback.moc"
