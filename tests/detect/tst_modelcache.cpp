#include "detect/detector.h"
#include "detect/facescan.h"
#include "detect/grayview.h"
#include "detect/landmarkflat.h"
#include "detect/landmarkpredictor.h"
#include "detect/modelcache.h"
#include "madeupmodel.h"
#include "testmain.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <dlib/image_processing/shape_predictor.h>
#include <dlib/revision.h>
#include <dlib/serialize.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>
#include <thread>

using namespace toonface;
using toonface::testing::writeModel;

namespace {

const QString kGracePath = QStringLiteral("/usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg");
// Run with this first argument, the test program loads a model through a cache and exits:
// the child of concurrentProcessesLeaveOneCache().
const char *const kChildArgument = "--load-through-cache";

using Cache = LandmarkModelLoad::Cache;

QImage testImage()
{
    QImage image(320, 240, QImage::Format_Grayscale8);
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            image.scanLine(y)[x] = uchar((x * 7 + y * 13 + (x * y) % 31) & 0xff);
    return image;
}

LandmarkPredictor::Shape predictOn(const LandmarkPredictor &model, const QImage &gray, QRect box)
{
    return model.predict(viewOf(gray), box);
}

double largestDifference(const LandmarkPredictor::Shape &a, const LandmarkPredictor::Shape &b)
{
    double worst = 0;
    for (int i = 0; i < kIbugPointCount; ++i)
        worst = std::max({worst, std::abs(a[i].x() - b[i].x()), std::abs(a[i].y() - b[i].y())});
    return worst;
}

QStringList entriesOf(const QString &dir)
{
    return QDir(dir).entryList(QDir::Files | QDir::Hidden, QDir::Name);
}

void setTime(const QString &path, const QDateTime &time)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadWrite));
    QVERIFY(f.setFileTime(time, QFileDevice::FileModificationTime));
}

} // namespace

class TestModelCache : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cacheDirFollowsTheEnvironment();
    void builtOnFirstUseThenReused();
    void cachedModelGivesTheSamePoints();
    void realModelThroughTheCache();
    void rebuiltWhenTheModelChanges();
    void damagedCacheRejectedAndRebuilt_data();
    void damagedCacheRejectedAndRebuilt();
    void damagedBlockNeverTrusted();
    void runawayLeavesGiveTheMeanShape();
    void cacheWrittenLater();
    void unwritableCacheStillLoads();
    void staleTemporaryFilesRemoved();
    void concurrentThreadsLeaveOneCache();
    void concurrentProcessesLeaveOneCache();
    void missingModelNamed();
    void faceDetectorCache();
    void faceDetectorCacheDamaged_data();
    void faceDetectorCacheDamaged();

private:
    std::unique_ptr<QTemporaryDir> m_dir;
    QString m_model;
    QString m_cacheDir;
};

void TestModelCache::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
    m_model = m_dir->filePath(QStringLiteral("model.dat"));
    m_cacheDir = m_dir->filePath(QStringLiteral("cache"));
    writeModel(m_model, 1);
}

void TestModelCache::cacheDirFollowsTheEnvironment()
{
    const QByteArray old = qgetenv("TOONFACE_CACHE_DIR");
    qputenv("TOONFACE_CACHE_DIR", QFile::encodeName(m_cacheDir));
    QCOMPARE(detectionCacheDir(), m_cacheDir);
    qunsetenv("TOONFACE_CACHE_DIR");
    const QString fallback = detectionCacheDir();
    QVERIFY(fallback.endsWith(QStringLiteral("/toonface")));
    QVERIFY(fallback != m_cacheDir);
    if (!old.isEmpty())
        qputenv("TOONFACE_CACHE_DIR", old);
    // One cache per model path, in the folder asked for.
    const QString a = landmarkCachePath(m_model, m_cacheDir);
    QCOMPARE(QFileInfo(a).absolutePath(), QDir(m_cacheDir).absolutePath());
    QVERIFY(a != landmarkCachePath(m_dir->filePath(QStringLiteral("other.dat")), m_cacheDir));
    QCOMPARE(landmarkCachePath(m_model, m_cacheDir), a);
}

