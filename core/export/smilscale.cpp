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

void elementsById(XmlNode &n, QHash<QByteArray, XmlNode *> *out)
{
    if (const QByteArray id = n.attribute("id"); !id.isEmpty())
        out->insert(id, &n);
    for (XmlNode &c : n.children)
        elementsById(c, out);
}

// The attribute as ten times larger text; false when it is not one number.
bool timesTen(const QByteArray &text, QByteArray *out)
{
    QVector<double> numbers;
    QByteArray letters;
    parseNumbers(text, &numbers, &letters);
    if (numbers.size() != 1 || !letters.isEmpty())
        return false;
    out->clear();
    appendFixed(*out, quantize(numbers[0] * 10, 3), 3);
    return true;
}

} // namespace

QSet<int> writeInTenths(
    XmlNode &document, const QVector<FacePart> &parts, const QVector<Channel> &channels, const QSet<int> &animated)
{
    const QSet<QByteArray> referenced = referencedIds(document);
    QHash<QByteArray, XmlNode *> byId;
    elementsById(document, &byId);
    QHash<int, QVector<const Channel *>> channelsOf;
    for (const Channel &c : channels) {
        if (c.part >= 0)
            channelsOf[c.part].append(&c);
    }

    QSet<int> done;
    for (const int p : animated) {
        const QByteArray id = parts[p].id.toLatin1();
        XmlNode *e = byId.value(id);
        if (!e || referenced.contains(id) || (e->name != "path" && e->name != "circle" && e->name != "ellipse"))
            continue;
        // The new text of every attribute, or nothing when the element must stay as it is.
        std::vector<std::pair<QByteArray, QByteArray>> rewritten;
        bool ok = true;
        bool strokeWidth = false; // the element's own, or it strokes nothing
        for (const auto &[key, value] : e->attributes) {
            if (key == "id")
                continue;
            const auto channel = std::find_if(channelsOf[p].cbegin(), channelsOf[p].cend(),
                [&](const Channel *c) { return c->attribute == QLatin1StringView(key); });
            if (channel != channelsOf[p].cend()) {
                // The geometry as the channel read it at time 0, ten times larger (to 0.001 px).
                const Channel &c = **channel;
                QVector<qint64> q;
                for (double x : c.base)
                    q.append(quantize(x * 10, 2));
                QByteArray text;
                if (c.kind == ChannelKind::Path)
                    appendAbsolutePath(text, c.commands, q.constData(), 2);
                else if (c.kind == ChannelKind::Number)
                    appendFixed(text, q.value(0), 2);
                else
                    ok = false;
                rewritten.push_back({key, text});
            } else if (parts[p].geometry.contains(QString::fromLatin1(key))) {
                ok = false; // geometry that is not a channel would stay unscaled
            } else if (key == "stroke-width") {
                QByteArray text;
                ok = ok && timesTen(value, &text);
                rewritten.push_back({key, text});
                strokeWidth = true;
            } else if (plainPaint(key) && !value.contains("url(")) {
                strokeWidth = strokeWidth || (key == "stroke" && value == "none");
            } else {
                ok = false;
            }
            if (!ok)
                break;
        }
        // A stroke without a width of its own draws with the inherited one, which would shrink.
        if (!ok || !strokeWidth)
            continue;
        for (auto &[key, value] : e->attributes) {
            for (const auto &[k, v] : rewritten) {
                if (k == key)
                    value = v;
            }
        }
        e->attributes.push_back({"transform", "scale(.1)"});
        done.insert(p);
    }
    return done;
}

} // namespace toonface::smil
