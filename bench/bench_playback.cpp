#include "benchmark.h"
#include "benchtimeline.h"

#include "anim/timelineevaluator.h"
#include "document/document.h"
#include "face/averageface.h"
#include "playback/playhead.h"
#include "render/svgface.h"
#include "views/previewrenderer.h"

#include <QEventLoop>
#include <QPainter>
#include <QSvgRenderer>

#include <algorithm>
#include <random>

using namespace toonface;

namespace {

constexpr QSize kPreviewSize(512, 512);

// The ten-minute talking timeline with a pose track (a key every 5 s moving mouth and brows).
Timeline benchTimeline(double fps)
{
    Timeline timeline = bench::tenMinuteTimeline();
    timeline.setFrameRate(fps);
    std::mt19937 rng(5);
    auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    for (double t = 0; t < 600; t += 5.0) {
        PoseKey key;
        key.time = t;
        for (const char *id : {"8.4", "8.3", "4.2", "4.1"})
            key.offsetsEs0.insert(QString::fromLatin1(id), QPointF(uniform(-0.05, 0.05), uniform(-0.05, 0.05)));
        timeline.addPoseKey(key);
    }
    return timeline;
}

void fill(Document &document, double fps)
{
    Project project;
    project.face = averageFace(QRectF(106, 130, 300, 330), kPreviewSize);
    project.style = Style::preset(QStringLiteral("normal"));
    project.timeline = benchTimeline(fps);
    document.reset(project, QImage(), {}, true);
}

struct Stats
{
    double median = 0;
    double p95 = 0;
    double max = 0;
};

Stats stats(QVector<double> ms)
{
    std::sort(ms.begin(), ms.end());
    if (ms.isEmpty())
        return {};
    return {ms[ms.size() / 2], ms[std::min(ms.size() - 1, qsizetype(ms.size() * 0.95))], ms.last()};
}

void insert(QJsonObject &r, const QString &name, const Stats &s)
{
    r.insert(name + QStringLiteral("Median"), s.median);
    r.insert(name + QStringLiteral("P95"), s.p95);
    r.insert(name + QStringLiteral("Max"), s.max);
}

// Milliseconds from `change` to the renderer's next picture, through the event loop as in the editor.
double msToPicture(PreviewRenderer &renderer, const std::function<void()> &change)
{
    QEventLoop loop;
    const auto connection = QObject::connect(&renderer, &PreviewRenderer::frameReady, &loop, &QEventLoop::quit);
    QElapsedTimer clock;
    clock.start();
    change();
    loop.exec();
    const double ms = clock.nsecsElapsed() / 1e6;
    QObject::disconnect(connection);
    return ms;
}

} // namespace

// Scrub latency: the playhead moved to a random time of a ten-minute project -> the preview's
// 512x512 picture of that pose ready (evaluate + SVG + QSvgRenderer, one event-loop turn).
// Also an edit's latency: an animation change (a pose drag's move) -> the picture, which
// rebuilds the evaluator of the whole timeline first.
TOONFACE_BENCHMARK("playback.scrubLatency512", [] {
    Document document;
    fill(document, 25);
    Playhead playhead;
    PreviewRenderer renderer(&document, &playhead);
    renderer.setImageSize(kPreviewSize);
    renderer.flush();

    std::mt19937 rng(11);
    QVector<double> scrub;
    for (int i = 0; i < 300; ++i) {
        const double t = std::uniform_real_distribution<double>(0, 600)(rng);
        scrub.append(msToPicture(renderer, [&] { playhead.setTime(t); }));
    }
    QVector<double> edit;
    for (int i = 0; i < 40; ++i) {
        Animation animation = document.animation();
        PoseKey key;
        key.time = playhead.time();
        key.offsetsEs0.insert(QStringLiteral("8.4"), QPointF(-0.001 * i, 0));
        animation.timeline.addPoseKey(key);
        edit.append(
            msToPicture(renderer, [&] { document.changeAnimation(animation, QStringLiteral("drag"), 77, false); }));
    }
    QJsonObject r;
    insert(r, QStringLiteral("scrubMs"), stats(scrub));
    insert(r, QStringLiteral("editMs"), stats(edit));
    r.insert(QStringLiteral("backgroundFrames"), renderer.backgroundFrames());
    r.insert(QStringLiteral("targetMs"), 16.0);
    return r;
});

// The work of one playback frame at 30 fps, 512x512, frame after frame through ten seconds of
// the ten-minute project: evaluate, SVG, parse + rasterise, and their sum per frame.
TOONFACE_BENCHMARK("playback.frameBudget30fps", [] {
    constexpr double fps = 30;
    const FaceModel face = averageFace(QRectF(106, 130, 300, 330), kPreviewSize);
    const Timeline timeline = benchTimeline(fps);
    const MouthShapeSet shapes;
    const TimelineEvaluator evaluator(timeline, face, shapes);
    SvgFace svgFace(face, Style::preset(QStringLiteral("normal")));
    const QRectF frame = headFrame(face, 1.0);
    svgFace.setFrame(frame);

    QVector<double> evaluateMs;
    QVector<double> svgMs;
    QVector<double> rasterMs;
    QVector<double> totalMs;
    QImage image(kPreviewSize, QImage::Format_ARGB32_Premultiplied);
    qint64 sink = 0;
    const int first = int(120 * fps);
    for (int f = first; f < first + int(10 * fps); ++f) {
        QElapsedTimer clock;
        clock.start();
        const Pose pose = evaluator.evaluate(f / fps);
        const qint64 a = clock.nsecsElapsed();
        const QByteArray svg = svgFace.svg(pose);
        const qint64 b = clock.nsecsElapsed();
        image.fill(Qt::white);
        QSvgRenderer renderer(svg);
        QPainter painter(&image);
        painter.setRenderHints(QPainter::Antialiasing | QPainter::SmoothPixmapTransform);
        renderer.setViewBox(frame);
        renderer.render(&painter, QRectF(QPointF(), QSizeF(kPreviewSize)));
        painter.end();
        const qint64 c = clock.nsecsElapsed();
        sink += image.pixel(256, 256);
        evaluateMs.append(a / 1e6);
        svgMs.append((b - a) / 1e6);
        rasterMs.append((c - b) / 1e6);
        totalMs.append(c / 1e6);
    }
    const double budget = 1000.0 / fps;
    QJsonObject r;
    insert(r, QStringLiteral("evaluateMs"), stats(evaluateMs));
    insert(r, QStringLiteral("svgMs"), stats(svgMs));
    insert(r, QStringLiteral("rasterMs"), stats(rasterMs));
    insert(r, QStringLiteral("frameMs"), stats(totalMs));
    r.insert(QStringLiteral("budgetMs"), budget);
    r.insert(QStringLiteral("framesOverBudget"),
        double(std::count_if(totalMs.begin(), totalMs.end(), [&](double ms) { return ms > budget; })));
    r.insert(QStringLiteral("frames"), double(totalMs.size()));
    r.insert(QStringLiteral("evaluatorBuildMs"),
        bench::medianMs([&] { TimelineEvaluator rebuilt(timeline, face, shapes); }, 5, 300));
    r.insert(QStringLiteral("checksum"), sink != 0);
    return r;
});
