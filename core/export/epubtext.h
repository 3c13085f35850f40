#pragma once

#include <QString>
#include <QStringList>
#include <QVector>

namespace toonface {

// The text of a read-aloud book, as read from a plain text or Markdown file: chapters of
// pages, each page a paragraph (the first page of a chapter also shows its heading), each
// paragraph split into sentences. Every sentence is spoken, headings included.
struct BookSentence
{
    QString text; // as shown and spoken, inline Markdown removed
    int line = 1; // where it starts in the file (1-based)
};

struct BookPage
{
    QVector<BookSentence> heading; // the chapter's heading (one sentence) on its first page
    int headingLevel = 0; // 1-6 with a heading
    QVector<BookSentence> sentences; // the paragraph
};

struct BookChapter
{
    QString title; // the heading, or empty for text before the first heading
    QVector<BookPage> pages;
};

struct BookTextParse
{
    QVector<BookChapter> chapters;
    QString error; // names the file and the problem; empty when the text can be a book
    bool ok() const { return error.isEmpty(); }
};

// Reads `text`: paragraphs are separated by blank lines (lines of one paragraph are joined, with
// no space between two CJK characters), or, in a text without blank lines, are its lines.
// Markdown (`markdown`) adds chapters at ATX headings (`#` to `######`), drops code blocks,
// rules, images, HTML tags and link targets, and keeps the text of emphasis, links and list
// items. A sentence ends at . ! ? … 。！？ ！ (a full stop only before a space or the end of
// the paragraph), with the closing quotes and brackets after it; a paragraph's last sentence
// needs no end mark. An empty text, or one without any sentence end, is an error naming
// `fileName`.
BookTextParse parseBookText(const QString &text, bool markdown, const QString &fileName);

// The sentences of one paragraph (see parseBookText), `line` set to `firstLine`.
QVector<BookSentence> splitSentences(const QString &paragraph, int firstLine);

} // namespace toonface
