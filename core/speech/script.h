#pragma once

#include <QString>
#include <QVector>

#include <optional>

namespace toonface {

enum class Language { Auto, Mandarin, English };

QString languageCode(Language language); // "auto", "cmn", "en"
std::optional<Language> languageFromCode(const QString &code);

// One spoken unit of a script: a Mandarin syllable (one character, one pinyin or one Zhuyin
// syllable) or, in an English script, one word.
struct ScriptSyllable
{
    QString text; // as written in the script
    QString pinyin; // normalised toneless pinyin (see PinyinSyllable); empty for English
    int tone = 5; // 1-4, 5 neutral; 0 for English
    int position = 0; // where `text` starts in the script (QString index, UTF-16 units)
    int length = 0; // its length there
    bool phraseBreakAfter = false; // punctuation or a line break follows
    bool operator==(const ScriptSyllable &) const = default;
};

struct Script
{
    Language language = Language::Mandarin;
    QVector<ScriptSyllable> syllables;
};

// Something in the script that cannot be spoken, by where it is.
struct ScriptProblem
{
    int position = 0; // QString index
    int line = 1; // 1-based
    int column = 1; // 1-based, in characters (code points)
    QString text;
    QString reason;
};

struct ScriptParse
{
    Script script;
    QVector<ScriptProblem> problems; // every unknown or unreadable piece
    QString error; // empty when the whole script was read
    bool ok() const { return error.isEmpty(); }
};

// Reads a script: Chinese characters (traditional or simplified; readings from
// PinyinDictionary, phrase by phrase), Hanyu pinyin with tone marks or numbers, Zhuyin, or a
// mix (Mandarin); or English words. Punctuation (, . ! ? ; : … and their CJK forms, dashes)
// and line breaks mark phrase breaks; spaces, quotes and brackets only separate. `Auto` picks
// Mandarin when the text holds Chinese characters or Zhuyin or nearly all its words are
// pinyin, English otherwise. Anything that cannot be spoken is a problem, never dropped; the
// error then names the first one ("line 2, column 5: 'ⓧ' is not ...").
ScriptParse parseScript(const QString &text, Language language = Language::Auto);

// The same, on a UTF-8 file; errors name the file. `textRead` gets the file's text (the file is
// read once: it may be a pipe).
ScriptParse readScriptFile(const QString &path, Language language = Language::Auto, QString *textRead = nullptr);

} // namespace toonface
