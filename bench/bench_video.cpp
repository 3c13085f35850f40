#include "benchmark.h"

#include "export/videoencoder.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QPainter>
#include <QPainterPath>
#include <QTemporaryDir>
#include <QThread>

#include <cmath>
#include <numbers>

using namespace toonface;

namespace {

constexpr double kFps = 25;
constexpr int kSeconds = 10;
constexpr int kFrames = int(kFps) * kSeconds;
const QSize kSize(512, 512);

// A cartoon face like the renderer draws: flat fills with dark outlines, antialiased edges;
// the mouth opens and closes, the eyes blink and the head sways, so every frame differs.
QImage cartoonFrame(int i)
{
    const double t = i / kFps;
    QImage image(kSize, QImage::Format_ARGB32_Premultiplied);
    image.fill(QColor(0xf4, 0xef, 0xe6));
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    p.translate(256 + 6 * std::sin(t * 1.3), 270 + 3 * std::sin(t * 0.7));
    p.rotate(4 * std::sin(t * 0.9));
    const QPen outline(QColor(0x5a, 0x3b, 0x22), 3);

    p.setPen(Qt::NoPen);
    p.setBrush(QColor(0x33, 0x22, 0x1a)); // hair behind the face
    p.drawEllipse(QPointF(0, -40), 170, 190);
    p.setPen(outline);
    p.setBrush(QColor(0xf2, 0xc9, 0xa0));
    p.drawEllipse(QPointF(-150, 10), 28, 45); // ears
    p.drawEllipse(QPointF(150, 10), 28, 45);
    p.drawEllipse(QPointF(0, 20), 150, 185); // face
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(0x33, 0x22, 0x1a)); // fringe
    QPainterPath fringe;
    fringe.moveTo(-150, -40);
    fringe.cubicTo(-120, -190, 120, -190, 150, -40);
    fringe.cubicTo(60, -110, -60, -110, -150, -40);
    p.drawPath(fringe);

    const bool blinking = std::fmod(t, 3.1) < 0.16;
    for (int side : {-1, 1}) {
        p.setPen(QPen(QColor(0x33, 0x22, 0x1a), 7, Qt::SolidLine, Qt::RoundCap));
        p.setBrush(Qt::NoBrush);
        p.drawArc(QRectF(side * 60 - 38, -65, 76, 30), 20 * 16, 140 * 16); // eyebrow
        p.setPen(outline);
        if (blinking) {
            p.drawLine(QPointF(side * 60 - 30, -10), QPointF(side * 60 + 30, -10));
            continue;
        }
        p.setBrush(Qt::white);
        p.drawEllipse(QPointF(side * 60, -10), 32, 20);
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(0x3b, 0x2a, 0x1e));
        p.drawEllipse(QPointF(side * 60 + 6 * std::sin(t * 0.5), -10), 12, 12);
        p.setBrush(Qt::white);
        p.drawEllipse(QPointF(side * 60 + 4 + 6 * std::sin(t * 0.5), -14), 3.5, 3.5);
    }
    p.setPen(outline);
    p.setBrush(Qt::NoBrush);
    p.drawArc(QRectF(-14, 30, 28, 24), 200 * 16, 140 * 16); // nose

    // The mouth opens with a syllable rhythm of about 4 Hz.
    const double open = std::max(0.0, std::sin(t * 2 * std::numbers::pi * 3.7)) * (0.6 + 0.4 * std::sin(t * 1.1));
    const double h = 4 + 38 * open;
    const double w = 70 - 14 * open;
    p.setBrush(QColor(0x6b, 0x1f, 0x1f));
    p.setPen(QPen(QColor(0xb8, 0x4a, 0x4a), 4));
    p.drawEllipse(QPointF(0, 105), w / 2, h / 2);
    if (h > 16) {
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(0xd9, 0x6b, 0x6b)); // tongue
        p.drawEllipse(QPointF(0, 105 + h / 4), w / 4, h / 6);
    }
    p.end();
    return image;
}

QVector<float> tone(double seconds, int rate)
{
    QVector<float> s(qsizetype(seconds * rate));
    for (qsizetype i = 0; i < s.size(); ++i)
        s[i] = float(0.3 * std::sin(2 * std::numbers::pi * 220 * double(i) / rate));
    return s;
}

qint64 totalBytes(const QString &path)
{
    const QFileInfo info(path);
    if (!info.isDir())
        return info.size();
    qint64 sum = 0;
    for (const QFileInfo &f : QDir(path).entryInfoList(QDir::Files))
        sum += f.size();
    return sum;
}

// Encodes the pre-rendered frames (so only the writer is timed) and reports its speed.
QJsonObject measure(VideoFormat format, const QString &name, const VideoOptions &options, bool withAudio)
{
    static const QVector<QImage> frames = [] {
        QVector<QImage> f;
        for (int i = 0; i < kFrames; ++i)
            f.append(cartoonFrame(i));
        return f;
    }();
    QTemporaryDir dir;
    const QString path = dir.filePath(name);
    const AudioSource audio = withAudio ? AudioSource::fromSamples(tone(kSeconds, 16000), 16000) : AudioSource {};
    QString error;
    bool ok = true;
    const double ms = bench::medianMs(
        [&] {
            ok = ok
                && writeVideo(
                    path, format, kSize, kFps, kFrames, [&](int i) { return frames[i]; }, audio, &error, options);
        },
        3, 0);
    QJsonObject r;
    if (!ok) {
        r.insert(QStringLiteral("error"), error);
        return r;
    }
    r.insert(QStringLiteral("frames"), kFrames);
    r.insert(QStringLiteral("videoSeconds"), kSeconds);
    r.insert(QStringLiteral("encodeMs"), ms);
    r.insert(QStringLiteral("framesPerSecond"), kFrames / (ms / 1000));
    r.insert(QStringLiteral("realTimeMultiple"), kSeconds / (ms / 1000));
    r.insert(QStringLiteral("bytes"), totalBytes(path));
    r.insert(QStringLiteral("kbitPerSecond"), totalBytes(path) * 8.0 / 1000 / kSeconds);
    return r;
}

// The machine's load while measuring (other work on the same cores slows the encoder down).
QString loadAverage()
{
    QFile f(QStringLiteral("/proc/loadavg"));
    return f.open(QIODevice::ReadOnly) ? QString::fromLatin1(f.readLine()).section(QLatin1Char(' '), 0, 2) : QString();
}

} // namespace

// MP4 at 512x512 (the target: at least 5x real time on 2 cores), with its sound.
TOONFACE_BENCHMARK("video.mp4", [] {
    QJsonObject r = measure(VideoFormat::Mp4, QStringLiteral("bench.mp4"), {}, true);
    r.insert(QStringLiteral("cores"), QThread::idealThreadCount());
    r.insert(QStringLiteral("loadAverage"), loadAverage());
    VideoOptions oneThread;
    oneThread.threads = 1;
    r.insert(QStringLiteral("oneThread"), measure(VideoFormat::Mp4, QStringLiteral("bench1.mp4"), oneThread, true));
    VideoOptions slower;
    slower.preset = QStringLiteral("medium");
    r.insert(QStringLiteral("presetMedium"), measure(VideoFormat::Mp4, QStringLiteral("benchm.mp4"), slower, true));
    return r;
});

TOONFACE_BENCHMARK("video.gif", [] { return measure(VideoFormat::Gif, QStringLiteral("bench.gif"), {}, false); });

TOONFACE_BENCHMARK("video.png", [] { return measure(VideoFormat::PngSequence, QStringLiteral("frames"), {}, false); });
