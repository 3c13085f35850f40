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

// Median wall time per stage over repeated detections (the model is loaded before timing).
QJsonObject stageTimes(const QImage &image, int runs = 15)
{
    QString error;
    if (!preloadLandmarkModel(&error))
        return {{QStringLiteral("skipped"), error}};
    QMap<QString, std::vector<double>> times;
    std::vector<double> cpu;
    DetectionResult r;
    for (int i = 0; i < runs; ++i) {
        const std::clock_t c0 = std::clock();
        r = detectFace(image);
        cpu.push_back(1000.0 * double(std::clock() - c0) / CLOCKS_PER_SEC);
        for (auto it = r.timingMs.cbegin(); it != r.timingMs.cend(); ++it)
            times[it.key()].push_back(it.value());
    }
    QJsonObject out;
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

bool readPts(const QString &path, std::array<QPointF, kIbugPointCount> *pts)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
        return false;
    const QString text = QString::fromUtf8(file.readAll());
    const int open = text.indexOf(QLatin1Char('{')), close = text.indexOf(QLatin1Char('}'));
    const QStringList nums
        = text.mid(open + 1, close - open - 1).split(QRegularExpression(QStringLiteral("\\s+")), Qt::SkipEmptyParts);
    if (open < 0 || close < open || nums.size() != 2 * kIbugPointCount)
        return false;
    for (int i = 0; i < kIbugPointCount; ++i)
        (*pts)[i] = QPointF(nums[2 * i].toDouble() - 1, nums[2 * i + 1].toDouble() - 1);
    return true;
}

} // namespace

// Loading the 100 MB landmark model. The model is cached per path, so the same file is named
// by an equivalent path ("dir/./file") to force a fresh load; the variable is restored after.
static QJsonObject benchModelLoad()
{
    const QString path = landmarkModelPath();
    const QFileInfo info(path);
    QJsonObject r;
    if (!info.isFile())
        return QJsonObject {{QStringLiteral("skipped"), QStringLiteral("no model at %1").arg(path)}};
    const QByteArray old = qgetenv("TOONFACE_LANDMARK_MODEL");
    const bool had = qEnvironmentVariableIsSet("TOONFACE_LANDMARK_MODEL");
    qputenv(
        "TOONFACE_LANDMARK_MODEL", QFile::encodeName(info.absolutePath() + QStringLiteral("/./") + info.fileName()));
    double ms = 0;
    QString error;
    const bool ok = preloadLandmarkModel(&error, &ms);
    if (had)
        qputenv("TOONFACE_LANDMARK_MODEL", old);
    else
        qunsetenv("TOONFACE_LANDMARK_MODEL");
    r.insert(QStringLiteral("ok"), ok);
    r.insert(QStringLiteral("loadMs"), ms);
    r.insert(QStringLiteral("modelBytes"), double(info.size()));
    if (!ok)
        r.insert(QStringLiteral("error"), error);
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

// The worst case: no face, so every detection pass runs.
static QJsonObject benchNoFace()
{
    QImage blank(640, 480, QImage::Format_RGB32);
    blank.fill(QColor(128, 128, 128));
    return stageTimes(blank, 5);
}

// Landmark accuracy on the research photos (300-W NME, shared/data/README.md protocol).
static QJsonObject benchNme()
{
    const QString dataDir = bench::sharedDataDir();
    if (dataDir.isEmpty())
        return QJsonObject {{QStringLiteral("skipped"), QStringLiteral("no shared data (TOONFACE_DATA_DIR)")}};
    const QDir dir(QDir(dataDir).filePath(QStringLiteral("faces")));
    QJsonArray rows;
    double sum = 0;
    int n = 0;
    for (const QFileInfo &pts : dir.entryInfoList({QStringLiteral("*.pts")}, QDir::Files, QDir::Name)) {
        QString imagePath;
        for (const char *ext : {".png", ".jpg"})
            if (QFileInfo::exists(dir.filePath(pts.completeBaseName() + QLatin1String(ext))))
                imagePath = dir.filePath(pts.completeBaseName() + QLatin1String(ext));
        std::array<QPointF, kIbugPointCount> truth {};
        if (imagePath.isEmpty() || !readPts(pts.filePath(), &truth))
            continue;
        const QImage image(imagePath);
        const DetectionResult r = detectFace(image);
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
    out.insert(QStringLiteral("images"), rows);
    out.insert(QStringLiteral("detected"), n);
    out.insert(QStringLiteral("meanNme"), n ? sum / n : 0.0);
    return out;
}

TOONFACE_BENCHMARK("detect.modelLoad", benchModelLoad);
TOONFACE_BENCHMARK("detect.grace640x480", benchGrace640);
TOONFACE_BENCHMARK("detect.grace1920x1080", benchGrace1080);
TOONFACE_BENCHMARK("detect.noFace640x480", benchNoFace);
TOONFACE_BENCHMARK("detect.nme", benchNme);
