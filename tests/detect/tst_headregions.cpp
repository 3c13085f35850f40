#include "detect/headregions.h"
#include "detect/landmarkmap.h"
#include "syntheticlandmarks.h"
#include "testmain.h"

#include <QPainter>
#include <QTest>

#include <cmath>

using namespace toonface;
using toonface::testing::syntheticLandmarks;

namespace {

enum class Hair { Short, Long, LongApart, Bald, LightHat, DarkHat };

const QColor kSkin(225, 180, 150);
const QColor kHair(60, 40, 25);
const QColor kLightBack(170, 200, 235);

// A drawn head around synthetic landmarks, in the face frame of headGeometry(): a face ellipse
// from the hairline to the chin, ears sticking out of the cheeks by 0.3 eye distances, dark
// eyes, brows and mouth, and the hair of `style`:
//  Short: the hair ellipse (1.15 times the geometric one) above the eye line only;
//  Long: the hair ellipse and, beside the face, hair falling to 3 d below the eyes;
//  LongApart: the same falling to 4 d, and below the jaw parted from the neck by a strip of
//  background 0.35 d wide (a collar, or the background seen between neck and hair);
//  Bald: a skin-coloured skull (0.95 times the geometric ellipse);
//  LightHat / DarkHat: short hair under a hat that covers the head from 0.3 d above the
//  hairline up (a light grey and a dark red one).
struct Scene
{
    QImage image;
    FaceModel geometric;
    HeadGeometry g;
    double d = 0;
    double earOuterL = 0, earOuterR = 0; // face-frame x of the drawn ears' outer edges
    double hairBottom = 0; // face-frame y where long hair ends
    double hatBottom = 0; // face-frame y of the hat's lower edge
    double skullTop = 0; // face-frame y of the top of the drawn head (hair or skull)
};

Scene drawScene(Hair style, QColor background = kLightBack)
{
    Scene s;
    const QSize size(700, 720);
    const auto ibug = syntheticLandmarks(QTransform().translate(230, 200).scale(240, 240));
    s.geometric = faceFromLandmarks68(ibug, size);
    s.g = headGeometry(s.geometric);
    const HeadGeometry &g = s.g;
    const double d = s.d = g.eyeDistance;
    auto L = [&](const char *id) { return g.toLocal(s.geometric.point(id)); };

    s.image = QImage(size, QImage::Format_RGB32);
    s.image.fill(background);
    QPainter p(&s.image);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(Qt::NoPen);
    p.setTransform(QTransform(g.ex.x(), g.ex.y(), g.ey.x(), g.ey.y(), g.origin.x(), g.origin.y()));
    const double ax = 1.15 * g.hairAx, ay = 1.1 * g.hairAy;
    s.skullTop = g.hairCentre.y() - ay;
    if (style == Hair::Bald) {
        p.setBrush(kSkin);
        p.drawEllipse(g.hairCentre, 0.95 * g.hairAx, 0.95 * g.hairAy);
        s.skullTop = g.hairCentre.y() - 0.95 * g.hairAy;
    } else {
        p.setBrush(kHair);
        p.save();
        if (style != Hair::Long && style != Hair::LongApart)
            p.setClipRect(QRectF(g.hairCentre.x() - 2 * ax, g.hairCentre.y() - 2 * ay, 4 * ax, 2 * ay + 0.2 * d));
        p.drawEllipse(g.hairCentre, ax, ay);
        p.restore();
        if (style == Hair::Long || style == Hair::LongApart) {
            s.hairBottom = (style == Hair::Long ? 3.0 : 4.0) * d;
            p.drawRect(QRectF(g.hairCentre.x() - ax, 0, 2 * ax, s.hairBottom));
        }
    }
    const double hairlineY = 0.8 * g.hairlineY;
    if (style == Hair::LightHat || style == Hair::DarkHat) {
        s.hatBottom = hairlineY - 0.3 * d;
        p.setBrush(style == Hair::LightHat ? QColor(235, 235, 235) : QColor(120, 15, 20));
        p.save();
        p.setClipRect(QRectF(g.hairCentre.x() - 2 * ax, g.hairCentre.y() - 3 * ay, 4 * ax, s.hatBottom + 3 * ay));
        p.drawEllipse(g.hairCentre, 1.1 * ax, 1.1 * ay);
        p.restore();
    }

    p.setBrush(kSkin);
    const double chinY = L("2.1").y();
    const double halfW = (L("5.1").x() - L("5.2").x()) / 2;
    p.drawEllipse(QPointF(g.hairCentre.x(), (hairlineY + chinY) / 2), halfW, (chinY - hairlineY) / 2);
    if (style == Hair::LongApart) {
        p.setBrush(background);
        const double jawY = L("2.12").y();
        p.drawRect(QRectF(g.midX - 0.45 * halfW - 0.35 * d, jawY, 0.9 * halfW + 0.7 * d, s.hairBottom + d - jawY));
        p.setBrush(kSkin);
    }
    // The neck, so that the face region goes on below the chin as in a photo.
    p.drawRect(QRectF(g.midX - 0.45 * halfW, chinY - 0.3 * d, 0.9 * halfW, 1.5 * d));
    const double earY = (g.browY + g.noseBaseY) / 2, earRy = (g.noseBaseY - g.browY) / 2;
    const double earOut = 0.3, earRx = (earOut + 0.15) * d / 2;
    s.earOuterL = L("5.2").x() - earOut * d;
    s.earOuterR = L("5.1").x() + earOut * d;
    p.drawEllipse(QPointF(s.earOuterL + earRx, earY), earRx, earRy);
    p.drawEllipse(QPointF(s.earOuterR - earRx, earY), earRx, earRy);

    const QColor dark(35, 25, 20);
    p.setBrush(dark);
    p.drawEllipse(L("3.6"), 0.15 * d, 0.1 * d);
    p.drawEllipse(L("3.5"), 0.15 * d, 0.1 * d);
    p.setPen(QPen(dark, 0.07 * d, Qt::SolidLine, Qt::RoundCap));
    p.drawLine(L("4.6"), L("4.2"));
    p.drawLine(L("4.1"), L("4.5"));
    p.setPen(QPen(QColor(150, 60, 60), 0.08 * d, Qt::SolidLine, Qt::RoundCap));
    p.drawLine(L("8.4"), L("8.3"));
    p.end();
    return s;
}

// True when `p` lies within `tol` of the boundary between `background`-coloured pixels and
// the rest: both kinds occur in the disc of radius tol around it.
bool onSilhouette(const QImage &image, QPointF p, double tol, QColor background)
{
    bool in = false, out = false;
    for (double dy = -tol; dy <= tol; dy += 1)
        for (double dx = -tol; dx <= tol; dx += 1) {
            if (dx * dx + dy * dy > tol * tol)
                continue;
            const QPoint q = (p + QPointF(dx, dy)).toPoint();
            if (!image.rect().contains(q))
                continue;
            const QColor c = image.pixelColor(q);
            const int diff = std::abs(c.red() - background.red()) + std::abs(c.green() - background.green())
                + std::abs(c.blue() - background.blue());
            (diff > 40 ? in : out) = true;
        }
    return in && out;
}

} // namespace

