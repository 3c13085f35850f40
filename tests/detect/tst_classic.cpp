// The classic pipeline as a whole (detectClassic, and detectFace with the classic method) on drawn
// and real faces; its steps are tested in tst_classiceyes and tst_classicfeatures.

#include "detect/classic.h"
#include "detect/detector.h"
#include "detect/landmarkmap.h"
#include "shareddata.h"
#include "testmain.h"

#include "testphotos.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QPainter>
#include <QRandomGenerator>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <functional>
#include <numbers>

using namespace toonface;

namespace {

// A drawn frontal face on a plain blue background: eyeball centres at (cx -+ 45, 230),
// so d = 90.
struct DrawnFace
{
    QImage image;
    QPointF eyeL {195, 230}, eyeR {285, 230};
    double irisR = 7;
    QRectF browL {172, 196, 46, 8}, browR {262, 196, 46, 8};
    QRectF mouth {205, 338, 70, 14};
    QPointF nostrilL {229, 300}, nostrilR {251, 300};
    QRectF head {130, 110, 220, 300}; // the skin ellipse
    QRectF hair {118, 80, 244, 200}; // the hair ellipse, behind the skin
};

// lightIrises: grey-blue irises with a small pupil, outlined by lash lines that thicken toward
// the outer corners (mascara), as in many photos: the dark points of an eye hold no iris disc.
DrawnFace drawFace(bool lightIrises = false)
{
    DrawnFace f;
    f.image = QImage(480, 480, QImage::Format_RGB32);
    f.image.fill(QColor(150, 180, 230));
    QPainter p(&f.image);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(60, 35, 20));
    p.drawEllipse(f.hair);
    const QColor skin(225, 180, 150);
    p.setBrush(skin);
    p.drawEllipse(QRectF(116, 215, 24, 50)); // ears
    p.drawEllipse(QRectF(340, 215, 24, 50));
    p.drawEllipse(f.head);
    p.setBrush(QColor(245, 245, 240));
    p.setPen(QPen(QColor(60, 40, 30), 2)); // the lash line
    p.drawEllipse(f.eyeL, 19, 8); // eye whites
    p.drawEllipse(f.eyeR, 19, 8);
    p.setPen(Qt::NoPen);
    p.setBrush(lightIrises ? QColor(150, 170, 185) : QColor(30, 20, 15));
    p.drawEllipse(f.eyeL, f.irisR, f.irisR);
    p.drawEllipse(f.eyeR, f.irisR, f.irisR);
    if (lightIrises) {
        p.setBrush(QColor(30, 20, 15));
        p.drawEllipse(f.eyeL, 2.0, 2.0);
        p.drawEllipse(f.eyeR, 2.0, 2.0);
        // The thick outer lash corners: wedges along the upper lids' outer ends.
        for (int side : {-1, 1}) {
            const QPointF e = side < 0 ? f.eyeL : f.eyeR;
            const QPointF tip = e + QPointF(side * 22, -1);
            const QPointF polygon[3] = {tip, e + QPointF(side * 8, -8.5), e + QPointF(side * 12, -4)};
            p.drawPolygon(polygon, 3);
            p.drawEllipse(e + QPointF(side * 16, -4), 4.5, 4.5);
        }
    }
    p.setBrush(QColor(70, 45, 30));
    p.drawRect(f.browL);
    p.drawRect(f.browR);
    p.setBrush(QColor(90, 50, 45));
    p.drawEllipse(f.nostrilL, 5, 3);
    p.drawEllipse(f.nostrilR, 5, 3);
    p.setBrush(QColor(150, 50, 60));
    p.drawEllipse(f.mouth);
    p.end();
    return f;
}

} // namespace

namespace {

using testing::sharedFacesDir;

} // namespace

class TestClassic : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void drawnFace();
    void lightIrises();
    void graceHopper();
    void realPortraits_data();
    void realPortraits();
    void greyAndTiny();
    void throughDetector();
    void noFaceAroundPair();
    void sharedDataNme_data();
    void sharedDataNme();
    void sharedDataNmeWithFaceBox_data();
    void sharedDataNmeWithFaceBox();
};

