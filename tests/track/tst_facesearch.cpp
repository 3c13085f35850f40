#include "talkingface.h"
#include "testmain.h"
#include "track/facesearch.h"

#include <QFileInfo>
#include <QLineF>
#include <QPainter>
#include <QTest>

using namespace toonface;

namespace {

const QString kPortrait = QStringLiteral("/usr/lib/python3/dist-packages/skimage/data/astronaut.png");

} // namespace

// FaceSearch finds a face's neutral look again anywhere in a frame and at another size, and
// finds nothing like it where there is no face.
class TestFaceSearch : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void findsTheFaceMovedAndResized_data()
    {
        QTest::addColumn<double>("size");
        QTest::addColumn<QPointF>("at"); // where the face's look is put, in look widths
        QTest::newRow("as it was") << 1.0 << QPointF(0.5, 0.4);
        QTest::newRow("moved right and down") << 1.0 << QPointF(2.6, 1.3);
        QTest::newRow("nearer") << 1.2 << QPointF(1.9, 0.2);
        QTest::newRow("further") << 0.85 << QPointF(0.1, 1.5);
    }

    void findsTheFaceMovedAndResized()
    {
        QFETCH(double, size);
        QFETCH(QPointF, at);
        if (!QFileInfo::exists(kPortrait))
            QSKIP("astronaut.png is not installed (package python3-skimage)");
        const testing::TalkingFace talking {QImage(kPortrait)};
        QVERIFY(talking.isValid());
        const QImage portrait = talking.frame(0, 1);
        const QPointF l = talking.face().point("3.6"), r = talking.face().point("3.5");
        const double d = QLineF(l, r).length();
        const QPointF mid = (l + r) / 2;
        const QRectF look(mid.x() - 0.8 * d, mid.y() - 0.35 * d, 1.6 * d, 1.7 * d);
        const FaceSearch search(portrait, look);
        QVERIFY(search.isValid());

        // The head (twice the look's size around it) on a plain backdrop four looks wide.
        const QRectF head
            = look.adjusted(-0.5 * look.width(), -0.5 * look.height(), 0.5 * look.width(), 0.5 * look.height());
        QImage frame(QSize(int(4 * look.width()), int(3 * look.height())), QImage::Format_RGB32);
        frame.fill(QColor(120, 130, 110));
        const QPointF lookAt = at * look.width();
        const QRectF target(lookAt - (look.topLeft() - head.topLeft()) * size, head.size() * size);
        QPainter(&frame).drawImage(target, portrait, head);

        const FaceSearchHit hit = search.find(frame);
        QVERIFY2(hit.likeness > 0.8, qPrintable(QString::number(hit.likeness)));
        const QRectF expected(lookAt, look.size() * size);
        QVERIFY2(QLineF(hit.box.center(), expected.center()).length() < 0.1 * d * size,
            qPrintable(QStringLiteral("found at (%1, %2), put at (%3, %4)")
                           .arg(hit.box.center().x())
                           .arg(hit.box.center().y())
                           .arg(expected.center().x())
                           .arg(expected.center().y())));
        QVERIFY2(
            std::abs(hit.box.width() / expected.width() - 1.0) < 0.1, qPrintable(QString::number(hit.box.width())));
    }

    // The best place at each size the search tries, smallest first, each box that size of the
    // look; the best of them is find()'s answer (the classic tracker checks the eyes at each).
    void eachSizeHasItsPlace()
    {
        if (!QFileInfo::exists(kPortrait))
            QSKIP("astronaut.png is not installed (package python3-skimage)");
        const testing::TalkingFace talking {QImage(kPortrait)};
        QVERIFY(talking.isValid());
        const QImage portrait = talking.frame(0, 1);
        const QPointF l = talking.face().point("3.6"), r = talking.face().point("3.5");
        const double d = QLineF(l, r).length();
        const QPointF mid = (l + r) / 2;
        const QRectF look(mid.x() - 0.8 * d, mid.y() - 0.35 * d, 1.6 * d, 1.7 * d);
        const FaceSearch search(portrait, look);
        const std::vector<FaceSearchHit> hits = search.findEachSize(portrait);
        QCOMPARE(hits.size(), size_t(5));
        const FaceSearchHit best = search.find(portrait);
        double widest = 0, top = -1;
        for (const FaceSearchHit &hit : hits) {
            QVERIFY(hit.box.width() > widest);
            widest = hit.box.width();
            top = std::max(top, hit.likeness);
        }
        QCOMPARE(best.likeness, top);
        QVERIFY2(std::abs(hits.front().box.width() / look.width() - 0.8) < 0.05,
            qPrintable(QString::number(hits.front().box.width())));
        QVERIFY2(std::abs(hits.back().box.width() / look.width() - 1.25) < 0.05,
            qPrintable(QString::number(hits.back().box.width())));
        // A frame only as large as the look holds no larger size.
        const QImage tight = portrait.copy(look.toAlignedRect());
        QVERIFY(search.findEachSize(tight).size() < hits.size());
        QVERIFY(search.findEachSize(QImage()).empty());
    }

    void findsNoFaceInAWall()
    {
        if (!QFileInfo::exists(kPortrait))
            QSKIP("astronaut.png is not installed (package python3-skimage)");
        const testing::TalkingFace talking {QImage(kPortrait)};
        QVERIFY(talking.isValid());
        const QPointF l = talking.face().point("3.6"), r = talking.face().point("3.5");
        const double d = QLineF(l, r).length();
        const QPointF mid = (l + r) / 2;
        const FaceSearch search(talking.frame(0, 1), QRectF(mid.x() - 0.8 * d, mid.y() - 0.35 * d, 1.6 * d, 1.7 * d));
        QImage wall(400, 300, QImage::Format_RGB32);
        for (int y = 0; y < wall.height(); ++y)
            for (int x = 0; x < wall.width(); ++x)
                wall.setPixelColor(x, y, ((x / 9 + y / 13) % 3) ? QColor(80, 70, 60) : QColor(200, 190, 170));
        QVERIFY(search.find(wall).likeness < 0.5);
        QImage plain(400, 300, QImage::Format_RGB32);
        plain.fill(Qt::gray);
        QVERIFY(search.find(plain).likeness < 0.5);
    }

    void badInputFindsNothing()
    {
        QImage small(40, 30, QImage::Format_RGB32);
        small.fill(Qt::white);
        // A look outside its frame, or too small to compare, is no look.
        QVERIFY(!FaceSearch(small, QRectF(30, 20, 40, 40)).isValid());
        QVERIFY(!FaceSearch(small, QRectF(0, 0, 4, 4)).isValid());
        QVERIFY(!FaceSearch(QImage(), QRectF(0, 0, 20, 20)).isValid());
        const FaceSearch search(small, QRectF(0, 0, 30, 24));
        QVERIFY(search.isValid());
        // A frame smaller than the face at every size: no place.
        const FaceSearchHit hit = search.find(QImage(10, 10, QImage::Format_RGB32));
        QVERIFY(hit.box.isEmpty());
        QCOMPARE(hit.likeness, 0.0);
        QCOMPARE(search.find(QImage()).likeness, 0.0);
    }
};

TOONFACE_TEST_MAIN(TestFaceSearch)
#include "tst_facesearch.moc"
