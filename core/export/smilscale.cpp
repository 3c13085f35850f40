#include "export/smilscale.h"

#include "export/svgnumbers.h"

#include <QHash>

#include <functional>

namespace toonface::smil {

namespace {

// Attributes a uniform scale leaves as they draw (besides the geometry, the id and the
// stroke width, which is scaled with the geometry). Anything else keeps the element as it is.
bool plainPaint(const QByteArray &name)
{
    static const QSet<QByteArray> names {"fill", "fill-opacity", "fill-rule", "stroke", "stroke-opacity",
        "stroke-linecap", "stroke-linejoin", "stroke-miterlimit", "opacity", "visibility", "display"};
    return names.contains(name);
}

// The ids that other elements refer to (href="#id", url(#id)).
QSet<QByteArray> referencedIds(const XmlNode &root)
{
    QSet<QByteArray> ids;
    std::function<void(const XmlNode &)> visit = [&](const XmlNode &n) {
        for (const auto &[key, value] : n.attributes) {
            if ((key == "xlink:href" || key == "href") && value.startsWith('#'))
                ids.insert(value.mid(1));
            for (qsizetype at = value.indexOf("url(#"); at >= 0; at = value.indexOf("url(#", at + 1)) {
                const qsizetype end = value.indexOf(')', at);
                if (end > at)
                    ids.insert(value.mid(at + 5, end - at - 5));
            }
        }
        for (const XmlNode &c : n.children)
            visit(c);
    };
    visit(root);
    return ids;
}

template<class Node>
void elementsById(Node &n, QHash<QByteArray, Node *> *out)
{
    if (const QByteArray id = n.attribute("id"); !id.isEmpty())
        out->insert(id, &n);
    for (auto &c : n.children)
        elementsById(c, out);
}

const Channel *channelOf(const QVector<Channel> &channels, int part, const QByteArray &attribute)
{
    for (const Channel &c : channels) {
        if (c.part == part && c.attribute == QLatin1StringView(attribute))
            return &c;
    }
    return nullptr;
}

// The attribute as one number; false when it is not one.
bool oneNumber(const QByteArray &text, double *out)
{
    QVector<double> numbers;
    QByteArray letters;
    parseNumbers(text, &numbers, &letters);
    if (numbers.size() != 1 || !letters.isEmpty())
        return false;
    *out = numbers[0];
    return true;
}

bool drawsTheSameInFifths(const XmlNode &e, int part, const FacePart &p, const QVector<Channel> &channels)
{
    if (e.name != "path" && e.name != "circle" && e.name != "ellipse")
        return false;
    bool strokeWidth = false; // the element's own, or it strokes nothing
    for (const auto &[key, value] : e.attributes) {
        double number = 0;
        if (key == "id")
            continue;
        if (const Channel *c = channelOf(channels, part, key)) {
            if (c->kind != ChannelKind::Path && c->kind != ChannelKind::Number)
                return false;
        } else if (p.geometry.contains(QString::fromLatin1(key))) {
            return false; // geometry that is not a channel would stay unscaled
        } else if (key == "stroke-width") {
            if (!oneNumber(value, &number))
                return false;
            strokeWidth = true;
        } else if (plainPaint(key) && !value.contains("url(")) {
            strokeWidth = strokeWidth || (key == "stroke" && value == "none");
        } else {
            return false;
        }
    }
    // A stroke without a width of its own draws with the inherited one, which would shrink.
    return strokeWidth;
}

} // namespace

QSet<int> partsInFifths(const XmlNode &document, const QVector<FacePart> &parts, const QVector<Channel> &channels)
{
    const QSet<QByteArray> referenced = referencedIds(document);
    QHash<QByteArray, const XmlNode *> byId;
    elementsById(document, &byId);
    QSet<int> out;
    for (qsizetype p = 0; p < parts.size(); ++p) {
        const QByteArray id = parts[p].id.toLatin1();
        const XmlNode *e = byId.value(id);
        if (e && !referenced.contains(id) && drawsTheSameInFifths(*e, int(p), parts[p], channels))
            out.insert(int(p));
    }
    return out;
}

void writeInFifths(
    XmlNode &document, const QVector<FacePart> &parts, const QVector<Channel> &channels, const QSet<int> &which)
{
    QHash<QByteArray, XmlNode *> byId;
    elementsById(document, &byId);
    for (const int p : which) {
        XmlNode *e = byId.value(parts[p].id.toLatin1());
        if (!e)
            continue;
        for (auto &[key, value] : e->attributes) {
            if (const Channel *c = channelOf(channels, p, key)) {
                // The geometry as the channel read it at time 0, five times larger.
                QVector<qint64> q;
                for (double x : c->base)
                    q.append(quantize(x * kUnitsPerPixel, 2));
                value.clear();
                if (c->kind == ChannelKind::Path)
                    appendAbsolutePath(value, c->commands, q.constData(), 2);
                else
                    appendFixed(value, q.value(0), 2);
            } else if (double width = 0; key == "stroke-width" && oneNumber(value, &width)) {
                value.clear();
                appendFixed(value, quantize(width * kUnitsPerPixel, 3), 3);
            }
        }
        e->attributes.push_back({"transform", "scale(.2)"});
    }
}

} // namespace toonface::smil