namespace {

// How far p lies off the ellipse's outline, in units of its semi-axes (0 on it).
double offEllipse(QPointF p, const QRectF &e)
{
    const QPointF c = e.center();
    return std::abs(std::hypot((p.x() - c.x()) / (e.width() / 2), (p.y() - c.y()) / (e.height() / 2)) - 1.0);
}

// x of the skin ellipse's edge at height y (left side).
double ellipseLeftX(const QRectF &e, double y)
{
    const double t = (y - e.center().y()) / (e.height() / 2);
    return e.center().x() - e.width() / 2 * std::sqrt(std::max(0.0, 1 - t * t));
}

} // namespace

// Every group of the drawn face within a stated tolerance: inner features within d/10,
// the contour and ears within d/5, the hair above the ears within 6% of the hair ellipse.
void TestClassic::drawnFace()
{
    const DrawnFace f = drawFace();
    const ClassicResult r = detectClassic(f.image, true);
    QVERIFY2(r.ok, qPrintable(r.error));
    const QString dir = qEnvironmentVariable("TOONFACE_CLASSIC_DEBUG");
    if (!dir.isEmpty()) {
        f.image.save(dir + QStringLiteral("/input.png"));
        for (auto it = r.debugImages.begin(); it != r.debugImages.end(); ++it)
            it.value().save(dir + QLatin1Char('/') + it.key() + QStringLiteral(".png"));
    }
    const double d = 90;
    QVERIFY(std::abs(r.d - d) < 2);
    auto near = [&](const char *id, QPointF expected, double tol) {
        const QPointF got = r.face.point(id);
        const double err = QLineF(got, expected).length();
        if (err > tol)
            qWarning("%s at (%.1f, %.1f), expected (%.1f, %.1f) within %.1f", id, got.x(), got.y(), expected.x(),
                expected.y(), tol);
        return err <= tol;
    };
    const double inner = d / 10, outer = d / 5;
    // Eyes
    QVERIFY(near("3.6", f.eyeL, 2));
    QVERIFY(near("3.5", f.eyeR, 2));
    QVERIFY(near("3.2", f.eyeL - QPointF(0, f.irisR), 2.5));
    QVERIFY(near("3.4", f.eyeL + QPointF(0, f.irisR), 2.5));
    QVERIFY(near("3.1", f.eyeR - QPointF(0, f.irisR), 2.5));
    QVERIFY(near("3.12", f.eyeL - QPointF(20, 0), inner));
    QVERIFY(near("3.8", f.eyeL + QPointF(20, 0), inner));
    QVERIFY(near("3.11", f.eyeR - QPointF(20, 0), inner));
    QVERIFY(near("3.7", f.eyeR + QPointF(20, 0), inner));
    // Brows
    const double browY = f.browL.center().y();
    QVERIFY(near("4.6", QPointF(f.browL.left(), browY), inner));
    QVERIFY(near("4.2", QPointF(f.browL.right(), browY), inner));
    QVERIFY(near("4.5", QPointF(f.browR.right(), browY), inner));
    QVERIFY(near("4.1", QPointF(f.browR.left(), browY), inner));
    for (const char *id : {"4.4a", "4.4", "4.3", "4.3a"})
        QVERIFY(near(id, QPointF(r.face.point(id).x(), browY), inner));
    QVERIFY(r.face.point("4.6").x() < r.face.point("4.4a").x() && r.face.point("4.4a").x() < r.face.point("4.4").x()
        && r.face.point("4.4").x() < r.face.point("4.2").x());
    // Nose: the tip on the midline at the nostrils' bottom, the wings at the nostrils' sides.
    QVERIFY(near("9.15", QPointF(240, f.nostrilL.y() + 3), inner));
    QVERIFY(near("9.2", QPointF(f.nostrilL.x() - 5, r.face.point("9.2").y()), inner));
    QVERIFY(near("9.1", QPointF(f.nostrilR.x() + 5, r.face.point("9.1").y()), inner));
    QVERIFY(std::abs(r.noseCut - 240) <= 1.5);
    // Mouth
    const QPointF mc = f.mouth.center();
    QVERIFY(near("8.4", QPointF(f.mouth.left(), mc.y()), inner));
    QVERIFY(near("8.3", QPointF(f.mouth.right(), mc.y()), inner));
    QVERIFY(near("8.1", QPointF(240, f.mouth.top()), inner));
    QVERIFY(near("8.2", QPointF(240, f.mouth.bottom()), inner));
    QVERIFY(near("2.2", mc, inner));
    QVERIFY(std::abs(r.mouthCut - 240) <= 1.5);
    // Contour
    QVERIFY(near("2.1", QPointF(240, f.head.bottom()), inner));
    QVERIFY(near("11.1", QPointF(240, f.head.top()), inner));
    QVERIFY(near("2.14", QPointF(ellipseLeftX(f.head, r.face.point("2.14").y()), r.face.point("2.14").y()), inner));
    QVERIFY(near("5.2", QPointF(ellipseLeftX(f.head, 230), 230), inner));
    QVERIFY(near("5.1", QPointF(480 - ellipseLeftX(f.head, 230), 230), inner));
    QVERIFY(offEllipse(r.face.point("2.12"), f.head) < 0.05);
    QVERIFY(offEllipse(r.face.point("2.11"), f.head) < 0.05);
    // Ears (drawn 116..140 and 340..364 wide, 215..265 high)
    QVERIFY(near("10.4", QPointF(116, r.face.point("10.4").y()), outer));
    QVERIFY(near("10.3", QPointF(364, r.face.point("10.3").y()), outer));
    QVERIFY(near("10.2", QPointF(r.face.point("10.2").x(), 215), outer));
    QVERIFY(near("10.1", QPointF(r.face.point("10.1").x(), 215), outer));
    // Hair: h.10 on the crown; the arc over the head on the hair ellipse.
    QVERIFY(near("h.10", QPointF(240, f.hair.top()), inner));
    for (int i = 3; i <= 15; ++i) {
        const QPointF h = r.face.point(pt::idx("h.1") + i);
        QVERIFY2(offEllipse(h, f.hair) < 0.06, qPrintable(QStringLiteral("h.%1").arg(i + 1)));
    }
    QVERIFY(r.face.isValid());
}

