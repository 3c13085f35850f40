#include "uifixture.h"

#include "views/photoview.h"
#include "views/pointhandle.h"
#include "views/previewview.h"

#include <QApplication>
#include <QHBoxLayout>
#include <QLineF>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>
#include <QWheelEvent>

using namespace toonface;

namespace {

// Drags from `from` by `by` (viewport pixels) in several mouse moves, as a hand would.
void drag(QWidget *viewport, QPoint from, QPoint by, int steps = 6)
{
    QTest::mousePress(viewport, Qt::LeftButton, Qt::NoModifier, from);
    for (int s = 1; s <= steps; ++s)
        QTest::mouseMove(viewport, from + by * s / steps);
    QTest::mouseRelease(viewport, Qt::LeftButton, Qt::NoModifier, from + by);
}

} // namespace

class TestPhotoView : public QObject
{
    Q_OBJECT

private:
    Document *m_doc = nullptr;
    QWidget *m_window = nullptr;
    PhotoView *m_photo = nullptr;
    PreviewView *m_preview = nullptr;

    QPoint viewportPos(int index) const { return m_photo->mapFromScene(m_doc->face().point(index)); }

private Q_SLOTS:
    void init()
    {
        m_doc = new Document;
        fixture::fill(*m_doc);
        m_window = new QWidget;
        auto *layout = new QHBoxLayout(m_window);
        m_photo = new PhotoView(m_doc);
        m_preview = new PreviewView(m_doc);
        layout->addWidget(m_photo, 3);
        layout->addWidget(m_preview, 2);
        m_window->resize(1000, 700);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window));
        m_photo->fitToWindow();
    }

    void cleanup()
    {
        delete m_window;
        delete m_doc;
    }

    void handlesSitOnThePoints()
    {
        for (int i = 0; i < kPointCount; ++i) {
            QVERIFY(m_photo->handle(i)->isVisible());
            QCOMPARE(m_photo->handle(i)->pos(), m_doc->face().point(i));
        }
    }

    void fitShowsTheWholePhoto()
    {
        QCOMPARE(m_photo->fitMode(), PhotoView::Fit::Photo);
        const QRect photoInView = m_photo->mapFromScene(QRectF(QPointF(), QSizeF(fixture::kPhotoSize))).boundingRect();
        QVERIFY2(m_photo->viewport()->rect().adjusted(-1, -1, 1, 1).contains(photoInView),
            qPrintable(QStringLiteral("photo at %1,%2 %3x%4")
                           .arg(photoInView.x())
                           .arg(photoInView.y())
                           .arg(photoInView.width())
                           .arg(photoInView.height())));
        // ... and fills the viewport in one direction at least (within a few pixels).
        QVERIFY(photoInView.height() >= m_photo->viewport()->height() * 0.7
            || photoInView.width() >= m_photo->viewport()->width() * 0.7);
    }

    void dragMovesPointAndPreviewFollows()
    {
        const int i = pt::idx("8.4"); // left mouth corner
        const QPointF before = m_doc->face().point(i);
        const QByteArray svgBefore = m_preview->svg();
        const QImage imageBefore = m_preview->image();
        QVERIFY(!svgBefore.isEmpty());
        QVERIFY(!imageBefore.isNull());

        const QPoint by(-24, 12);
        drag(m_photo->viewport(), viewportPos(i), by);

        // Moved by the drag in photo pixels (the view is zoomed), and now the user's point.
        const QPointF expected = before + QPointF(by) / m_photo->zoom();
        QVERIFY2(QLineF(m_doc->face().point(i), expected).length() < 1.5 / m_photo->zoom(),
            qPrintable(QStringLiteral("at %1,%2, expected %3,%4")
                           .arg(m_doc->face().point(i).x())
                           .arg(m_doc->face().point(i).y())
                           .arg(expected.x())
                           .arg(expected.y())));
        QVERIFY(m_doc->face().isHandPlaced(i));
        QCOMPARE(m_photo->handle(i)->pos(), m_doc->face().point(i));
        QCOMPARE(m_doc->undoStack()->count(), 1);

        const QByteArray svgMoved = m_preview->svg();
        const QImage imageMoved = m_preview->image();
        QVERIFY(svgMoved != svgBefore);
        QVERIFY(imageMoved != imageBefore);

        m_doc->undoStack()->undo();
        QCOMPARE(m_doc->face().point(i), before);
        QVERIFY(!m_doc->face().isHandPlaced(i));
        QCOMPARE(m_photo->handle(i)->pos(), before);
        QCOMPARE(m_preview->svg(), svgBefore);
        QCOMPARE(m_preview->image(), imageBefore);

        m_doc->undoStack()->redo();
        QVERIFY(QLineF(m_doc->face().point(i), expected).length() < 1.5 / m_photo->zoom());
        QVERIFY(m_doc->face().isHandPlaced(i));
        QCOMPARE(m_preview->svg(), svgMoved);
        QCOMPARE(m_preview->image(), imageMoved);
    }

    void eachDragIsOneUndoStep()
    {
        const int i = pt::idx("3.6");
        const QPointF start = m_doc->face().point(i);
        drag(m_photo->viewport(), viewportPos(i), QPoint(10, 0), 8);
        QCOMPARE(m_doc->undoStack()->count(), 1);
        const QPointF afterFirst = m_doc->face().point(i);
        drag(m_photo->viewport(), viewportPos(i), QPoint(0, 10), 8);
        QCOMPARE(m_doc->undoStack()->count(), 2);
        m_doc->undoStack()->undo();
        QCOMPARE(m_doc->face().point(i), afterFirst);
        m_doc->undoStack()->undo();
        QCOMPARE(m_doc->face().point(i), start);
    }

    void clickWithoutMoveChangesNothing()
    {
        const QPoint at = viewportPos(pt::idx("9.15"));
        QTest::mouseClick(m_photo->viewport(), Qt::LeftButton, Qt::NoModifier, at);
        QCOMPARE(m_doc->undoStack()->count(), 0);
        QVERIFY(!m_doc->isModified());
    }

    void hoverNamesThePoint()
    {
        QSignalSpy spy(m_photo, &PhotoView::pointHovered);
        const int i = pt::idx("9.15");
        QTest::mouseMove(m_photo->viewport(), viewportPos(i) + QPoint(30, 30));
        QTest::mouseMove(m_photo->viewport(), viewportPos(i));
        QTRY_VERIFY(!spy.isEmpty());
        QCOMPARE(spy.last().first().toInt(), i);
        QVERIFY(m_photo->handle(i)->isHovered());
        QVERIFY(m_photo->handle(i)->toolTip().contains(QStringLiteral("9.15")));
    }

    void wheelZoomsAndFitRestores()
    {
        const double fitted = m_photo->zoom();
        const QPointF centre = m_photo->viewport()->rect().center();
        QWheelEvent wheel(centre, m_photo->viewport()->mapToGlobal(centre), QPoint(), QPoint(0, 240), Qt::NoButton,
            Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(m_photo->viewport(), &wheel);
        QVERIFY(m_photo->zoom() > fitted * 1.2);
        QCOMPARE(m_photo->fitMode(), PhotoView::Fit::None);
        m_photo->fitToWindow();
        QVERIFY(qAbs(m_photo->zoom() - fitted) < 1e-6);
        m_photo->zoomToActualSize();
        QCOMPARE(m_photo->zoom(), 1.0);
    }

    void zoomToFaceFramesThePoints()
    {
        const double photoZoom = m_photo->zoom();
        m_photo->zoomToFace();
        QCOMPARE(m_photo->fitMode(), PhotoView::Fit::Face);
        QVERIFY(m_photo->zoom() > photoZoom);
        const QRect face = m_photo->mapFromScene(m_doc->face().bounds()).boundingRect();
        QVERIFY(m_photo->viewport()->rect().contains(face));

        // The mode holds across a resize and a new face.
        m_window->resize(1100, 800);
        QTRY_VERIFY(m_photo->viewport()->rect().contains(m_photo->mapFromScene(m_doc->face().bounds()).boundingRect()));
        m_doc->replaceFace(averageFace(QRectF(40, 40, 100, 120), fixture::kPhotoSize), false, QStringLiteral("Move"));
        const QRect moved = m_photo->mapFromScene(m_doc->face().bounds()).boundingRect();
        QVERIFY(m_photo->viewport()->rect().contains(moved));
        QVERIFY(moved.width() > m_photo->viewport()->width() / 3 || moved.height() > m_photo->viewport()->height() / 3);
    }

    void handlesHiddenWithoutFace()
    {
        Project project;
        project.face = FaceModel(fixture::kPhotoSize);
        m_doc->reset(project, fixture::photo(), {}, false);
        for (int i = 0; i < kPointCount; ++i)
            QVERIFY(!m_photo->handle(i)->isVisible());
        QVERIFY(m_preview->svg().isEmpty());
    }

    void showIdsWidensHandles()
    {
        PointHandle *h = m_photo->handle(pt::idx("2.1"));
        const QRectF without = h->boundingRect();
        m_photo->setShowPointIds(true);
        QVERIFY(h->boundingRect().width() > without.width());
        m_photo->setShowPointIds(false);
        QCOMPARE(h->boundingRect(), without);
    }

    void previewRebuildsOncePerBurstOfChanges()
    {
        m_preview->svg(); // settle
        const int before = m_preview->rebuildCount();
        const int i = pt::idx("8.2");
        const QPointF start = m_doc->face().point(i);
        for (int s = 1; s <= 20; ++s)
            m_doc->movePoint(i, start + QPointF(0, s * 0.5), false);
        m_doc->movePoint(i, start + QPointF(0, 10), true);
        QCOMPARE(m_preview->rebuildCount(), before); // nothing rebuilt inside the burst
        QTRY_COMPARE(m_preview->rebuildCount(), before + 1);
    }

    void previewFrameHoldsStillDuringDrag()
    {
        const QRectF frame = m_preview->frame();
        QVERIFY(!frame.isEmpty());
        QVERIFY(frame.contains(m_doc->face().bounds()));
        m_doc->movePoint(pt::idx("h.10"), m_doc->face().point("h.10") - QPointF(0, 40), true);
        m_preview->svg();
        QCOMPARE(m_preview->frame(), frame);
        m_doc->replaceFace(
            averageFace(QRectF(120, 160, 180, 220), fixture::kPhotoSize), false, QStringLiteral("Re-detect"));
        m_preview->svg();
        QVERIFY(m_preview->frame() != frame); // a new face frames itself afresh
    }
};

QTEST_MAIN(TestPhotoView)
#include "tst_photoview.moc"
