#include "detect/detector.h"
#include "detect/facescan.h"
#include "detect/modelcache.h"
#include "testmain.h"

#include <QDir>
#include <QFile>
#include <QImage>
#include <QTemporaryDir>
#include <QTest>

#include <thread>

using namespace toonface;

namespace {

const QString kPortrait = QStringLiteral("/usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg");

void compareResults(const DetectionResult &a, const DetectionResult &b)
{
    QCOMPARE(a.status, DetectStatus::Ok);
    QCOMPARE(b.status, DetectStatus::Ok);
    QCOMPARE(a.method, b.method);
    QCOMPARE(a.faceCount, b.faceCount);
    QCOMPARE(a.faceBox, b.faceBox);
    for (int i = 0; i < kPointCount; ++i)
        QCOMPARE(a.face.point(i), b.face.point(i));
}

} // namespace

// The warm-up of detection: it loads the model through the cache, and a detection after it
// places the very points the first detection of a cold process placed.
class TestDetectionWarmUp : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void firstDetectionWithoutWarmUp();
    void warmUpLoadsTheModelThroughItsCache();
    void warmUpChangesNoPoint();
    void warmUpIsOncePerProcess();
    void detectionsOnSeveralThreadsAfterWarmUp();

private:
    QTemporaryDir m_cache;
    QImage m_photo;
    DetectionResult m_cold;
};

void TestDetectionWarmUp::initTestCase()
{
    QVERIFY(m_cache.isValid());
    qputenv("TOONFACE_CACHE_DIR", QFile::encodeName(m_cache.path()));
    if (!QFile::exists(landmarkModelPath()))
        QSKIP("The landmark model is not installed (package libdlib-data).");
    m_photo = QImage(kPortrait);
    if (m_photo.isNull())
        QSKIP("grace_hopper.jpg is not installed (package python-matplotlib-data)");
    // Nothing loaded yet in this process.
    QVERIFY(!landmarkModelLoad().model);
}

void TestDetectionWarmUp::firstDetectionWithoutWarmUp()
{
    m_cold = detectFace(m_photo);
    QCOMPARE(m_cold.status, DetectStatus::Ok);
    QCOMPARE(m_cold.method, QStringLiteral("landmarks"));
}

void TestDetectionWarmUp::warmUpLoadsTheModelThroughItsCache()
{
    warmUpDetection();
    waitForDetectionWarmUp();
    const LandmarkModelLoad load = landmarkModelLoad();
    QVERIFY(load.model);
    // The first detection built the cache in the folder given; the model is the one it loaded.
    QCOMPARE(load.cache, LandmarkModelLoad::Cache::Built);
    QCOMPARE(QFileInfo(load.cachePath).absolutePath(), QDir(m_cache.path()).absolutePath());
    QVERIFY(QFileInfo::exists(load.cachePath));
}

void TestDetectionWarmUp::warmUpChangesNoPoint()
{
    compareResults(detectFace(m_photo), m_cold);
    // The made-up portrait of the warm-up left nothing behind either in the landmarks' sub-steps.
    DetectOptions options;
    options.method = DetectionMethod::Landmarks;
    compareResults(detectFace(m_photo, options), m_cold);
}

void TestDetectionWarmUp::warmUpIsOncePerProcess()
{
    const auto model = landmarkModelLoad().model;
    warmUpDetection();
    waitForDetectionWarmUp();
    QCOMPARE(landmarkModelLoad().model, model);
    // One cache for the model, one for the face detector, each made once.
    QCOMPARE(QDir(m_cache.path()).entryList(QDir::Files).size(), 2);
    const FaceDetectorLoad detector = faceDetectorLoad();
    QCOMPARE(detector.cache, CacheUse::Built);
    QCOMPARE(QFileInfo(detector.cachePath).absolutePath(), QDir(m_cache.path()).absolutePath());
}

// The scan threads are shared by the process: detections at once each get one.
void TestDetectionWarmUp::detectionsOnSeveralThreadsAfterWarmUp()
{
    constexpr int kThreads = 3;
    DetectionResult results[kThreads];
    std::thread threads[kThreads];
    for (int i = 0; i < kThreads; ++i)
        threads[i] = std::thread([&, i] { results[i] = detectFace(m_photo); });
    for (auto &t : threads)
        t.join();
    for (const DetectionResult &r : results)
        compareResults(r, m_cold);
}

TOONFACE_TEST_GUILESS_MAIN(TestDetectionWarmUp)
#include "tst_detectionwarmup.moc"