// Light irises: the eye regions are the lash lines, whose thickest part (the outer corner)
// would hold the largest dark circle; the eyeball centre must still be the eye's middle.
void TestClassic::lightIrises()
{
    const DrawnFace f = drawFace(true);
    const ClassicResult r = detectClassic(f.image, true);
    const QString dir = qEnvironmentVariable("TOONFACE_CLASSIC_DEBUG");
    if (!dir.isEmpty())
        for (auto it = r.debugImages.begin(); it != r.debugImages.end(); ++it)
            it.value().save(dir + QStringLiteral("/light-") + it.key() + QStringLiteral(".png"));
    QVERIFY2(r.ok, qPrintable(r.error));
    qInfo("eyeballs (%.1f, %.1f) r %.1f and (%.1f, %.1f) r %.1f", r.eyeballs[0].centre.x(), r.eyeballs[0].centre.y(),
        r.eyeballs[0].radius, r.eyeballs[1].centre.x(), r.eyeballs[1].centre.y(), r.eyeballs[1].radius);
    // Within a third of the iris' width of the drawn centres, horizontally and vertically.
    QVERIFY(QLineF(r.face.point("3.6"), f.eyeL).length() <= 2 * f.irisR / 3 + 1);
    QVERIFY(QLineF(r.face.point("3.5"), f.eyeR).length() <= 2 * f.irisR / 3 + 1);
    QVERIFY(std::abs(r.d - 90) < 6);
}

