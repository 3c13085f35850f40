#include "benchmark.h"

#include "media/mediareader.h"

#include <QDir>
#include <QDirIterator>
#include <QFileInfo>
#include <QJsonArray>
#include <QTemporaryDir>

#include <cmath>

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

} // namespace

TOONFACE_BENCHMARK("export.stickers", benchStickers);
