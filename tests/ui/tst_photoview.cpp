#include "testmain.h"
#include "uifixture.h"

#include "views/photoview.h"
#include "views/pointhandle.h"
#include "views/previewview.h"

#include <QApplication>
#include <QGraphicsPixmapItem>
#include <QGraphicsScene>
#include <QHBoxLayout>
#include <QLineF>
#include <QSet>
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

// A picture of the photo's frame at `size`: opaque red on its left half, transparent on the right.
QImage halfRedOverlay(QSize size)
{
    QImage image(size, QImage::Format_ARGB32);
    image.fill(Qt::transparent);
    for (int y = 0; y < size.height(); ++y)
        for (int x = 0; x < size.width() / 2; ++x)
            image.setPixel(x, y, qRgb(255, 0, 0));
    return image;
}

bool isPureRed(QRgb c)
{
    return qRed(c) >= 250 && qGreen(c) <= 5 && qBlue(c) <= 5;
}

} // namespace

// Counts a view's viewport resizes; past a bound it stops the view's fit mode (which ends a
// resize loop) and says so.
class ResizeGuard : public QObject
{
public:
    explicit ResizeGuard(PhotoView *view)
        : m_view(view)
    { }
    int resizes = 0;
    bool tripped = false;

protected:
    bool eventFilter(QObject *watched, QEvent *event) override
    {
        if (event->type() == QEvent::Resize && ++resizes > 200 && !tripped) {
            tripped = true;
            m_view->zoomIn();
        }
        return QObject::eventFilter(watched, event);
    }

private:
    PhotoView *m_view;
};

class TestPhotoView : public QObject
{
    Q_OBJECT

private:
    Document *m_doc = nullptr;
    QWidget *m_window = nullptr;
    PhotoView *m_photo = nullptr;
    PreviewView *m_preview = nullptr;

    QPoint viewportPos(int index) const { return m_photo->mapFromScene(m_doc->face().point(index)); }

    QImage grabView() const
    {
        QCoreApplication::processEvents(); // pending scene updates
        return m_photo->viewport()->grab().toImage();
    }

    // View pixels at the centres of photo pixels on a grid, left or right of the photo's middle
    // (a margin away from it and from the edges).
    QList<QPoint> samples(bool leftHalf) const
    {
        QList<QPoint> points;
        const int w = fixture::kPhotoSize.width();
        const int h = fixture::kPhotoSize.height();
        for (int y = 8; y < h - 8; y += 9) {
            for (int x = 8; x < w - 8; x += 9) {
                if ((x < w / 2 - 6) != leftHalf || std::abs(x - w / 2) < 6)
                    continue;
                const QPoint v = m_photo->mapFromScene(QPointF(x + 0.5, y + 0.5));
                if (m_photo->viewport()->rect().contains(v))
                    points.append(v);
            }
        }
        return points;
    }

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

    void emptyViewSaysHowToGetAPhoto()
    {
        // Ink across the middle of the empty view: the hint's text.
        Document empty;
        PhotoView view(&empty);
        view.resize(600, 400);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        const QImage image = view.viewport()->grab().toImage();
        const QRgb background = image.pixel(image.width() / 2, 60);
        int ink = 0;
        for (int y = image.height() / 2 - 8; y < image.height() / 2 + 8; ++y)
            for (int x = 40; x < image.width() - 40; ++x)
                ink += image.pixel(x, y) != background ? 1 : 0;
        QVERIFY2(ink > 50, qPrintable(QString::number(ink)));
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
        QVERIFY(m_photo->handle(i)->toolTip().startsWith(QStringLiteral("Tip of the nose")));
    }