// The thesis' assumptions (plain background, frontal light) hold only roughly here; the
// test reports what the pipeline finds and checks the groups are ordered like a face.
void TestClassic::graceHopper()
{
    const QString path = QStringLiteral("/usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg");
    QImage img(path);
    if (img.isNull())
        QSKIP("grace_hopper.jpg is not installed (package python-matplotlib-data)");
    const ClassicResult r = detectClassic(img, true);
    const QString dir = qEnvironmentVariable("TOONFACE_CLASSIC_DEBUG");
    if (!dir.isEmpty())
        for (auto it = r.debugImages.begin(); it != r.debugImages.end(); ++it)
            it.value().save(dir + QStringLiteral("/hopper-") + it.key() + QStringLiteral(".png"));
    QVERIFY2(r.ok, qPrintable(r.error));
    qInfo("grace_hopper: %d eye-pair candidates, eyeballs (%.0f, %.0f) r %.1f and (%.0f, %.0f) r %.1f, d = %.1f, "
          "nose tip (%.0f, %.0f), mouth %.0f..%.0f at y %.0f, chin y %.0f, %.1f ms",
        r.candidateCount, r.eyeballs[0].centre.x(), r.eyeballs[0].centre.y(), r.eyeballs[0].radius,
        r.eyeballs[1].centre.x(), r.eyeballs[1].centre.y(), r.eyeballs[1].radius, r.d, r.face.point("9.15").x(),
        r.face.point("9.15").y(), r.face.point("8.4").x(), r.face.point("8.3").x(), r.face.point("8.4").y(),
        r.face.point("2.1").y(), r.timingMs.value(QStringLiteral("total")));
    const FaceModel &f = r.face;
    QVERIFY(f.isValid());
    QVERIFY(f.point("4.4").y() < f.point("3.6").y());
    QVERIFY(f.point("3.6").y() < f.point("9.15").y());
    QVERIFY(f.point("9.15").y() < f.point("8.2").y());
    QVERIFY(f.point("8.2").y() < f.point("2.1").y());
}

// Public-domain portraits that meet the thesis' assumptions (a large frontal face, a plain or
// simple background, frontal light): every group is found and placed like a face. Where the
// landmark model is installed, its result is the reference for where the eyes are.
void TestClassic::realPortraits_data()
{
    QTest::addColumn<QString>("path");
    QTest::addColumn<QString>("package");
    QTest::newRow("grace_hopper") << QStringLiteral("/usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg")
                                  << QStringLiteral("python-matplotlib-data");
    QTest::newRow("astronaut") << QStringLiteral("/usr/lib/python3/dist-packages/skimage/data/astronaut.png")
                               << QStringLiteral("python3-skimage");
}

