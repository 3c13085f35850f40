#include "io/facejson.h"

#include "detect/detector.h"
#include "face/fapu.h"
#include "i18n/coretext.h"
#include "io/jsonfield.h"
#include "io/pointsjson.h"

#include <QJsonArray>
#include <QPolygonF>
#include <QRegularExpression>

#include <utility>

namespace toonface {

namespace {

QJsonObject mapToJson(const QMap<QString, double> &map)
{
    QJsonObject o;
    for (auto it = map.cbegin(); it != map.cend(); ++it)
        o.insert(it.key(), it.value());
    return o;
}

QJsonObject boxToJson(const QRectF &r)
{
    QJsonObject o;
    o.insert(QStringLiteral("x"), r.x());
    o.insert(QStringLiteral("y"), r.y());
    o.insert(QStringLiteral("width"), r.width());
    o.insert(QStringLiteral("height"), r.height());
    return o;
}

QJsonArray pointToJson(QPointF p)
{
    return QJsonArray {p.x(), p.y()};
}

QJsonArray polygonToJson(const QPolygonF &poly)
{
    QJsonArray a;
    for (const QPointF &p : poly)
        a.append(pointToJson(p));
    return a;
}

QJsonArray pairToJson(const QRectF (&boxes)[2])
{
    return QJsonArray {boxToJson(boxes[0]), boxToJson(boxes[1])};
}

QJsonObject colourToJson(const ColourStats &c)
{
    QJsonObject o;
    o.insert(QStringLiteral("samples"), c.samples);
    o.insert(QStringLiteral("r"), c.r);
    o.insert(QStringLiteral("g"), c.g);
    o.insert(QStringLiteral("b"), c.b);
    o.insert(QStringLiteral("spread"), c.spread);
    return o;
}

QJsonObject regionsToJson(const FaceRegions &r)
{
    QJsonObject o;
    o.insert(QStringLiteral("face"), boxToJson(r.face));
    o.insert(QStringLiteral("faceOutline"), polygonToJson(r.faceOutline));
    o.insert(QStringLiteral("hair"), boxToJson(r.hair));
    o.insert(QStringLiteral("hairOutline"), polygonToJson(r.hairOutline));
    o.insert(QStringLiteral("ears"), pairToJson(r.ears));
    o.insert(QStringLiteral("brows"), pairToJson(r.brows));
    o.insert(QStringLiteral("eyes"), pairToJson(r.eyes));
    o.insert(QStringLiteral("nose"), boxToJson(r.nose));
    o.insert(QStringLiteral("mouth"), boxToJson(r.mouth));
    return o;
}

QJsonObject trackingToJson(const TrackingSeed &t)
{
    QJsonObject o;
    o.insert(QStringLiteral("rect"), boxToJson(t.rect));
    o.insert(QStringLiteral("m1"), t.m1);
    o.insert(QStringLiteral("s1"), t.s1);
    o.insert(QStringLiteral("t1"), t.t1);
    o.insert(QStringLiteral("m2"), t.m2);
    o.insert(QStringLiteral("s2"), t.s2);
    o.insert(QStringLiteral("d"), t.d);
    o.insert(QStringLiteral("eyeMid"), pointToJson(t.eyeMid));
    QJsonArray eyeballs;
    for (int k = 0; k < 2; ++k) {
        QJsonObject e;
        e.insert(QStringLiteral("x"), t.eyeballs[k].x());
        e.insert(QStringLiteral("y"), t.eyeballs[k].y());
        e.insert(QStringLiteral("radius"), t.eyeballRadius[k]);
        eyeballs.append(e);
    }
    o.insert(QStringLiteral("eyeballs"), eyeballs);
    o.insert(QStringLiteral("divEE"), t.divEE);
    o.insert(QStringLiteral("divEN"), t.divEN);
    o.insert(QStringLiteral("divNM"), t.divNM);
    o.insert(QStringLiteral("mouth"), boxToJson(t.mouth));
    QJsonArray edgeThresholds;
    for (double v : t.edgeThresholds)
        edgeThresholds.append(v);
    o.insert(QStringLiteral("edgeThresholds"), edgeThresholds);
    o.insert(QStringLiteral("skin"), colourToJson(t.skin));
    o.insert(QStringLiteral("hair"), colourToJson(t.hair));
    return o;
}

// Coordinates and statistics are bounded so that a corrupt file cannot smuggle in absurd values.
constexpr double kCoordinateLimit = 1e7;

bool numberFrom(const JsonField &f, double *out, QString *error)
{
    return f.toBoundedNumber(kCoordinateLimit, out, error);
}

bool pointFrom(const JsonField &f, QPointF *out, QString *error)
{
    QJsonArray a;
    if (!f.toArray(&a, error))
        return false;
    if (a.size() != 2)
        return f.expected(ProjectText::tr("an [x, y] pair"), error);
    double x = 0, y = 0;
    if (!numberFrom(f.at(0), &x, error) || !numberFrom(f.at(1), &y, error))
        return false;
    *out = QPointF(x, y);
    return true;
}

bool boxFrom(const JsonField &f, QRectF *out, QString *error)
{
    QJsonObject unused;
    if (!f.toObject(&unused, error))
        return false;
    double x = 0, y = 0, w = 0, h = 0;
    if (!numberFrom(f.member("x"), &x, error) || !numberFrom(f.member("y"), &y, error)
        || !numberFrom(f.member("width"), &w, error) || !numberFrom(f.member("height"), &h, error))
        return false;
    if (w < 0 || h < 0)
        return f.fail(ProjectText::tr("a box of negative size"), error);
    *out = QRectF(x, y, w, h);
    return true;
}

bool polygonFrom(const JsonField &f, QPolygonF *out, QString *error)
{
    QJsonArray a;
    if (!f.toArray(&a, error))
        return false;
    QPolygonF poly;
    for (qsizetype i = 0; i < a.size(); ++i) {
        QPointF p;
        if (!pointFrom(f.at(i), &p, error))
            return false;
        poly << p;
    }
    *out = poly;
    return true;
}

bool pairFrom(const JsonField &f, QRectF (&out)[2], QString *error)
{
    QJsonArray a;
    if (!f.toArray(&a, error))
        return false;
    if (a.size() != 2)
        return f.expected(ProjectText::tr("two boxes, image-left first"), error);
    return boxFrom(f.at(0), &out[0], error) && boxFrom(f.at(1), &out[1], error);
}

bool colourFrom(const JsonField &f, ColourStats *out, QString *error)
{
    QJsonObject unused;
    if (!f.toObject(&unused, error))
        return false;
    return f.member("samples").toInt(0, 1 << 30, &out->samples, error) && numberFrom(f.member("r"), &out->r, error)
        && numberFrom(f.member("g"), &out->g, error) && numberFrom(f.member("b"), &out->b, error)
        && numberFrom(f.member("spread"), &out->spread, error);
}

bool regionsFrom(const JsonField &f, FaceRegions *r, QString *error)
{
    QJsonObject unused;
    return f.toObject(&unused, error) && boxFrom(f.member("face"), &r->face, error)
        && polygonFrom(f.member("faceOutline"), &r->faceOutline, error) && boxFrom(f.member("hair"), &r->hair, error)
        && polygonFrom(f.member("hairOutline"), &r->hairOutline, error) && pairFrom(f.member("ears"), r->ears, error)
        && pairFrom(f.member("brows"), r->brows, error) && pairFrom(f.member("eyes"), r->eyes, error)
        && boxFrom(f.member("nose"), &r->nose, error) && boxFrom(f.member("mouth"), &r->mouth, error);
}

bool trackingFrom(const JsonField &f, TrackingSeed *t, QString *error)
{
    QJsonObject unused;
    if (!f.toObject(&unused, error) || !boxFrom(f.member("rect"), &t->rect, error))
        return false;
    const std::pair<const char *, double *> numbers[] = {{"m1", &t->m1}, {"s1", &t->s1}, {"t1", &t->t1}, {"m2", &t->m2},
        {"s2", &t->s2}, {"d", &t->d}, {"divEE", &t->divEE}, {"divEN", &t->divEN}, {"divNM", &t->divNM}};
    for (const auto &[key, out] : numbers)
        if (!numberFrom(f.member(key), out, error))
            return false;
    if (!pointFrom(f.member("eyeMid"), &t->eyeMid, error))
        return false;
    const JsonField eyeballs = f.member("eyeballs");
    QJsonArray a;
    if (!eyeballs.toArray(&a, error))
        return false;
    if (a.size() != 2)
        return eyeballs.expected(ProjectText::tr("two eyeballs, image-left first"), error);
    for (int k = 0; k < 2; ++k) {
        const JsonField e = eyeballs.at(k);
        double x = 0, y = 0;
        if (!e.toObject(&unused, error) || !numberFrom(e.member("x"), &x, error)
            || !numberFrom(e.member("y"), &y, error) || !numberFrom(e.member("radius"), &t->eyeballRadius[k], error))
            return false;
        t->eyeballs[k] = QPointF(x, y);
    }
    if (!boxFrom(f.member("mouth"), &t->mouth, error) || !colourFrom(f.member("skin"), &t->skin, error)
        || !colourFrom(f.member("hair"), &t->hair, error))
        return false;
    // Files written before the edge thresholds were kept have none: they read as not measured.
    const JsonField edges = f.member("edgeThresholds");
    t->edgeThresholds = {};
    if (!edges.isMissing()) {
        if (!edges.toArray(&a, error))
            return false;
        if (a.size() != 4)
            return edges.expected(ProjectText::tr("four edge thresholds, top part first"), error);
        for (int k = 0; k < 4; ++k)
            if (!numberFrom(edges.at(k), &t->edgeThresholds[size_t(k)], error))
                return false;
    }
    t->valid = true;
    return true;
}

} // namespace

QJsonObject faceToJson(const FaceModel &face, const QString &imagePath, const DetectionResult *detection)
{
    QJsonObject json;
    json.insert(QStringLiteral("format"), QLatin1StringView(kFaceFormat));
    json.insert(QStringLiteral("points"), pointsToJson(face, true));

    const Fapu f = face.fapu();
    QJsonObject fapu;
    fapu.insert(QStringLiteral("ES0"), f.es0);
    fapu.insert(QStringLiteral("ENS0"), f.ens0);
    fapu.insert(QStringLiteral("MNS0"), f.mns0);
    fapu.insert(QStringLiteral("MW0"), f.mw0);
    fapu.insert(QStringLiteral("LeftEyeH"), f.leftEyeH);
    fapu.insert(QStringLiteral("RightEyeH"), f.rightEyeH);
    fapu.insert(QStringLiteral("UpperLipH"), f.upperLipH);
    fapu.insert(QStringLiteral("LowerLipH"), f.lowerLipH);
    fapu.insert(QStringLiteral("JawH"), f.jawH);
    json.insert(QStringLiteral("fapu"), fapu);

    QJsonObject image;
    image.insert(QStringLiteral("path"), imagePath);
    if (face.imageSize().isValid()) {
        image.insert(QStringLiteral("width"), face.imageSize().width());
        image.insert(QStringLiteral("height"), face.imageSize().height());
    }
    json.insert(QStringLiteral("image"), image);

    if (detection) {
        json.insert(QStringLiteral("method"), detection->method);
        json.insert(QStringLiteral("timingMs"), mapToJson(detection->timingMs));
        json.insert(QStringLiteral("faceCount"), detection->faceCount);
        const QRect box = detection->faceBox;
        QJsonObject faceBox;
        faceBox.insert(QStringLiteral("x"), box.x());
        faceBox.insert(QStringLiteral("y"), box.y());
        faceBox.insert(QStringLiteral("width"), box.width());
        faceBox.insert(QStringLiteral("height"), box.height());
        json.insert(QStringLiteral("faceBox"), faceBox);
        json.insert(QStringLiteral("groupConfidence"), mapToJson(detection->groupConfidence));
        if (detection->status == DetectStatus::Ok)
            json.insert(QStringLiteral("regions"), regionsToJson(detection->regions));
        if (detection->tracking.valid)
            json.insert(QStringLiteral("tracking"), trackingToJson(detection->tracking));
    } else {
        json.insert(QStringLiteral("method"), QStringLiteral("none"));
    }
    return json;
}

std::optional<FaceModel> faceFromJson(const QJsonObject &json, QString *error, QString *imagePath)
{
    QString scratch;
    if (!error)
        error = &scratch;
    const JsonField root(json, QString());

    const JsonField formatField = root.member("format");
    QString format;
    if (!formatField.toString(&format, error))
        return std::nullopt;
    const QString want = QLatin1StringView(kFaceFormat);
    if (format != want) {
        static const QRegularExpression versioned(QStringLiteral("^toonface\\.face/(\\d+)$"));
        const auto m = versioned.match(format);
        if (m.hasMatch() && m.captured(1).toInt() > 1) {
            formatField.fail(
                ProjectText::tr("%1 was made by a newer Toonface (this version reads %2)").arg(format, want), error);
        } else {
            formatField.expected(QStringLiteral("\"%1\"").arg(want), error);
        }
        return std::nullopt;
    }

    FaceModel face;
    if (!pointsFromJson(root.member("points"), &face, error))
        return std::nullopt;

    const JsonField image = root.member("image");
    QJsonObject unused;
    if (!image.toObject(&unused, error))
        return std::nullopt;
    QString path;
    if (!image.member("path").toString(&path, error))
        return std::nullopt;
    const JsonField width = image.member("width");
    const JsonField height = image.member("height");
    if (!width.isMissing() || !height.isMissing()) {
        int w = 0;
        int h = 0;
        if (!width.toInt(0, 1000000, &w, error) || !height.toInt(0, 1000000, &h, error))
            return std::nullopt;
        face.setImageSize(QSize(w, h));
    }
    if (imagePath)
        *imagePath = path;
    return face;
}

} // namespace toonface

namespace toonface {

bool faceRegionsFromJson(const QJsonObject &json, FaceRegions *regions, TrackingSeed *tracking, QString *error)
{
    QString scratch;
    if (!error)
        error = &scratch;
    const JsonField root(json, QString());
    FaceRegions r;
    TrackingSeed t;
    const JsonField rf = root.member("regions");
    if (!rf.isMissing() && !regionsFrom(rf, &r, error))
        return false;
    const JsonField tf = root.member("tracking");
    if (!tf.isMissing() && !trackingFrom(tf, &t, error))
        return false;
    if (regions)
        *regions = r;
    if (tracking)
        *tracking = t;
    return true;
}

} // namespace toonface
