#include "io/layersjson.h"

#include "i18n/coretext.h"
#include "render/svglayer.h"

namespace toonface {

namespace {

constexpr double kMaxOffset = 100; // ES0: far off the face, but finite
constexpr double kMaxWidth = 100;

} // namespace

QJsonArray styleLayersToJson(const QVector<StyleLayer> &layers)
{
    QJsonArray out;
    for (const StyleLayer &layer : layers) {
        QJsonObject o;
        o.insert(QStringLiteral("name"), layer.name);
        o.insert(QStringLiteral("svg"), QString::fromUtf8(layer.svg));
        o.insert(QStringLiteral("x"), layer.offset.x());
        o.insert(QStringLiteral("y"), layer.offset.y());
        o.insert(QStringLiteral("width"), layer.width);
        o.insert(QStringLiteral("front"), layer.front);
        o.insert(QStringLiteral("visible"), layer.visible);
        o.insert(QStringLiteral("followsHead"), layer.followsHead);
        out.append(o);
    }
    return out;
}

bool styleLayersFromJson(const JsonField &field, QVector<StyleLayer> *layers, QString *error)
{
    layers->clear();
    if (field.isMissing())
        return true;
    QJsonArray array;
    if (!field.toArray(&array, error))
        return false;
    for (qsizetype i = 0; i < array.size(); ++i) {
        const JsonField f = field.at(i);
        QJsonObject unused;
        StyleLayer layer;
        QString svg;
        double x = 0, y = 0;
        if (!f.toObject(&unused, error) || !f.member("name").toString(&layer.name, error)
            || !f.member("svg").toString(&svg, error) || !f.member("x").toBoundedNumber(kMaxOffset, &x, error)
            || !f.member("y").toBoundedNumber(kMaxOffset, &y, error)
            || !f.member("width").toBoundedNumber(kMaxWidth, &layer.width, error)
            || !f.member("front").toBool(&layer.front, error) || !f.member("visible").toBool(&layer.visible, error))
            return false;
        // Added later: layers of files from before stay still as the head moves.
        if (const JsonField follows = f.member("followsHead");
            !follows.isMissing() && !follows.toBool(&layer.followsHead, error))
            return false;
        if (!(layer.width > 0))
            return f.member("width").expected(ProjectText::tr("a width more than 0"), error);
        layer.offset = QPointF(x, y);
        // A shared project's layer is cleaned on the way in: the project holds, and saves, only
        // the inert copy (scripts and outside references are gone before anything draws it).
        QString why;
        if (!cleanLayerSvg(svg.toUtf8(), &layer.svg, &why))
            return f.member("svg").fail(ProjectText::tr("not an SVG drawing: %1").arg(why), error);
        layers->append(layer);
    }
    return true;
}

} // namespace toonface
