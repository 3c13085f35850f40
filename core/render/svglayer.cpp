#include "render/svglayer.h"

#include "i18n/coretext.h"
#include "media/userfile.h"
#include "render/style.h"
#include "render/svgallowlist.h"

#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QRegularExpression>
#include <QXmlStreamReader>
#include <QXmlStreamWriter>

#include <cmath>

namespace toonface {

namespace {

const QString kSvgNamespace = QStringLiteral("http://www.w3.org/2000/svg");
const QString kXlinkNamespace = QStringLiteral("http://www.w3.org/1999/xlink");
const QString kXmlNamespace = QStringLiteral("http://www.w3.org/XML/1998/namespace");

// A layer is a drawing, not a data structure: deeper nesting or more elements than any drawing
// needs is refused, so nothing that walks the tree later (the SMIL writer, the renderer) can
// run out of stack or memory on it.
constexpr int kMaxDepth = 64;
constexpr int kMaxElements = 100000;

// The named character references of HTML that drawings exported by editors use in text, written
// out as their characters; a layer carrying an SVG 1.1 DOCTYPE uses them without declaring them.
QString namedCharacter(QStringView name)
{
    static const QHash<QString, QChar> known
        = {{QStringLiteral("nbsp"), QChar(0x00a0)}, {QStringLiteral("ensp"), QChar(0x2002)},
            {QStringLiteral("emsp"), QChar(0x2003)}, {QStringLiteral("thinsp"), QChar(0x2009)},
            {QStringLiteral("copy"), QChar(0x00a9)}, {QStringLiteral("reg"), QChar(0x00ae)},
            {QStringLiteral("trade"), QChar(0x2122)}, {QStringLiteral("hellip"), QChar(0x2026)},
            {QStringLiteral("mdash"), QChar(0x2014)}, {QStringLiteral("ndash"), QChar(0x2013)},
            {QStringLiteral("lsquo"), QChar(0x2018)}, {QStringLiteral("rsquo"), QChar(0x2019)},
            {QStringLiteral("ldquo"), QChar(0x201c)}, {QStringLiteral("rdquo"), QChar(0x201d)},
            {QStringLiteral("laquo"), QChar(0x00ab)}, {QStringLiteral("raquo"), QChar(0x00bb)},
            {QStringLiteral("deg"), QChar(0x00b0)}, {QStringLiteral("middot"), QChar(0x00b7)},
            {QStringLiteral("times"), QChar(0x00d7)}, {QStringLiteral("bull"), QChar(0x2022)}};
    const auto it = known.constFind(name.toString());
    return it == known.constEnd() ? QString() : QString(*it);
}

QString withPrefixedUrls(const QString &text, const QString &prefix)
{
    QString out = text;
    static const QRegularExpression url(QStringLiteral("url\\(\\s*(['\"]?)#"));
    return out.replace(url, QStringLiteral("url(\\1#") + prefix);
}

// Copies the reader's start element with only the attributes of drawing, each inert, its ids
// and references to them prefixed. A link (<a>) becomes a plain group: its drawing stays, the
// way to another document does not.
void writeInertStart(const QXmlStreamReader &reader, QXmlStreamWriter &writer, const QString &prefix)
{
    const bool link = reader.name() == QLatin1StringView("a");
    writer.writeStartElement(kSvgNamespace, link ? QStringLiteral("g") : reader.name().toString());
    const bool picture = reader.name() == QLatin1StringView("image") || reader.name() == QLatin1StringView("feImage");
    const QXmlStreamAttributes attributes = reader.attributes();
    for (const QXmlStreamAttribute &a : attributes) {
        const QStringView ns = a.namespaceUri();
        const QStringView name = a.name();
        if (ns == kXmlNamespace) {
            if (name == QLatin1StringView("space") || name == QLatin1StringView("lang"))
                writer.writeAttribute(kXmlNamespace, name.toString(), a.value().toString());
            continue;
        }
        const bool href = name == QLatin1StringView("href") && (ns.isEmpty() || ns == kXlinkNamespace);
        if (href) {
            if (link || !svgallow::isInternalLink(a.value(), picture))
                continue;
            QString value = a.value().toString().trimmed();
            if (value.startsWith(QLatin1Char('#')))
                value = QLatin1Char('#') + prefix + value.mid(1);
            writer.writeAttribute(kXlinkNamespace, QStringLiteral("href"), value);
            continue;
        }
        if (!ns.isEmpty() || !svgallow::isDrawingAttribute(name))
            continue;
        if (name == QLatin1StringView("id")) {
            writer.writeAttribute(name.toString(), prefix + a.value().toString());
            continue;
        }
        if (!svgallow::isInertCss(a.value()))
            continue;
        writer.writeAttribute(name.toString(), withPrefixedUrls(a.value().toString(), prefix));
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
    int elements = 0;
    int skipFrom = 0; // the depth of the element being left out with its content, or 0
    bool sawRoot = false;
    bool svgDefault = false; // the root has no namespace: its elements are SVG's
    auto failAt = [&](const QString &what) {
        *error = ImageText::tr("line %1, column %2: %3").arg(reader.lineNumber()).arg(reader.columnNumber()).arg(what);
        return false;
    };
    while (!reader.atEnd()) {
        const auto token = reader.readNext();
        if (reader.hasError())
            break;
        if (token == QXmlStreamReader::StartElement) {
            if (!sawRoot) {
                sawRoot = true;
                if (reader.name() != QLatin1StringView("svg")
                    || !(reader.namespaceUri().isEmpty() || reader.namespaceUri() == kSvgNamespace)) {
                    *error = ImageText::tr("the root element is <%1>, not <svg>").arg(reader.qualifiedName());
                    return false;
                }
                svgDefault = reader.namespaceUri().isEmpty();
                out->viewBox = rootBox(reader.attributes());
                // Declared once on a wrapper so the copied elements need no prefixes.
                writer.writeNamespace(kXlinkNamespace, QStringLiteral("xlink"));
                writer.writeDefaultNamespace(kSvgNamespace);
                writer.writeStartElement(kSvgNamespace, QStringLiteral("g"));
                continue;
            }
            ++depth;
            if (depth > kMaxDepth)
                return failAt(ImageText::tr("elements nested more than %1 deep").arg(kMaxDepth));
            if (++elements > kMaxElements)
                return failAt(ImageText::tr("more than %1 elements").arg(kMaxElements));
            if (skipFrom != 0)
                continue;
            const bool svg = reader.namespaceUri() == kSvgNamespace || (svgDefault && reader.namespaceUri().isEmpty());
            const bool link = svg && reader.name() == QLatin1StringView("a");
            if (!svg || (!link && !svgallow::isDrawingElement(reader.name()))) {
                skipFrom = depth; // not drawing (script, animation, another namespace): left out with its content
                continue;
            }
            if (reader.name() == QLatin1StringView("style")) {
                // A style sheet is kept only when it refers to nothing outside the file.
                const QString sheet = reader.readElementText(QXmlStreamReader::SkipChildElements);
                --depth;
                if (reader.hasError())
                    break;
                if (!svgallow::isInertCss(sheet))
                    continue;
                writer.writeStartElement(kSvgNamespace, QStringLiteral("style"));
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
                writer.writeEndElement();
        } else if (sawRoot && depth > 0 && skipFrom == 0 && token == QXmlStreamReader::Characters) {
            writer.writeCharacters(reader.text().toString());
        } else if (sawRoot && depth > 0 && skipFrom == 0 && token == QXmlStreamReader::EntityReference) {
            // An entity the document uses without declaring it (its DTD is not read).
            const QString character = namedCharacter(reader.name());
            if (character.isEmpty())
                return failAt(ImageText::tr("the entity &%1; is not defined").arg(reader.name()));
            writer.writeCharacters(character);
        }
    }
    if (reader.hasError())
        return failAt(reader.errorString());
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

QByteArray layerDocument(const LayerDrawing &drawing)
{
    QByteArray box;
    for (const double v : {drawing.viewBox.x(), drawing.viewBox.y(), drawing.viewBox.width(), drawing.viewBox.height()})
        box += (box.isEmpty() ? "" : " ") + QByteArray::number(v, 'g', 10);
    return "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" viewBox=\"" + box
        + "\">" + drawing.fragment + "</svg>\n";
}

bool cleanLayerSvg(const QByteArray &content, QByteArray *cleaned, QString *error)
{
    LayerDrawing drawing;
    if (!readLayerSvg(content, QString(), &drawing, error))
        return false;
    *cleaned = layerDocument(drawing);
    return true;
}

bool loadLayerFile(const QString &path, StyleLayer *out, QString *error)
{
    QString why;
    const std::optional<QByteArray> content = readUserFile(path, kMaxLayerFileBytes, &why);
    if (!content) {
        *error = ImageText::tr("cannot read layer file %1: %2").arg(path, why);
        return false;
    }
    QByteArray cleaned;
    if (!cleanLayerSvg(*content, &cleaned, &why)) {
        *error = ImageText::tr("layer file %1 is not a valid SVG file: %2").arg(path, why);
        return false;
    }
    StyleLayer layer;
    layer.name = QFileInfo(path).fileName();
    layer.svg = cleaned;
    *out = layer;
    return true;
}

} // namespace toonface