void TestClassic::realPortraits()
{
    QFETCH(QString, path);
    QFETCH(QString, package);
    const QImage img(path);
    if (img.isNull())
        QSKIP(qPrintable(QStringLiteral("%1 is not installed (package %2)").arg(path, package)));
    const ClassicResult r = detectClassic(img);
    QVERIFY2(r.ok, qPrintable(r.error));
    QVERIFY(r.eyePairInFace); // found by the face check, not the thesis' fallback
    const FaceModel &f = r.face;
    QVERIFY(f.isValid());
    auto mean = [&](std::initializer_list<const char *> ids) {
        QPointF sum;
        for (const char *id : ids)
            sum += f.point(id);
        return sum / double(ids.size());
    };
    const QPointF brows = mean({"4.6", "4.4a", "4.4", "4.2", "4.5", "4.3a", "4.3", "4.1"});
    const QPointF eyes = mean({"3.6", "3.5"});
    const QPointF nose = mean({"9.2", "9.1", "9.15"});
    const QPointF mouth = mean({"8.4", "8.3", "8.1", "8.2"});
    const QPointF chin = f.point("2.1");
    qInfo("%s: d %.1f, k %.1f, rect (%d, %d), brows y %.0f, eyes y %.0f, nose y %.0f, mouth y %.0f, chin y %.0f",
        qPrintable(QFileInfo(path).fileName()), r.d, r.eyeLevelK, r.centralRect.x(), r.centralRect.y(), brows.y(),
        eyes.y(), nose.y(), mouth.y(), chin.y());
    // Top to bottom; image-left before image-right; all on the face's midline within d/2.
    QVERIFY(brows.y() < eyes.y());
    QVERIFY(eyes.y() < nose.y());
    QVERIFY(nose.y() < mouth.y());
    QVERIFY(mouth.y() < chin.y());
    QVERIFY(f.point("3.6").x() < f.point("3.5").x());
    QVERIFY(f.point("4.6").x() < f.point("4.5").x());
    QVERIFY(f.point("8.4").x() < f.point("8.3").x());
    QVERIFY(f.point("9.2").x() < f.point("9.1").x());
    for (const QPointF &p : {brows, nose, mouth, chin})
        QVERIFY(std::abs(p.x() - eyes.x()) < r.d / 2);
    // Proportions of a face: the mouth about d below the eyes (the thesis' Div_NM).
    QVERIFY(mouth.y() - eyes.y() > 0.6 * r.d && mouth.y() - eyes.y() < 1.6 * r.d);

    if (!preloadLandmarkModel())
        return;
    const DetectionResult ref = detectFace(img, {});
    QCOMPARE(ref.status, DetectStatus::Ok);
    const double refD = QLineF(ref.face.point("3.6"), ref.face.point("3.5")).length();
    for (const char *id : {"3.6", "3.5", "9.15", "2.2"})
        QVERIFY2(ref.faceBox.contains(f.point(id).toPoint()), id);
    // Eyeball centres within a fifth of the eye distance of the landmark method's.
    QVERIFY(QLineF(f.point("3.6"), ref.face.point("3.6")).length() < 0.2 * refD);
    QVERIFY(QLineF(f.point("3.5"), ref.face.point("3.5")).length() < 0.2 * refD);
}

// A grey photo has no hue, so no face region from eq. (3.9): the inner features are still
// found and the outline falls back to its rules. A tiny image is refused with a reason.
void TestClassic::greyAndTiny()
{
    const DrawnFace f = drawFace();
    const ClassicResult r = detectClassic(f.image.convertToFormat(QImage::Format_Grayscale8));
    QVERIFY2(r.ok, qPrintable(r.error));
    QVERIFY(r.face.isValid());
    QVERIFY(QLineF(r.face.point("3.6"), f.eyeL).length() <= 2);
    QVERIFY(QLineF(r.face.point("3.5"), f.eyeR).length() <= 2);
    QVERIFY(QLineF(r.face.point("8.4"), QPointF(f.mouth.left(), f.mouth.center().y())).length() <= 9);
    for (int i = 0; i < kPointCount; ++i)
        QVERIFY2(QRectF(0, 0, 480, 480).contains(r.face.point(i)), qPrintable(pointId(i)));

    for (const QSize size : {QSize(1, 1), QSize(15, 200)}) {
        QImage tiny(size, QImage::Format_RGB32);
        tiny.fill(Qt::gray);
        const ClassicResult t = detectClassic(tiny);
        QVERIFY(!t.ok);
        QVERIFY(t.error.contains(QLatin1String("too small")));
    }
}

// detectFace(method classic) gives the pipeline's points and writes the thesis' figures.
void TestClassic::throughDetector()
{
    const DrawnFace f = drawFace();
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    DetectOptions options;
    options.method = DetectionMethod::Classic;
    options.debugDir = dir.filePath(QStringLiteral("debug"));
    const DetectionResult r = detectFace(f.image, options);
    QCOMPARE(r.status, DetectStatus::Ok);
    QCOMPARE(r.method, QStringLiteral("classic"));
    QCOMPARE(r.faceCount, 1);
    QVERIFY(QLineF(r.face.point("3.6"), f.eyeL).length() < 2);
    QVERIFY(r.faceBox.contains(f.mouth.center().toPoint()));
    QVERIFY(r.timingMs.contains(QStringLiteral("total")));
    QCOMPARE(r.groupConfidence.size(), 7);
    for (const char *name : {"classic-b1", "classic-b2", "classic-b3", "classic-face-hair", "classic-eye-pairs",
             "classic-eyeballs", "classic-edges", "classic-feature-regions", "classic-points"}) {
        const QImage img(QDir(options.debugDir).filePath(QLatin1StringView(name) + QStringLiteral(".png")));
        QVERIFY2(img.size() == f.image.size(), name);
    }
}

