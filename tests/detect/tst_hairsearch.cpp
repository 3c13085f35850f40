#include "detect/hairsearch.h"
#include "detect/landmarkmap.h"
#include "syntheticlandmarks.h"
#include "testmain.h"

#include <QPainter>
#include <QTest>

#include <cmath>

using namespace toonface;
using toonface::testing::syntheticLandmarks;

Q_DECLARE_METATYPE(QTransform)

namespace {

// A drawn head around synthetic landmarks: background, a hair ellipse `hairScale` times the
// geometric one, a skin-coloured face ellipse from `hairlineFactor` times the geometric
// hairline height down to the chin, and two skin-coloured ears sticking out of the cheeks
// by `earOut` eye distances.
struct Scene
{
    QImage image;
    FaceModel geometric;
    HeadGeometry g;
    double drawnHairlineY = 0;
    double earOuterL = 0, earOuterR = 0; // face-frame x of the ears' outer edges
};

Scene drawScene(const QTransform &placement, double hairScale, double hairlineFactor, double earOut)
{
    Scene s;
    const QSize size(700, 700);
    const auto ibug = syntheticLandmarks(placement);
    s.geometric = faceFromLandmarks68(ibug, size);
    s.g = headGeometry(s.geometric);
    const HeadGeometry &g = s.g;
    const double d = g.eyeDistance;
    auto L = [&](const char *id) { return g.toLocal(s.geometric.point(id)); };

    s.image = QImage(size, QImage::Format_RGB32);
    s.image.fill(QColor(170, 200, 235));
    QPainter p(&s.image);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(Qt::NoPen);
    p.setTransform(QTransform(g.ex.x(), g.ex.y(), g.ey.x(), g.ey.y(), g.origin.x(), g.origin.y()));
    p.setBrush(QColor(60, 40, 25));
    p.drawEllipse(g.hairCentre, hairScale * g.hairAx, hairScale * g.hairAy);

    const QColor skin(225, 180, 150);
    p.setBrush(skin);
    const double chinY = L("2.1").y();
    s.drawnHairlineY = hairlineFactor * g.hairlineY;
    const double halfW = (L("5.1").x() - L("5.2").x()) / 2;
    p.drawEllipse(QPointF(g.hairCentre.x(), (s.drawnHairlineY + chinY) / 2), halfW, (chinY - s.drawnHairlineY) / 2);
    const double earY = (g.browY + g.noseBaseY) / 2, earRy = (g.noseBaseY - g.browY) / 2;
    const double earRx = (earOut + 0.15) * d / 2;
    s.earOuterL = L("5.2").x() - earOut * d;
    s.earOuterR = L("5.1").x() + earOut * d;
    p.drawEllipse(QPointF(s.earOuterL + earRx, earY), earRx, earRy);
    p.drawEllipse(QPointF(s.earOuterR - earRx, earY), earRx, earRy);
    p.end();
    return s;
}

double hairRatio(const HeadGeometry &g, const FaceModel &face, int i)
{
    const QPointF centre = g.hairCentre;
    return QLineF(centre, g.toLocal(face.point(i))).length() / QLineF(centre, g.hairPoint(i)).length();
}

} // namespace

class TestHairSearch : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void drawnHead_data();
    void drawnHead();
    void noContrastKeepsEstimate();
    void measuredPointsUntouched();
};

void TestHairSearch::drawnHead_data()
{
    QTest::addColumn<QTransform>("placement");
    QTest::addColumn<double>("hairScale");
    QTest::newRow("upright, big hair") << QTransform().translate(230, 250).scale(240, 240) << 1.25;
    QTest::newRow("upright, tight hair") << QTransform().translate(230, 250).scale(240, 240) << 0.9;
    QTest::newRow("tilted 12deg") << QTransform().translate(260, 230).rotate(12).scale(220, 220) << 1.2;
    QTest::newRow("small face") << QTransform().translate(300, 320).scale(90, 90) << 1.2;
}

