#include "detect/detector.h"
#include "detect/facescan.h"
#include "detect/modelcache.h"
#include "testmain.h"

#include <QDir>
#include <QFile>
#include <QImage>
#include <QTemporaryDir>
#include <QTest>

using namespace toonface;

// The CLI's warm-up (its own process: a warm-up runs once per process): it loads the landmark
// model and decodes the face detector through their caches, and leaves the later stages'
// first run to the detection that follows, which finds the same points as a cold one.
class TestModelsWarmUp : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void loadsTheModelsOnly()
    {
        QTemporaryDir cache;
        QVERIFY(cache.isValid());
        qputenv("TOONFACE_CACHE_DIR", QFile::encodeName(cache.path()));
        if (!QFile::exists(landmarkModelPath()))
            QSKIP("The landmark model is not installed (package libdlib-data).");
        const QImage photo(QStringLiteral("/usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg"));
        if (photo.isNull())
            QSKIP("grace_hopper.jpg is not installed (package python-matplotlib-data)");
        QVERIFY(!landmarkModelLoad().model);

        warmUpDetectionModels();
        waitForDetectionWarmUp();
        const LandmarkModelLoad load = landmarkModelLoad();
        QVERIFY(load.model);
        QCOMPARE(load.cache, LandmarkModelLoad::Cache::Built);
        QCOMPARE(faceDetectorLoad().cache, CacheUse::Built);
        QCOMPARE(QDir(cache.path()).entryList(QDir::Files).size(), 2);

        const DetectionResult first = detectFace(photo);
        QCOMPARE(first.status, DetectStatus::Ok);
        QCOMPARE(first.method, QStringLiteral("landmarks"));
        // The detection used the warmed model, and a second one places the very same points.
        QCOMPARE(landmarkModelLoad().model, load.model);
        const DetectionResult second = detectFace(photo);
        for (int i = 0; i < kPointCount; ++i)
            QCOMPARE(second.face.point(i), first.face.point(i));
        // A full warm-up asked for later does nothing more: once per process.
        warmUpDetection();
        waitForDetectionWarmUp();
        QCOMPARE(landmarkModelLoad().model, load.model);
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestModelsWarmUp)
#include "tst_modelswarmup.moc"
