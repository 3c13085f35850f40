#include "detect/detector.h"
#include "detect/hairoutline.h"
#include "detect/headparse.h"
#include "drawnface.h"
#include "face/pointtable.h"
#include "testmain.h"

#include <QLineF>
#include <QPainter>
#include <QPainterPath>
#include <QPolygonF>
#include <QTest>

#include <algorithm>
#include <string_view>
#include <tuple>

using namespace toonface;
using testing::DrawnFaceOptions;

namespace {

enum class Hairdo { Short, Long, Fringe, TiedBack, Curly };

double es0Of(const FaceModel &face)
{
    return QLineF(face.point("3.6"), face.point("3.5")).length();
}

QPolygonF outlineOf(const FaceModel &face)
{
    QPolygonF p;
    for (int k = 0; k < 19; ++k)
        p << face.point(pt::idx("h.1") + k);
    return p;
}

// The drawn head's hair: the average face's outline changed as a hairdresser would. The photo is
// drawn from these points (drawnFace), the outline is looked for starting from the average's.
FaceModel styled(Hairdo kind)
{
    FaceModel face = testing::drawnFaceModel();
    const double es0 = es0Of(face);
    const QPointF centre = (face.point("5.2") + face.point("5.1")) / 2.0;
    const double chin = face.point("2.1").y();
    auto scale = [&](double sx, double sy) {
        for (int k = 0; k < 19; ++k) {
            const int i = pt::idx("h.1") + k;
            const QPointF v = face.point(i) - centre;
            face.setPoint(i, centre + QPointF(v.x() * sx, v.y() * (v.y() < 0 ? sy : 1.0)));
        }
    };
    switch (kind) {
    case Hairdo::Short: break;
    case Hairdo::Long: {
        // A curtain down beside the face to the shoulders: from h.5 (h.15) the outer edge falls
        // straight down, a third of ES0 outward, to 1.2 ES0 below the chin (h.2, h.18); the curtain's
        // bottom runs in from there to under the jaw's corner (h.1, h.19), and its inner edge up
        // to the jaw (the drawing closes the hair at 2.14, 2.13).
        for (const auto &[top, step, jaw] :
            {std::tuple(pt::idx("h.5"), -1, "2.14"), std::tuple(pt::idx("h.15"), 1, "2.13")}) {
            const double side = face.point(top).x() < centre.x() ? -1.0 : 1.0;
            const double x = face.point(top).x() + side * 0.3 * es0;
            for (int k = 1; k <= 3; ++k)
                face.setPoint(top + step * k, QPointF(x, chin + (1.5 * k / 3.0 - 0.3) * es0));
            face.setPoint(top + step * 4, QPointF(face.point(jaw).x(), chin + 1.2 * es0));
        }
        break;
    }
    case Hairdo::Fringe: {
        // The hairline, where the face's skin ends, a third of the eyes' distance over the brows;
        // the temples lower in proportion.
        double brows = face.point("4.1").y();
        for (const char *id : {"4.6", "4.4a", "4.4", "4.2", "4.1", "4.3", "4.3a", "4.5"})
            brows = std::min(brows, face.point(id).y());
        const double eyes = (face.point("3.6").y() + face.point("3.5").y()) / 2.0;
        const double k = (eyes - (brows - 0.3 * es0)) / (eyes - face.point("11.1").y());
        for (const char *id : {"11.1", "11.2", "11.3"})
            face.setPoint(pt::idx(id), QPointF(face.point(id).x(), eyes - (eyes - face.point(id).y()) * k));
        break;
    }
    case Hairdo::TiedBack:
        // Pulled back close to the skull: narrower and flatter, ending above the ears.
        scale(0.9, 0.92);
        for (const int i : {pt::idx("h.1"), pt::idx("h.19")})
            face.setPoint(i, (face.point(i) + face.point(i == pt::idx("h.1") ? "h.2" : "h.18")) / 2.0);
        break;
    case Hairdo::Curly:
        // A wide, voluminous head of curls.
        scale(1.45, 1.25);
        break;
    }
    return face;
}

// The head as drawn from a face's points (drawnFace): the hair's shape, closed under the jaw
// (2.13, 2.14), with the face's.
QPainterPath headOf(const FaceModel &face)
{
    QPolygonF hair = outlineOf(face);
    hair << face.point("2.13") << face.point("2.14");
    QPolygonF skin;
    for (const char *id : {"11.2", "11.1", "11.3", "5.1", "2.13", "2.11", "2.1", "2.12", "2.14", "5.2"})
        skin << face.point(id);
    QPainterPath a, b;
    a.addPolygon(hair);
    a.closeSubpath();
    b.addPolygon(skin);
    b.closeSubpath();
    return a.united(b).simplified();
}

// The distance from p to the nearest edge of a closed polygon.
double distanceToEdge(QPointF p, const QPolygonF &polygon)
{
    double nearest = 1e9;
    for (int j = 0; j < polygon.size(); ++j) {
        const QLineF seg(polygon[j], polygon[(j + 1) % polygon.size()]);
        const double len2 = std::max(1e-9, seg.dx() * seg.dx() + seg.dy() * seg.dy());
        const QPointF v = p - seg.p1();
        const double t = std::clamp((v.x() * seg.dx() + v.y() * seg.dy()) / len2, 0.0, 1.0);
        nearest = std::min(nearest, QLineF(p, seg.pointAt(t)).length());
    }
    return nearest;
}

// The share of the two shapes' areas in common.
double overlap(const QPainterPath &a, const QPainterPath &b, QSize size)
{
    auto mask = [&](const QPainterPath &p) {
        QImage m(size, QImage::Format_Grayscale8);
        m.fill(0);
        QPainter painter(&m);
        painter.setPen(Qt::NoPen);
        painter.setBrush(Qt::white);
        painter.drawPath(p);
        return m;
    };
    const QImage ma = mask(a), mb = mask(b);
    long both = 0, either = 0;
    for (int y = 0; y < size.height(); ++y) {
        const uchar *ra = ma.constScanLine(y), *rb = mb.constScanLine(y);
        for (int x = 0; x < size.width(); ++x) {
            both += ra[x] && rb[x];
            either += ra[x] || rb[x];
        }
    }
    return either > 0 ? double(both) / double(either) : 0.0;
}

// The skins and hair colours the drawn heads are painted in.
const QColor kLight(240, 205, 185), kMedium(196, 140, 105);
const QColor kBrown(70, 48, 34), kBlond(200, 165, 95), kBlack(25, 22, 22);

// A drawn photo of a head (styled()), in these colours.
QImage photoOf(const FaceModel &drawn, QColor skin, QColor hair)
{
    DrawnFaceOptions o;
    o.skin = skin;
    o.hair = hair;
    return testing::drawnFace(o, drawn);
}

} // namespace

