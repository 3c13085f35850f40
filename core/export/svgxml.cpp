#include "export/svgxml.h"

#include "export/svgnumbers.h"
#include "i18n/coretext.h"

#include <QVector>
#include <QXmlStreamReader>

namespace toonface::smil {

bool parseXml(const QByteArray &data, XmlNode *root, QString *error)
{
    QXmlStreamReader reader(data);
    std::vector<XmlNode *> stack;
    while (!reader.atEnd()) {
        const auto token = reader.readNext();
        if (token == QXmlStreamReader::StartElement) {
            // Every walk of the tree (writeXml, findById) recurses: its depth is bounded here.
            if (stack.size() >= kMaxXmlDepth) {
                *error = ExportText::tr("the drawing is nested more than %1 levels deep").arg(kMaxXmlDepth);
                return false;
            }
            XmlNode n;
            n.name = reader.qualifiedName().toUtf8();
            for (const auto &ns : reader.namespaceDeclarations()) {
                n.attributes.emplace_back(ns.prefix().isEmpty() ? QByteArray("xmlns") : "xmlns:" + ns.prefix().toUtf8(),
                    ns.namespaceUri().toUtf8());
            }
            for (const auto &a : reader.attributes())
                n.attributes.emplace_back(a.qualifiedName().toUtf8(), a.value().toUtf8());
            if (stack.empty()) {
                *root = std::move(n);
                stack.push_back(root);
            } else {
                stack.back()->children.push_back(std::move(n));
                stack.push_back(&stack.back()->children.back());
            }
        } else if (token == QXmlStreamReader::EndElement) {
            stack.pop_back();
        } else if (token == QXmlStreamReader::Characters && !stack.empty()) {
            XmlNode t;
            t.text = reader.text().toUtf8();
            stack.back()->children.push_back(std::move(t));
        }
    }
    if (reader.hasError()) {
        *error = ExportText::tr("the drawing is not valid XML: %1").arg(reader.errorString());
        return false;
    }
    return true;
}

void appendEscaped(QByteArray &out, const QByteArray &s, bool attribute)
{
    for (const char c : s) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += attribute ? "&quot;" : "\""; break;
        default: out += c;
        }
    }
}

void appendStartTag(QByteArray &out, const XmlNode &n, bool close)
{
    out += '<';
    out += n.name;
    for (const auto &[k, v] : n.attributes) {
        out += ' ';
        out += k;
        out += "=\"";
        appendEscaped(out, v, true);
        out += '"';
    }
    out += close ? "/>" : ">";
}

void writeXml(QByteArray &out, const XmlNode &n, const XmlInjector &inject)
{
    if (n.name.isEmpty()) {
        appendEscaped(out, n.text, false);
        return;
    }
    QByteArray first, last;
    if (inject)
        inject(n, &first, &last);
    if (n.children.empty() && first.isEmpty() && last.isEmpty()) {
        appendStartTag(out, n, true);
        return;
    }
    appendStartTag(out, n, false);
    out += first;
    for (const XmlNode &child : n.children)
        writeXml(out, child, inject);
    out += last;
    out += "</" + n.name + '>';
}

const XmlNode *findById(const XmlNode &n, const QByteArray &id)
{
    if (!n.name.isEmpty() && n.attribute("id") == id)
        return &n;
    for (const XmlNode &c : n.children) {
        if (const XmlNode *found = findById(c, id))
            return found;
    }
    return nullptr;
}

QRectF viewBoxOf(const XmlNode &root)
{
    QVector<double> v;
    parseNumbers(root.attribute("viewBox"), &v);
    return v.size() == 4 ? QRectF(v[0], v[1], v[2], v[3]) : QRectF(0, 0, 512, 512);
}

} // namespace toonface::smil
