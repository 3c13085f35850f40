// Start-up: what a new process pays before its first points. The landmark model's load with
// and without its cache, the first detection of a process against its tenth, toonface-cli's
// whole process (detect, cartoon) with a cold and a warm model cache beside a plain dlib
// program doing detector + predictor, and the editor from launch to the points on screen.
// Each measurement of a whole process runs it anew (QProcess) on a 640x480 portrait.

#include "benchmark.h"

#include "detect/detector.h"
#include "detect/facescan.h"
#include "detect/modelcache.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QGuiApplication>
#include <QImage>
#include <QJsonArray>
#include <QPainter>
#include <QProcess>
#include <QTemporaryDir>

#include <sys/resource.h>

#include <algorithm>
#include <optional>

using namespace toonface;

namespace {

const QString kGrace = QStringLiteral("/usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg");
constexpr int kDetections = 10;

double median(std::vector<double> v)
{
    if (v.empty())
        return 0;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

QJsonArray toArray(const std::vector<double> &v)
{
    QJsonArray a;
    for (double x : v)
        a.append(std::round(x * 10) / 10);
    return a;
}

// The portrait in a 640x480 frame (grey borders), as a JPEG in `dir`; empty when missing.
QString writePortrait(const QDir &dir)
{
    const QImage photo(kGrace);
    if (photo.isNull())
        return {};
    const QImage fitted = photo.scaled(640, 480, Qt::KeepAspectRatio, Qt::SmoothTransformation);
    QImage frame(640, 480, QImage::Format_RGB32);
    frame.fill(QColor(128, 128, 128));
    QPainter p(&frame);
    p.drawImage((640 - fitted.width()) / 2, (480 - fitted.height()) / 2, fitted);
    p.end();
    const QString path = dir.filePath(QStringLiteral("portrait640x480.jpg"));
    return frame.save(path, "JPEG", 92) ? path : QString();
}

struct ProcessRun
{
    bool ok = false;
    double wallMs = 0;
    double cpuMs = 0; // user + system of the child
    QString error;
};

double childCpuMs()
{
    rusage usage {};
    getrusage(RUSAGE_CHILDREN, &usage);
    return usage.ru_utime.tv_sec * 1e3 + usage.ru_utime.tv_usec / 1e3 + usage.ru_stime.tv_sec * 1e3
        + usage.ru_stime.tv_usec / 1e3;
}

ProcessRun runProcess(const QString &program, const QStringList &args, const QProcessEnvironment &env)
{
    ProcessRun run;
    QProcess process;
    process.setProcessEnvironment(env);
    const double cpu0 = childCpuMs();
    QElapsedTimer timer;
    timer.start();
    process.start(program, args);
    const bool finished = process.waitForFinished(120000);
    run.wallMs = timer.nsecsElapsed() / 1e6;
    run.cpuMs = childCpuMs() - cpu0;
    run.ok = finished && process.exitStatus() == QProcess::NormalExit && process.exitCode() == 0;
    if (!run.ok)
        run.error = QString::fromLocal8Bit(process.readAllStandardError()).trimmed();
    return run;
}

QProcessEnvironment environmentWith(const QString &cacheDir)
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("TOONFACE_CACHE_DIR"), cacheDir);
    return env;
}

// Runs `program args` `runs` times; each run with a fresh empty cache folder when `cold`,
// else with `warmCache`. Median wall and processor times, and the runs' wall times.
QJsonObject timeProcess(
    const QString &program, const QStringList &args, int runs, bool cold, const QString &warmCache, const QDir &scratch)
{
    std::vector<double> wall, cpu;
    for (int i = 0; i < runs; ++i) {
        QString cache = warmCache;
        if (cold) {
            cache = scratch.filePath(QStringLiteral("cold-cache-%1").arg(i));
            QDir(cache).removeRecursively();
        }
        const ProcessRun run = runProcess(program, args, environmentWith(cache));
        if (!run.ok)
            return {{QStringLiteral("error"), run.error}};
        wall.push_back(run.wallMs);
        cpu.push_back(run.cpuMs);
        if (cold)
            QDir(cache).removeRecursively();
    }
    return {{QStringLiteral("medianWallMs"), median(wall)}, {QStringLiteral("medianCpuMs"), median(cpu)},
        {QStringLiteral("wallMs"), toArray(wall)}};
}

// The caches (the landmark model's and the face detector's) made once for the whole-process
// measurements that want them warm.
QString warmCacheIn(const QDir &scratch)
{
    const QString dir = scratch.filePath(QStringLiteral("warm-cache"));
    loadLandmarkModel(landmarkModelPath(), dir);
    loadFaceDetector(dir);
    return dir;
}

} // namespace

