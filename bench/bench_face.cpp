#include "benchmark.h"

#include "face/averageface.h"
#include "face/emotion.h"
#include "face/mouthshape.h"
#include "face/pose.h"

using namespace toonface;

TOONFACE_BENCHMARK("face.posedPoints", [] {
    const FaceModel face = averageFace(QRectF(100, 100, 300, 360), QSize(512, 512));
    const MouthShapeSet shapes;
    const Pose pose = mouthPose(face, shapes, MouthShape::A) + emotionPose(face, Emotion::Smile, 0.7);
    double sink = 0;
    const double ms = bench::medianMs([&] {
        for (int i = 0; i < 1000; ++i)
            sink += posedPoints(face, pose)[i % kPointCount].x();
    });
    QJsonObject r;
    r.insert(QStringLiteral("usPerPose"), ms); // 1000 poses per run: ms per run == µs per pose
    r.insert(QStringLiteral("checksum"), sink > 0);
    return r;
});