void TestModelCache::builtOnFirstUseThenReused()
{
    QVERIFY(!QFileInfo::exists(m_cacheDir));
    const LandmarkModelLoad first = loadLandmarkModel(m_model, m_cacheDir);
    QVERIFY2(first.model, qPrintable(first.error));
    QCOMPARE(first.cache, Cache::Built);
    QVERIFY2(first.cacheNote.contains(QStringLiteral("no cache yet")), qPrintable(first.cacheNote));
    QCOMPARE(entriesOf(m_cacheDir), QStringList {QFileInfo(first.cachePath).fileName()});
    // The cache holds the header and the model's block, nothing else.
    QCOMPARE(QFileInfo(first.cachePath).size(), qint64(first.model->flat().size()) + 64);

    const QDateTime written = QFileInfo(first.cachePath).lastModified();
    const LandmarkModelLoad second = loadLandmarkModel(m_model, m_cacheDir);
    QVERIFY(second.model);
    QCOMPARE(second.cache, Cache::Used);
    QVERIFY2(second.cacheNote.isEmpty(), qPrintable(second.cacheNote));
    QCOMPARE(second.cachePath, first.cachePath);
    QCOMPARE(QFileInfo(first.cachePath).lastModified(), written);
    QCOMPARE(entriesOf(m_cacheDir).size(), 1);
}

// Asked to, the load leaves the cache's writing to its caller: the model first, the file
// once the writing runs, and a cache then that a later load uses.
void TestModelCache::cacheWrittenLater()
{
    LandmarkModelLoad first = loadLandmarkModel(m_model, m_cacheDir, CacheWrite::Later);
    QVERIFY2(first.model, qPrintable(first.error));
    QVERIFY(first.writeCache);
    QVERIFY(!QFileInfo::exists(first.cachePath));
    first.writeCache(&first);
    QCOMPARE(first.cache, Cache::Built);
    QCOMPARE(QFileInfo(first.cachePath).size(), qint64(first.model->flat().size()) + 64);
    const LandmarkModelLoad second = loadLandmarkModel(m_model, m_cacheDir, CacheWrite::Later);
    QCOMPARE(second.cache, Cache::Used);
    QVERIFY(!second.writeCache); // nothing to write
    const QImage gray = testImage();
    QCOMPARE(largestDifference(predictOn(*first.model, gray, QRect(60, 40, 150, 150)),
                 predictOn(*second.model, gray, QRect(60, 40, 150, 150))),
        0.0);

    // A folder that cannot be made: the writing says why, and the model is still there.
    QFile blocker(m_dir->filePath(QStringLiteral("blocker")));
    QVERIFY(blocker.open(QIODevice::WriteOnly));
    blocker.close();
    LandmarkModelLoad blocked
        = loadLandmarkModel(m_model, m_dir->filePath(QStringLiteral("blocker/cache")), CacheWrite::Later);
    QVERIFY(blocked.model);
    QVERIFY(blocked.writeCache);
    blocked.writeCache(&blocked);
    QCOMPARE(blocked.cache, Cache::NotWritten);
    QVERIFY2(blocked.cacheNote.contains(QStringLiteral("blocker")), qPrintable(blocked.cacheNote));
}

void TestModelCache::cachedModelGivesTheSamePoints()
{
    QString error;
    const auto original = LandmarkPredictor::read(m_model, &error);
    QVERIFY2(original, qPrintable(error));
    QCOMPARE(loadLandmarkModel(m_model, m_cacheDir).cache, Cache::Built);
    const LandmarkModelLoad cached = loadLandmarkModel(m_model, m_cacheDir);
    QCOMPARE(cached.cache, Cache::Used);
    const QImage gray = testImage();
    for (const QRect &box : {QRect(60, 40, 150, 150), QRect(100, 20, 90, 120), QRect(-50, 100, 200, 200)}) {
        const auto a = predictOn(*original, gray, box);
        const auto b = predictOn(*cached.model, gray, box);
        QVERIFY(largestDifference(a, b) <= 1e-4);
    }
    QCOMPARE(cached.model->meanShape(), original->meanShape());
}

