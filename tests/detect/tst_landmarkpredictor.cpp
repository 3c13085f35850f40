#include "detect/detector.h"
#include "detect/grayview.h"
#include "detect/landmarkpredictor.h"
#include "testmain.h"

#include <QDir>
#include <QFile>
#include <QImage>
#include <QTemporaryDir>
#include <QTest>

// dlib's predictor only: the face's box comes from the project's detector (detectFace), since
// instantiating dlib's HOG detector for GrayView made this the slowest file of the tests to
// compile (23 CPU-s).
#include <dlib/image_processing/shape_predictor.h>
#include <dlib/serialize.h>

#include <cmath>
#include <sstream>

using namespace toonface;

namespace {

const QString kGracePath = QStringLiteral("/usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg");

QImage grayOf(const QString &path)
{
    return QImage(path).convertToFormat(QImage::Format_Grayscale8);
}

} // namespace

class TestLandmarkPredictor : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void agreesWithDlib_data();
    void agreesWithDlib();
    void keepsSubPixelPrecision();
    void badFilesAreNamed_data();
    void badFilesAreNamed();

private:
    QString m_modelPath;
    std::shared_ptr<const LandmarkPredictor> m_model;
    dlib::shape_predictor m_dlib;
    QRect m_faceBox; // the detector's box of the face in kGracePath
};

void TestLandmarkPredictor::initTestCase()
{
    m_modelPath = landmarkModelPath();
    if (!QFile::exists(m_modelPath))
        QSKIP("The landmark model is not installed (package libdlib-data).");
    QString error;
    m_model = LandmarkPredictor::read(m_modelPath, &error);
    QVERIFY2(m_model, qPrintable(error));
    dlib::deserialize(QFile::encodeName(m_modelPath).toStdString()) >> m_dlib;
    QVERIFY(QFile::exists(kGracePath));
    const DetectionResult found = detectFace(QImage(kGracePath));
    QVERIFY2(found.status == DetectStatus::Ok, qPrintable(found.error));
    QCOMPARE(found.faceCount, 1);
    m_faceBox = found.faceBox;
}

void TestLandmarkPredictor::agreesWithDlib_data()
{
    QTest::addColumn<QRect>("shift"); // added to the detector's box: x, y, and width/height change
    QTest::newRow("detector box") << QRect(0, 0, 0, 0);
    QTest::newRow("shifted left and up") << QRect(-9, -7, 0, 0);
    QTest::newRow("shifted right, larger") << QRect(11, 3, 14, 14);
    QTest::newRow("smaller") << QRect(4, 6, -12, -12);
    QTest::newRow("half off the photo") << QRect(-150, 0, 0, 0);
}

// The same model evaluated by dlib and by the flat predictor: the same points, except for
// dlib's rounding to whole pixels.
void TestLandmarkPredictor::agreesWithDlib()
{
    QFETCH(QRect, shift);
    const QImage gray = grayOf(kGracePath);
    QVERIFY(!gray.isNull());
    const GrayView view = viewOf(gray);
    // Both predictors are given the detector's box, moved by `shift`.
    const QRect face = m_faceBox;
    const dlib::rectangle box(face.left() + shift.x(), face.top() + shift.y(), face.right() + shift.x() + shift.width(),
        face.bottom() + shift.y() + shift.height());

    const dlib::full_object_detection theirs = m_dlib(view, box);
    const LandmarkPredictor::Shape ours
        = m_model->predict(view, QRect(QPoint(box.left(), box.top()), QPoint(box.right(), box.bottom())));
    double worst = 0, sum = 0;
    for (int i = 0; i < kIbugPointCount; ++i) {
        const double dx = ours[i].x() - theirs.part(i).x(), dy = ours[i].y() - theirs.part(i).y();
        worst = std::max({worst, std::abs(dx), std::abs(dy)});
        sum += std::hypot(dx, dy);
    }
    // Rounding moves a coordinate by at most half a pixel (a hair more for float sums in another order).
    QVERIFY2(worst <= 0.5 + 1e-3, qPrintable(QStringLiteral("worst coordinate differs by %1 px").arg(worst)));
    QVERIFY2(sum / kIbugPointCount < 0.5, qPrintable(QStringLiteral("mean %1 px").arg(sum / kIbugPointCount)));
}

// dlib rounds to whole pixels; the flat predictor does not, which matters for small faces.
void TestLandmarkPredictor::keepsSubPixelPrecision()
{
    const QImage gray = grayOf(kGracePath);
    const QRect box(170, 110, 250, 250);
    const LandmarkPredictor::Shape shape = m_model->predict(viewOf(gray), box);
    int fractional = 0;
    for (const QPointF &p : shape) {
        QVERIFY(
            box.adjusted(-box.width() / 2, -box.height() / 2, box.width() / 2, box.height() / 2).contains(p.toPoint()));
        if (std::abs(p.x() - std::round(p.x())) > 0.01 || std::abs(p.y() - std::round(p.y())) > 0.01)
            ++fractional;
    }
    QVERIFY2(fractional > kIbugPointCount / 2, qPrintable(QString::number(fractional)));
    // The mean shape lies in the unit square of the box.
    for (const QPointF &p : m_model->meanShape())
        QVERIFY(p.x() > -0.2 && p.x() < 1.2 && p.y() > -0.2 && p.y() < 1.2);
}

void TestLandmarkPredictor::badFilesAreNamed_data()
{
    QTest::addColumn<QString>("kind");
    QTest::addColumn<QString>("expected");
    QTest::newRow("missing") << QStringLiteral("missing") << QStringLiteral("is missing");
    QTest::newRow("empty") << QStringLiteral("empty") << QStringLiteral("could not be read");
    QTest::newRow("truncated") << QStringLiteral("truncated") << QStringLiteral("could not be read");
    QTest::newRow("text") << QStringLiteral("text") << QStringLiteral("could not be read");
    QTest::newRow("five points") << QStringLiteral("five") << QStringLiteral("gives 5 points");
}

void TestLandmarkPredictor::badFilesAreNamed()
{
    QFETCH(QString, kind);
    QFETCH(QString, expected);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("model.dat"));
    if (kind != QStringLiteral("missing")) {
        QFile out(path);
        QVERIFY(out.open(QIODevice::WriteOnly));
        if (kind == QStringLiteral("truncated")) {
            QFile model(m_modelPath);
            QVERIFY(model.open(QIODevice::ReadOnly));
            out.write(model.read(5'000'000));
        } else if (kind == QStringLiteral("text")) {
            out.write("shape_predictor_68_face_landmarks, but not really\n");
        } else if (kind == QStringLiteral("five")) {
            // A well-formed start of a model of five points (dlib's serialisation of its header).
            std::ostringstream s;
            dlib::serialize(1, s);
            dlib::matrix<float, 0, 1> initial(10);
            initial = 0.5f;
            dlib::serialize(initial, s);
            out.write(s.str().data(), qint64(s.str().size()));
        }
    }
    QString error;
    QVERIFY(!LandmarkPredictor::read(path, &error));
    QVERIFY2(error.contains(QDir::toNativeSeparators(path)), qPrintable(error));
    QVERIFY2(error.contains(expected), qPrintable(error));
}

TOONFACE_TEST_GUILESS_MAIN(TestLandmarkPredictor)
#include "tst_landmarkpredictor.moc"
