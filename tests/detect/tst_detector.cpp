#include "detect/classic.h"
#include "detect/detector.h"
#include "detect/landmarkmap.h"
#include "shareddata.h"
#include "testmain.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QPainter>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <atomic>
#include <cmath>
#include <thread>

using namespace toonface;

namespace {

const QString kGracePath = QStringLiteral("/usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg");

QImage grace()
{
    return QImage(kGracePath);
}

using testing::sharedFacesDir;

// Restores an environment variable when the test ends, even when it fails.
class EnvGuard
{
public:
    explicit EnvGuard(const char *name)
        : m_name(name)
        , m_had(qEnvironmentVariableIsSet(name))
        , m_old(qgetenv(name))
    { }
    ~EnvGuard()
    {
        if (m_had)
            qputenv(m_name, m_old);
        else
            qunsetenv(m_name);
    }

private:
    const char *m_name;
    bool m_had;
    QByteArray m_old;
};

} // namespace

class TestDetector : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void methodNames();
    void classicWithoutFace();
    void nullImageIsBad();
    void noFace_data();
    void noFace();
    void graceHopper();
    void imageFormats_data();
    void imageFormats();
    void progressAndTimings();
    void twoFacesLargerChosen_data();
    void twoFacesLargerChosen();
    void twoFacesVeryDifferentSizes();
    void faceOfEverySize_data();
    void faceOfEverySize();
    void cancelBeforeStart();
    void cancelDuringDetection();
    void missingModel();
    void debugImages();
    void concurrentCalls();
    void sharedDataNme_data();
    void sharedDataNme();
    void photoGroupsPlausible_data();
    void photoGroupsPlausible();
    void resultHasRegions();
};

void TestDetector::initTestCase()
{
    QString error;
    double ms = -1;
    if (!preloadLandmarkModel(&error, &ms))
        QSKIP(qPrintable(QStringLiteral("landmark model unavailable: %1").arg(error)));
    QVERIFY(ms >= 0);
}

void TestDetector::methodNames()
{
    for (DetectionMethod m : {DetectionMethod::Auto, DetectionMethod::Classic, DetectionMethod::Landmarks}) {
        DetectionMethod back = DetectionMethod::Auto;
        QVERIFY(detectionMethodFromName(detectionMethodName(m), &back));
        QCOMPARE(back, m);
    }
    QCOMPARE(detectionMethodName(DetectionMethod::Landmarks), QStringLiteral("landmarks"));
    DetectionMethod m = DetectionMethod::Landmarks;
    QVERIFY(!detectionMethodFromName(QStringLiteral("neural"), &m));
    QCOMPARE(m, DetectionMethod::Landmarks);
}

// A blank image has no eye pair: the classic method says so (its drawn-face tests are in
// tst_classic).
void TestDetector::classicWithoutFace()
{
    DetectOptions options;
    options.method = DetectionMethod::Classic;
    QImage blank(64, 64, QImage::Format_RGB32);
    blank.fill(Qt::white);
    const DetectionResult r = detectFace(blank, options);
    QCOMPARE(r.status, DetectStatus::NoFace);
    QVERIFY(r.error.contains(QLatin1String("eye pair")));
    QCOMPARE(r.method, QStringLiteral("classic"));
}

void TestDetector::nullImageIsBad()
{
    const DetectionResult r = detectFace(QImage());
    QCOMPARE(r.status, DetectStatus::BadImage);
    QVERIFY(!r.error.isEmpty());
}

void TestDetector::noFace_data()
{
    QTest::addColumn<QImage>("image");
    QImage blank(640, 480, QImage::Format_RGB32);
    blank.fill(QColor(128, 128, 128));
    QTest::newRow("blank 640x480") << blank;
    QImage one(1, 1, QImage::Format_RGB32);
    one.fill(Qt::white);
    QTest::newRow("1x1") << one;
    QImage thin(2000, 3, QImage::Format_Grayscale8);
    thin.fill(0);
    QTest::newRow("2000x3") << thin;
    QImage noise(320, 240, QImage::Format_Grayscale8);
    for (int y = 0; y < noise.height(); ++y)
        for (int x = 0; x < noise.width(); ++x)
            noise.setPixel(x, y, uint((x * 7919 + y * 104729) % 251));
    QTest::newRow("pattern 320x240") << noise;
}

