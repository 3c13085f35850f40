#pragma once

// A small parsed XML tree for the render tests: structure checks and golden comparisons.

#include <QByteArray>
#include <QList>
#include <QPair>
#include <QString>
#include <QXmlStreamReader>

#include <algorithm>

namespace toonface::test {

struct Node
{
    QString name; // qualified ("tf:audio")
    QList<QPair<QString, QString>> attributes; // in document order, qualified names
    QList<Node> children;

    QString attribute(const QString &key) const
    {
        for (const auto &[k, v] : attributes) {
            if (k == key)
                return v;
        }
        return {};
    }
    bool has(const QString &key) const
    {
        return std::any_of(attributes.cbegin(), attributes.cend(), [&](const auto &a) { return a.first == key; });
    }
};

inline bool parseXml(const QByteArray &data, Node *root, QString *error)
{
    QXmlStreamReader reader(data);
    QList<Node> stack;
    bool done = false;
    while (!reader.atEnd()) {
        reader.readNext();
        if (reader.isStartElement()) {
            Node n;
            n.name = reader.qualifiedName().toString();
            for (const QXmlStreamAttribute &a : reader.attributes())
                n.attributes.append({a.qualifiedName().toString(), a.value().toString()});
            stack.append(n);
        } else if (reader.isEndElement()) {
            Node n = stack.takeLast();
            if (stack.isEmpty()) {
                *root = n;
                done = true;
            } else {
                stack.last().children.append(n);
            }
        }
    }
    if (reader.hasError()) {
        *error = QStringLiteral("line %1: %2").arg(reader.lineNumber()).arg(reader.errorString());
        return false;
    }
    if (!done)
        *error = QStringLiteral("no root element");
    return done;
}

// The element with this id, depth first; null when there is none.
inline const Node *findId(const Node &n, const QString &id)
{
    if (n.attribute(QStringLiteral("id")) == id)
        return &n;
    for (const Node &c : n.children) {
        if (const Node *f = findId(c, id))
            return f;
    }
    return nullptr;
}

// Every element named `name` (qualified) in `n`, `n` included, in document order.
inline void collectNamed(const Node &n, const QString &name, QList<const Node *> *out)
{
    if (n.name == name)
        out->append(&n);
    for (const Node &c : n.children)
        collectNamed(c, name, out);
}

inline QList<const Node *> elementsNamed(const Node &n, const QString &name)
{
    QList<const Node *> out;
    collectNamed(n, name, &out);
    return out;
}

} // namespace toonface::test
