#include "benchmark.h"

#include "face/averageface.h"
#include "face/emotion.h"
#include "face/mouthshape.h"
#include "face/pose.h"
#include "render/svgface.h"

#include <QPainter>
#include <QSvgRenderer>

using namespace toonface;

namespace {

FaceModel benchFace()
{
    return averageFace(QRectF(106, 130, 300, 330), QSize(512, 512));
}

Pose benchPose(const FaceModel &face)
{
    Pose pose = mouthPose(face, MouthShapeSet(), MouthShape::A) + emotionPose(face, Emotion::Smile, 0.7);
    pose.leftEyeOpen = 0.5;
    pose.head.rotationDeg = 4;
    return pose;
}

} // namespace

// The SVG of one pose: what every preview frame and every exported frame costs.
TOONFACE_BENCHMARK("render.svgOfOnePose", [] {
    const FaceModel face = benchFace();
    const Pose pose = benchPose(face);
    QJsonObject r;
    qsizetype bytes = 0;
    for (const QString &name : {QStringLiteral("normal"), QStringLiteral("cute")}) {
        const SvgFace svgFace(face, Style::preset(name));
        const double ms = bench::medianMs([&] {
            for (int i = 0; i < 100; ++i)
                bytes = svgFace.svg(pose).size();
        });
        r.insert(QStringLiteral("msPerPose.%1").arg(name), ms / 100.0);
    }
    const SvgFace svgFace(face, Style::preset(QStringLiteral("normal")));
    const double partsMs = bench::medianMs([&] {
        for (int i = 0; i < 100; ++i)
            bytes += svgFace.parts(pose).size() > 0 ? 0 : 1;
    });
    r.insert(QStringLiteral("msPerParts"), partsMs / 100.0);
    r.insert(QStringLiteral("svgBytes"), double(svgFace.svg(pose).size()));
    r.insert(QStringLiteral("targetMs"), 0.2);
    return r;
});

// QSvgRenderer rasterizing that SVG at 512x512, with and without parsing it again.
TOONFACE_BENCHMARK("render.raster512", [] {
    const FaceModel face = benchFace();
    const QByteArray svg = SvgFace(face, Style::preset(QStringLiteral("normal"))).svg(benchPose(face));
    qint64 sink = 0;
    const double total = bench::medianMs([&] { sink += rasterizeSvg(svg, QSize(512, 512)).width(); }, 20, 500);
    QSvgRenderer renderer(svg);
    QImage image(512, 512, QImage::Format_ARGB32_Premultiplied);
    const double paintOnly = bench::medianMs(
        [&] {
            image.fill(Qt::white);
            QPainter p(&image);
            p.setRenderHint(QPainter::Antialiasing);
            renderer.render(&p);
        },
        20, 500);
    QJsonObject r;
    r.insert(QStringLiteral("msRasterizeSvg"), total);
    r.insert(QStringLiteral("msPaintOnly"), paintOnly);
    r.insert(QStringLiteral("targetMs"), 5.0);
    r.insert(QStringLiteral("checksum"), sink > 0);
    return r;
});