void TestDetector::noFace()
{
    QFETCH(QImage, image);
    const DetectionResult r = detectFace(image);
    QCOMPARE(r.status, DetectStatus::NoFace);
    QCOMPARE(r.faceCount, 0);
    QVERIFY(r.error.contains(QStringLiteral("%1 x %2").arg(image.width()).arg(image.height())));
}

void TestDetector::graceHopper()
{
    const QImage image = grace();
    if (image.isNull())
        QSKIP("grace_hopper.jpg is not installed (package python-matplotlib-data)");
    const DetectionResult r = detectFace(image);
    QCOMPARE(r.status, DetectStatus::Ok);
    QVERIFY(r.error.isEmpty());
    QCOMPARE(r.method, QStringLiteral("landmarks"));
    QCOMPARE(r.faceCount, 1);
    const FaceModel &f = r.face;
    QCOMPARE(f.imageSize(), image.size());
    QVERIFY(f.isValid());
    for (int i = 0; i < kPointCount; ++i) {
        const QPointF p = f.point(i);
        QVERIFY2(std::isfinite(p.x()) && std::isfinite(p.y()), qPrintable(pointId(i)));
        QVERIFY2(p.x() >= 0 && p.y() >= 0 && p.x() < image.width() && p.y() < image.height(), qPrintable(pointId(i)));
    }
    QVERIFY(r.faceBox.contains(f.point("3.6").toPoint()) && r.faceBox.contains(f.point("3.5").toPoint()));

    // Top to bottom: hair top, forehead, brows, eyes, nose tip, mouth, chin.
    auto Y = [&](const char *id) { return f.point(id).y(); };
    QVERIFY(Y("h.10") < Y("11.1"));
    QVERIFY(Y("11.1") < std::min(Y("4.4"), Y("4.3")));
    QVERIFY(std::max(Y("4.4"), Y("4.3")) < std::min(Y("3.2"), Y("3.1")));
    QVERIFY(std::max(Y("3.4"), Y("3.3")) < Y("9.15"));
    QVERIFY(Y("9.15") < Y("8.1"));
    QVERIFY(Y("8.1") < Y("2.2") && Y("2.2") <= Y("2.3") && Y("2.3") < Y("8.2"));
    QVERIFY(Y("8.2") < Y("2.1"));
    // Left to right (the portrait is frontal and upright).
    auto X = [&](const char *id) { return f.point(id).x(); };
    QVERIFY(X("5.2") < X("3.12") && X("3.12") < X("3.6") && X("3.6") < X("3.8") && X("3.8") < X("3.11"));
    QVERIFY(X("3.11") < X("3.5") && X("3.5") < X("3.7") && X("3.7") < X("5.1"));
    QVERIFY(X("4.6") < X("4.4a") && X("4.4a") < X("4.4") && X("4.4") < X("4.2") && X("4.2") < X("4.1"));
    QVERIFY(X("4.1") < X("4.3") && X("4.3") < X("4.3a") && X("4.3a") < X("4.5"));
    QVERIFY(X("8.4") < X("8.9") && X("8.9") < X("8.1") && X("8.1") < X("8.10") && X("8.10") < X("8.3"));
    QVERIFY(X("9.2") < X("9.15") && X("9.15") < X("9.1"));
    QVERIFY(X("10.4") < X("5.2") && X("10.3") > X("5.1"));
    QVERIFY(X("h.1") < X("h.10") && X("h.10") < X("h.19"));
    // The FAPUs are those of a face of this size: ES0 is about a third of the face box.
    const double es0 = QLineF(f.point("3.6"), f.point("3.5")).length();
    QVERIFY(es0 > 0.25 * r.faceBox.width() && es0 < 0.6 * r.faceBox.width());

    for (const QString &g : {QStringLiteral("hair"), QStringLiteral("contour"), QStringLiteral("ears"),
             QStringLiteral("eyebrows"), QStringLiteral("eyes"), QStringLiteral("nose"), QStringLiteral("mouth")}) {
        QVERIFY2(r.groupConfidence.contains(g), qPrintable(g));
        QVERIFY(r.groupConfidence[g] > 0 && r.groupConfidence[g] <= 1);
    }
    QVERIFY(r.groupConfidence[QStringLiteral("hair")] < r.groupConfidence[QStringLiteral("eyes")]);
    QVERIFY(r.groupConfidence[QStringLiteral("ears")] < r.groupConfidence[QStringLiteral("eyes")]);
}