// The model detection uses: dlib's own file, parsed or through its cache, places the same
// points on a real face.
void TestModelCache::realModelThroughTheCache()
{
    const QString path = landmarkModelPath();
    if (!QFile::exists(path))
        QSKIP("The landmark model is not installed (package libdlib-data).");
    const QImage gray = QImage(kGracePath).convertToFormat(QImage::Format_Grayscale8);
    if (gray.isNull())
        QSKIP("The Grace Hopper portrait (python3-matplotlib) is not installed.");
    QString error;
    const auto parsed = LandmarkPredictor::read(path, &error);
    QVERIFY2(parsed, qPrintable(error));
    const LandmarkModelLoad built = loadLandmarkModel(path, m_cacheDir);
    QCOMPARE(built.cache, Cache::Built);
    const LandmarkModelLoad cached = loadLandmarkModel(path, m_cacheDir);
    QCOMPARE(cached.cache, Cache::Used);
    for (const QRect &box : {QRect(170, 110, 250, 250), QRect(160, 120, 230, 240), QRect(190, 100, 260, 270)}) {
        const double worst = largestDifference(predictOn(*parsed, gray, box), predictOn(*cached.model, gray, box));
        QVERIFY2(worst <= 1e-4, qPrintable(QString::number(worst)));
    }
}

void TestModelCache::rebuiltWhenTheModelChanges()
{
    const QImage gray = testImage();
    const QRect box(60, 40, 150, 150);
    const LandmarkModelLoad a = loadLandmarkModel(m_model, m_cacheDir);
    QCOMPARE(a.cache, Cache::Built);
    const auto pointsA = predictOn(*a.model, gray, box);

    // Another model at the same path.
    writeModel(m_model, 2);
    const LandmarkModelLoad b = loadLandmarkModel(m_model, m_cacheDir);
    QCOMPARE(b.cache, Cache::Built);
    QVERIFY2(b.cacheNote.contains(QStringLiteral("another model")), qPrintable(b.cacheNote));
    QString error;
    const auto parsedB = LandmarkPredictor::read(m_model, &error);
    QVERIFY(parsedB);
    const auto pointsB = predictOn(*b.model, gray, box);
    QVERIFY(largestDifference(pointsB, predictOn(*parsedB, gray, box)) <= 1e-4);
    QVERIFY(largestDifference(pointsA, pointsB) > 0.1);
    QCOMPARE(loadLandmarkModel(m_model, m_cacheDir).cache, Cache::Used);

    // Only touched: rebuilt too (the time is part of the key).
    setTime(m_model, QFileInfo(m_model).lastModified().addSecs(5));
    QCOMPARE(loadLandmarkModel(m_model, m_cacheDir).cache, Cache::Built);

    // The same size and time, another content: the checksum tells.
    const QDateTime time = QFileInfo(m_model).lastModified();
    const qint64 size = QFileInfo(m_model).size();
    writeModel(m_model, 2, 3, 40, 3, -1);
    QCOMPARE(QFileInfo(m_model).size(), size);
    setTime(m_model, time);
    const LandmarkModelLoad c = loadLandmarkModel(m_model, m_cacheDir);
    QCOMPARE(c.cache, Cache::Built);
    QVERIFY(largestDifference(predictOn(*c.model, gray, box), pointsB) > 0.1);
    QCOMPARE(entriesOf(m_cacheDir).size(), 1);
}

void TestModelCache::damagedCacheRejectedAndRebuilt_data()
{
    QTest::addColumn<QString>("damage");
    QTest::addColumn<QString>("expected");
    QTest::newRow("empty") << QStringLiteral("empty") << QStringLiteral("cut short");
    QTest::newRow("header only, cut") << QStringLiteral("cut40") << QStringLiteral("cut short");
    QTest::newRow("cut in half") << QStringLiteral("half") << QStringLiteral("bytes, not the");
    QTest::newRow("one byte short") << QStringLiteral("short1") << QStringLiteral("bytes, not the");
    QTest::newRow("a byte longer") << QStringLiteral("long1") << QStringLiteral("bytes, not the");
    QTest::newRow("a leaf byte changed") << QStringLiteral("flipEnd") << QStringLiteral("checksum");
    QTest::newRow("a table byte changed") << QStringLiteral("flipTable") << QStringLiteral("checksum");
    QTest::newRow("magic") << QStringLiteral("magic") << QStringLiteral("not a cache of this kind");
    QTest::newRow("version") << QStringLiteral("version") << QStringLiteral("another version");
    QTest::newRow("text") << QStringLiteral("text") << QStringLiteral("cut short");
    QTest::newRow("random bytes") << QStringLiteral("random") << QStringLiteral("not a cache of this kind");
}

