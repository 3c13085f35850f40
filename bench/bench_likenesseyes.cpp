#include "benchmark.h"
#include "crossvalidation.h"
#include "facecache.h"

#include "detect/labcolour.h"
#include "detect/photocolours.h"
#include "face/fapu.h"
#include "render/style.h"
#include "render/svgface.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QRegularExpression>
#include <QTextStream>

#include <cmath>
#include <ctime>
#include <map>

// likeness.eyes: the eyes drawn for every face of faces-attributes (research-only: measured here,
// never shipped). The drawn iris's hue against a by-eye label of each iris (dark, hazel, light:
// blue, green or grey) read from the file TOONFACE_IRIS_LABELS ("fa_sNNN<TAB>label" lines, "?"
// where the iris cannot be judged; kept outside the repository, as the data's licence asks),
// when given; the rank correlation of the drawn eyes' opening (lids' distance over width) and
// width against the face's with the photo's landmarks'; the drawn eye's size by age group; and
// how many faces of each age group are drawn as children. TOONFACE_FACE_CACHE=DIR keeps each
// face's detected points there.

using namespace toonface;

namespace {

struct EyeRow
{
    QString name, age;
    QString irisLabel = QStringLiteral("?");
    bool detected = false, drawnChild = false, drawnCool = false;
    QColor iris;
    double photoOpening = 0, photoWidth = 0, photoWidthToFace = 0;
    double drawnOpening = 0, drawnWidth = 0, drawnWidthToFace = 0;
};

QPointF cubicAt(const std::vector<QPointF> &v, size_t i, double t)
{
    const double s = 1 - t;
    return v[i] * (s * s * s) + v[i + 1] * (3 * s * s * t) + v[i + 2] * (3 * s * t * t) + v[i + 3] * (t * t * t);
}

// An eye outline's width and opening from its path (svgfacebuild.cpp's makeEye: M corner, the
// upper lid's cubic to the other corner, the lower lid's back).
std::pair<double, double> eyeOf(const QString &d)
{
    static const QRegularExpression number(QStringLiteral("-?[0-9]+(?:\\.[0-9]+)?"));
    std::vector<double> n;
    for (auto it = number.globalMatch(d); it.hasNext();)
        n.push_back(it.next().captured().toDouble());
    if (n.size() < 14)
        return {0, 0};
    std::vector<QPointF> v;
    for (size_t i = 0; i + 1 < n.size(); i += 2)
        v.emplace_back(n[i], n[i + 1]);
    const double width = QLineF(v[0], v[3]).length();
    const double opening = QLineF(cubicAt(v, 0, 0.5), cubicAt(v, 3, 0.5)).length();
    return {width, width > 0 ? opening / width : 0};
}

// The face's width at the eyes: between the cheeks' points at eye level.
double faceWidth(const FaceModel &face)
{
    return QLineF(face.point("5.1"), face.point("5.2")).length();
}

void measure(EyeRow *row, const QImage &photo, const FaceModel &face)
{
    Style style = Style::preset(QStringLiteral("normal"));
    sampleColours(photo, face, &style);
    row->iris = style.components.value(QStringLiteral("eyeballs")).fill;
    const LabColour lab = labOf(row->iris);
    const double hue = std::fmod(std::atan2(lab.b, lab.a) * 180.0 / M_PI + 360.0, 360.0);
    // Brown reads warm (an orange to yellow hue with some colour) or near black; anything else
    // (blue, green, grey) is a light iris's colour.
    row->drawnCool = !(lab.l < 30 || (std::hypot(lab.a, lab.b) > 8 && hue >= 20 && hue <= 100));
    row->drawnChild = style.appearance.age == AgeGroup::Child;
    auto at = [&](const char *id) { return face.point(id); };
    const double es0 = face.fapu().es0;
    const double wl = QLineF(at("3.12"), at("3.8")).length(), wr = QLineF(at("3.7"), at("3.11")).length();
    row->photoWidth = (wl + wr) / 2.0 / es0;
    row->photoOpening = (QLineF(at("3.2"), at("3.4")).length() / wl + QLineF(at("3.1"), at("3.3")).length() / wr) / 2.0;
    row->photoWidthToFace = (wl + wr) / 2.0 / faceWidth(face);
    const SvgFace drawing(face, style);
    const QVector<FacePart> parts = drawing.parts();
    double width = 0, opening = 0;
    int eyes = 0;
    for (const FacePart &p : parts) {
        if (p.id == QLatin1String("eye-left") || p.id == QLatin1String("eye-right")) {
            const auto [w, o] = eyeOf(p.geometry.value(QStringLiteral("d")));
            width += w;
            opening += o;
            ++eyes;
        }
    }
    if (eyes == 0)
        return;
    // The drawn eye distance (between the eyeballs' centres) and face width (the face outline's
    // widest span, sampled along its cubics).
    QPointF balls[2];
    double left = 1e300, right = -1e300;
    for (const FacePart &p : parts) {
        if (p.id == QLatin1String("eyeball-left") || p.id == QLatin1String("eyeball-right"))
            balls[p.id == QLatin1String("eyeball-right")] = QPointF(
                p.geometry.value(QStringLiteral("cx")).toDouble(), p.geometry.value(QStringLiteral("cy")).toDouble());
        if (p.id != QLatin1String("face"))
            continue;
        static const QRegularExpression number(QStringLiteral("-?[0-9]+(?:\\.[0-9]+)?"));
        std::vector<QPointF> v;
        std::vector<double> n;
        for (auto it = number.globalMatch(p.geometry.value(QStringLiteral("d"))); it.hasNext();)
            n.push_back(it.next().captured().toDouble());
        for (size_t i = 0; i + 1 < n.size(); i += 2)
            v.emplace_back(n[i], n[i + 1]);
        for (size_t i = 0; i + 3 < v.size(); i += 3) {
            for (int k = 0; k <= 10; ++k) {
                const double x = cubicAt(v, i, k / 10.0).x();
                left = std::min(left, x);
                right = std::max(right, x);
            }
        }
    }
    const double drawnEs0 = QLineF(balls[0], balls[1]).length();
    if (drawnEs0 <= 0 || right <= left)
        return;
    row->drawnWidth = width / eyes / drawnEs0;
    row->drawnOpening = opening / eyes;
    row->drawnWidthToFace = width / eyes / (right - left);
}

std::map<QString, QString> irisLabels()
{
    std::map<QString, QString> out;
    QFile f(qEnvironmentVariable("TOONFACE_IRIS_LABELS"));
    if (f.fileName().isEmpty() || !f.open(QIODevice::ReadOnly | QIODevice::Text))
        return out;
    QTextStream in(&f);
    while (!in.atEnd()) {
        const QStringList c = in.readLine().split(QLatin1Char('\t'));
        if (c.size() >= 2)
            out[c[0].trimmed()] = c[1].trimmed();
    }
    return out;
}

QJsonObject eyes()
{
    const QString data = bench::sharedDataDir();
    const QString dir = data.isEmpty() ? QString() : QDir(data).filePath(QStringLiteral("faces-attributes"));
    QFile tsv(QDir(dir).filePath(QStringLiteral("labels.tsv")));
    if (dir.isEmpty() || !tsv.open(QIODevice::ReadOnly | QIODevice::Text))
        return {{QStringLiteral("error"),
            QStringLiteral("faces-attributes/labels.tsv not found under the shared data folder")}};
    const std::map<QString, QString> iris = irisLabels();
    const std::clock_t cpu0 = std::clock();
    QTextStream in(&tsv);
    const QStringList header = in.readLine().split(QLatin1Char('\t'));
    const qsizetype fileCol = header.indexOf(QStringLiteral("file")),
                    ageCol = header.indexOf(QStringLiteral("age_group"));
    std::vector<EyeRow> rows;
    while (!in.atEnd()) {
        const QStringList c = in.readLine().split(QLatin1Char('\t'));
        if (c.size() < header.size())
            continue;
        EyeRow r;
        r.name = QFileInfo(c[fileCol]).completeBaseName();
        r.age = c[ageCol];
        if (auto it = iris.find(r.name); it != iris.end())
            r.irisLabel = it->second;
        const QImage photo(QDir(dir).filePath(c[fileCol]));
        if (photo.isNull())
            return {{QStringLiteral("error"), QStringLiteral("%1: not readable").arg(c[fileCol])}};
        if (const auto face = bench::detectCached(photo, r.name)) {
            r.detected = true;
            measure(&r, photo, *face);
        }
        rows.push_back(r);
    }
    const double cpuSeconds = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
    QStringList report;
    std::vector<double> po, dO, pw, dw;
    for (const EyeRow &r : rows) {
        if (!r.detected || r.drawnWidth <= 0)
            continue;
        po.push_back(r.photoOpening);
        dO.push_back(r.drawnOpening);
        pw.push_back(r.photoWidthToFace);
        dw.push_back(r.drawnWidthToFace);
    }
    report << QStringLiteral("faces %1, drawn %2; CPU %3 s").arg(rows.size()).arg(po.size()).arg(cpuSeconds, 0, 'f', 1);
    report << QStringLiteral("eye opening (lids / width), drawn vs landmarks: rank correlation %1")
                  .arg(bench::spearman(po, dO), 0, 'f', 3);
    report << QStringLiteral("eye width / face width, drawn vs landmarks: rank correlation %1")
                  .arg(bench::spearman(pw, dw), 0, 'f', 3);
    report << QStringLiteral(
        "by age group: median eye width (ES0) landmarks / drawn, opening landmarks / drawn, drawn as child");
    for (const char *group : {"child", "young", "adult", "elderly"}) {
        std::vector<double> a, b, c, d;
        int n = 0, child = 0;
        for (const EyeRow &r : rows) {
            if (r.age != QLatin1String(group) || !r.detected || r.drawnWidth <= 0)
                continue;
            ++n;
            child += r.drawnChild ? 1 : 0;
            a.push_back(r.photoWidth);
            b.push_back(r.drawnWidth);
            c.push_back(r.photoOpening);
            d.push_back(r.drawnOpening);
        }
        report << QStringLiteral("  %1 (%2): width %3 / %4, opening %5 / %6, drawn as child %7")
                      .arg(QLatin1String(group))
                      .arg(n)
                      .arg(bench::quantile(a, 0.5), 0, 'f', 3)
                      .arg(bench::quantile(b, 0.5), 0, 'f', 3)
                      .arg(bench::quantile(c, 0.5), 0, 'f', 3)
                      .arg(bench::quantile(d, 0.5), 0, 'f', 3)
                      .arg(child);
    }
    if (iris.empty()) {
        report << QStringLiteral("iris: no TOONFACE_IRIS_LABELS file; drawn cool (blue, green, grey) on %1 faces")
                      .arg(std::count_if(rows.begin(), rows.end(), [](const EyeRow &r) { return r.drawnCool; }));
    } else {
        report << QStringLiteral("iris label: drawn brown / drawn cool");
        for (const char *label : {"dark", "hazel", "light", "?"}) {
            int brown = 0, cool = 0;
            for (const EyeRow &r : rows) {
                if (r.detected && r.irisLabel == QLatin1String(label))
                    (r.drawnCool ? cool : brown) += 1;
            }
            report << QStringLiteral("  %1: %2 / %3").arg(QLatin1String(label)).arg(brown).arg(cool);
        }
    }
    QJsonArray perFace;
    for (const EyeRow &r : rows)
        perFace.append(QJsonObject {{QStringLiteral("file"), r.name}, {QStringLiteral("iris"), r.iris.name()},
            {QStringLiteral("cool"), r.drawnCool}, {QStringLiteral("child"), r.drawnChild}});
    QJsonObject out;
    out.insert(QStringLiteral("report"), QJsonArray::fromStringList(report));
    out.insert(QStringLiteral("load"), bench::loadAverage());
    if (qEnvironmentVariableIsSet("TOONFACE_LIKENESS_DUMP"))
        out.insert(QStringLiteral("faces"), perFace);
    return out;
}

} // namespace

TOONFACE_BENCHMARK("likeness.eyes", eyes);