// Two dark blobs on a plain wall pair as eyes by eq. (3.5), but nothing around them is a face:
// the pipeline keeps the thesis' choice and says it failed the face checks; the detector
// refuses it with those checks named, as the classic method and as auto's last resort.
void TestClassic::noFaceAroundPair()
{
    const QImage wall = testing::darkPairOnAWall();
    const ClassicResult c = detectClassic(wall);
    QVERIFY2(c.ok, qPrintable(c.error));
    QVERIFY(!c.eyePairInFace);
    QVERIFY(QLineF(c.eyeballs[0].centre, QPointF(190, 200)).length() < 3);
    QVERIFY2(c.faceCheck.contains(QLatin1String("(190, 200) and (290, 200)")), qPrintable(c.faceCheck));
    QVERIFY2(c.faceCheck.contains(QLatin1String("no mouth row")), qPrintable(c.faceCheck));

    for (DetectionMethod m : {DetectionMethod::Classic, DetectionMethod::Auto}) {
        DetectOptions options;
        options.method = m;
        const DetectionResult r = detectFace(wall, options);
        QCOMPARE(r.status, DetectStatus::NoFace);
        if (m == DetectionMethod::Classic)
            QCOMPARE(r.error, QStringLiteral("The classic method found no face: %1.").arg(c.faceCheck));
        QVERIFY(!r.face.isValid());
    }

    // The drawn face passes the checks and is a face through the detector.
    const ClassicResult drawn = detectClassic(drawFace().image);
    QVERIFY(drawn.eyePairInFace);
    QVERIFY(drawn.faceCheck.isEmpty());
}

void TestClassic::sharedDataNme_data()
{
    QTest::addColumn<QString>("image");
    QTest::addColumn<QString>("pts");
    QTest::addColumn<double>("bound");
    // Measured bounds (NME 0.101 and 0.087 when set) for the photos that meet the thesis'
    // assumptions: a frontal face over the middle of the picture on a plain background.
    // lfpw 0003 (the face in the top third over a bare chest of the same hue, light eyes) and
    // einstein (grey, a small face off-centre in a busy scene) do not: measured only.
    const QMap<QString, double> bounds {
        {QStringLiteral("lfpw_trainset_image_0001"), 0.15}, {QStringLiteral("lfpw_trainset_image_0002"), 0.15}};
    const QDir dir(sharedFacesDir());
    int rows = 0;
    for (const QFileInfo &pts : dir.entryInfoList({QStringLiteral("*.pts")}, QDir::Files, QDir::Name)) {
        for (const char *ext : {".png", ".jpg"}) {
            const QString image = dir.filePath(pts.completeBaseName() + QLatin1String(ext));
            if (QFileInfo::exists(image)) {
                QTest::newRow(qPrintable(pts.completeBaseName()))
                    << image << pts.filePath() << bounds.value(pts.completeBaseName(), -1.0);
                ++rows;
                break;
            }
        }
    }
    if (rows == 0)
        QTest::newRow("no data") << QString() << QString() << -1.0;
}