void TestDetector::imageFormats_data()
{
    QTest::addColumn<int>("format");
    QTest::newRow("RGB888") << int(QImage::Format_RGB888);
    QTest::newRow("ARGB32") << int(QImage::Format_ARGB32);
    QTest::newRow("RGBX8888") << int(QImage::Format_RGBX8888);
    QTest::newRow("RGBA64") << int(QImage::Format_RGBA64);
    QTest::newRow("Grayscale8") << int(QImage::Format_Grayscale8);
}

// The same pixels in any format give the same landmarks. The grey row holds the grey levels
// the detector makes from colour, (R + G + B) / 3 as dlib does; only the measured points are
// compared, the colour search for hair and ears seeing grey input differently by design.
void TestDetector::imageFormats()
{
    QFETCH(int, format);
    const QImage image = grace().convertToFormat(QImage::Format_RGB32);
    if (image.isNull())
        QSKIP("grace_hopper.jpg is not installed");
    QImage input;
    if (format == QImage::Format_Grayscale8) {
        input = QImage(image.size(), QImage::Format_Grayscale8);
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const QRgb c = image.pixel(x, y);
                input.scanLine(y)[x] = uchar((qRed(c) + qGreen(c) + qBlue(c)) / 3);
            }
    } else {
        input = image.convertToFormat(QImage::Format(format));
    }
    const DetectionResult ref = detectFace(image);
    const DetectionResult r = detectFace(input);
    QCOMPARE(r.status, DetectStatus::Ok);
    for (const char *id : {"3.6", "3.5", "3.12", "3.7", "8.4", "8.3", "9.15", "2.1", "4.6", "4.5"})
        QVERIFY2(r.face.point(id) == ref.face.point(id), id);
}

void TestDetector::progressAndTimings()
{
    const QImage image = grace();
    if (image.isNull())
        QSKIP("grace_hopper.jpg is not installed");
    QList<double> fractions;
    QStringList stages;
    const DetectionResult r = detectFace(image, {}, [&](double f, const QString &stage) {
        fractions << f;
        stages << stage;
    });
    QCOMPARE(r.status, DetectStatus::Ok);
    QVERIFY(fractions.size() >= 3);
    for (int i = 1; i < fractions.size(); ++i)
        QVERIFY(fractions[i] >= fractions[i - 1]);
    QCOMPARE(fractions.front(), 0.0);
    QCOMPARE(fractions.back(), 1.0);
    double sum = 0;
    for (const QString &stage :
        {QStringLiteral("prepare"), QStringLiteral("faces"), QStringLiteral("landmarks"), QStringLiteral("hair")}) {
        QVERIFY2(r.timingMs.contains(stage), qPrintable(stage));
        QVERIFY(r.timingMs[stage] >= 0);
        sum += r.timingMs[stage];
    }
    QVERIFY(r.timingMs.contains(QStringLiteral("total")));
    QVERIFY(r.timingMs[QStringLiteral("total")] >= 0.99 * sum);
}

void TestDetector::twoFacesLargerChosen_data()
{
    QTest::addColumn<bool>("largeOnLeft");
    QTest::newRow("large left") << true;
    QTest::newRow("large right") << false;
}

void TestDetector::twoFacesLargerChosen()
{
    QFETCH(bool, largeOnLeft);
    const QImage big = grace().convertToFormat(QImage::Format_RGB32);
    if (big.isNull())
        QSKIP("grace_hopper.jpg is not installed");
    const QImage small = big.scaled(big.size() * 0.8, Qt::KeepAspectRatio, Qt::SmoothTransformation);
    QImage canvas(big.width() + small.width(), big.height(), QImage::Format_RGB32);
    canvas.fill(QColor(90, 120, 160));
    QPainter p(&canvas);
    const QRect bigRect(QPoint(largeOnLeft ? 0 : small.width(), 0), big.size());
    const QRect smallRect(QPoint(largeOnLeft ? big.width() : 0, (big.height() - small.height()) / 2), small.size());
    p.drawImage(bigRect, big);
    p.drawImage(smallRect, small);
    p.end();

    const DetectionResult r = detectFace(canvas);
    QCOMPARE(r.status, DetectStatus::Ok);
    QCOMPARE(r.faceCount, 2);
    QVERIFY(bigRect.contains(r.faceBox.center()));
    QVERIFY(bigRect.contains(r.face.point("3.6").toPoint()));
}

