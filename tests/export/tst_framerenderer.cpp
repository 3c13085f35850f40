#include "animationfixture.h"
#include "testmain.h"

#include "anim/timeline.h"
#include "anim/timelineevaluator.h"
#include "export/framerenderer.h"
#include "render/svgface.h"

#include <QPainter>
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

    // Frames drawn in parallel, their under pass reused between them (svgface.h: svgPasses()),
    // are each the plain rasterization of their SVG, pixel for pixel: through the head's shake
    // and nod (the under pass moves), the emotions (the brows in it move) and the still
    // stretches between, on a background colour and over a backdrop, with the hat, glasses and
    // a layer in each place.
    void reusedLayersGiveThePlainFrame_data()
    {
        QTest::addColumn<bool>("backdrop");
        QTest::newRow("background colour") << false;
        QTest::newRow("backdrop") << true;
    }

    void reusedLayersGiveThePlainFrame()
    {
        QFETCH(bool, backdrop);
        Style style = Style::preset(QStringLiteral("normal"));
        style.appearance.hat = true;
        style.appearance.glasses = GlassesShape::Round;
        const QByteArray square = "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 10 10\">"
                                  "<rect width=\"10\" height=\"10\" fill=\"#00ff00\"/></svg>";
        for (const bool front : {false, true}) {
            for (const bool follows : {false, true}) {
                StyleLayer l;
                l.svg = square;
                l.offset = QPointF(front ? 1.2 : -1.2, follows ? -0.8 : 1.0);
                l.width = 0.5;
                l.front = front;
                l.followsHead = follows;
                style.layers.append(l);
            }
        }
        const QSize size(120, 100);
        QImage picture(size, QImage::Format_RGB32);
        for (int y = 0; y < size.height(); ++y) {
            for (int x = 0; x < size.width(); ++x)
                picture.setPixel(x, y, qRgb(x * 2, y * 2, 90));
        }
        const FrameRenderer r(
            SvgFace(m_face, style), m_timeline, m_shapes, size, QColor(250, 240, 200), backdrop ? picture : QImage());
        int checked = 0;
        const bool finished = renderFrames(r, [&](int frame, const QImage &image) {
            QImage plain = rasterizeSvg(
                r.svgAt(r.frameTime(frame)), size, backdrop ? QColor(Qt::transparent) : QColor(250, 240, 200));
            if (backdrop) {
                QImage under = picture.convertToFormat(QImage::Format_ARGB32_Premultiplied);
                QPainter painter(&under);
                painter.drawImage(0, 0, plain);
                painter.end();
                plain = under;
            }
            if (image != plain) {
                qWarning("frame %d differs from its plain rasterization", frame);
                return false;
            }
            ++checked;
            return true;
        });
        QVERIFY(finished);
        QCOMPARE(checked, r.frameCount());
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
