#include "export/epubtext.h"

#include "i18n/coretext.h"

#include <QRegularExpression>

namespace toonface {

namespace {

bool isCjk(QChar c)
{
    const ushort u = c.unicode();
    return c.script() == QChar::Script_Han || c.script() == QChar::Script_Bopomofo || (u >= 0x3000 && u <= 0x30ff)
        || (u >= 0xff00 && u <= 0xffef);
}

// Ends a sentence wherever it stands.
bool isWideEnd(QChar c)
{
    return QStringView(u"。！？…‼⁇⁈⁉").contains(c);
}

// Ends a sentence before a space, the end of the paragraph or a CJK character.
bool isNarrowEnd(QChar c)
{
    return c == QLatin1Char('.') || c == QLatin1Char('!') || c == QLatin1Char('?');
}

bool isCloser(QChar c)
{
    return QStringView(u"\"'”’」』）)]》〉】»").contains(c);
}

bool hasWords(const QString &s)
{
    for (QChar c : s) {
        if (c.isLetterOrNumber())
            return true;
    }
    return false;
}

// A paragraph being gathered: its text and the file line of each of its characters.
struct Gathering
{
    QString text;
    QVector<int> lines;

    void append(const QString &line, int number)
    {
        const QString piece = line.trimmed();
        if (piece.isEmpty())
            return;
        if (!text.isEmpty() && !(isCjk(text.back()) && isCjk(piece.front()))) {
            text += QLatin1Char(' ');
            lines.append(number);
        }
        text += piece;
        lines.insert(lines.size(), piece.size(), number);
    }
};

QString inlineText(QString line)
{
    static const QRegularExpression image(QStringLiteral("!\\[[^\\]]*\\]\\([^)]*\\)"));
    static const QRegularExpression link(QStringLiteral("\\[([^\\]]*)\\]\\([^)]*\\)"));
    static const QRegularExpression tag(QStringLiteral("<[^>]*>"));
    static const QRegularExpression marks(QStringLiteral("\\*\\*|__|~~|`|\\*"));
    static const QRegularExpression underscore(QStringLiteral("(?<![\\p{L}\\p{N}])_|_(?![\\p{L}\\p{N}])"));
    static const QRegularExpression escape(QStringLiteral("\\\\([\\\\`*_{}\\[\\]()#+\\-.!>])"));
    line.replace(image, QString());
    line.replace(link, QStringLiteral("\\1"));
    line.replace(tag, QString());
    // Escaped marks survive the removal of the unescaped ones.
    line.replace(escape, QStringLiteral("\x01\\1"));
    QString out;
    for (qsizetype i = 0; i < line.size(); ++i) {
        if (line[i] == QChar(1) && i + 1 < line.size()) {
            out += QChar(0xe000 + line[++i].unicode()); // a private-use stand-in, put back below
            continue;
        }
        out += line[i];
    }
    out.replace(marks, QString());
    out.replace(underscore, QString());
    for (QChar &c : out) {
        if (c.unicode() >= 0xe000 && c.unicode() < 0xe080)
            c = QChar(c.unicode() - 0xe000);
    }
    return out;
}

} // namespace

QVector<BookSentence> splitSentences(const QString &paragraph, int firstLine)
{
    QVector<BookSentence> out;
    qsizetype start = 0;
    const qsizetype n = paragraph.size();
    auto cut = [&](qsizetype end) {
        const QString s = paragraph.mid(start, end - start).trimmed();
        start = end;
        if (s.isEmpty())
            return;
        if (!hasWords(s) && !out.isEmpty()) {
            // Punctuation alone belongs to the sentence before it.
            out.last().text += (isCjk(s.front()) ? QString() : QStringLiteral(" ")) + s;
            return;
        }
        out.append(BookSentence {s, firstLine});
    };
    for (qsizetype i = 0; i < n; ++i) {
        const QChar c = paragraph[i];
        if (!isWideEnd(c) && !isNarrowEnd(c))
            continue;
        qsizetype j = i + 1;
        while (j < n && (isWideEnd(paragraph[j]) || isNarrowEnd(paragraph[j]) || isCloser(paragraph[j])))
            ++j;
        const bool wide = isWideEnd(c) || (j > i + 1 && isWideEnd(paragraph[j - 1]));
        if (wide || j == n || paragraph[j].isSpace() || isCjk(paragraph[j])) {
            cut(j);
            i = j - 1;
        }
    }
    cut(n);
    // A first sentence of punctuation alone goes with the one after it.
    if (out.size() > 1 && !hasWords(out.first().text)) {
        out[1].text.prepend(out.first().text);
        out.removeFirst();
    }
    if (out.size() == 1 && !hasWords(out.first().text))
        out.clear();
    return out;
}

BookTextParse parseBookText(const QString &text, bool markdown, const QString &fileName)
{
    BookTextParse parse;
    QStringList lines = text.split(QLatin1Char('\n'));
    for (QString &line : lines) {
        if (line.endsWith(QLatin1Char('\r')))
            line.chop(1);
    }
    // Without any blank line between text, every line is a paragraph (a Chinese text often has
    // one paragraph a line); otherwise blank lines separate them.
    bool blankSeparates = false;
    for (qsizetype i = 1; i + 1 < lines.size() && !blankSeparates; ++i) {
        blankSeparates = lines[i].trimmed().isEmpty() && !lines[i - 1].trimmed().isEmpty();
    }

    static const QRegularExpression heading(QStringLiteral("^ {0,3}(#{1,6})\\s+(.*?)(\\s+#+)?\\s*$"));
    static const QRegularExpression rule(QStringLiteral("^ {0,3}([-*_])(\\s*\\1){2,}\\s*$"));
    static const QRegularExpression fence(QStringLiteral("^ {0,3}(```|~~~)"));
    static const QRegularExpression item(QStringLiteral("^\\s*([-*+]|\\d{1,9}[.)])\\s+"));
    static const QRegularExpression quote(QStringLiteral("^\\s*(>\\s?)+"));

    bool anyEnd = false;
    BookPage pendingHeading;
    Gathering paragraph;
    int paragraphLine = 1;
    auto chapter = [&parse]() -> BookChapter & {
        if (parse.chapters.isEmpty())
            parse.chapters.append(BookChapter {});
        return parse.chapters.last();
    };
    auto flush = [&]() {
        if (paragraph.text.isEmpty())
            return;
        QVector<BookSentence> sentences = splitSentences(paragraph.text, paragraphLine);
        // Each sentence's line: where its text starts in the paragraph.
        qsizetype from = 0;
        for (BookSentence &s : sentences) {
            const qsizetype at = paragraph.text.indexOf(s.text.left(8), from);
            if (at >= 0) {
                s.line = paragraph.lines.value(at, paragraphLine);
                from = at;
            }
        }
        for (const BookSentence &s : sentences) {
            qsizetype last = s.text.size() - 1;
            while (last > 0 && isCloser(s.text[last]))
                --last;
            anyEnd = anyEnd || isWideEnd(s.text[last]) || isNarrowEnd(s.text[last]);
        }
        paragraph = Gathering {};
        if (sentences.isEmpty())
            return;
        BookPage page = pendingHeading;
        pendingHeading = BookPage {};
        page.sentences = sentences;
        chapter().pages.append(page);
    };
    auto closeHeading = [&]() {
        if (!pendingHeading.heading.isEmpty())
            chapter().pages.append(pendingHeading);
        pendingHeading = BookPage {};
    };

    bool inFence = false;
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const int number = int(i) + 1;
        QString line = lines[i];
        if (markdown) {
            if (fence.match(line).hasMatch()) {
                flush();
                inFence = !inFence;
                continue;
            }
            if (inFence)
                continue;
            if (const QRegularExpressionMatch h = heading.match(line); h.hasMatch()) {
                flush();
                closeHeading();
                const QString title = inlineText(h.captured(2)).trimmed();
                if (title.isEmpty() || !hasWords(title))
                    continue;
                parse.chapters.append(BookChapter {title, {}});
                pendingHeading.heading = {BookSentence {title, number}};
                pendingHeading.headingLevel = int(h.capturedLength(1));
                continue;
            }
            if (rule.match(line).hasMatch()) {
                flush();
                continue;
            }
            line.remove(quote);
            if (const QRegularExpressionMatch m = item.match(line); m.hasMatch()) {
                flush();
                line = line.mid(m.capturedLength());
            }
            line = inlineText(line);
        }
        if (line.trimmed().isEmpty() || !blankSeparates)
            flush();
        if (paragraph.text.isEmpty())
            paragraphLine = number;
        paragraph.append(line, number);
    }
    flush();
    closeHeading();
    parse.chapters.removeIf([](const BookChapter &c) { return c.pages.isEmpty(); });

    if (parse.chapters.isEmpty())
        parse.error
            = QStringLiteral("%1: %2").arg(fileName, ExportText::tr("the text is empty: there is nothing to read"));
    else if (!anyEnd)
        parse.error = QStringLiteral("%1: %2").arg(fileName,
            ExportText::tr("no sentence ends anywhere in the text: end its sentences with . ! ? or 。！？ so that "
                           "the book can highlight them as they are read"));
    return parse;
}

} // namespace toonface
