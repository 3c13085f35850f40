#include "benchmark.h"

#include "export/animationexport.h"
#include "export/exportpreset.h"
#include "face/averageface.h"
#include "media/mediareader.h"

#include <QDir>
#include <QDirIterator>
#include <QFileInfo>
#include <QJsonArray>
#include <QTemporaryDir>

#include <cmath>

#include <sys/resource.h>

using namespace toonface;

namespace {

const QString kPortrait = QStringLiteral("/usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg");

// Bytes of a file, or of every file in a folder (PNG frames).
qint64 bytesOf(const QString &path)
{
    const QFileInfo info(path);
    if (!info.isDir())
        return info.size();
    qint64 total = 0;
    QDirIterator it(path, QDir::Files);
    while (it.hasNext())
        total += QFileInfo(it.next()).size();
    return total;
}

// A 3-second sticker of Grace Hopper's talking face in every transparent format (and MP4 for
// comparison): toonface-cli animate of her project (made once: detection and speech are not
// measured), 25 fps, the automatic size; per format the file's size and the process's wall and CPU time.
QJsonObject benchStickers()
{
    if (!QFileInfo::exists(kPortrait))
        return {{QStringLiteral("skipped"), QStringLiteral("grace_hopper.jpg is absent")}};
    QTemporaryDir dir;
    const QString project = dir.filePath(QStringLiteral("grace.toonface"));
    const QStringList env = {QStringLiteral("QT_QPA_PLATFORM=offscreen")};
    const bench::ChildRun made = bench::runMeasured(QStringLiteral(TOONFACE_CLI_PATH),
        {QStringLiteral("animate"), kPortrait, QStringLiteral("--say"),
            QStringLiteral("Hello there, this is a talking sticker made from one photo of my face."),
            QStringLiteral("--project"), project, QStringLiteral("-o"), dir.filePath(QStringLiteral("grace.svg"))},
        env, true);
    if (!made.ok)
        return {{QStringLiteral("error"), QString::fromUtf8(made.stderrText)}};

    struct Case
    {
        const char *name;
        QString output;
        QStringList options;
    };
    const QStringList sticker = {QStringLiteral("--duration"), QStringLiteral("3")};
    const QStringList size512 = {QStringLiteral("--duration"), QStringLiteral("3"), QStringLiteral("--background"),
        QStringLiteral("transparent")};
    const Case cases[] = {
        {"telegram-sticker", QStringLiteral("sticker.webm"),
            sticker + QStringList {u"--preset"_qs, u"telegram-sticker"_qs}},
        {"emoji", QStringLiteral("emoji.webm"), sticker + QStringList {u"--preset"_qs, u"emoji"_qs}},
        {"webm", QStringLiteral("clip.webm"), size512},
        {"mov", QStringLiteral("clip.mov"), size512},
        {"apng", QStringLiteral("clip.apng"), size512},
        {"webp", QStringLiteral("clip.webp"), size512},
        {"gif", QStringLiteral("clip.gif"), size512},
        {"png frames", QStringLiteral("frames/"), size512},
        {"mp4 (opaque)", QStringLiteral("clip.mp4"), sticker},
    };
    QJsonObject r;
    for (const Case &c : cases) {
        const QString out = dir.filePath(c.output);
        QStringList args = {QStringLiteral("animate"), project, QStringLiteral("-o"), out};
        args += c.options;
        const bench::ChildRun run = bench::runMeasured(QStringLiteral(TOONFACE_CLI_PATH), args, env, true);
        if (!run.ok) {
            r.insert(
                QLatin1StringView(c.name), QJsonObject {{QStringLiteral("error"), QString::fromUtf8(run.stderrText)}});
            continue;
        }
        QString side;
        if (const std::optional<MediaInfo> info = probeMedia(out, nullptr); info && info->width > 0)
            side = QStringLiteral("%1x%2").arg(info->width).arg(info->height);
        r.insert(QLatin1StringView(c.name),
            QJsonObject {{QStringLiteral("kb"), std::round(bytesOf(out) / 102.4) / 10.0},
                {QStringLiteral("frameSize"), side}, {QStringLiteral("wallMs"), qRound(run.wallMs)},
                {QStringLiteral("cpuMs"), qRound(run.cpuMs)}, {QStringLiteral("peakMb"), qRound(run.peakMb)}});
    }
    r.insert(QStringLiteral("clip"),
        QStringLiteral("3 s of Grace Hopper talking, 25 fps, the automatic frame size (presets: their own)"));
    r.insert(QStringLiteral("telegramLimitKb"), 256);
    return r;
}

double cpuMs()
{
    rusage u {};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) * 1000.0
        + double(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1000.0;
}

// A sticker over its size limit: the preset's tries at lower quality encode the frames its first
// try drew. A 3-second 512-pixel talking face (the average face, mouth shapes changing every
// 0.15 s, blinks, a head shake) whose limit is 40 % of its first try's size: the CPU time of one
// try (drawing and encoding) against the whole preset export, its tries and the frames drawn.
QJsonObject benchStickerRetries()
{
    ExportRequest r;
    r.face = averageFace(QRectF(106, 130, 300, 330), QSize(512, 512));
    r.style = Style::preset(QStringLiteral("normal"));
    QVector<MouthCue> cues;
    for (int i = 0; i < 20; ++i)
        cues.append({i * 0.15, (i + 1) * 0.15, kAllMouthShapes[size_t(i) % kAllMouthShapes.size()]});
    r.timeline.setFrameRate(30);
    r.timeline.addMouthCues(cues);
    r.timeline.generateBlinks(29, 3.0);
    r.timeline.addShake(0.2, 2.6, 10.0, 1.5);
    ExportPreset preset = *exportPresetNamed(QStringLiteral("telegram-sticker"));
    QTemporaryDir dir;
    ExportRequest first = withPreset(r, preset);
    first.outputPath = dir.filePath(QStringLiteral("first.webm"));
    first.vp9Crf = 30; // the preset's first try
    const double before = cpuMs();
    const ExportResult one = exportAnimation(first);
    const double oneTry = cpuMs() - before;
    if (!one.ok())
        return {{QStringLiteral("error"), one.error}};
    preset.maxBytes = QFileInfo(first.outputPath).size() * 4 / 10;
    r.outputPath = dir.filePath(QStringLiteral("sticker.webm"));
    const double start = cpuMs();
    const ExportResult fitted = exportWithPreset(r, preset);
    const double all = cpuMs() - start;
    if (!fitted.ok())
        return {{QStringLiteral("error"), fitted.error}};
    return {{QStringLiteral("frames"), exportFrameCount(withPreset(r, preset))},
        {QStringLiteral("limitKb"), std::round(double(preset.maxBytes) / 102.4) / 10.0},
        {QStringLiteral("kb"), std::round(double(QFileInfo(r.outputPath).size()) / 102.4) / 10.0},
        {QStringLiteral("encodings"), fitted.encodings}, {QStringLiteral("framesDrawn"), fitted.framesDrawn},
        {QStringLiteral("cpuMsOneTry"), qRound(oneTry)}, {QStringLiteral("cpuMsPreset"), qRound(all)},
        {QStringLiteral("cpuMsIfEveryTryDrew"), qRound(oneTry * fitted.encodings)}};
}

} // namespace

TOONFACE_BENCHMARK("export.stickers", benchStickers);
TOONFACE_BENCHMARK("export.stickerRetries", benchStickerRetries);