void TestModelCache::damagedCacheRejectedAndRebuilt()
{
    QFETCH(QString, damage);
    QFETCH(QString, expected);
    const LandmarkModelLoad built = loadLandmarkModel(m_model, m_cacheDir);
    QCOMPARE(built.cache, Cache::Built);
    const QImage gray = testImage();
    const QRect box(60, 40, 150, 150);
    const auto good = predictOn(*built.model, gray, box);

    QFile file(built.cachePath);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QByteArray bytes = file.readAll();
    file.close();
    if (damage == QLatin1StringView("empty"))
        bytes.clear();
    else if (damage == QLatin1StringView("cut40"))
        bytes.truncate(40);
    else if (damage == QLatin1StringView("half"))
        bytes.truncate(bytes.size() / 2);
    else if (damage == QLatin1StringView("short1"))
        bytes.chop(1);
    else if (damage == QLatin1StringView("long1"))
        bytes.append('\0');
    else if (damage == QLatin1StringView("flipEnd"))
        bytes[bytes.size() - 5] = char(bytes[bytes.size() - 5] ^ 0x10);
    else if (damage == QLatin1StringView("flipTable"))
        bytes[64 + 700] = char(bytes[64 + 700] ^ 0x01);
    else if (damage == QLatin1StringView("magic"))
        bytes[0] = 'X';
    else if (damage == QLatin1StringView("version"))
        bytes[8] = char(bytes[8] + 1);
    else if (damage == QLatin1StringView("text"))
        bytes = "a landmark model, honestly\n";
    else if (damage == QLatin1StringView("random")) {
        std::mt19937 random(7);
        for (char &c : bytes)
            c = char(random());
    }
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write(bytes);
    file.close();

    const LandmarkModelLoad again = loadLandmarkModel(m_model, m_cacheDir);
    QVERIFY2(again.model, qPrintable(again.error));
    QCOMPARE(again.cache, Cache::Built);
    QVERIFY2(again.cacheNote.contains(expected), qPrintable(again.cacheNote));
    QVERIFY(largestDifference(predictOn(*again.model, gray, box), good) <= 1e-4);
    // Rebuilt whole: used next time.
    const LandmarkModelLoad third = loadLandmarkModel(m_model, m_cacheDir);
    QCOMPARE(third.cache, Cache::Used);
    QVERIFY(largestDifference(predictOn(*third.model, gray, box), good) <= 1e-4);
}

