#include "face/fapu.h"

#include "face/facemodel.h"

#include <QLineF>

#include <cmath>

namespace toonface {

Fapu Fapu::measure(const FaceModel &face)
{
    auto dist = [&](const char *a, const char *b) { return QLineF(face.point(a), face.point(b)).length(); };
    Fapu f;
    const QPointF l = face.point("3.6");
    const QPointF r = face.point("3.5");
    f.eyeMid = (l + r) / 2.0;
    f.es0 = QLineF(l, r).length();
    f.ens0 = std::abs(face.point("9.15").y() - f.eyeMid.y());
    f.mns0 = std::abs(face.point("2.2").y() - face.point("9.15").y());
    f.mw0 = dist("8.4", "8.3");
    f.leftEyeH = dist("3.2", "3.4");
    f.rightEyeH = dist("3.1", "3.3");
    f.upperLipH = dist("8.1", "2.2");
    f.lowerLipH = dist("2.3", "8.2");
    f.jawH = std::abs(face.point("2.1").y() - face.point("8.2").y());
    return f;
}

} // namespace toonface
