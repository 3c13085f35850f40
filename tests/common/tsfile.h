#pragma once

// Reads a Qt Linguist .ts file for the translation tests: every message with its context,
// source, comment, state and translations (one, or the numerus forms).
#include <QFile>
#include <QHash>
#include <QString>
#include <QStringList>
#include <QXmlStreamReader>

namespace toonface::fixture {

struct TsMessage
{
    QString context;
    QString source;
    QString comment;
    QString type; // the translation's type attribute: "", "unfinished", "vanished", "obsolete"
    bool numerus = false;
    QStringList translations; // the translation, or each numerus form
};

struct TsFile
{
    QString language;
    QList<TsMessage> messages;
    QString error;

    // The translation of `source` in `context` (its first form), or an empty string.
    QString translate(const QString &context, const QString &source) const
    {
        for (const TsMessage &m : messages) {
            if (m.context == context && m.source == source)
                return m.translations.value(0);
        }
        return {};
    }
};

inline TsFile readTsFile(const QString &path)
{
    TsFile ts;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        ts.error = path + QStringLiteral(": ") + file.errorString();
        return ts;
    }
    QXmlStreamReader xml(&file);
    QString context;
    TsMessage message;
    while (!xml.atEnd()) {
        xml.readNext();
        if (xml.isStartElement()) {
            const auto name = xml.name();
            if (name == QLatin1StringView("TS")) {
                ts.language = xml.attributes().value(QStringLiteral("language")).toString();
            } else if (name == QLatin1StringView("name")) {
                context = xml.readElementText();
            } else if (name == QLatin1StringView("message")) {
                message = TsMessage {};
                message.context = context;
                message.numerus = xml.attributes().value(QStringLiteral("numerus")) == QLatin1StringView("yes");
            } else if (name == QLatin1StringView("source")) {
                message.source = xml.readElementText();
            } else if (name == QLatin1StringView("comment")) {
                message.comment = xml.readElementText();
            } else if (name == QLatin1StringView("translation")) {
                message.type = xml.attributes().value(QStringLiteral("type")).toString();
                if (!message.numerus)
                    message.translations << xml.readElementText();
            } else if (name == QLatin1StringView("numerusform")) {
                message.translations << xml.readElementText();
            }
        } else if (xml.isEndElement() && xml.name() == QLatin1StringView("message")) {
            ts.messages << message;
        }
    }
    if (xml.hasError())
        ts.error = QStringLiteral("%1: %2 at line %3").arg(path, xml.errorString()).arg(xml.lineNumber());
    return ts;
}

} // namespace toonface::fixture
