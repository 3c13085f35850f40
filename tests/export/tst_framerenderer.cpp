#include "animationfixture.h"
#include "testmain.h"

#include "anim/timeline.h"
#include "anim/timelineevaluator.h"
#include "export/framerenderer.h"
#include "render/svgface.h"

#include <QTest>
#include <QThread>

using namespace toonface;

class TestFrameRenderer : public QObject
{
    Q_OBJECT

private:
    FaceModel m_face = test::animationFace();
    Timeline m_timeline = test::animationTimeline();
    MouthShapeSet m_shapes;

    FrameRenderer renderer(QSize size = QSize(96, 96)) const
    {
        return FrameRenderer(SvgFace(m_face, Style()), m_timeline, m_shapes, size);
    }

private Q_SLOTS:
    void framesAndTimes()
    {
        const FrameRenderer r = renderer();
        QCOMPARE(r.frameRate(), 25.0);
        QCOMPARE(r.frameCount(), m_timeline.frameCount());
        QCOMPARE(r.frameCount(), 250);
        QCOMPARE(r.frameTime(0), 0.0);
        QCOMPARE(r.frameTime(30), 1.2);
        QCOMPARE(r.size(), QSize(96, 96));
    }

    // A frame is the renderer's SVG of the evaluated pose, rasterized.
    void frameIsTheDrawingOfItsTime_data()
    {
        QTest::addColumn<int>("frame");
        for (int f : {0, 46, 57, 140, 249})
            QTest::newRow(qPrintable(QString::number(f))) << f;
    }

    void frameIsTheDrawingOfItsTime()
    {
        QFETCH(int, frame);
        const FrameRenderer r = renderer(QSize(200, 150));
        const SvgFace svgFace(m_face, Style());
        const TimelineEvaluator evaluator(m_timeline, m_face, m_shapes);
        const QByteArray svg = svgFace.svg(evaluator.evaluate(frame / 25.0));
        QCOMPARE(r.svgAt(frame / 25.0), svg);
        const QImage image = r.render(frame);
        QCOMPARE(image.size(), QSize(200, 150));
        QCOMPARE(image, rasterizeSvg(svg, QSize(200, 150)));
        // The open mouth at the vowel is not the shut one.
        if (frame == 46)
            QVERIFY(image != r.renderAt(test::silenceTime()));
    }

    void everyFrameArrivesInOrder_data()
    {
        QTest::addColumn<int>("first");
        QTest::addColumn<int>("count");
        QTest::addColumn<int>("batch");
        QTest::addColumn<int>("expected");
        QTest::newRow("all, default batches") << 0 << -1 << 0 << 250;
        QTest::newRow("all, one at a time") << 0 << -1 << 1 << 250;
        QTest::newRow("a stretch, odd batches") << 17 << 40 << 7 << 40;
        QTest::newRow("past the end") << 240 << 50 << 4 << 10;
        QTest::newRow("nothing") << 250 << 10 << 4 << 0;
    }

    void everyFrameArrivesInOrder()
    {
        QFETCH(int, first);
        QFETCH(int, count);
        QFETCH(int, batch);
        QFETCH(int, expected);
        const FrameRenderer r = renderer(QSize(32, 32));
        QVector<int> frames;
        QVector<std::pair<int, int>> progress;
        QThread *const caller = QThread::currentThread();
        bool onCaller = true;
        QImage sample;
        FrameRenderOptions o;
        o.first = first;
        o.count = count;
        o.batch = batch;
        o.progress = [&](int done, int total) { progress.append({done, total}); };
        const bool finished = renderFrames(
            r,
            [&](int frame, const QImage &image) {
                onCaller = onCaller && QThread::currentThread() == caller;
                frames.append(frame);
                if (frame == first + 3)
                    sample = image;
                return true;
            },
            o);
        QVERIFY(finished);
        QVERIFY(onCaller);
        QCOMPARE(frames.size(), expected);
        for (int i = 0; i < frames.size(); ++i)
            QCOMPARE(frames[i], first + i);
        QCOMPARE(progress.size(), expected);
        if (expected > 0) {
            QCOMPARE(progress.last(), std::make_pair(expected, expected));
            QCOMPARE(sample, r.render(first + 3));
        }
    }

    void sinkCanStop()
    {
        const FrameRenderer r = renderer(QSize(32, 32));
        int delivered = 0;
        FrameRenderOptions o;
        o.batch = 3;
        const bool finished = renderFrames(
            r, [&](int, const QImage &) { return ++delivered < 5; }, o);
        QVERIFY(!finished);
        QCOMPARE(delivered, 5);
    }

    void cancelStops()
    {
        const FrameRenderer r = renderer(QSize(32, 32));
        std::atomic_bool cancel = false;
        int delivered = 0;
        FrameRenderOptions o;
        o.cancel = &cancel;
        const bool finished = renderFrames(
            r,
            [&](int, const QImage &) {
                if (++delivered == 12)
                    cancel = true;
                return true;
            },
            o);
        QVERIFY(!finished);
        QCOMPARE(delivered, 12);
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestFrameRenderer)
#include "tst_framerenderer.moc"