// A face a third the size of the other would need a finer detection pass than the large one,
// which the search does not run once a face is found (each finer pass costs four times more):
// the large face is used and counted alone.
void TestDetector::twoFacesVeryDifferentSizes()
{
    const QImage big = grace().convertToFormat(QImage::Format_RGB32);
    if (big.isNull())
        QSKIP("grace_hopper.jpg is not installed");
    const QImage small = big.scaled(big.size() * 0.3, Qt::KeepAspectRatio, Qt::SmoothTransformation);
    QImage canvas(big.width() + small.width() + 40, big.height(), QImage::Format_RGB32);
    canvas.fill(QColor(90, 120, 160));
    QPainter p(&canvas);
    const QRect smallRect(QPoint(big.width() + 20, big.height() - small.height() - 60), small.size());
    p.drawImage(QPoint(0, 0), big);
    p.drawImage(smallRect, small);
    p.end();

    const DetectionResult r = detectFace(canvas);
    QCOMPARE(r.status, DetectStatus::Ok);
    QCOMPARE(r.faceCount, 1);
    QVERIFY(r.otherFaces.isEmpty());
    QVERIFY(QRect(QPoint(0, 0), big.size()).contains(r.faceBox.center()));
    QVERIFY(r.faceBox.width() > 2 * small.width() / 3);

    // Asked for the small face, the search goes on to its size; both are then counted.
    DetectOptions options;
    const QPointF smallCentre = smallRect.topLeft() + QPointF(r.faceBox.center()) * 0.3;
    options.faceAt = smallCentre;
    const DetectionResult asked = detectFace(canvas, options);
    QCOMPARE(asked.status, DetectStatus::Ok);
    QCOMPARE(asked.faceCount, 2);
    QVERIFY(smallRect.contains(asked.faceBox));
    QVERIFY(asked.faceBox.contains(smallCentre.toPoint()));
    QCOMPARE(asked.otherFaces.size(), 1);
    QVERIFY(QRect(QPoint(0, 0), big.size()).contains(asked.otherFaces.constFirst().center()));

    // A point on no face: the default choice.
    options.faceAt = QPointF(canvas.width() - 2, 2);
    const DetectionResult nowhere = detectFace(canvas, options);
    QCOMPARE(nowhere.status, DetectStatus::Ok);
    QVERIFY(QRect(QPoint(0, 0), big.size()).contains(nowhere.faceBox.center()));
}

void TestDetector::faceOfEverySize_data()
{
    QTest::addColumn<double>("fraction"); // the face box's width over the frame's shorter side
    // Steps of about 10%, across the sizes where one detection pass hands over to the next.
    for (double f = 0.62; f >= 0.085; f /= 1.1)
        QTest::newRow(qPrintable(QStringLiteral("%1").arg(f, 0, 'f', 3))) << f;
}

