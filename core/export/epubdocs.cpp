#include "export/epubdocs.h"

#include <QStringList>

#include <algorithm>

namespace toonface::epub {

namespace {

QByteArray esc(const QString &s)
{
    return s.toHtmlEscaped().toUtf8();
}

QByteArray htmlStart(const QString &language, const QString &title, const QString &stylesheetHref)
{
    QByteArray out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!DOCTYPE html>\n"
                     "<html xmlns=\"http://www.w3.org/1999/xhtml\" xmlns:epub=\"http://www.idpf.org/2007/ops\" "
                     "xml:lang=\""
        + esc(language) + "\" lang=\"" + esc(language) + "\">\n<head>\n<meta charset=\"utf-8\"/>\n<title>" + esc(title)
        + "</title>\n";
    if (!stylesheetHref.isEmpty())
        out += "<link rel=\"stylesheet\" type=\"text/css\" href=\"" + esc(stylesheetHref) + "\"/>\n";
    return out + "</head>\n";
}

void appendSentence(QByteArray &out, const PageSentence &s)
{
    out += "<span id=\"" + esc(s.clip.id) + "\">";
    for (const PageSentence::Piece &p : s.pieces) {
        if (p.clip.id.isEmpty())
            out += esc(p.text);
        else
            out += "<span id=\"" + esc(p.clip.id) + "\">" + esc(p.text) + "</span>";
    }
    out += "</span>";
}

QByteArray audioElement(const QString &audioHref, const ReadClip &clip)
{
    return "<audio src=\"" + esc(audioHref) + "\" clipBegin=\"" + clipValue(clip.beginMs).toLatin1() + "\" clipEnd=\""
        + clipValue(clip.endMs).toLatin1() + "\"/>";
}

} // namespace

QString clockValue(qint64 ms)
{
    const qint64 h = ms / 3600000, m = ms / 60000 % 60, s = ms / 1000 % 60, rest = ms % 1000;
    return QStringLiteral("%1:%2:%3.%4")
        .arg(h)
        .arg(m, 2, 10, QLatin1Char('0'))
        .arg(s, 2, 10, QLatin1Char('0'))
        .arg(rest, 3, 10, QLatin1Char('0'));
}

QString clipValue(qint64 ms)
{
    return QStringLiteral("%1.%2s").arg(ms / 1000).arg(ms % 1000, 3, 10, QLatin1Char('0'));
}

QByteArray pageXhtml(const PageDocument &page)
{
    QByteArray out = htmlStart(page.language, page.title, page.stylesheetHref);
    out += "<body>\n<section class=\"tf-page\">\n<div class=\"tf-face\">\n";
    if (page.faceVideoHref.isEmpty()) {
        out += page.faceSvg;
    } else {
        // Played by the reader's press (no autoplay: a reading system with media overlays reads
        // the page itself); the poster, the cartoon, is the fallback content.
        out += "<video src=\"" + esc(page.faceVideoHref) + "\" controls=\"controls\" preload=\"none\" poster=\""
            + esc(page.posterHref) + "\" width=\"" + QByteArray::number(page.videoWidth) + "\" height=\""
            + QByteArray::number(page.videoHeight) + "\"><img src=\"" + esc(page.posterHref) + "\" alt=\""
            + esc(page.title) + "\"/></video>";
    }
    out += "\n</div>\n<div class=\"tf-text\">\n";
    qsizetype first = 0;
    if (page.headingLevel > 0 && !page.sentences.isEmpty()) {
        const QByteArray h = "h" + QByteArray::number(std::clamp(page.headingLevel, 1, 6));
        out += "<" + h + ">";
        appendSentence(out, page.sentences.first());
        out += "</" + h + ">\n";
        first = 1;
    }
    if (first < page.sentences.size()) {
        out += "<p>";
        for (qsizetype i = first; i < page.sentences.size(); ++i) {
            // Sentences of a language written with spaces are spaced; Chinese ones are not.
            if (i > first) {
                const PageSentence &before = page.sentences[i - 1];
                const QString last = before.pieces.isEmpty() ? QString() : before.pieces.last().text;
                if (!last.isEmpty() && last.back().unicode() < 0x2e80)
                    out += ' ';
            }
            appendSentence(out, page.sentences[i]);
        }
        out += "</p>\n";
    }
    out += "</div>\n</section>\n</body>\n</html>\n";
    return out;
}

QByteArray overlaySmil(const PageDocument &page, const QString &pageHref, const QString &audioHref, bool bySyllable)
{
    QByteArray out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                     "<smil xmlns=\"http://www.w3.org/ns/SMIL\" xmlns:epub=\"http://www.idpf.org/2007/ops\" "
                     "version=\"3.0\">\n<body>\n";
    int par = 0;
    for (const PageSentence &s : page.sentences) {
        QVector<const ReadClip *> leaves;
        if (bySyllable) {
            for (const PageSentence::Piece &p : s.pieces) {
                if (!p.clip.id.isEmpty())
                    leaves.append(&p.clip);
            }
        }
        if (leaves.isEmpty()) {
            out += "<par id=\"tf-par" + QByteArray::number(++par) + "\"><text src=\"" + esc(pageHref) + '#'
                + esc(s.clip.id) + "\"/>" + audioElement(audioHref, s.clip) + "</par>\n";
            continue;
        }
        out += "<seq id=\"tf-seq-" + esc(s.clip.id) + "\" epub:textref=\"" + esc(pageHref) + '#' + esc(s.clip.id)
            + "\">\n";
        for (const ReadClip *c : leaves) {
            out += "<par id=\"tf-par" + QByteArray::number(++par) + "\"><text src=\"" + esc(pageHref) + '#' + esc(c->id)
                + "\"/>" + audioElement(audioHref, *c) + "</par>\n";
        }
        out += "</seq>\n";
    }
    out += "</body>\n</smil>\n";
    return out;
}

QByteArray containerXml(const QString &packagePath)
{
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
           "<container version=\"1.0\" xmlns=\"urn:oasis:names:tc:opendocument:xmlns:container\">\n"
           "<rootfiles>\n<rootfile full-path=\""
        + esc(packagePath) + "\" media-type=\"application/oebps-package+xml\"/>\n</rootfiles>\n</container>\n";
}

QByteArray stylesheet()
{
    // The face beside the text on a wide screen, above it on a narrow one; the sentence being
    // read is highlighted (the reading system adds kActiveClass to its element).
    return QByteArray("body { margin: 0.5em; }\n"
                      ".tf-page { display: flex; flex-direction: row; align-items: flex-start; }\n"
                      ".tf-face { flex: 0 0 38%; max-width: 38%; margin-right: 1em; }\n"
                      ".tf-face svg, .tf-face video, .tf-face img { display: block; width: 100%; height: auto; }\n"
                      ".tf-text { flex: 1 1 auto; font-size: 1.25em; line-height: 1.7; }\n"
                      ".tf-text h1, .tf-text h2, .tf-text h3, .tf-text h4, .tf-text h5, .tf-text h6 "
                      "{ margin-top: 0; line-height: 1.3; }\n"
                      ".tf-cover { text-align: center; }\n"
                      ".tf-cover img { max-width: 100%; max-height: 70vh; }\n"
                      "@media (max-aspect-ratio: 1/1) {\n"
                      "  .tf-page { flex-direction: column; align-items: center; }\n"
                      "  .tf-face { flex: none; width: 60%; max-width: 60%; margin: 0 auto 1em auto; }\n"
                      "}\n.")
        + kActiveClass + " { background-color: #ffe27a; color: #000; border-radius: 0.2em; }\n";
}

QByteArray coverXhtml(const QString &language, const QString &title, const QString &author, const QString &imageHref,
    const QString &stylesheetHref)
{
    QByteArray out = htmlStart(language, title, stylesheetHref);
    out += "<body>\n<section class=\"tf-cover\" epub:type=\"cover\">\n<img src=\"" + esc(imageHref) + "\" alt=\""
        + esc(title) + "\"/>\n<h1>" + esc(title) + "</h1>\n";
    if (!author.isEmpty())
        out += "<p>" + esc(author) + "</p>\n";
    out += "</section>\n</body>\n</html>\n";
    return out;
}

QByteArray navXhtml(const QString &language, const QString &title, const QVector<NavEntry> &entries)
{
    QByteArray out = htmlStart(language, title, {});
    out += "<body>\n<nav epub:type=\"toc\" id=\"toc\">\n<h1>" + esc(title) + "</h1>\n<ol>\n";
    // A heading nests under the nearest one before it of a higher level (a smaller number).
    QVector<int> levels;
    int previous = -1;
    for (const NavEntry &e : entries) {
        while (!levels.isEmpty() && levels.last() >= e.level)
            levels.removeLast();
        const int depth = int(levels.size());
        levels.append(e.level);
        if (previous >= 0 && depth > previous) {
            out += "\n<ol>\n";
        } else if (previous >= 0) {
            out += "</li>\n";
            for (int d = previous; d > depth; --d)
                out += "</ol>\n</li>\n";
        }
        out += "<li><a href=\"" + esc(e.href) + "\">" + esc(e.title) + "</a>";
        previous = depth;
    }
    if (previous >= 0) {
        out += "</li>\n";
        for (int d = previous; d > 0; --d)
            out += "</ol>\n</li>\n";
    }
    out += "</ol>\n</nav>\n</body>\n</html>\n";
    return out;
}

QByteArray packageOpf(const PackageMetadata &meta, const QVector<ManifestItem> &manifest, const QStringList &spine)
{
    QByteArray out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                     "<package xmlns=\"http://www.idpf.org/2007/opf\" version=\"3.0\" unique-identifier=\"tf-id\" "
                     "xml:lang=\""
        + esc(meta.language) + "\">\n<metadata xmlns:dc=\"http://purl.org/dc/elements/1.1/\">\n";
    out += "<dc:identifier id=\"tf-id\">" + esc(meta.identifier) + "</dc:identifier>\n";
    out += "<dc:title>" + esc(meta.title) + "</dc:title>\n";
    out += "<dc:language>" + esc(meta.language) + "</dc:language>\n";
    if (!meta.author.isEmpty())
        out += "<dc:creator id=\"tf-author\">" + esc(meta.author) + "</dc:creator>\n";
    out += "<meta property=\"dcterms:modified\">"
        + esc(meta.modified.toUTC().toString(QStringLiteral("yyyy-MM-ddTHH:mm:ssZ"))) + "</meta>\n";
    qint64 total = 0;
    for (const ManifestItem &item : manifest) {
        if (item.overlayMs < 0)
            continue;
        out += "<meta property=\"media:duration\" refines=\"#" + esc(item.id) + "\">"
            + clockValue(item.overlayMs).toLatin1() + "</meta>\n";
        total += item.overlayMs;
    }
    out += "<meta property=\"media:duration\">" + clockValue(total).toLatin1() + "</meta>\n";
    out += "<meta property=\"media:active-class\">" + QByteArray(kActiveClass) + "</meta>\n";
    out += "</metadata>\n<manifest>\n";
    for (const ManifestItem &item : manifest) {
        out += "<item id=\"" + esc(item.id) + "\" href=\"" + esc(item.href) + "\" media-type=\"" + esc(item.mediaType)
            + '"';
        if (!item.properties.isEmpty())
            out += " properties=\"" + esc(item.properties) + '"';
        if (!item.mediaOverlay.isEmpty())
            out += " media-overlay=\"" + esc(item.mediaOverlay) + '"';
        out += "/>\n";
    }
    out += "</manifest>\n<spine>\n";
    for (const QString &id : spine)
        out += "<itemref idref=\"" + esc(id) + "\"/>\n";
    out += "</spine>\n</package>\n";
    return out;
}

} // namespace toonface::epub
