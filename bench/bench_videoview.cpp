#include "benchmark.h"

#include "capture/framedecoder.h"
#include "capture/videoview.h"
#include "document/document.h"
#include "playback/playhead.h"

#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QTimer>

#include <algorithm>

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
