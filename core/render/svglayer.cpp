#include "render/svglayer.h"

#include "i18n/coretext.h"
#include "render/style.h"

#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QXmlStreamReader>
#include <QXmlStreamWriter>

#include <cmath>

namespace toonface {

namespace {

const QString kSvgNamespace = QStringLiteral("http://www.w3.org/2000/svg");

// Elements that would run code or show other documents where the exported animation is
// opened (a browser): a layer's drawing never needs them.
bool isActiveElement(QStringView name)
{
    return name == QLatin1StringView("script") || name == QLatin1StringView("foreignObject")
        || name == QLatin1StringView("iframe") || name == QLatin1StringView("handler")
        || name == QLatin1StringView("object") || name == QLatin1StringView("embed");
}

// An attribute value as a browser reads a URL's scheme: lower case, with the white space and
// control characters it skips inside "java\tscript:" left out.
QString squeezed(QStringView value)
{
    QString out;
    out.reserve(value.size());
    for (const QChar c : value) {
        if (c.unicode() > 0x20)
            out.append(c.toLower());
    }
    return out;
}

// Whether an attribute value could run code or open another document: a javascript: or
// vbscript: URL anywhere in it (an <animate> or <set> can put one into a link through its
// values, to or from), or a data: document that is not an image.
bool isActiveValue(QStringView value)
{
    const QString v = squeezed(value);
    return v.contains(QLatin1StringView("javascript:")) || v.contains(QLatin1StringView("vbscript:"))
        || v.contains(QLatin1StringView("data:text")) || v.contains(QLatin1StringView("data:application"));
}

// A link the layer may keep: to an element of its own, or an embedded picture.
bool isInternalLink(QStringView value)
{
    const QString v = squeezed(value);
    return v.startsWith(QLatin1Char('#')) || v.startsWith(QLatin1StringView("data:image/png"))
        || v.startsWith(QLatin1StringView("data:image/jpeg")) || v.startsWith(QLatin1StringView("data:image/gif"))
        || v.startsWith(QLatin1StringView("data:image/webp"));
}

// Whether a style or attribute text refers to something outside the file: url(...) to anything
// but one of its own elements, or an @import.
bool refersOutside(QStringView text)
{
    const QString v = squeezed(text);
    if (v.contains(QLatin1StringView("@import")) || v.contains(QLatin1StringView("expression(")))
        return true;
    static const QRegularExpression url(QStringLiteral("url\\(['\"]?([^'\")]*)"));
    for (auto it = url.globalMatch(v); it.hasNext();) {
        const QString target = it.next().captured(1);
        if (!target.startsWith(QLatin1Char('#')))
            return true;
    }
    return false;
}

// An <animate> or <set> of a link (href) could point it anywhere at play time: a drawing never
// needs one.
bool animatesLink(const QXmlStreamAttributes &attributes)
{
    return squeezed(attributes.value(QLatin1StringView("attributeName"))).endsWith(QLatin1StringView("href"));
}

QString withPrefixedUrls(const QString &text, const QString &prefix)
{
    QString out = text;
    static const QRegularExpression url(QStringLiteral("url\\(\\s*(['\"]?)#"));
    return out.replace(url, QStringLiteral("url(\\1#") + prefix);
}

// Copies the reader's start element without what could run code or fetch anything, its ids
// and references to them prefixed.
void writeInertStart(const QXmlStreamReader &reader, QXmlStreamWriter &writer, const QString &prefix)
{
    const QXmlStreamNamespaceDeclarations declarations = reader.namespaceDeclarations();
    writer.writeStartElement(reader.namespaceUri().toString(), reader.name().toString());
    for (const QXmlStreamNamespaceDeclaration &d : declarations)
        writer.writeNamespace(d.namespaceUri().toString(), d.prefix().toString());
    const QXmlStreamAttributes attributes = reader.attributes();
    for (const QXmlStreamAttribute &a : attributes) {
        const QStringView name = a.name();
        if (name.startsWith(QLatin1StringView("on"), Qt::CaseInsensitive) || isActiveValue(a.value()))
            continue;
        QString value = a.value().toString();
        if (name == QLatin1StringView("href") || name == QLatin1StringView("src")) {
            if (!isInternalLink(value))
                continue;
            if (value.trimmed().startsWith(QLatin1Char('#')))
                value = QLatin1Char('#') + prefix + value.trimmed().mid(1);
        } else if (name == QLatin1StringView("id")) {
            value = prefix + value;
        } else if (refersOutside(value)) {
            continue;
        } else {
            value = withPrefixedUrls(value, prefix);
        }
        writer.writeAttribute(a.namespaceUri().toString(), name.toString(), value);
    }
}

// The root's viewBox, or its width and height (numbers in any unit, read as user units).
QRectF rootBox(const QXmlStreamAttributes &root)
{
    static const QRegularExpression separators(QStringLiteral("[\\s,]+"));
    const QStringList box = root.value(QLatin1StringView("viewBox")).toString().trimmed().split(separators);
    if (box.size() == 4) {
        bool ok[4];
        const QRectF r(
            box[0].toDouble(&ok[0]), box[1].toDouble(&ok[1]), box[2].toDouble(&ok[2]), box[3].toDouble(&ok[3]));
        if (ok[0] && ok[1] && ok[2] && ok[3] && r.width() > 0 && r.height() > 0 && std::isfinite(r.width())
            && std::isfinite(r.height()))
            return r;
    }
    static const QRegularExpression leadingNumber(QStringLiteral("^\\s*([0-9]*\\.?[0-9]+(e[-+]?[0-9]+)?)"));
    auto length = [&](const char *name) {
        const auto m = leadingNumber.match(root.value(QLatin1StringView(name)));
        return m.hasMatch() ? m.captured(1).toDouble() : 0.0;
    };
    const double w = length("width"), h = length("height");
    if (w > 0 && h > 0 && std::isfinite(w) && std::isfinite(h))
        return QRectF(0, 0, w, h);
    return QRectF(0, 0, 100, 100);
}

} // namespace

bool readLayerSvg(const QByteArray &content, const QString &idPrefix, LayerDrawing *out, QString *error)
{
    QXmlStreamReader reader(content);
    QByteArray written;
    QXmlStreamWriter writer(&written);
    int depth = 0;
    int skipFrom = 0; // the depth of the active element being left out, or 0
    bool sawRoot = false;
    while (!reader.atEnd()) {
        const auto token = reader.readNext();
        if (reader.hasError())
            break;
        if (token == QXmlStreamReader::StartElement) {
            if (!sawRoot) {
                sawRoot = true;
                if (reader.name() != QLatin1StringView("svg")) {
                    *error = ImageText::tr("the root element is <%1>, not <svg>").arg(reader.name());
                    return false;
                }
                out->viewBox = rootBox(reader.attributes());
                // Declared once on a wrapper so the copied elements need no prefixes.
                writer.writeNamespace(QStringLiteral("http://www.w3.org/1999/xlink"), QStringLiteral("xlink"));
                writer.writeDefaultNamespace(kSvgNamespace);
                writer.writeStartElement(kSvgNamespace, QStringLiteral("g"));
                continue;
            }
            ++depth;
            if (skipFrom == 0 && (isActiveElement(reader.name()) || animatesLink(reader.attributes())))
                skipFrom = depth; // a script or foreign content: left out with everything inside
            if (skipFrom != 0)
                continue;
            if (reader.name() == QLatin1StringView("style")) {
                // A style sheet is kept only when it refers to nothing outside the file.
                const QXmlStreamAttributes attributes = reader.attributes();
                const QString sheet = reader.readElementText(QXmlStreamReader::IncludeChildElements);
                --depth;
                if (reader.hasError())
                    break;
                if (refersOutside(sheet))
                    continue;
                writer.writeStartElement(kSvgNamespace, QStringLiteral("style"));
                for (const QXmlStreamAttribute &a : attributes) {
                    if (!a.name().startsWith(QLatin1StringView("on"), Qt::CaseInsensitive))
                        writer.writeAttribute(a.name().toString(), a.value().toString());
                }
                writer.writeCharacters(withPrefixedUrls(sheet, idPrefix));
                writer.writeEndElement();
                continue;
            }
            writeInertStart(reader, writer, idPrefix);
        } else if (token == QXmlStreamReader::EndElement) {
            if (depth == 0)
                continue; // the root's end
            const bool skipped = skipFrom != 0;
            if (skipFrom == depth)
                skipFrom = 0;
            --depth;
            if (!skipped)
                writer.writeCurrentToken(reader);
        } else if (sawRoot && depth > 0 && skipFrom == 0
            && (token == QXmlStreamReader::Characters || token == QXmlStreamReader::EntityReference)) {
            writer.writeCurrentToken(reader);
        }
    }
    if (reader.hasError()) {
        *error = ImageText::tr("line %1, column %2: %3")
                     .arg(reader.lineNumber())
                     .arg(reader.columnNumber())
                     .arg(reader.errorString());
        return false;
    }
    if (!sawRoot) {
        *error = ImageText::tr("no root element");
        return false;
    }
    writer.writeEndElement();
    // Keep only the children: drop the wrapper's start and end tags.
    const qsizetype open = written.indexOf('>');
    const qsizetype close = written.lastIndexOf("</");
    if (open < 0 || close < open)
        out->fragment.clear(); // an empty root: <g .../> with no children
    else
        out->fragment = written.mid(open + 1, close - open - 1);
    return true;
}

bool loadLayerFile(const QString &path, StyleLayer *out, QString *error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = ImageText::tr("cannot read layer file %1: %2").arg(path, file.errorString());
        return false;
    }
    constexpr qint64 kMaxLayerBytes = 16 << 20;
    if (file.size() > kMaxLayerBytes) {
        *error = ImageText::tr("layer file %1 is too large (more than 16 MB)").arg(path);
        return false;
    }
    const QByteArray content = file.readAll();
    LayerDrawing drawing;
    QString why;
    if (!readLayerSvg(content, QString(), &drawing, &why)) {
        *error = ImageText::tr("layer file %1 is not a valid SVG file: %2").arg(path, why);
        return false;
    }
    StyleLayer layer;
    layer.name = QFileInfo(path).fileName();
    layer.svg = content;
    *out = layer;
    return true;
}

} // namespace toonface