// A photo with a bound must be found within it; the others must either place a valid face or
// say why not.
void TestClassic::sharedDataNme()
{
    QFETCH(QString, image);
    QFETCH(QString, pts);
    QFETCH(double, bound);
    if (image.isEmpty())
        QSKIP("no research photos (set TOONFACE_DATA_DIR to the shared data folder)");
    std::array<QPointF, kIbugPointCount> truth {};
    QVERIFY2(readIbugPts(pts, &truth), qPrintable(pts));
    const QImage photo(image);
    QVERIFY2(!photo.isNull(), qPrintable(image));
    const ClassicResult r = detectClassic(photo, true);
    const QString dir = qEnvironmentVariable("TOONFACE_CLASSIC_DEBUG");
    if (!dir.isEmpty())
        for (auto it = r.debugImages.begin(); it != r.debugImages.end(); ++it)
            it.value().save(dir + QLatin1Char('/') + QFileInfo(image).completeBaseName() + QLatin1Char('-') + it.key()
                + QStringLiteral(".png"));
    if (!r.ok) {
        QVERIFY(!r.error.isEmpty());
        qInfo("%s: classic found no face: %s", qPrintable(QFileInfo(image).fileName()), qPrintable(r.error));
        QVERIFY2(bound < 0, "a photo that meets the thesis' assumptions must be found");
        return;
    }
    QVERIFY(r.face.isValid());
    const double nme = normalizedMeanError(r.face, truth);
    QVERIFY(std::isfinite(nme));
    qInfo("%s: classic NME %.4f (bound %s), %.1f ms%s", qPrintable(QFileInfo(image).fileName()), nme,
        bound < 0 ? "none" : qPrintable(QString::number(bound)), r.timingMs.value(QStringLiteral("total")),
        r.eyePairInFace ? "" : qPrintable(QStringLiteral("; the detector refuses it: ") + r.faceCheck));
    // A pair that failed the face checks is not a face for the detector: the check must say why.
    QCOMPARE(r.faceCheck.isEmpty(), r.eyePairInFace);
    if (bound >= 0) {
        QVERIFY2(nme <= bound, qPrintable(QStringLiteral("NME %1 > %2").arg(nme).arg(bound)));
        QVERIFY(r.eyePairInFace);
    }
}

// The same, with the central rectangle taken from the landmark detector's face box.
void TestClassic::sharedDataNmeWithFaceBox_data()
{
    sharedDataNme_data();
}

void TestClassic::sharedDataNmeWithFaceBox()
{
    QFETCH(QString, image);
    QFETCH(QString, pts);
    QFETCH(double, bound);
    Q_UNUSED(bound); // measured only: the face box moves the central rectangle off the thesis' own
    if (image.isEmpty())
        QSKIP("no research photos (set TOONFACE_DATA_DIR to the shared data folder)");
    if (!preloadLandmarkModel())
        QSKIP("the landmark model (libdlib-data) is not installed; no face box to seed with");
    std::array<QPointF, kIbugPointCount> truth {};
    QVERIFY2(readIbugPts(pts, &truth), qPrintable(pts));
    const QImage photo(image);
    QVERIFY2(!photo.isNull(), qPrintable(image));
    const DetectionResult box = detectFace(photo, {});
    QCOMPARE(box.status, DetectStatus::Ok);
    const ClassicResult r = detectClassic(photo, true, box.faceBox);
    const QString dir = qEnvironmentVariable("TOONFACE_CLASSIC_DEBUG");
    if (!dir.isEmpty())
        for (auto it = r.debugImages.begin(); it != r.debugImages.end(); ++it)
            it.value().save(dir + QLatin1Char('/') + QFileInfo(image).completeBaseName() + QStringLiteral("-boxed-")
                + it.key() + QStringLiteral(".png"));
    if (!r.ok) {
        QVERIFY(!r.error.isEmpty());
        qInfo("%s: classic in the face box found no face: %s", qPrintable(QFileInfo(image).fileName()),
            qPrintable(r.error));
        return;
    }
    QVERIFY(r.face.isValid());
    const double nme = normalizedMeanError(r.face, truth);
    QVERIFY(std::isfinite(nme));
    qInfo("%s: classic in the face box NME %.4f (landmarks %.4f), %.1f ms", qPrintable(QFileInfo(image).fileName()),
        nme, normalizedMeanError(box.face, truth), r.timingMs.value(QStringLiteral("total")));
}

TOONFACE_TEST_MAIN(TestClassic)
#include "tst_classic.moc"