// Leaves are not checked when a model is read (there are millions): a damaged model whose
// leaves push the shape past any position gives its mean shape, placed in the box, and never
// turns such a position into a pixel (UndefinedBehaviorSanitizer caught one: a float too large
// for an integer). Offsets and the mean shape are checked when the model is read.
void TestModelCache::runawayLeavesGiveTheMeanShape()
{
    QString error;
    const auto model = LandmarkPredictor::read(m_model, &error);
    QVERIFY2(model, qPrintable(error));
    std::vector<std::byte> copy(model->flat().begin(), model->flat().end());
    flat::Header header;
    std::memcpy(&header, copy.data(), sizeof header);
    flat::Cascade first;
    std::memcpy(&first, copy.data() + header.tableAt, sizeof first);
    const quint64 leaves = quint64(first.trees) * (first.splitsPerTree + 1) * flat::kShapeValues;
    const float huge = 1e30f;
    for (quint64 i = 0; i < leaves; ++i)
        std::memcpy(copy.data() + first.leavesAt + i * sizeof huge, &huge, sizeof huge);
    auto owner = std::make_shared<std::vector<std::byte>>(copy);
    const auto damaged
        = LandmarkPredictor::fromFlat(owner, std::span<const std::byte>(owner->data(), owner->size()), &error);
    QVERIFY2(damaged, qPrintable(error));
    const QRect box(60, 40, 150, 150);
    const LandmarkPredictor::Shape points = predictOn(*damaged, testImage(), box);
    for (int i = 0; i < kIbugPointCount; ++i) {
        const QPointF m = damaged->meanShape()[i];
        const QPointF expected(
            box.left() + m.x() * (box.right() - box.left()), box.top() + m.y() * (box.bottom() - box.top()));
        QVERIFY2(std::abs(points[i].x() - expected.x()) < 1e-3 && std::abs(points[i].y() - expected.y()) < 1e-3,
            qPrintable(QStringLiteral("point %1").arg(i)));
    }

    // A pixel feature's offset, or a mean shape value, that is no position: refused on reading.
    std::vector<std::byte> badOffset(model->flat().begin(), model->flat().end());
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(badOffset.data() + first.deltasAt, &nan, sizeof nan);
    QVERIFY(!LandmarkPredictor::fromFlat({}, std::span<const std::byte>(badOffset.data(), badOffset.size()), &error));
    QVERIFY2(error.contains(QStringLiteral("offset")), qPrintable(error));
    std::vector<std::byte> badMean(model->flat().begin(), model->flat().end());
    std::memcpy(badMean.data() + header.initialAt, &huge, sizeof huge);
    QVERIFY(!LandmarkPredictor::fromFlat({}, std::span<const std::byte>(badMean.data(), badMean.size()), &error));
    QVERIFY2(error.contains(QStringLiteral("mean shape")), qPrintable(error));
}

// A block whose checksum was right but whose counts or offsets are wrong (a bug, or another
// build's layout) is refused, never read past its end: every byte of the header and the table
// set to 0xff in turn, and the block cut at every length up to the end of the table.
void TestModelCache::damagedBlockNeverTrusted()
{
    QString error;
    const auto model = LandmarkPredictor::read(m_model, &error);
    QVERIFY(model);
    const std::span<const std::byte> block = model->flat();
    const QImage gray = testImage();
    const size_t tableEnd = 1024; // past the header (40 bytes), the mean shape and 3 table rows
    QVERIFY(block.size() > tableEnd);
    int refused = 0;
    for (size_t i = 0; i < tableEnd; ++i) {
        std::vector<std::byte> copy(block.begin(), block.end());
        copy[i] = std::byte(0xff);
        auto owner = std::make_shared<std::vector<std::byte>>(std::move(copy));
        const auto damaged
            = LandmarkPredictor::fromFlat(owner, std::span<const std::byte>(owner->data(), owner->size()), &error);
        if (!damaged) {
            QVERIFY(!error.isEmpty());
            ++refused;
            continue;
        }
        predictOn(*damaged, gray, QRect(60, 40, 150, 150)); // a changed float: a model still
    }
    QVERIFY(refused > 40);
    for (size_t n = 0; n < tableEnd; n += 7) {
        QVERIFY(!LandmarkPredictor::fromFlat({}, block.first(n), &error));
        QVERIFY(!error.isEmpty());
    }
    QVERIFY(!LandmarkPredictor::fromFlat({}, block.first(block.size() - 1), &error));
}

void TestModelCache::unwritableCacheStillLoads()
{
    // The cache folder's place is taken by a file: no cache, but the model all the same.
    QFile blocker(m_cacheDir);
    QVERIFY(blocker.open(QIODevice::WriteOnly));
    blocker.close();
    const LandmarkModelLoad load = loadLandmarkModel(m_model, m_cacheDir);
    QVERIFY(load.model);
    QCOMPARE(load.cache, Cache::NotWritten);
    QVERIFY2(load.cacheNote.contains(m_cacheDir), qPrintable(load.cacheNote));
    // No folder at all: no cache looked for.
    const LandmarkModelLoad none = loadLandmarkModel(m_model, QString());
    QVERIFY(none.model);
    QCOMPARE(none.cache, Cache::Off);
}