// Whatever its size, from a close-up down to the smallest the finest pass can see (40 px), a
// face is found: the passes leave no gap between the sizes they look for.
void TestDetector::faceOfEverySize()
{
    QFETCH(double, fraction);
    const QImage photo = grace().convertToFormat(QImage::Format_RGB32);
    if (photo.isNull())
        QSKIP("grace_hopper.jpg is not installed");
    const DetectionResult whole = detectFace(photo);
    QCOMPARE(whole.status, DetectStatus::Ok);
    const QSize frameSize(640, 480);
    const double zoom = fraction * frameSize.height() / whole.faceBox.width();
    QImage frame(frameSize, QImage::Format_RGB32);
    frame.fill(QColor(128, 128, 128));
    QPainter p(&frame);
    p.setRenderHint(QPainter::SmoothPixmapTransform);
    const QPointF centre(frameSize.width() / 2.0, frameSize.height() / 2.0);
    p.translate(centre);
    p.scale(zoom, zoom);
    p.translate(-QRectF(whole.faceBox).center());
    p.drawImage(QPoint(0, 0), photo);
    p.end();
    const QRectF expected(centre - QPointF(whole.faceBox.width(), whole.faceBox.height()) * zoom / 2.0,
        QSizeF(whole.faceBox.size()) * zoom);

    const DetectionResult r = detectFace(frame);
    QCOMPARE(r.status, DetectStatus::Ok);
    QCOMPARE(r.method, detectionMethodName(DetectionMethod::Landmarks)); // not the classic fallback
    const QRectF common = expected.intersected(QRectF(r.faceBox));
    const double iou = common.width() * common.height()
        / (expected.width() * expected.height() + r.faceBox.width() * r.faceBox.height()
            - common.width() * common.height());
    QVERIFY2(iou > 0.5, qPrintable(QStringLiteral("box overlap %1").arg(iou)));
}

void TestDetector::cancelBeforeStart()
{
    const QImage image = grace();
    if (image.isNull())
        QSKIP("grace_hopper.jpg is not installed");
    std::atomic_bool cancel {true};
    const DetectionResult r = detectFace(image, {}, {}, &cancel);
    QCOMPARE(r.status, DetectStatus::Cancelled);
    QVERIFY(!r.error.isEmpty());
}

void TestDetector::cancelDuringDetection()
{
    const QImage image = grace();
    if (image.isNull())
        QSKIP("grace_hopper.jpg is not installed");
    for (const QString &at : {QStringLiteral("faces"), QStringLiteral("landmarks"), QStringLiteral("hair")}) {
        std::atomic_bool cancel {false};
        QStringList seen;
        const DetectionResult r = detectFace(
            image, {},
            [&](double, const QString &stage) {
                seen << stage;
                if (stage == at)
                    cancel = true;
            },
            &cancel);
        QCOMPARE(r.status, DetectStatus::Cancelled);
        QCOMPARE(seen.last(), at); // no stage after the cancelled one was started
    }
}

void TestDetector::missingModel()
{
    EnvGuard guard("TOONFACE_LANDMARK_MODEL");
    const QString missing = QStringLiteral("/nonexistent/toonface-test/landmarks.dat");
    qputenv("TOONFACE_LANDMARK_MODEL", QFile::encodeName(missing));
    QCOMPARE(landmarkModelPath(), missing);
    QString error;
    QVERIFY(!preloadLandmarkModel(&error));
    QVERIFY(error.contains(missing));
    QImage image(320, 240, QImage::Format_RGB32);
    image.fill(Qt::gray);
    const DetectionResult r = detectFace(image);
    QCOMPARE(r.status, DetectStatus::ModelMissing);
    QVERIFY(r.error.contains(missing));

    // A file that is not a model is reported as unreadable, naming it.
    QTemporaryDir dir;
    const QString junk = dir.filePath(QStringLiteral("junk.dat"));
    QFile f(junk);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("not a shape predictor");
    f.close();
    qputenv("TOONFACE_LANDMARK_MODEL", QFile::encodeName(junk));
    const DetectionResult r2 = detectFace(image);
    QCOMPARE(r2.status, DetectStatus::ModelMissing);
    QVERIFY(r2.error.contains(junk));

    // With a face in the photo, auto falls back to the thesis' pipeline and says why; the
    // landmark method on its own still reports the missing model.
    const QImage portrait = grace();
    if (portrait.isNull())
        return;
    const DetectionResult r3 = detectFace(portrait);
    QCOMPARE(r3.status, DetectStatus::Ok);
    QCOMPARE(r3.method, QStringLiteral("classic"));
    QVERIFY(r3.note.contains(junk));
    DetectOptions landmarks;
    landmarks.method = DetectionMethod::Landmarks;
    QCOMPARE(detectFace(portrait, landmarks).status, DetectStatus::ModelMissing);
}