// The landmark model read from dlib's file, and through its cache: built (the first run) and
// used (every later one).
static QJsonObject benchModelCache()
{
    const QString model = landmarkModelPath();
    if (!QFile::exists(model))
        return {{QStringLiteral("skipped"), QStringLiteral("no model at %1").arg(model)}};
    QTemporaryDir dir;
    std::vector<double> built, used;
    LandmarkModelLoad last;
    for (int i = 0; i < 3; ++i) {
        const QString cache = dir.filePath(QStringLiteral("cache-%1").arg(i));
        last = loadLandmarkModel(model, cache);
        if (last.cache != LandmarkModelLoad::Cache::Built)
            return {{QStringLiteral("error"), last.cacheNote + last.error}};
        built.push_back(last.ms);
    }
    for (int i = 0; i < 15; ++i) {
        last = loadLandmarkModel(model, dir.filePath(QStringLiteral("cache-0")));
        if (last.cache != LandmarkModelLoad::Cache::Used)
            return {{QStringLiteral("error"), last.cacheNote}};
        used.push_back(last.ms);
    }
    // dlib's file decoded by the project's reader (shapemodelfile.h), and through dlib's own
    // stream deserialisation, the way it was read before.
    std::vector<double> parsed, parsedByDlib;
    for (int i = 0; i < 5; ++i) {
        QElapsedTimer t;
        t.start();
        LandmarkPredictor::read(model, nullptr);
        parsed.push_back(t.nsecsElapsed() / 1e6);
    }
    for (int i = 0; i < 3; ++i) {
        QElapsedTimer t;
        t.start();
        LandmarkPredictor::readThroughDlib(model, nullptr);
        parsedByDlib.push_back(t.nsecsElapsed() / 1e6);
    }
    return {{QStringLiteral("parseModelFileMedianMs"), median(parsed)},
        {QStringLiteral("parseModelFileThroughDlibMedianMs"), median(parsedByDlib)},
        {QStringLiteral("buildCacheMedianMs"), median(built)}, {QStringLiteral("loadFromCacheMedianMs"), median(used)},
        {QStringLiteral("loadFromCacheMs"), toArray(used)}, {QStringLiteral("modelBytes"), QFileInfo(model).size()},
        {QStringLiteral("cacheBytes"), QFileInfo(last.cachePath).size()}};
}

// In a process of its own: `kDetections` detections of IMAGE one after the other. MODE
// "cli": the models' warm-up starts with the process, as toonface-cli's does, and the
// detections follow at once (the first waits for what it needs of it); "warmed": they follow the
// warm-up's end, as a photo opened in the editor after launch; "none": no warm-up, the model
// loaded before (the one-time work falls on the first detection).
static QJsonObject childDetections(const QStringList &args)
{
    QElapsedTimer process;
    process.start();
    const QString mode = args.value(1);
    if (mode == QLatin1StringView("cli"))
        warmUpDetectionModels();
    else if (mode == QLatin1StringView("warmed"))
        warmUpDetection();
    int argc = 1;
    char name[] = "toonface-bench";
    char *argv[] = {name, nullptr};
    QGuiApplication app(argc, argv);
    if (mode == QLatin1StringView("warmed"))
        waitForDetectionWarmUp();
    if (mode == QLatin1StringView("none"))
        preloadLandmarkModel();
    const QImage image(args.value(0));
    std::vector<double> calls, totals;
    QJsonObject firstStages, lastStages;
    double firstDoneAt = 0;
    for (int i = 0; i < kDetections; ++i) {
        QElapsedTimer t;
        t.start();
        const DetectionResult r = detectFace(image);
        calls.push_back(t.nsecsElapsed() / 1e6);
        if (r.status != DetectStatus::Ok)
            return {{QStringLiteral("error"), r.error}};
        totals.push_back(r.timingMs.value(QStringLiteral("total")));
        QJsonObject stages;
        for (auto it = r.timingMs.cbegin(); it != r.timingMs.cend(); ++it)
            stages.insert(it.key(), std::round(it.value() * 10) / 10);
        if (i == 0) {
            firstStages = stages;
            firstDoneAt = process.nsecsElapsed() / 1e6;
        }
        lastStages = stages;
    }
    waitForDetectionWarmUp();
    return {{QStringLiteral("callMs"), toArray(calls)}, {QStringLiteral("firstStagesMs"), firstStages},
        {QStringLiteral("tenthStagesMs"), lastStages}, {QStringLiteral("firstPointsAtMs"), firstDoneAt}};
}