void TestModelCache::staleTemporaryFilesRemoved()
{
    QVERIFY(QDir().mkpath(m_cacheDir));
    const QString target = landmarkCachePath(m_model, m_cacheDir);
    const QString stale = target + QStringLiteral(".aB3dE9.tmp");
    const QString recent = target + QStringLiteral(".Zz9yX8.tmp");
    for (const QString &path : {stale, recent}) {
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("half a cache");
    }
    setTime(stale, QDateTime::currentDateTime().addDays(-1));
    QCOMPARE(loadLandmarkModel(m_model, m_cacheDir).cache, Cache::Built);
    QVERIFY(!QFileInfo::exists(stale));
    // A builder may be writing this one now.
    QVERIFY(QFileInfo::exists(recent));
}

void TestModelCache::concurrentThreadsLeaveOneCache()
{
    writeModel(m_model, 3, 4, 300, 4); // about 10 MB of leaves: writes that overlap
    constexpr int kThreads = 6;
    std::vector<LandmarkModelLoad> loads(kThreads);
    std::vector<std::thread> threads;
    for (int i = 0; i < kThreads; ++i)
        threads.emplace_back([&, i] { loads[i] = loadLandmarkModel(m_model, m_cacheDir); });
    for (std::thread &t : threads)
        t.join();
    const QImage gray = testImage();
    const auto expected = predictOn(*LandmarkPredictor::read(m_model, nullptr), gray, QRect(60, 40, 150, 150));
    for (const LandmarkModelLoad &load : loads) {
        QVERIFY2(load.model, qPrintable(load.error));
        QVERIFY(load.cache == Cache::Built || load.cache == Cache::Used);
        QVERIFY(largestDifference(predictOn(*load.model, gray, QRect(60, 40, 150, 150)), expected) <= 1e-4);
    }
    QCOMPARE(entriesOf(m_cacheDir), QStringList {QFileInfo(landmarkCachePath(m_model, m_cacheDir)).fileName()});
    QCOMPARE(loadLandmarkModel(m_model, m_cacheDir).cache, Cache::Used);
}

void TestModelCache::concurrentProcessesLeaveOneCache()
{
    writeModel(m_model, 4, 4, 300, 4);
    constexpr int kProcesses = 5;
    std::vector<std::unique_ptr<QProcess>> children;
    for (int i = 0; i < kProcesses; ++i) {
        auto child = std::make_unique<QProcess>();
        child->start(QCoreApplication::applicationFilePath(),
            toonface::test::suiteArguments() + QStringList {QString::fromLatin1(kChildArgument), m_model, m_cacheDir});
        children.push_back(std::move(child));
    }
    int built = 0;
    for (auto &child : children) {
        QVERIFY(child->waitForFinished(120000));
        const QByteArray out = child->readAllStandardOutput().trimmed();
        QVERIFY2(child->exitCode() == 0, child->readAllStandardError().constData());
        QVERIFY2(out == "built" || out == "used", out.constData());
        built += out == "built";
    }
    QVERIFY(built >= 1);
    QCOMPARE(entriesOf(m_cacheDir), QStringList {QFileInfo(landmarkCachePath(m_model, m_cacheDir)).fileName()});
    const LandmarkModelLoad after = loadLandmarkModel(m_model, m_cacheDir);
    QCOMPARE(after.cache, Cache::Used);
    const QImage gray = testImage();
    QVERIFY(largestDifference(predictOn(*after.model, gray, QRect(60, 40, 150, 150)),
                predictOn(*LandmarkPredictor::read(m_model, nullptr), gray, QRect(60, 40, 150, 150)))
        <= 1e-4);
}

void TestModelCache::missingModelNamed()
{
    const QString missing = m_dir->filePath(QStringLiteral("nothing-here.dat"));
    const LandmarkModelLoad load = loadLandmarkModel(missing, m_cacheDir);
    QVERIFY(!load.model);
    QVERIFY2(load.error.contains(missing) && load.error.contains(QStringLiteral("is missing")), qPrintable(load.error));
    QVERIFY(entriesOf(m_cacheDir).isEmpty());
}