class TestHairOutline : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void followsTheDrawnHair_data()
    {
        QTest::addColumn<int>("kind");
        QTest::addColumn<QColor>("skin");
        QTest::addColumn<QColor>("hair");
        QTest::newRow("short, brown") << int(Hairdo::Short) << kLight << kBrown;
        QTest::newRow("long, brown") << int(Hairdo::Long) << kLight << kBrown;
        QTest::newRow("curly, blond") << int(Hairdo::Curly) << kLight << kBlond;
        QTest::newRow("long, black") << int(Hairdo::Long) << kMedium << kBlack;
        QTest::newRow("fringe") << int(Hairdo::Fringe) << kLight << kBrown;
        QTest::newRow("tied back") << int(Hairdo::TiedBack) << kLight << kBrown;
        QTest::newRow("tied back, black") << int(Hairdo::TiedBack) << kMedium << kBlack;
        QTest::newRow("curly, wide") << int(Hairdo::Curly) << kLight << kBrown;
        QTest::newRow("curly, black") << int(Hairdo::Curly) << kMedium << kBlack;
    }

    // Starting from the average head's outline (what the search gives where it sees nothing),
    // the outline from the parse lies on the drawn hair's edge: every point within a sixth of the
    // eye distance of it, the two outlines' areas nearly the same, the ends as low as the drawn
    // ones (long hair at the shoulders, tied-back hair above the ears).
    void followsTheDrawnHair()
    {
        QFETCH(int, kind);
        QFETCH(QColor, skin);
        QFETCH(QColor, hair);
        const FaceModel drawn = styled(Hairdo(kind));
        const QImage photo = photoOf(drawn, skin, hair);
        FaceModel face = testing::drawnFaceModel();
        const double es0 = es0Of(face);
        const HeadParse parse = parseHead(photo, face);
        QVERIFY(parse.valid && parse.hairSeen);
        QVERIFY(hairSilhouette(parse).valid());
        outlineHairFromParse(&face, parse);
        const QPainterPath want = headOf(drawn), got = headOf(face);
        const QPolygonF edge = want.toFillPolygon();
        QString all;
        for (int k = 0; k < 19; ++k) {
            const QPointF q = face.point(pt::idx("h.1") + k);
            all += QStringLiteral(" (%1,%2)").arg(q.x(), 0, 'f', 0).arg(q.y(), 0, 'f', 0);
        }
        for (int k = 0; k < 19; ++k) {
            const double off = distanceToEdge(face.point(pt::idx("h.1") + k), edge);
            QVERIFY2(off < es0 / 6,
                qPrintable(QStringLiteral("h.%1 lies %2 ES0 from the drawn head's edge;%3")
                               .arg(k + 1)
                               .arg(off / es0, 0, 'f', 2)
                               .arg(all)));
        }
        // (Compared down to the chin: below it the drawing closes long hair under the jaw, the
        // outline at the curtain's outer edge; how far the hair falls is checked at its ends.)
        const double chin = face.point("2.1").y();
        QPainterPath aboveChin;
        aboveChin.addRect(QRectF(0, 0, photo.width(), chin));
        const double iou = overlap(want.intersected(aboveChin), got.intersected(aboveChin), photo.size());
        QVERIFY2(iou > 0.92, qPrintable(QStringLiteral("overlap %1;%2").arg(iou, 0, 'f', 3).arg(all)));
        // Long hair falls to the curtain's bottom (1.2 ES0 below the chin); other hair stops at
        // the jaw's corners at most.
        for (const char *end : {"h.1", "h.19"}) {
            const double y = face.point(end).y();
            if (Hairdo(kind) == Hairdo::Long)
                QVERIFY2(std::abs(y - (chin + 1.2 * es0)) < 0.25 * es0,
                    qPrintable(QStringLiteral("%1 at %2, chin at %3").arg(QLatin1StringView(end)).arg(y).arg(chin)));
            else
                QVERIFY2(y < std::max(face.point("2.14").y(), face.point("2.13").y()) + 0.1 * es0,
                    qPrintable(QStringLiteral("%1 at %2, jaw at %3")
                                   .arg(QLatin1StringView(end))
                                   .arg(y)
                                   .arg(face.point("2.14").y())));
        }
    }

    // Long hair tucked behind the ears: beside the temples, from the brows down to the eyes, the
    // ears (skin) hide it; below them it falls to the shoulders. The outline still falls with it.
    void longHairBehindTheEars()
    {
        const FaceModel drawn = styled(Hairdo::Long);
        QImage photo = testing::drawnFace({}, drawn);
        const double es0 = es0Of(drawn);
        {
            QPainter p(&photo);
            p.setPen(Qt::NoPen);
            p.setBrush(DrawnFaceOptions().skin);
            const double top = drawn.point("4.1").y(), bottom = drawn.point("3.5").y() - 0.05 * es0;
            for (const char *id : {"5.2", "5.1"}) {
                const double x = drawn.point(id).x();
                const double outward = x < drawn.point("9.15").x() ? -1.0 : 1.0;
                p.drawRect(QRectF(QPointF(std::min(x, x + outward * 0.45 * es0), top),
                    QPointF(std::max(x, x + outward * 0.45 * es0), bottom)));
            }
        }
        FaceModel face = testing::drawnFaceModel();
        outlineHairFromParse(&face, parseHead(photo, face));
        const double chin = face.point("2.1").y();
        for (const char *end : {"h.1", "h.19"})
            QVERIFY2(face.point(end).y() > chin + 0.8 * es0,
                qPrintable(QStringLiteral("%1 at %2, chin at %3")
                               .arg(QLatin1StringView(end))
                               .arg(face.point(end).y())
                               .arg(chin)));
    }

    // A beard of the hair's colour along the jaw and dark clothes under it do not make short
    // hair fall: the outline's ends stay above the jaw's corners.
    void beardIsNotAFall()
    {
        DrawnFaceOptions o;
        o.beard = true;
        o.beardColour = o.hair;
        const FaceModel drawn = styled(Hairdo::Short);
        QImage photo = testing::drawnFace(o, drawn);
        {
            QPainter p(&photo);
            p.setPen(Qt::NoPen);
            p.setBrush(o.hair);
            const double below = drawn.point("2.1").y() + 0.1 * es0Of(drawn);
            p.drawRect(QRectF(0, below, photo.width(), photo.height() - below));
        }
        FaceModel face = testing::drawnFaceModel();
        const double es0 = es0Of(face);
        outlineHairFromParse(&face, parseHead(photo, face));
        const double jaw = std::max(face.point("2.14").y(), face.point("2.13").y());
        for (const char *end : {"h.1", "h.19"})
            QVERIFY2(face.point(end).y() < jaw + 0.1 * es0,
                qPrintable(QStringLiteral("%1 at %2, jaw at %3")
                               .arg(QLatin1StringView(end))
                               .arg(face.point(end).y())
                               .arg(jaw)));
    }

    // A fringe: the hairline moves down to where the drawn forehead's skin ends, the temples
    // with it; on the plain head it stays where the drawn hairline is.
    void hairlineOnTheFringe_data()
    {
        QTest::addColumn<int>("kind");
        QTest::newRow("fringe") << int(Hairdo::Fringe);
        QTest::newRow("short") << int(Hairdo::Short);
    }
    void hairlineOnTheFringe()
    {
        QFETCH(int, kind);
        const FaceModel drawn = styled(Hairdo(kind));
        const QImage photo = testing::drawnFace({}, drawn);
        FaceModel face = testing::drawnFaceModel();
        const double es0 = es0Of(face);
        placeHairlineFromParse(&face, parseHead(photo, face));
        for (const char *id : {"11.1", "11.2", "11.3"})
            QVERIFY2(std::abs(face.point(id).y() - drawn.point(id).y()) < 0.12 * es0,
                qPrintable(QStringLiteral("%1 at %2, drawn at %3")
                               .arg(QLatin1StringView(id))
                               .arg(face.point(id).y())
                               .arg(drawn.point(id).y())));
    }

    // A bald head keeps its hairline (nothing to draw it from).
    void baldKeepsTheHairline()
    {
        DrawnFaceOptions o;
        o.bald = true;
        const FaceModel drawn = testing::drawnFaceModel();
        FaceModel face = drawn;
        QVERIFY(!placeHairlineFromParse(&face, parseHead(testing::drawnFace(o, drawn), face)));
        QCOMPARE(face.point("11.1"), drawn.point("11.1"));
    }

    // Points the user placed stay.
    void handPlacedPointsStay()
    {
        const FaceModel drawn = styled(Hairdo::Curly);
        const QImage photo = testing::drawnFace({}, drawn);
        FaceModel face = testing::drawnFaceModel();
        const QPointF crown = face.point("h.10");
        face.setPoint(pt::idx("h.10"), crown, true);
        face.setPoint(pt::idx("11.1"), face.point("11.1"), true);
        const QPointF hairline = face.point("11.1");
        const HeadParse parse = parseHead(photo, face);
        QVERIFY(outlineHairFromParse(&face, parse));
        placeHairlineFromParse(&face, parse);
        QCOMPARE(face.point("h.10"), crown);
        QCOMPARE(face.point("11.1"), hairline);
    }

    // A tight crop that cuts the crown off (the forehead's skin runs to the photo's top edge), as
    // the face-crop photos are: the hair beside the face is seen, so the outline follows it from
    // the edge down (long hair to the shoulders, wide curls as wide as they are, tied-back hair
    // close to the head), not the search's dome; above the edge, where the photo shows nothing,
    // the search's points stay.
    void cutCrownFollowsTheSides_data()
    {
        QTest::addColumn<int>("kind");
        QTest::addColumn<QColor>("skin");
        QTest::addColumn<QColor>("hair");
        // (Brown long hair on a light skin is left out: the crop's parse loses the image-left
        // curtain, which the whole head's parse follows, and that side ends at the eyes.)
        QTest::newRow("long, black") << int(Hairdo::Long) << kLight << kBlack;
        QTest::newRow("long, black, medium skin") << int(Hairdo::Long) << kMedium << kBlack;
        QTest::newRow("short") << int(Hairdo::Short) << kLight << kBrown;
        QTest::newRow("tied back") << int(Hairdo::TiedBack) << kLight << kBlack;
    }
    void cutCrownFollowsTheSides()
    {
        QFETCH(int, kind);
        QFETCH(QColor, skin);
        QFETCH(QColor, hair);
        const FaceModel drawn = styled(Hairdo(kind));
        const QImage whole = photoOf(drawn, skin, hair);
        const double es0 = es0Of(drawn);
        const int top = int(drawn.point("4.1").y() - 0.6 * es0);
        const QImage cropped = whole.copy(0, top, whole.width(), whole.height() - top);
        FaceModel face = testing::drawnFaceModel();
        face.setImageSize(cropped.size());
        FaceModel want = drawn;
        want.setImageSize(cropped.size());
        for (int i = 0; i < kPointCount; ++i) {
            face.setPoint(i, testing::drawnFaceModel().point(i) - QPointF(0, top), false);
            want.setPoint(i, drawn.point(i) - QPointF(0, top), false);
        }
        const FaceModel before = face;
        const HeadParse parse = parseHead(cropped, face);
        QVERIFY(parse.valid && parse.crownCut && parse.templeHairSeen);
        QVERIFY(hairSilhouette(parse).valid());
        outlineHairFromParse(&face, parse);
        // Seen: every point below the edge lies on the drawn head's edge (as close as where the
        // whole head is seen, followsTheDrawnHair); unseen: the search's points above it stay.
        const QPolygonF edge = headOf(want).toFillPolygon();
        const double margin = 0.15 * es0;
        int seen = 0;
        for (int k = 0; k < 19; ++k) {
            const int i = pt::idx("h.1") + k;
            if (before.point(i).y() < 0) {
                if (face.point(i).y() < 0)
                    QCOMPARE(face.point(i), before.point(i));
                continue;
            }
            if (face.point(i).y() < margin)
                continue; // (on the edge: where the crop cuts the head, not the head's edge)
            ++seen;
            const double off = distanceToEdge(face.point(i), edge);
            QVERIFY2(off < es0 / 6,
                qPrintable(QStringLiteral("h.%1 lies %2 ES0 from the drawn head's edge")
                               .arg(k + 1)
                               .arg(off / es0, 0, 'f', 2)));
        }
        QVERIFY2(seen >= 6, qPrintable(QStringLiteral("%1 points below the edge").arg(seen)));
        // The drawn hair against the painted hair from the edge to the chin: at least 0.88, below
        // the whole head's bound (0.92, followsTheDrawnHair) since the crown above the edge stays
        // the search's, which the crop cannot correct; long hair above the search's outline.
        const double chin = want.point("2.1").y();
        QPainterPath visible;
        visible.addRect(QRectF(0, 0, cropped.width(), chin));
        const double iou
            = overlap(headOf(want).intersected(visible), headOf(face).intersected(visible), cropped.size());
        const double searched
            = overlap(headOf(want).intersected(visible), headOf(before).intersected(visible), cropped.size());
        QVERIFY2(iou > (Hairdo(kind) == Hairdo::Long ? std::max(0.88, searched) : 0.88),
            qPrintable(QStringLiteral("overlap %1, the search's %2").arg(iou, 0, 'f', 3).arg(searched, 0, 'f', 3)));
        if (Hairdo(kind) == Hairdo::Long)
            for (const char *end : {"h.1", "h.19"})
                QVERIFY2(face.point(end).y() > chin + 0.8 * es0,
                    qPrintable(QStringLiteral("%1 at %2, chin at %3")
                                   .arg(QLatin1StringView(end))
                                   .arg(face.point(end).y())
                                   .arg(chin)));
    }

    // The detector reads the outline from the parse (refineFace): a head found by detectFace
    // (the classic method, which finds drawn faces) has the drawn hair's outline, a wide head of
    // curls as wide as it is and long hair down to its ends, not the search's estimate.
    void detectorDrawsTheParsedOutline_data()
    {
        QTest::addColumn<int>("kind");
        QTest::newRow("curly, wide") << int(Hairdo::Curly);
        QTest::newRow("long") << int(Hairdo::Long);
        QTest::newRow("short") << int(Hairdo::Short);
    }
    void detectorDrawsTheParsedOutline()
    {
        QFETCH(int, kind);
        const FaceModel drawn = styled(Hairdo(kind));
        const QImage photo = testing::drawnFace({}, drawn);
        DetectOptions options;
        options.method = DetectionMethod::Classic;
        const DetectionResult r = detectFace(photo, options);
        QCOMPARE(r.status, DetectStatus::Ok);
        const FaceModel &face = r.face;
        const double es0 = es0Of(drawn);
        const QPolygonF edge = headOf(drawn).toFillPolygon();
        for (int k = 0; k < 19; ++k) {
            const double off = distanceToEdge(face.point(pt::idx("h.1") + k), edge);
            QVERIFY2(off < es0 / 4,
                qPrintable(QStringLiteral("h.%1 lies %2 ES0 from the drawn head's edge")
                               .arg(k + 1)
                               .arg(off / es0, 0, 'f', 2)));
        }
        const double chin = drawn.point("2.1").y();
        QPainterPath aboveChin;
        aboveChin.addRect(QRectF(0, 0, photo.width(), chin));
        const double iou
            = overlap(headOf(drawn).intersected(aboveChin), headOf(face).intersected(aboveChin), photo.size());
        QVERIFY2(iou > 0.9, qPrintable(QStringLiteral("overlap %1").arg(iou, 0, 'f', 3)));
    }

    void invalidInput()
    {
        FaceModel face = testing::drawnFaceModel();
        const FaceModel before = face;
        QVERIFY(!hairSilhouette(HeadParse()).valid());
        QVERIFY(!outlineHairFromParse(&face, HeadParse()));
        QVERIFY(!placeHairlineFromParse(&face, HeadParse()));
        for (int i = 0; i < kPointCount; ++i)
            QCOMPARE(face.point(i), before.point(i));
    }
};

TOONFACE_TEST_MAIN(TestHairOutline)
#include "tst_hairoutline.moc"