// The refined outline follows the drawn head (hair, or ears and face where they stick out of
// it), the forehead line the drawn skin's top, the
// ears the drawn ears: each within a tenth of the eye distance.
void TestHairSearch::drawnHead()
{
    QFETCH(QTransform, placement);
    QFETCH(double, hairScale);
    const Scene s = drawScene(placement, hairScale, 0.8, 0.3);
    FaceModel face = s.geometric;
    HairSearchReport report;
    refineFromPhoto(&face, s.image, &report);
    const HeadGeometry &g = s.g;
    const double d = g.eyeDistance;

    // The drawn head's outline along each ray, found by walking in from outside until the
    // first pixel that is not background (the head is star-shaped about the hair centre).
    const QPointF centre = g.toImage(g.hairCentre);
    const QColor back = s.image.pixelColor(0, 0);
    auto drawnRadius = [&](int i) {
        const QPointF dir = g.toImage(g.hairPoint(i)) - centre;
        const double len = std::hypot(dir.x(), dir.y());
        for (double r = 2 * len; r > 0; r -= 0.5) {
            const QPoint p = (centre + dir * (r / len)).toPoint();
            if (!s.image.rect().contains(p))
                continue;
            const QColor c = s.image.pixelColor(p);
            if (std::abs(c.red() - back.red()) + std::abs(c.green() - back.green()) + std::abs(c.blue() - back.blue())
                > 40)
                return r;
        }
        return 0.0;
    };
    int close = 0;
    for (int i = 0; i < 19; ++i) {
        const double got = QLineF(centre, face.point(i)).length();
        if (std::abs(got - drawnRadius(i)) < 0.1 * d)
            ++close;
        else
            qDebug("%s off by %.2f d", qPrintable(pointId(i)), (got - drawnRadius(i)) / d);
    }
    QVERIFY2(close >= 17, qPrintable(QStringLiteral("%1 of 19 hair points on the drawn outline").arg(close)));
    QVERIFY(report.hairFraction >= 15.0 / 19.0);
    QCOMPARE(report.rays.size(), size_t(19));

    QCOMPARE_LE(std::abs(g.toLocal(face.point("11.1")).y() - s.drawnHairlineY), 0.1 * d);
    QVERIFY(g.toLocal(face.point("11.2")).y() < g.browY && g.toLocal(face.point("11.3")).y() < g.browY);

    QCOMPARE(report.earFraction, 1.0);
    QCOMPARE_LE(std::abs(g.toLocal(face.point("10.4")).x() - s.earOuterL), 0.1 * d);
    QCOMPARE_LE(std::abs(g.toLocal(face.point("10.3")).x() - s.earOuterR), 0.1 * d);
    QVERIFY(g.toLocal(face.point("10.2")).y() < g.toLocal(face.point("10.6")).y());
    QVERIFY(g.toLocal(face.point("10.1")).y() < g.toLocal(face.point("10.5")).y());
}

// A photo without contrast cannot move the estimate: the forehead and ears stay, and the hair
// outline stays within a tenth of the geometric one.
void TestHairSearch::noContrastKeepsEstimate()
{
    const auto ibug = syntheticLandmarks(QTransform().translate(230, 250).scale(240, 240));
    QImage grey(700, 700, QImage::Format_RGB32);
    grey.fill(QColor(128, 128, 128));
    const FaceModel geometric = faceFromLandmarks68(ibug, grey.size());
    FaceModel face = geometric;
    HairSearchReport report;
    refineFromPhoto(&face, grey, &report);
    const HeadGeometry g = headGeometry(geometric);
    for (int i = 0; i < 19; ++i)
        QVERIFY2(std::abs(hairRatio(g, face, i) - 1.0) <= 0.1, qPrintable(pointId(i)));
    QCOMPARE(report.earFraction, 0.0);
    for (const char *id : {"11.1", "11.2", "11.3", "10.2", "10.4", "10.6", "10.10", "10.1", "10.3", "10.5", "10.9"})
        QCOMPARE(face.point(id), geometric.point(id));
}

void TestHairSearch::measuredPointsUntouched()
{
    const Scene s = drawScene(QTransform().translate(230, 250).scale(240, 240), 1.2, 0.8, 0.3);
    FaceModel face = s.geometric;
    refineFromPhoto(&face, s.image);
    for (int i = 0; i < kPointCount; ++i) {
        const PointGroup grp = pointTable()[i].group;
        const QString id = pointId(i);
        if (grp == PointGroup::Hair || grp == PointGroup::Ears || id.startsWith(QLatin1String("11.")))
            continue;
        QVERIFY2(face.point(i) == s.geometric.point(i), qPrintable(id));
    }
}

TOONFACE_TEST_GUILESS_MAIN(TestHairSearch)
#include "tst_hairsearch.moc"