Q_DECLARE_METATYPE(Hair)

class TestHeadRegions : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void hairOutline_data();
    void hairOutline();
    void hatIsNotHair_data();
    void hatIsNotHair();
    void ears();
    void skinColouredBackground();
    void darkBackground();
    void seedMeasured();
};

void TestHeadRegions::hairOutline_data()
{
    QTest::addColumn<Hair>("style");
    QTest::newRow("short") << Hair::Short;
    QTest::newRow("long") << Hair::Long;
    QTest::newRow("long, parted from the neck") << Hair::LongApart;
    QTest::newRow("bald") << Hair::Bald;
}

// Every hair point lies on the drawn head's outline (hair, or skull and ears where there is no
// hair) within 0.1 d; h.10 at its top; long hair takes the outline's ends down to where the
// hair ends (within 0.15 d), short hair and a bald head keep them above the nose.
void TestHeadRegions::hairOutline()
{
    QFETCH(Hair, style);
    const Scene s = drawScene(style);
    FaceModel face = s.geometric;
    const HeadRegionReport r = refineFromRegions(&face, s.image);
    QVERIFY2(r.hairUsable, qPrintable(r.hairProblem));
    const double d = s.d;
    for (int i = 0; i < 19; ++i) {
        const QPointF p = face.point(i);
        QVERIFY2(onSilhouette(s.image, p, 0.1 * d, kLightBack),
            qPrintable(QStringLiteral("%1 at %2, %3 (face frame)")
                           .arg(pointId(i))
                           .arg(s.g.toLocal(p).x() / d)
                           .arg(s.g.toLocal(p).y() / d)));
    }
    QCOMPARE_LE(std::abs(s.g.toLocal(face.point("h.10")).y() - s.skullTop), 0.1 * d);
    QCOMPARE_LE(std::abs(s.g.toLocal(face.point("h.10")).x() - s.g.midX), 0.1 * d);
    const double endL = s.g.toLocal(face.point("h.1")).y(), endR = s.g.toLocal(face.point("h.19")).y();
    QCOMPARE(r.longHair, style == Hair::Long || style == Hair::LongApart);
    if (r.longHair) {
        QCOMPARE_LE(std::abs(endL - s.hairBottom), 0.15 * d);
        QCOMPARE_LE(std::abs(endR - s.hairBottom), 0.15 * d);
    } else {
        QCOMPARE_LT(endL, s.g.noseBaseY);
        QCOMPARE_LT(endR, s.g.noseBaseY);
    }
    // Measured points are not moved.
    for (int i = 0; i < kPointCount; ++i) {
        const PointGroup grp = pointTable()[i].group;
        if (grp != PointGroup::Hair && grp != PointGroup::Ears)
            QVERIFY2(face.point(i) == s.geometric.point(i), qPrintable(pointId(i)));
    }
}

void TestHeadRegions::hatIsNotHair_data()
{
    QTest::addColumn<Hair>("style");
    QTest::newRow("light hat") << Hair::LightHat;
    QTest::newRow("dark red hat") << Hair::DarkHat;
}