void TestDetector::debugImages()
{
    const QImage image = grace();
    if (image.isNull())
        QSKIP("grace_hopper.jpg is not installed");
    QTemporaryDir dir;
    DetectOptions options;
    options.debugDir = dir.filePath(QStringLiteral("debug"));
    const DetectionResult r = detectFace(image, options);
    QCOMPARE(r.status, DetectStatus::Ok);
    QVERIFY(r.debugImages.isEmpty()); // written, not kept
    // The landmarks' steps, and the thesis' figures of the same photo beside them.
    const QStringList names {QStringLiteral("detect-landmarks"), QStringLiteral("detect-points-crop"),
        QStringLiteral("detect-hair-region"), QStringLiteral("detect-head-regions"), QStringLiteral("classic-b1"),
        QStringLiteral("classic-b2"), QStringLiteral("classic-b3"), QStringLiteral("classic-face-hair"),
        QStringLiteral("classic-eye-pairs"), QStringLiteral("classic-eyeballs"), QStringLiteral("classic-edges"),
        QStringLiteral("classic-feature-regions"), QStringLiteral("classic-points")};
    for (const QString &name : names) {
        const QImage png(QDir(options.debugDir).filePath(name + QStringLiteral(".png")));
        QVERIFY2(!png.isNull(), qPrintable(name));
    }

    // Kept in memory for the editor's overlays, photo-sized except the zoomed crop.
    DetectOptions keep;
    keep.keepDebugImages = true;
    const DetectionResult k = detectFace(image, keep);
    QCOMPARE(k.status, DetectStatus::Ok);
    QCOMPARE(k.debugImages.keys(), [&] {
        QStringList sorted = names;
        sorted.sort();
        return sorted;
    }());
    for (auto it = k.debugImages.cbegin(); it != k.debugImages.cend(); ++it) {
        if (!it.key().endsWith(QStringLiteral("-crop")))
            QCOMPARE(it.value().size(), image.size());
    }
}

void TestDetector::concurrentCalls()
{
    const QImage image = grace();
    if (image.isNull())
        QSKIP("grace_hopper.jpg is not installed");
    const DetectionResult ref = detectFace(image);
    DetectionResult results[3];
    std::thread threads[3];
    for (int i = 0; i < 3; ++i)
        threads[i] = std::thread([&, i] { results[i] = detectFace(image); });
    for (auto &t : threads)
        t.join();
    for (const auto &r : results) {
        QCOMPARE(r.status, DetectStatus::Ok);
        QCOMPARE(r.face, ref.face);
    }
}

void TestDetector::sharedDataNme_data()
{
    QTest::addColumn<QString>("image");
    QTest::addColumn<QString>("pts");
    const QDir dir(sharedFacesDir());
    int rows = 0;
    for (const QFileInfo &pts : dir.entryInfoList({QStringLiteral("*.pts")}, QDir::Files, QDir::Name)) {
        for (const char *ext : {".png", ".jpg"}) {
            const QString image = dir.filePath(pts.completeBaseName() + QLatin1String(ext));
            if (QFileInfo::exists(image)) {
                QTest::newRow(qPrintable(pts.completeBaseName())) << image << pts.filePath();
                ++rows;
                break;
            }
        }
    }
    if (rows == 0)
        QTest::newRow("no data") << QString() << QString();
}

void TestDetector::sharedDataNme()
{
    QFETCH(QString, image);
    QFETCH(QString, pts);
    if (image.isEmpty())
        QSKIP("no research photos (set TOONFACE_DATA_DIR to the shared data folder)");
    std::array<QPointF, kIbugPointCount> truth {};
    QVERIFY2(readIbugPts(pts, &truth), qPrintable(pts));
    const QImage photo(image);
    QVERIFY2(!photo.isNull(), qPrintable(image));
    const DetectionResult r = detectFace(photo);
    QCOMPARE(r.status, DetectStatus::Ok);
    const double nme = normalizedMeanError(r.face, truth);
    qInfo("%s: NME %.4f (%d faces)", qPrintable(QFileInfo(image).fileName()), nme, r.faceCount);
    QVERIFY2(nme <= 0.08, qPrintable(QStringLiteral("NME %1").arg(nme)));
}

void TestDetector::photoGroupsPlausible_data()
{
    sharedDataNme_data();
    QTest::newRow("grace_hopper") << kGracePath << QString();
}

