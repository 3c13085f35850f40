#pragma once

#include <QByteArray>
#include <QRectF>
#include <QString>

#include <functional>
#include <utility>
#include <vector>

// The drawing as a tree of XML elements, parsed and written back as it was (for the SMIL
// export, which adds its animations to the renderer's document).
namespace toonface::smil {

// A parsed XML element (or text, when name is empty).
struct XmlNode
{
    QByteArray name;
    std::vector<std::pair<QByteArray, QByteArray>> attributes; // qualified names; namespace declarations included
    std::vector<XmlNode> children;
    QByteArray text;

    QByteArray attribute(const char *key) const
    {
        for (const auto &[k, v] : attributes) {
            if (k == key)
                return v;
        }
        return {};
    }
};

// Reads a drawing into a tree at most kMaxXmlDepth deep (the face's own are about ten deep, a
// layer at most 64 below it); false with *error for invalid XML or a deeper tree.
inline constexpr size_t kMaxXmlDepth = 256;
bool parseXml(const QByteArray &data, XmlNode *root, QString *error);

void appendEscaped(QByteArray &out, const QByteArray &s, bool attribute);
void appendStartTag(QByteArray &out, const XmlNode &n, bool close);

// Writes `n`; `inject` may add content at the start and at the end of any element.
using XmlInjector = std::function<void(const XmlNode &, QByteArray *first, QByteArray *last)>;
void writeXml(QByteArray &out, const XmlNode &n, const XmlInjector &inject);

const XmlNode *findById(const XmlNode &n, const QByteArray &id);

// The root's viewBox (0 0 512 512 when it has none).
QRectF viewBoxOf(const XmlNode &root);

} // namespace toonface::smil