// The first detection of a process against its tenth (medians over several processes).
static QJsonObject benchFirstVsTenth()
{
    QTemporaryDir dir;
    const QString portrait = writePortrait(QDir(dir.path()));
    if (portrait.isEmpty() || !QFile::exists(landmarkModelPath()))
        return {{QStringLiteral("skipped"), QStringLiteral("no portrait or no landmark model")}};
    const QString cache = warmCacheIn(QDir(dir.path()));
    QJsonObject out;
    for (const QString &mode : {QStringLiteral("warmed"), QStringLiteral("cli"), QStringLiteral("none")}) {
        std::vector<double> first, tenth, firstTotal, tenthTotal, at;
        QJsonObject sample;
        for (int run = 0; run < 5; ++run) {
            const QJsonObject r = bench::runChild(
                QStringLiteral("detections"), {portrait, mode}, {QStringLiteral("TOONFACE_CACHE_DIR=") + cache});
            if (r.contains(QStringLiteral("error")))
                return r;
            const QJsonArray calls = r.value(QStringLiteral("callMs")).toArray();
            first.push_back(calls.first().toDouble());
            tenth.push_back(calls.last().toDouble());
            firstTotal.push_back(
                r.value(QStringLiteral("firstStagesMs")).toObject().value(QStringLiteral("total")).toDouble());
            tenthTotal.push_back(
                r.value(QStringLiteral("tenthStagesMs")).toObject().value(QStringLiteral("total")).toDouble());
            at.push_back(r.value(QStringLiteral("firstPointsAtMs")).toDouble());
            sample = r;
        }
        out.insert(mode,
            QJsonObject {{QStringLiteral("firstCallMedianMs"), median(first)},
                {QStringLiteral("tenthCallMedianMs"), median(tenth)},
                {QStringLiteral("firstTotalMedianMs"), median(firstTotal)},
                {QStringLiteral("tenthTotalMedianMs"), median(tenthTotal)},
                {QStringLiteral("firstOverTenth"), median(first) / std::max(median(tenth), 1e-3)},
                {QStringLiteral("firstPointsSinceProcessStartMedianMs"), median(at)},
                {QStringLiteral("lastRun"), sample}});
    }
    return out;
}

// toonface-cli detect and cartoon, whole process, cold and warm model cache, beside the plain
// dlib program on the same photo.
static QJsonObject benchCli()
{
    QTemporaryDir dir;
    const QDir scratch(dir.path());
    const QString portrait = writePortrait(scratch);
    const QString model = landmarkModelPath();
    if (portrait.isEmpty() || !QFile::exists(model))
        return {{QStringLiteral("skipped"), QStringLiteral("no portrait or no landmark model")}};
    const QString cli = QStringLiteral(TOONFACE_CLI_PATH);
    const QString cache = warmCacheIn(scratch);
    const QStringList detect {
        QStringLiteral("detect"), portrait, QStringLiteral("-o"), scratch.filePath(QStringLiteral("face.json"))};
    const QStringList cartoon {
        QStringLiteral("cartoon"), portrait, QStringLiteral("-o"), scratch.filePath(QStringLiteral("face.svg"))};
    QJsonObject out;
    out.insert(QStringLiteral("image"), QStringLiteral("grace_hopper.jpg in a 640x480 frame"));
    out.insert(QStringLiteral("detectWarmCache"), timeProcess(cli, detect, 9, false, cache, scratch));
    out.insert(QStringLiteral("detectColdCache"), timeProcess(cli, detect, 3, true, cache, scratch));
    out.insert(QStringLiteral("cartoonWarmCache"), timeProcess(cli, cartoon, 9, false, cache, scratch));
    out.insert(QStringLiteral("cartoonColdCache"), timeProcess(cli, cartoon, 3, true, cache, scratch));
    out.insert(QStringLiteral("plainDlib"),
        timeProcess(QStringLiteral(TOONFACE_PLAIN_DLIB_PATH), {model, portrait}, 5, false, cache, scratch));
    return out;
}