// On real photos, in the face frame (x along the eye line, y down, from EyeMid): the crown of
// the hair outline (h.6 .. h.14) lies above the brows, h.10 above the forehead point 11.1
// (within 0.05 d); each ear lies beside its cheek (its outermost point 10.4/10.3 no nearer
// the midline than the cheek 5.2/5.1 minus 0.1 d, and within a full d of it) between the brows
// and the mouth (0.3 d of slack above).
void TestDetector::photoGroupsPlausible()
{
    QFETCH(QString, image);
    if (image.isEmpty())
        QSKIP("no research photos (set TOONFACE_DATA_DIR to the shared data folder)");
    const QImage photo(image);
    if (photo.isNull())
        QSKIP(qPrintable(QStringLiteral("%1 is not installed").arg(image)));
    const DetectionResult r = detectFace(photo);
    QCOMPARE(r.status, DetectStatus::Ok);
    const HeadGeometry g = headGeometry(r.face);
    const double d = g.eyeDistance;
    auto L = [&](const char *id) { return g.toLocal(r.face.point(id)); };
    for (int i = pt::idx("h.6"); i <= pt::idx("h.14"); ++i)
        QVERIFY2(g.toLocal(r.face.point(i)).y() < g.browY, qPrintable(pointId(i)));
    QCOMPARE_LE(L("h.10").y(), L("11.1").y() + 0.05 * d);
    const double mouthY = (L("8.4").y() + L("8.3").y()) / 2;
    for (const char *id : {"10.2", "10.4", "10.6", "10.10", "10.1", "10.3", "10.5", "10.9"}) {
        const double y = L(id).y();
        QVERIFY2(y > g.browY - 0.3 * d && y < mouthY, id);
    }
    QCOMPARE_LE(L("10.4").x(), L("5.2").x() + 0.1 * d);
    QCOMPARE_GE(L("10.4").x(), L("5.2").x() - d);
    QCOMPARE_GE(L("10.3").x(), L("5.1").x() - 0.1 * d);
    QCOMPARE_LE(L("10.3").x(), L("5.1").x() + d);
}

// The result carries the regions of its points and a tracking seed measured on the photo.
void TestDetector::resultHasRegions()
{
    const QImage image = grace();
    if (image.isNull())
        QSKIP("grace_hopper.jpg is not installed");
    for (DetectionMethod m : {DetectionMethod::Landmarks, DetectionMethod::Classic}) {
        DetectOptions options;
        options.method = m;
        const DetectionResult r = detectFace(image, options);
        if (r.status != DetectStatus::Ok) {
            QCOMPARE(m, DetectionMethod::Classic); // the classic method may miss a real photo
            continue;
        }
        QCOMPARE(r.regions.hairOutline.size(), 19);
        QVERIFY(r.regions.face.contains(r.face.point("9.15")));
        QVERIFY(r.regions.eyes[0].center().x() < r.regions.eyes[1].center().x());
        QVERIFY(r.regions.mouth.center().y() > r.regions.nose.top());
        QVERIFY(r.tracking.valid);
        QCOMPARE_GT(r.tracking.d, 10.0);
        QVERIFY(r.regions.face.contains(r.tracking.eyeMid));
        QCOMPARE_LT(r.tracking.divEE, r.tracking.divEN);
        QCOMPARE_LT(r.tracking.divEN, r.tracking.divNM);
        QCOMPARE_GT(r.tracking.skin.samples, 0);
        // Skin is lighter than the threshold that separates the dark features.
        QCOMPARE_GT((r.tracking.skin.r + r.tracking.skin.g + r.tracking.skin.b) / 3, r.tracking.t1);
        // Thesis 6.3's edge thresholds: both methods measure them the same way from the seed's
        // geometry (the photo is below 640 pixels, so the classic method works on its pixels).
        TrackingSeed remeasured = r.tracking;
        remeasured.edgeThresholds = {};
        measureEdgeThresholds(image, &remeasured);
        QVERIFY(remeasured.edgeThresholds == r.tracking.edgeThresholds);
        for (double t : r.tracking.edgeThresholds)
            QCOMPARE_GT(t, 0.0);
    }
}

TOONFACE_TEST_GUILESS_MAIN(TestDetector)
#include "tst_detector.moc"
