#include "render/svgface.h"
#include "face/averageface.h"
#include "face/mouthshape.h"
#include "face/pose.h"
#include <QRegularExpression>
#include <cstdio>
using namespace toonface;
static QVector<double> nums(const QString &s) {
    QVector<double> v; static QRegularExpression re(QStringLiteral("-?[0-9]*\\.?[0-9]+"));
    auto it = re.globalMatch(s); while (it.hasNext()) v.append(it.next().captured().toDouble()); return v; }
int main() {
    FaceModel face = averageFace(QRectF(100, 100, 300, 360), QSize(512, 512));
    Style style = Style::preset(QStringLiteral("normal"));
    SvgFace svg(face, style);
    MouthShapeSet shapes;
    MouthShape pairs[][2] = {{MouthShape::M, MouthShape::A}, {MouthShape::A, MouthShape::I}, {MouthShape::O, MouthShape::E}, {MouthShape::F, MouthShape::U}};
    for (auto &pr : pairs) {
        Pose a = mouthPose(face, shapes, pr[0]), b = mouthPose(face, shapes, pr[1]);
        auto pa = svg.parts(a), pb = svg.parts(b);
        QMap<QString, double> worst;
        for (int k = 1; k < 200; ++k) {
            double s = k / 200.0;
            auto pm = svg.parts(Pose::lerp(a, b, s));
            for (int i = 0; i < pm.size(); ++i) {
                for (auto it = pm[i].geometry.begin(); it != pm[i].geometry.end(); ++it) {
                    auto vm = nums(it.value()), va = nums(pa[i].geometry[it.key()]), vb = nums(pb[i].geometry[it.key()]);
                    if (vm.size() != va.size() || vm.size() != vb.size()) { printf("size mismatch %s\n", qPrintable(pm[i].id)); continue; }
                    double w = 0; for (int j = 0; j < vm.size(); ++j) w = std::max(w, std::abs(vm[j] - (va[j] + (vb[j]-va[j])*s)));
                    QString key = pm[i].id + QLatin1Char('.') + it.key();
                    worst[key] = std::max(worst[key], w);
                }
            }
        }
        printf("%d->%d\n", int(pr[0]), int(pr[1]));
        for (auto it = worst.begin(); it != worst.end(); ++it) if (it.value() > 0.011) printf("  %s %.3f\n", qPrintable(it.key()), it.value());
    }
    auto n = svg.parts(); printf("ES0 %f\n", face.fapu().es0);
    for (auto &p : n) printf("%s %s %s\n", qPrintable(p.id), qPrintable(p.layer), qPrintable(p.geometry.values().join(QLatin1Char('|'))));
}
