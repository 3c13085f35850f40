#include "benchmark.h"

#include "capture/livesession.h"
#include "document/document.h"
#include "face/averageface.h"
#include "render/style.h"
#include "track/videofilesource.h"

#include <QEventLoop>
#include <QFileInfo>
#include <QJsonArray>
#include <QTimer>

#include <algorithm>
#include <chrono>
#include <thread>

using namespace toonface;

namespace {

constexpr QSize kPreviewSize(512, 512);

// Decoded frames replayed as a camera at `fps` would deliver them: each at its time after the
// first next(), frames the reader is more than a period late for dropped.
class PacedFrames : public FrameSource
{
public:
    PacedFrames(QVector<QImage> frames, double fps, int count)
        : m_frames(std::move(frames))
        , m_fps(fps)
        , m_count(count)
    { }

    std::optional<VideoFrame> next() override
    {
        if (!m_clock.isValid())
            m_clock.start();
        for (; m_next < m_count && !m_stopped; ++m_next) {
            const double due = m_next / m_fps;
            const double now = m_clock.nsecsElapsed() / 1e9;
            if (now - due > 1.0 / m_fps) {
                ++m_dropped;
                continue;
            }
            while (!m_stopped && m_clock.nsecsElapsed() / 1e9 < due)
                std::this_thread::sleep_for(std::chrono::microseconds(500));
            const int i = m_next++;
            return VideoFrame {m_frames[i % m_frames.size()], due, i};
        }
        return std::nullopt;
    }
    double frameRate() const override { return m_fps; }
    QSize frameSize() const override { return m_frames.isEmpty() ? QSize() : m_frames.first().size(); }
    int frameCount() const override { return m_count; }
    void stop() override { m_stopped = true; }
    int dropped() const { return m_dropped; }

private:
    QVector<QImage> m_frames;
    double m_fps;
    int m_count;
    int m_next = 0;
    int m_dropped = 0;
    std::atomic_bool m_stopped {false};
    QElapsedTimer m_clock;
};

double percentile(QVector<double> values, double p)
{
    if (values.isEmpty())
        return 0;
    std::sort(values.begin(), values.end());
    return values[std::min(values.size() - 1, qsizetype(p * double(values.size() - 1) + 0.5))];
}

// Runs a live session on `source` until it ends, the GUI thread taking each picture as a
// preview would; the figures.
QJsonObject runLive(std::unique_ptr<FrameSource> source, int sourceDropped(const FrameSource *))
{
    Document document;
    Project project;
    project.face = averageFace(QRectF(106, 130, 300, 330), kPreviewSize);
    project.style = Style::preset(QStringLiteral("normal"));
    document.reset(project, QImage(), {}, true);
    LiveSession session(&document);
    session.setImageSize(kPreviewSize);
    QEventLoop loop;
    QObject::connect(&session, &LiveSession::finished, &loop, &QEventLoop::quit);
    const double fps = source->frameRate();
    FrameSource *raw = source.get();
    int dropped = 0;
    QObject::connect(&session, &LiveSession::finished, &loop, [&] { dropped = sourceDropped(raw); });
    session.start(std::move(source));
    QTimer::singleShot(60000, &loop, &QEventLoop::quit);
    loop.exec();
    const LiveFigures f = session.figures();
    QJsonObject out;
    out[QStringLiteral("fps")] = fps;
    out[QStringLiteral("previewSize")] = QStringLiteral("%1x%2").arg(kPreviewSize.width()).arg(kPreviewSize.height());
    out[QStringLiteral("sourceDropped")] = dropped;
    out[QStringLiteral("delivered")] = f.delivered;
    out[QStringLiteral("shown")] = f.shown;
    out[QStringLiteral("replaced")] = f.replaced;
    out[QStringLiteral("shownPerDelivered")] = f.delivered > 0 ? double(f.shown) / f.delivered : 0.0;
    out[QStringLiteral("facesLost")] = f.lost;
    out[QStringLiteral("restPose")] = session.hasRestPose();
    out[QStringLiteral("readyMsMedian")] = percentile(f.readyMs, 0.5);
    out[QStringLiteral("readyMsP95")] = percentile(f.readyMs, 0.95);
    out[QStringLiteral("shownMsMedian")] = percentile(f.shownMs, 0.5);
    out[QStringLiteral("shownMsP95")] = percentile(f.shownMs, 0.95);
    return out;
}

QJsonObject benchLive()
{
    const QString dir = bench::sharedDataDir();
    const QString clip = dir + QStringLiteral("/video/bbaf2n.mpg");
    if (dir.isEmpty() || !QFileInfo::exists(clip))
        return {{QStringLiteral("skipped"), QStringLiteral("the GRID clips of shared/data/video are absent")}};
    QJsonObject out;
    out[QStringLiteral("what")] = QStringLiteral(
        "live mode: a paced source -> tracker -> cartoon drawn at 512x512 on the worker -> taken by the GUI thread; "
        "latency from a frame's arrival to its picture drawn (ready) and taken by the GUI (shown)");

    // The GRID clip at its own pace (25 fps).
    auto file = std::make_unique<VideoFileSource>();
    VideoFileSource::Options options;
    options.paced = true;
    QString error;
    if (!file->open(clip, options, &error))
        return {{QStringLiteral("error"), error}};
    out[QStringLiteral("clip")] = runLive(
        std::move(file), [](const FrameSource *s) { return static_cast<const VideoFileSource *>(s)->droppedFrames(); });

    // Its frames replayed as a 30 fps camera for 6 s.
    VideoFileSource decoder;
    if (!decoder.open(clip, &error))
        return {{QStringLiteral("error"), error}};
    QVector<QImage> frames;
    while (std::optional<VideoFrame> f = decoder.next())
        frames.append(f->image);
    out[QStringLiteral("camera30")] = runLive(std::make_unique<PacedFrames>(frames, 30.0, 180),
        [](const FrameSource *s) { return static_cast<const PacedFrames *>(s)->dropped(); });
    return out;
}

} // namespace

TOONFACE_BENCHMARK("live", benchLive);