    // Each point is named as a user would name it ("Mouth, left corner"), not by the model's ID
    // ("Point 8.4 (mouth)"); no two points share a name.
    void pointsHavePlainNames()
    {
        QCOMPARE(m_photo->handle(pt::idx("8.4"))->toolTip().section(QLatin1Char('\n'), 0, 0),
            QStringLiteral("Mouth, left corner"));
        QSet<QString> names;
        for (int i = 0; i < kPointCount; ++i) {
            const QString name = m_photo->handle(i)->toolTip().section(QLatin1Char('\n'), 0, 0);
            QVERIFY2(!name.contains(pointId(i)) || pointId(i).startsWith(QLatin1String("h.")), qPrintable(name));
            QVERIFY2(!name.contains(QLatin1Char('.')), qPrintable(name));
            QVERIFY2(!name.startsWith(QLatin1String("Point")), qPrintable(name));
            names.insert(name);
        }
        QCOMPARE(names.size(), kPointCount);
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

    void fitModesHideTheScrollBars()
    {
        // init() fitted the photo.
        QCOMPARE(m_photo->horizontalScrollBarPolicy(), Qt::ScrollBarAlwaysOff);
        QCOMPARE(m_photo->verticalScrollBarPolicy(), Qt::ScrollBarAlwaysOff);
        m_photo->zoomIn();
        QCOMPARE(m_photo->fitMode(), PhotoView::Fit::None);
        QCOMPARE(m_photo->horizontalScrollBarPolicy(), Qt::ScrollBarAsNeeded);
        QCOMPARE(m_photo->verticalScrollBarPolicy(), Qt::ScrollBarAsNeeded);
        m_photo->zoomToFace();
        QCOMPARE(m_photo->horizontalScrollBarPolicy(), Qt::ScrollBarAlwaysOff);
        QCOMPARE(m_photo->verticalScrollBarPolicy(), Qt::ScrollBarAlwaysOff);

        // Framing the face at many sizes settles each time: with scroll bars that came and went
        // with the zoom, the fit changed the room it fitted into, and the view resized itself
        // without end. A guard counts the viewport's resizes and breaks such a loop by leaving
        // the fit mode.
        ResizeGuard guard(m_photo);
        m_photo->viewport()->installEventFilter(&guard);
        for (const QRectF &box : {QRectF(60, 60, 280, 380), QRectF(30, 20, 340, 470), QRectF(100, 150, 200, 240)}) {
            m_doc->replaceFace(averageFace(box, fixture::kPhotoSize), false, QStringLiteral("Face"));
            m_photo->zoomToFace();
            for (int h = 300; h <= 700 && !guard.tripped; h += 150) {
                for (int w = 300; w <= 1000 && !guard.tripped; w += 17) {
                    guard.resizes = 0;
                    m_window->resize(w, h);
                    QCoreApplication::processEvents();
                }
            }
            QVERIFY2(!guard.tripped,
                qPrintable(
                    QStringLiteral("the view kept resizing at %1x%2").arg(m_window->width()).arg(m_window->height())));
        }
    }

    void overlayLiesExactlyOverThePhoto_data()
    {
        QTest::addColumn<QSize>("size");
        QTest::newRow("photo's size") << fixture::kPhotoSize;
        QTest::newRow("working size") << fixture::kPhotoSize / 2;
        QTest::newRow("odd size") << QSize(133, 167);
    }

    void overlayLiesExactlyOverThePhoto()
    {
        QFETCH(QSize, size);
        QVERIFY(!m_photo->hasOverlay());
        m_photo->setOverlay(halfRedOverlay(size));
        QVERIFY(m_photo->hasOverlay());
        const QGraphicsPixmapItem *overlay = m_photo->overlayItem();
        QVERIFY(overlay->isVisible());
        const QRectF rect = overlay->sceneBoundingRect();
        const QRectF photo(QPointF(), QSizeF(fixture::kPhotoSize));
        const double tolerance = 1e-9;
        QVERIFY2(std::abs(rect.left() - photo.left()) < tolerance && std::abs(rect.top() - photo.top()) < tolerance
                && std::abs(rect.right() - photo.right()) < tolerance
                && std::abs(rect.bottom() - photo.bottom()) < tolerance,
            qPrintable(QStringLiteral("overlay at %1,%2 %3x%4")
                           .arg(rect.x())
                           .arg(rect.y())
                           .arg(rect.width())
                           .arg(rect.height())));

        // Over the photo, under the outlines and every handle; it takes no clicks.
        const QGraphicsPixmapItem *photoItem = nullptr;
        const QList<QGraphicsItem *> items = m_photo->scene()->items();
        for (const QGraphicsItem *item : items) {
            const auto *pixmap = dynamic_cast<const QGraphicsPixmapItem *>(item);
            if (pixmap && pixmap != overlay)
                photoItem = pixmap;
        }
        QVERIFY(photoItem);
        QVERIFY(overlay->zValue() > photoItem->zValue());
        for (int i = 0; i < kPointCount; ++i)
            QVERIFY(overlay->zValue() < m_photo->handle(i)->zValue());
        QCOMPARE(overlay->acceptedMouseButtons(), Qt::NoButton);

        m_photo->clearOverlay();
        QVERIFY(!m_photo->hasOverlay());
        QVERIFY(!overlay->isVisible());
    }

    void overlayCoversThePhotoWhereOpaque()
    {
        m_photo->setOverlayOpacity(1.0);
        const QImage plain = grabView();
        m_photo->setOverlay(halfRedOverlay(fixture::kPhotoSize));
        QCOMPARE(m_photo->overlayItem()->opacity(), 1.0);
        const QImage covered = grabView();
        QCOMPARE(covered.size(), plain.size());

        // Where the overlay is opaque the view changed (to red, except under outlines and
        // handles, which stay on top); where it is transparent nothing changed.
        const QList<QPoint> opaque = samples(true);
        const QList<QPoint> clear = samples(false);
        QVERIFY(opaque.size() > 200 && clear.size() > 200);
        int changed = 0;
        int red = 0;
        for (const QPoint &p : opaque) {
            changed += plain.pixel(p) != covered.pixel(p);
            red += isPureRed(covered.pixel(p));
        }
        QVERIFY2(
            changed >= opaque.size() * 0.95, qPrintable(QStringLiteral("%1 of %2").arg(changed).arg(opaque.size())));
        QVERIFY2(red >= opaque.size() * 0.8, qPrintable(QStringLiteral("%1 of %2").arg(red).arg(opaque.size())));
        for (const QPoint &p : clear)
            QCOMPARE(covered.pixel(p), plain.pixel(p));

        // At half opacity the photo shows through: halfway between it and red (±3 levels).
        m_photo->setOverlayOpacity(0.5);
        QCOMPARE(m_photo->overlayItem()->opacity(), 0.5);
        const QImage blended = grabView();
        int checked = 0;
        for (const QPoint &p : opaque) {
            if (!isPureRed(covered.pixel(p)))
                continue; // an outline or a handle
            const QRgb under = plain.pixel(p);
            const QRgb mix = blended.pixel(p);
            QVERIFY(std::abs(qRed(mix) - (qRed(under) + 255) / 2) <= 3);
            QVERIFY(std::abs(qGreen(mix) - qGreen(under) / 2) <= 3);
            QVERIFY(std::abs(qBlue(mix) - qBlue(under) / 2) <= 3);
            ++checked;
        }
        QVERIFY(checked > 100);
        m_photo->setOverlayOpacity(2.0);
        QCOMPARE(m_photo->overlayOpacity(), 1.0);
    }

    void dragWorksThroughTheOverlay()
    {
        m_photo->setOverlayOpacity(1.0);
        QImage dark(fixture::kPhotoSize, QImage::Format_RGB32);
        dark.fill(QColor(20, 20, 20));
        m_photo->setOverlay(dark);
        const int i = pt::idx("8.4");
        const QPointF before = m_doc->face().point(i);
        const QPoint by(-20, 10);
        drag(m_photo->viewport(), viewportPos(i), by);
        const QPointF expected = before + QPointF(by) / m_photo->zoom();
        QVERIFY(QLineF(m_doc->face().point(i), expected).length() < 1.5 / m_photo->zoom());
        QVERIFY(m_doc->face().isHandPlaced(i));
        QCOMPARE(m_doc->undoStack()->count(), 1);
        QVERIFY(m_photo->hasOverlay());
    }

    void newPhotoDropsTheOverlay()
    {
        m_photo->setOverlay(halfRedOverlay(fixture::kPhotoSize));
        m_doc->movePoint(pt::idx("2.1"), m_doc->face().point("2.1") + QPointF(0, 5), true);
        m_doc->replaceFace(fixture::face(), false, QStringLiteral("Re-detect"));
        QVERIFY(m_photo->hasOverlay()); // the points changed, not the photo
        fixture::fill(*m_doc);
        QVERIFY(!m_photo->hasOverlay());
        QVERIFY(!m_photo->overlayItem()->isVisible());
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

TOONFACE_TEST_MAIN(TestPhotoView)
#include "tst_photoview.moc"