namespace {

// One launch of the editor with TOONFACE_TIMINGS: the events it printed (milliseconds since its
// main() began) and when the benchmark read them (since it started the process).
struct EditorRun
{
    QJsonObject editorMs;
    QJsonObject wallMs;
    QString error;
};

EditorRun launchEditor(const QString &photo, int openDelayMs, const QString &cache, const QDir &home)
{
    EditorRun run;
    QProcessEnvironment env = environmentWith(cache);
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    env.insert(QStringLiteral("TOONFACE_TIMINGS"), QStringLiteral("1"));
    env.insert(QStringLiteral("TOONFACE_TIMINGS_OPEN_DELAY_MS"), QString::number(openDelayMs));
    // A home of its own: no settings, recent files or unsaved work of earlier sessions.
    env.insert(QStringLiteral("HOME"), home.path());
    env.insert(QStringLiteral("XDG_CONFIG_HOME"), home.filePath(QStringLiteral("config")));
    env.insert(QStringLiteral("XDG_DATA_HOME"), home.filePath(QStringLiteral("data")));
    QProcess process;
    process.setProcessEnvironment(env);
    process.setProcessChannelMode(QProcess::SeparateChannels);
    QElapsedTimer timer;
    timer.start();
    process.start(QStringLiteral(TOONFACE_EDITOR_PATH), {photo});
    // The timings come on stderr: waitForReadyRead() waits on the channel read.
    process.setReadChannel(QProcess::StandardError);
    QByteArray pending;
    while (timer.elapsed() < 30000 && !run.editorMs.contains(QStringLiteral("points-shown"))) {
        if (!process.waitForReadyRead(30000 - int(timer.elapsed())) && process.state() != QProcess::Running)
            break;
        pending += process.readAllStandardError();
        const double at = timer.nsecsElapsed() / 1e6;
        while (pending.contains('\n')) {
            const QByteArray line = pending.left(pending.indexOf('\n'));
            pending.remove(0, line.size() + 1);
            const QList<QByteArray> words = line.split(' ');
            if (line.startsWith("toonface: timing: ") && words.size() == 4) {
                run.editorMs.insert(QString::fromLatin1(words[2]), words[3].toDouble());
                run.wallMs.insert(QString::fromLatin1(words[2]), at);
            }
        }
    }
    if (!run.editorMs.contains(QStringLiteral("points-shown")))
        run.error = QStringLiteral("the editor did not show the points: ") + QString::fromLocal8Bit(pending);
    process.kill();
    process.waitForFinished(5000);
    return run;
}

} // namespace

// The editor: launch to a usable window, and a 640x480 photo to its points on screen, opened
// with the launch or a second after it (detection warmed up meanwhile).
static QJsonObject benchEditor()
{
    QTemporaryDir dir;
    const QDir scratch(dir.path());
    const QString portrait = writePortrait(scratch);
    if (portrait.isEmpty() || !QFile::exists(landmarkModelPath()))
        return {{QStringLiteral("skipped"), QStringLiteral("no portrait or no landmark model")}};
    const QString cache = warmCacheIn(scratch);
    QJsonObject out;
    for (const int delay : {0, 1000}) {
        std::vector<double> usable, usableWall, points, openToPoints;
        QJsonObject sample;
        for (int i = 0; i < 5; ++i) {
            QTemporaryDir home;
            const EditorRun run = launchEditor(portrait, delay, cache, QDir(home.path()));
            if (!run.error.isEmpty())
                return {{QStringLiteral("error"), run.error}};
            usable.push_back(run.editorMs.value(QStringLiteral("window-usable")).toDouble());
            usableWall.push_back(run.wallMs.value(QStringLiteral("window-usable")).toDouble());
            points.push_back(run.wallMs.value(QStringLiteral("points-shown")).toDouble());
            openToPoints.push_back(run.editorMs.value(QStringLiteral("points-shown")).toDouble()
                - run.editorMs.value(QStringLiteral("open")).toDouble());
            sample = QJsonObject {{QStringLiteral("editorMs"), run.editorMs}, {QStringLiteral("wallMs"), run.wallMs}};
        }
        out.insert(delay == 0 ? QStringLiteral("photoAtLaunch") : QStringLiteral("photoOneSecondAfterLaunch"),
            QJsonObject {{QStringLiteral("launchToWindowUsableMedianMs"), median(usableWall)},
                {QStringLiteral("mainToWindowUsableMedianMs"), median(usable)},
                {QStringLiteral("launchToPointsMedianMs"), median(points)},
                {QStringLiteral("openToPointsMedianMs"), median(openToPoints)},
                {QStringLiteral("openToPointsMs"), toArray(openToPoints)}, {QStringLiteral("lastRun"), sample}});
    }
    return out;
}

TOONFACE_BENCH_CHILD("detections", childDetections);
TOONFACE_BENCHMARK("startup.modelCache", benchModelCache);
TOONFACE_BENCHMARK("startup.firstVsTenth", benchFirstVsTenth);
TOONFACE_BENCHMARK("startup.cli", benchCli);
TOONFACE_BENCHMARK("startup.editor", benchEditor);