// A hat of another colour than the hair is not hair: the crown of the outline stays at the
// hat's lower edge (within 0.1 d), not on the hat's top.
void TestHeadRegions::hatIsNotHair()
{
    QFETCH(Hair, style);
    const Scene s = drawScene(style);
    FaceModel face = s.geometric;
    const HeadRegionReport r = refineFromRegions(&face, s.image);
    QVERIFY2(r.hairUsable, qPrintable(r.hairProblem));
    for (const char *id : {"h.8", "h.10", "h.12"})
        QCOMPARE_LE(std::abs(s.g.toLocal(face.point(id)).y() - s.hatBottom), 0.1 * s.d);
}

// The ears are the face region's bulges beside the cheeks: the outermost points on the drawn
// ears' outer edges within 0.1 d, their tops above their lobes, beside the cheeks between
// the brows and the mouth; with short and with long hair behind them.
void TestHeadRegions::ears()
{
    for (Hair style : {Hair::Short, Hair::Long}) {
        const Scene s = drawScene(style);
        FaceModel face = s.geometric;
        const HeadRegionReport r = refineFromRegions(&face, s.image);
        QVERIFY(r.earUsable[0] && r.earUsable[1]);
        const HeadGeometry &g = s.g;
        QCOMPARE_LE(std::abs(g.toLocal(face.point("10.4")).x() - s.earOuterL), 0.1 * s.d);
        QCOMPARE_LE(std::abs(g.toLocal(face.point("10.3")).x() - s.earOuterR), 0.1 * s.d);
        QCOMPARE_LT(g.toLocal(face.point("10.2")).y(), g.toLocal(face.point("10.6")).y());
        QCOMPARE_LT(g.toLocal(face.point("10.1")).y(), g.toLocal(face.point("10.5")).y());
        const double mouthY = g.toLocal(face.point("8.4")).y();
        for (const char *id : {"10.2", "10.4", "10.6", "10.10", "10.1", "10.3", "10.5", "10.9"}) {
            const double y = g.toLocal(face.point(id)).y();
            QVERIFY2(y > g.browY - 0.3 * s.d && y < mouthY, id);
        }
    }
}

// A background of skin colour merges with the face region: neither hair nor ears can be
// told, and the points keep the estimate they came with.
void TestHeadRegions::skinColouredBackground()
{
    const Scene s = drawScene(Hair::Bald, kSkin);
    FaceModel face = s.geometric;
    const HeadRegionReport r = refineFromRegions(&face, s.image);
    QVERIFY(!r.hairUsable);
    QVERIFY(!r.hairProblem.isEmpty());
    QVERIFY(!r.earUsable[0] && !r.earUsable[1]);
    QVERIFY(face == s.geometric);
}

// A dark background merges with the hair: the outline cannot be followed and keeps its
// estimate; the ears, skin against dark, are still found.
void TestHeadRegions::darkBackground()
{
    const Scene s = drawScene(Hair::Short, QColor(20, 20, 25));
    FaceModel face = s.geometric;
    const HeadRegionReport r = refineFromRegions(&face, s.image);
    QVERIFY(!r.hairUsable);
    for (int i = 0; i < 19; ++i)
        QCOMPARE(face.point(i), s.geometric.point(i));
    QVERIFY(r.earUsable[0] && r.earUsable[1]);
}

// The reserved thresholds: t1 = m1 - s1 below the skin's intensity and above the features';
// the skin's hue within s2 of m2; the skin and hair colours as drawn (within 12 levels).
void TestHeadRegions::seedMeasured()
{
    const Scene s = drawScene(Hair::Short);
    FaceModel face = s.geometric;
    const HeadRegionReport r = refineFromRegions(&face, s.image);
    QVERIFY(r.seed.valid);
    QCOMPARE(r.seed.t1, r.seed.m1 - r.seed.s1);
    const double skinI = (kSkin.red() + kSkin.green() + kSkin.blue()) / 3.0;
    QCOMPARE_LT(r.seed.t1, skinI);
    QCOMPARE_GT(r.seed.t1, 35.0);
    QVERIFY(r.seed.rect.contains(face.point("3.6")) && r.seed.rect.contains(face.point("9.15")));
    QVERIFY(r.seed.skin.samples > 100);
    QCOMPARE_LE(std::abs(r.seed.skin.r - kSkin.red()), 12.0);
    QCOMPARE_LE(std::abs(r.seed.skin.g - kSkin.green()), 12.0);
    QCOMPARE_LE(std::abs(r.seed.skin.b - kSkin.blue()), 12.0);
    QVERIFY(r.seed.hair.samples > 0);
    QCOMPARE_LE(std::abs(r.seed.hair.r - kHair.red()), 12.0);
    QCOMPARE_LE(std::abs(r.seed.hair.g - kHair.green()), 12.0);
    QCOMPARE_LE(std::abs(r.seed.hair.b - kHair.blue()), 12.0);
    QVERIFY(r.seed.s2 >= 4.0);
}

TOONFACE_TEST_GUILESS_MAIN(TestHeadRegions)
#include "tst_headregions.moc"