// dlib's face detector, decoded once (about 0.4 s) and then read from its cache: the same
// detector either way.
void TestModelCache::faceDetectorCache()
{
    const FaceDetectorLoad built = loadFaceDetector(m_cacheDir);
    QCOMPARE(built.cache, CacheUse::Built);
    QVERIFY(QFileInfo::exists(built.cachePath));
    QCOMPARE(QFileInfo(built.cachePath).absolutePath(), QDir(m_cacheDir).absolutePath());
    const FaceDetectorLoad used = loadFaceDetector(m_cacheDir);
    QCOMPARE(used.cache, CacheUse::Used);
    QCOMPARE(used.fingerprint, built.fingerprint);
    const FaceDetectorLoad decoded = loadFaceDetector(QString());
    QCOMPARE(decoded.cache, CacheUse::Off);
    QCOMPARE(decoded.fingerprint, built.fingerprint);
}

void TestModelCache::faceDetectorCacheDamaged_data()
{
    QTest::addColumn<QString>("damage");
    QTest::addColumn<QString>("expected");
    QTest::newRow("cut") << QStringLiteral("cut") << QStringLiteral("bytes, not the");
    QTest::newRow("a byte changed") << QStringLiteral("flip") << QStringLiteral("checksum");
    // A whole file of the right kind whose content is not a detector.
    QTest::newRow("not a detector") << QStringLiteral("garbage") << QStringLiteral("damaged");
    QTest::newRow("a model's cache") << QStringLiteral("model") << QStringLiteral("not a cache of this kind");
}

void TestModelCache::faceDetectorCacheDamaged()
{
    QFETCH(QString, damage);
    QFETCH(QString, expected);
    const FaceDetectorLoad built = loadFaceDetector(m_cacheDir);
    QCOMPARE(built.cache, CacheUse::Built);
    if (damage == QLatin1StringView("garbage")) {
        const QByteArray junk(4000, 'x');
        QString error;
        QVERIFY(writeCacheFile(built.cachePath, "HOGD",
            {quint64(DLIB_MAJOR_VERSION) * 1000000 + DLIB_MINOR_VERSION * 1000 + DLIB_PATCH_VERSION, 0, 0},
            std::as_bytes(std::span(junk.constData(), size_t(junk.size()))), &error));
    } else if (damage == QLatin1StringView("model")) {
        const LandmarkModelLoad model = loadLandmarkModel(m_model, m_cacheDir);
        QVERIFY(QFile::remove(built.cachePath));
        QVERIFY(QFile::copy(model.cachePath, built.cachePath));
    } else {
        QFile file(built.cachePath);
        QVERIFY(file.open(QIODevice::ReadWrite));
        if (damage == QLatin1StringView("cut")) {
            QVERIFY(file.resize(file.size() - 100));
        } else {
            file.seek(5000);
            const char c = file.read(1).at(0);
            file.seek(5000);
            file.write(QByteArray(1, char(c ^ 0x04)));
        }
    }
    const FaceDetectorLoad again = loadFaceDetector(m_cacheDir);
    QCOMPARE(again.cache, CacheUse::Built);
    QVERIFY2(again.cacheNote.contains(expected), qPrintable(again.cacheNote));
    QCOMPARE(again.fingerprint, built.fingerprint);
    QCOMPARE(loadFaceDetector(m_cacheDir).cache, CacheUse::Used);
}

namespace {

int suiteMain(int argc, char *argv[])
{
    if (argc == 4 && qstrcmp(argv[1], kChildArgument) == 0) {
        const LandmarkModelLoad load
            = loadLandmarkModel(QString::fromLocal8Bit(argv[2]), QString::fromLocal8Bit(argv[3]));
        if (!load.model) {
            std::fprintf(stderr, "%s\n", qPrintable(load.error));
            return 1;
        }
        std::printf("%s\n", load.cache == Cache::Built ? "built" : load.cache == Cache::Used ? "used" : "other");
        return 0;
    }
    QCoreApplication app(argc, argv);
    TestModelCache test;
    return QTest::qExec(&test, argc, argv);
}

} // namespace

TOONFACE_TEST_REGISTER(suiteMain)

#include "tst_modelcache.moc"
