#include "benchmark.h"

#include "capture/framedecoder.h"
#include "capture/videoview.h"
#include "document/document.h"
#include "export/videoencoder.h"
#include "playback/playhead.h"
#include "track/videofilesource.h"

#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QJsonArray>
#include <QPainter>
#include <QTemporaryDir>
#include <QTimer>

#include <algorithm>
#include <cmath>

using namespace toonface;

namespace {

// The Video dock during playback of a GRID clip (360x288, 25 fps): the playhead advances in real
// time at `speed` times the clip's rate, ticking every 1000/60 ms as the playback clock does;
// how many of the clip's frames were shown, how many requests were dropped, and the delay from
// the playhead reaching a frame's time to that frame on screen.
QJsonObject playClip(const QString &clip, double speed)
{
    Document document;
    Project project;
    project.timeline.setVideo(VideoClip {clip, 0.0, 3.0, 25.0});
    document.reset(project, QImage(), {}, false);
    Playhead playhead;
    VideoView view(&document, &playhead);
    if (!view.decoder()->isOpen())
        return {{QStringLiteral("error"), view.text()}};
    const int frames = std::max(1, view.decoder()->frameCount());
    const double duration = frames / 25.0;

    QVector<double> latencyMs;
    QVector<qint64> wantedAt(frames, -1); // when the playhead first reached each frame
    QElapsedTimer clock;
    int shown = 0;
    QObject::connect(&view, &VideoView::frameShown, [&](int index) {
        ++shown;
        if (index >= 0 && index < frames && wantedAt[index] >= 0)
            latencyMs.append((clock.nsecsElapsed() - wantedAt[index]) / 1e6);
    });
    QEventLoop loop;
    QTimer tick;
    tick.setInterval(1000 / 60);
    QObject::connect(&tick, &QTimer::timeout, [&] {
        const double t = clock.nsecsElapsed() / 1e9 * speed;
        if (t >= duration) {
            loop.quit();
            return;
        }
        const int index = int(t * 25.0 + 1e-9);
        if (wantedAt[index] < 0)
            wantedAt[index] = clock.nsecsElapsed();
        playhead.setTime(t);
    });
    clock.start();
    tick.start();
    loop.exec();
    std::sort(latencyMs.begin(), latencyMs.end());
    QJsonObject r;
    r.insert(QStringLiteral("clipFrames"), frames);
    r.insert(QStringLiteral("framesShown"), shown);
    r.insert(QStringLiteral("requestsDropped"), view.decoder()->droppedRequests());
    if (!latencyMs.isEmpty()) {
        r.insert(QStringLiteral("latencyMedianMs"), latencyMs[latencyMs.size() / 2]);
        r.insert(QStringLiteral("latencyP95Ms"),
            latencyMs[std::min(latencyMs.size() - 1, qsizetype(latencyMs.size() * 0.95))]);
    }
    return r;
}

// The GRID clip at `speed` times its rate, or an error when the research data is absent.
QJsonObject playGrid(double speed)
{
    const QString path = QDir(bench::sharedDataDir()).filePath(QStringLiteral("video/bbaf2n.mpg"));
    if (!QFileInfo::exists(path))
        return QJsonObject {{QStringLiteral("error"), QStringLiteral("the GRID clip video/bbaf2n.mpg is absent")}};
    return playClip(path, speed);
}

} // namespace

TOONFACE_BENCHMARK("videoview.playback25fps", [] { return playGrid(1.0); });
TOONFACE_BENCHMARK("videoview.playback4x", [] { return playGrid(4.0); });

namespace {

// Jumps in a ten-minute clip (360x288, 25 fps, a key frame every 2 s as the MP4 export writes):
// from the playhead's frame to one far ahead, back near the start, to the middle, as a user
// clicking on the timeline does; how long each takes to be on screen and how many frames it
// decoded.
QJsonObject jumpTenMinutes()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("ten-minutes.mp4"));
    const double fps = 25;
    const int frames = int(600 * fps);
    {
        VideoWriter writer;
        QString error;
        if (!writer.open(path, VideoFormat::Mp4, QSize(360, 288), fps, AudioSource {}, &error))
            return {{QStringLiteral("error"), error}};
        QImage image(360, 288, QImage::Format_RGB32);
        for (int i = 0; i < frames; ++i) {
            image.fill(QColor::fromHsv(i % 360, 120, 200));
            QPainter(&image).fillRect(i % 300, 100, 60, 88, Qt::black);
            if (!writer.addFrame(image, &error))
                return {{QStringLiteral("error"), error}};
        }
        if (!writer.finish(&error))
            return {{QStringLiteral("error"), error}};
    }
    FrameDecoder decoder;
    QString error;
    if (!decoder.open(path, &error))
        return {{QStringLiteral("error"), error}};
    QJsonArray jumps;
    for (const int target : {0, 14037, 14038, 261, 7519, 3044, 11999, 123}) {
        QEventLoop loop;
        const QMetaObject::Connection a
            = QObject::connect(&decoder, &FrameDecoder::frameReady, &loop, &QEventLoop::quit);
        const QMetaObject::Connection b = QObject::connect(&decoder, &FrameDecoder::failed, &loop, &QEventLoop::quit);
        const int before = decoder.framesDecoded();
        QElapsedTimer t;
        t.start();
        decoder.request(target);
        loop.exec();
        QObject::disconnect(a);
        QObject::disconnect(b);
        QJsonObject j;
        j.insert(QStringLiteral("to"), target);
        j.insert(QStringLiteral("ms"), std::round(t.nsecsElapsed() / 1e5) / 10);
        j.insert(QStringLiteral("framesDecoded"), decoder.framesDecoded() - before);
        jumps.append(j);
    }
    // What a jump far ahead cost when the decoder could only read on: every frame up to it.
    VideoFileSource source;
    QElapsedTimer t;
    t.start();
    int read = 0;
    if (source.open(path, &error)) {
        while (std::optional<VideoFrame> f = source.next()) {
            if (++read > 14037)
                break;
        }
    }
    return {{QStringLiteral("what"),
                QStringLiteral("Video dock frame decoder: jumps in a 10-minute 360x288 MP4 (key frame every 2 s)")},
        {QStringLiteral("jumps"), jumps}, {QStringLiteral("readingOnTo14037Ms"), std::round(t.nsecsElapsed() / 1e6)}};
}

} // namespace

TOONFACE_BENCHMARK("videoview.jumpTenMinutes", jumpTenMinutes);
