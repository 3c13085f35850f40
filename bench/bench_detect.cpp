#include "benchmark.h"

#include "detect/detector.h"
#include "detect/landmarkmap.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QPainter>
#include <QRegularExpression>

#include <algorithm>
#include <ctime>

using namespace toonface;

namespace {

const QString kGrace = QStringLiteral("/usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg");

// The portrait fitted into a frame of the given size (aspect kept, grey borders), as a webcam
// frame or a video still of that size would hold it.
QImage framed(const QImage &photo, QSize size)
{
    const QImage fitted = photo.scaled(size, Qt::KeepAspectRatio, Qt::SmoothTransformation);
    QImage frame(size, QImage::Format_RGB32);
    frame.fill(QColor(128, 128, 128));
    QPainter p(&frame);
    p.drawImage((size.width() - fitted.width()) / 2, (size.height() - fitted.height()) / 2, fitted);
    p.end();
    return frame;
}

double median(std::vector<double> v)
{
    if (v.empty())
        return 0;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// Median wall time per stage over repeated detections with `method` (the landmark model is
// loaded before timing; the classic method needs none).
QJsonObject stageTimes(const QImage &image, int runs = 15, DetectionMethod method = DetectionMethod::Auto)
{
    QString error;
    if (method != DetectionMethod::Classic && !preloadLandmarkModel(&error))
        return {{QStringLiteral("skipped"), error}};
    DetectOptions options;
    options.method = method;
    QMap<QString, std::vector<double>> times;
    std::vector<double> cpu;
    DetectionResult r;
    for (int i = 0; i < runs; ++i) {
        const std::clock_t c0 = std::clock();
        r = detectFace(image, options);
        cpu.push_back(1000.0 * double(std::clock() - c0) / CLOCKS_PER_SEC);
        for (auto it = r.timingMs.cbegin(); it != r.timingMs.cend(); ++it)
            times[it.key()].push_back(it.value());
    }
    QJsonObject out;
    out.insert(QStringLiteral("method"), detectionMethodName(method));
    out.insert(QStringLiteral("size"), QStringLiteral("%1x%2").arg(image.width()).arg(image.height()));
    out.insert(QStringLiteral("status"), int(r.status));
    out.insert(QStringLiteral("faceCount"), r.faceCount);
    QJsonObject ms;
    for (auto it = times.cbegin(); it != times.cend(); ++it)
        ms.insert(it.key(), median(it.value()));
    out.insert(QStringLiteral("medianMs"), ms);
    // Processor time of the whole call (one thread): less disturbed than wall time when
    // other processes share the cores.
    out.insert(QStringLiteral("medianCpuMs"), median(cpu));
    out.insert(QStringLiteral("runs"), runs);
    return out;
}

} // namespace

// Parsing dlib's 100 MB landmark model file, without the cache (startup.modelCache times the
// cache).
static QJsonObject benchModelLoad()
{
    const QString path = landmarkModelPath();
    const QFileInfo info(path);
    if (!info.isFile())
        return QJsonObject {{QStringLiteral("skipped"), QStringLiteral("no model at %1").arg(path)}};
    const LandmarkModelLoad load = loadLandmarkModel(path, QString());
    QJsonObject r;
    r.insert(QStringLiteral("ok"), bool(load.model));
    r.insert(QStringLiteral("loadMs"), load.ms);
    r.insert(QStringLiteral("modelBytes"), double(info.size()));
    if (!load.model)
        r.insert(QStringLiteral("error"), load.error);
    return r;
}

static QJsonObject benchGrace640()
{
    const QImage photo(kGrace);
    if (photo.isNull())
        return QJsonObject {{QStringLiteral("skipped"), QStringLiteral("%1 missing").arg(kGrace)}};
    return stageTimes(framed(photo, QSize(640, 480)));
}

static QJsonObject benchGrace1080()
{
    const QImage photo(kGrace);
    if (photo.isNull())
        return QJsonObject {{QStringLiteral("skipped"), QStringLiteral("%1 missing").arg(kGrace)}};
    return stageTimes(framed(photo, QSize(1920, 1080)));
}

// The thesis pipeline on the same frames: its stages are hsi, regions, eyePair, eyeballs, edges,
// features, featurePoints, outline (classic.cpp); it works on a copy at most 640 px wide.
static QJsonObject benchClassic640()
{
    const QImage photo(kGrace);
    if (photo.isNull())
        return QJsonObject {{QStringLiteral("skipped"), QStringLiteral("%1 missing").arg(kGrace)}};
    return stageTimes(framed(photo, QSize(640, 480)), 15, DetectionMethod::Classic);
}

static QJsonObject benchClassic1080()
{
    const QImage photo(kGrace);
    if (photo.isNull())
        return QJsonObject {{QStringLiteral("skipped"), QStringLiteral("%1 missing").arg(kGrace)}};
    return stageTimes(framed(photo, QSize(1920, 1080)), 15, DetectionMethod::Classic);
}

// Auto on every portrait at hand, each fitted into a 640x480 frame (a webcam frame's size):
// the public-domain portraits the project installs and the shared research photos.
static QJsonObject benchPhotos640()
{
    QStringList paths {kGrace, QStringLiteral("/usr/lib/python3/dist-packages/skimage/data/astronaut.png")};
    const QString dataDir = bench::sharedDataDir();
    if (!dataDir.isEmpty()) {
        const QDir dir(QDir(dataDir).filePath(QStringLiteral("faces")));
        for (const QFileInfo &f :
            dir.entryInfoList({QStringLiteral("*.png"), QStringLiteral("*.jpg")}, QDir::Files, QDir::Name))
            paths.append(f.filePath());
    }
    QJsonObject out;
    std::vector<double> totals, cpus;
    for (const QString &path : paths) {
        const QImage photo(path);
        if (photo.isNull())
            continue;
        const QJsonObject r = stageTimes(framed(photo, QSize(640, 480)));
        out.insert(QFileInfo(path).fileName(), r);
        // The worst of the photos whose face was found; a face too small for the frame (the
        // whole figure of a person in a 640x480 frame) costs every pass and is listed apart.
        if (r.value(QStringLiteral("status")).toInt() != int(DetectStatus::Ok)) {
            QJsonArray missed = out.value(QStringLiteral("noFace")).toArray();
            missed.append(QFileInfo(path).fileName());
            out.insert(QStringLiteral("noFace"), missed);
            continue;
        }
        totals.push_back(r.value(QStringLiteral("medianMs")).toObject().value(QStringLiteral("total")).toDouble());
        cpus.push_back(r.value(QStringLiteral("medianCpuMs")).toDouble());
    }
    out.insert(QStringLiteral("photosWithAFace"), int(totals.size()));
    out.insert(QStringLiteral("worstMedianMs"), totals.empty() ? 0.0 : *std::max_element(totals.begin(), totals.end()));
    out.insert(QStringLiteral("worstMedianCpuMs"), cpus.empty() ? 0.0 : *std::max_element(cpus.begin(), cpus.end()));
    return out;
}

// The worst case: no face, so every detection pass runs.
static QJsonObject benchNoFace()
{
    QImage blank(640, 480, QImage::Format_RGB32);
    blank.fill(QColor(128, 128, 128));
    return stageTimes(blank, 5);
}

// Landmark accuracy on the research photos (300-W NME, shared/data/README.md protocol) for
// one method: per image and the mean over the images where a face was placed.
static QJsonObject nmeTable(DetectionMethod method)
{
    const QString dataDir = bench::sharedDataDir();
    if (dataDir.isEmpty())
        return QJsonObject {{QStringLiteral("skipped"), QStringLiteral("no shared data (TOONFACE_DATA_DIR)")}};
    QString error;
    if (method != DetectionMethod::Classic && !preloadLandmarkModel(&error))
        return QJsonObject {{QStringLiteral("skipped"), error}};
    const QDir dir(QDir(dataDir).filePath(QStringLiteral("faces")));
    DetectOptions options;
    options.method = method;
    QJsonArray rows;
    double sum = 0;
    int n = 0;
    for (const QFileInfo &pts : dir.entryInfoList({QStringLiteral("*.pts")}, QDir::Files, QDir::Name)) {
        QString imagePath;
        for (const char *ext : {".png", ".jpg"})
            if (QFileInfo::exists(dir.filePath(pts.completeBaseName() + QLatin1String(ext))))
                imagePath = dir.filePath(pts.completeBaseName() + QLatin1String(ext));
        std::array<QPointF, kIbugPointCount> truth {};
        if (imagePath.isEmpty() || !readIbugPts(pts.filePath(), &truth))
            continue;
        const QImage image(imagePath);
        const DetectionResult r = detectFace(image, options);
        QJsonObject row;
        row.insert(QStringLiteral("image"), QFileInfo(imagePath).fileName());
        row.insert(QStringLiteral("size"), QStringLiteral("%1x%2").arg(image.width()).arg(image.height()));
        row.insert(QStringLiteral("faceCount"), r.faceCount);
        row.insert(QStringLiteral("totalMs"), r.timingMs.value(QStringLiteral("total")));
        if (r.status == DetectStatus::Ok) {
            const double nme = normalizedMeanError(r.face, truth);
            row.insert(QStringLiteral("nme"), nme);
            sum += nme;
            ++n;
        } else {
            row.insert(QStringLiteral("error"), r.error);
        }
        rows.append(row);
    }
    QJsonObject out;
    out.insert(QStringLiteral("method"), detectionMethodName(method));
    out.insert(QStringLiteral("images"), rows);
    out.insert(QStringLiteral("detected"), n);
    out.insert(QStringLiteral("meanNme"), n ? sum / n : 0.0);
    return out;
}

static QJsonObject benchNme()
{
    return nmeTable(DetectionMethod::Auto);
}

static QJsonObject benchNmeLandmarks()
{
    return nmeTable(DetectionMethod::Landmarks);
}

static QJsonObject benchNmeClassic()
{
    return nmeTable(DetectionMethod::Classic);
}

TOONFACE_BENCHMARK("detect.modelLoad", benchModelLoad);
TOONFACE_BENCHMARK("detect.grace640x480", benchGrace640);
TOONFACE_BENCHMARK("detect.grace1920x1080", benchGrace1080);
TOONFACE_BENCHMARK("detect.photos640x480", benchPhotos640);
TOONFACE_BENCHMARK("detect.noFace640x480", benchNoFace);
TOONFACE_BENCHMARK("detect.classic640x480", benchClassic640);
TOONFACE_BENCHMARK("detect.classic1920x1080", benchClassic1080);
TOONFACE_BENCHMARK("detect.nme", benchNme);
TOONFACE_BENCHMARK("detect.nmeLandmarks", benchNmeLandmarks);
TOONFACE_BENCHMARK("detect.nmeClassic", benchNmeClassic);
