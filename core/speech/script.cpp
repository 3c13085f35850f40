#include "speech/script.h"

#include "i18n/coretext.h"
#include "speech/pinyin.h"
#include "speech/pinyindictionary.h"
#include "speech/zhuyin.h"

#include <QFile>

namespace toonface {

namespace {

struct CodePoint
{
    char32_t c;
    int pos; // QString index
    int len; // 1 or 2 UTF-16 units
    int line;
    int column;
};

enum class Kind { Han, Zhuyin, Word, Break, Problem };

struct Token
{
    Kind kind;
    int first; // index into the code points
    int count;
};

bool isBreakPunctuation(char32_t c)
{
    static const std::u32string breaks = U",.!?;:…，。！？；：、—–‥⋯｡､︐︒︔︕︖";
    return breaks.find(c) != std::u32string::npos;
}

bool isHan(char32_t c)
{
    return QChar::script(c) == QChar::Script_Han && QChar::isLetterOrNumber(c);
}

bool isWordChar(char32_t c)
{
    if (QChar::isDigit(c))
        return true;
    if (QChar::isLetter(c))
        return QChar::script(c) == QChar::Script_Latin;
    return QChar::category(c) == QChar::Mark_NonSpacing; // decomposed tone marks
}

bool isWordJoiner(char32_t c) // inside a word only: xi'an, lu:, ni-hao
{
    return c == U'\'' || c == U'’' || c == U'-' || c == U':';
}

} // namespace

QString languageCode(Language language)
{
    switch (language) {
    case Language::Auto: return QStringLiteral("auto");
    case Language::Mandarin: return QStringLiteral("cmn");
    case Language::English: return QStringLiteral("en");
    }
    return {};
}

std::optional<Language> languageFromCode(const QString &code)
{
    const QString c = code.trimmed().toLower();
    if (c == QLatin1String("auto") || c.isEmpty())
        return Language::Auto;
    if (c == QLatin1String("cmn") || c == QLatin1String("zh") || c == QLatin1String("mandarin"))
        return Language::Mandarin;
    if (c == QLatin1String("en") || c == QLatin1String("english"))
        return Language::English;
    return std::nullopt;
}

ScriptParse parseScript(const QString &text, Language language)
{
    ScriptParse result;
    std::vector<CodePoint> cps;
    {
        int line = 1, column = 1;
        for (int i = 0; i < text.size();) {
            char32_t c = text.at(i).unicode();
            int len = 1;
            if (QChar::isHighSurrogate(c) && i + 1 < text.size() && text.at(i + 1).isLowSurrogate()) {
                c = QChar::surrogateToUcs4(text.at(i), text.at(i + 1));
                len = 2;
            }
            cps.push_back({c, i, len, line, column});
            if (c == U'\n') {
                ++line;
                column = 1;
            } else {
                ++column;
            }
            i += len;
        }
    }

    std::vector<Token> tokens;
    for (int i = 0; i < int(cps.size());) {
        const char32_t c = cps[size_t(i)].c;
        auto runWhile = [&](auto pred) {
            int j = i;
            while (j < int(cps.size()) && pred(j))
                ++j;
            return j;
        };
        if (isHan(c)) {
            const int j = runWhile([&](int k) { return isHan(cps[size_t(k)].c); });
            tokens.push_back({Kind::Han, i, j - i});
            i = j;
        } else if (isZhuyinChar(c)) {
            const int j = runWhile([&](int k) { return isZhuyinChar(cps[size_t(k)].c); });
            tokens.push_back({Kind::Zhuyin, i, j - i});
            i = j;
        } else if (isWordChar(c)) {
            const int j = runWhile([&](int k) {
                const char32_t x = cps[size_t(k)].c;
                if (isWordChar(x))
                    return true;
                return isWordJoiner(x) && k + 1 < int(cps.size()) && isWordChar(cps[size_t(k + 1)].c);
            });
            // "lu:" keeps its colon.
            int end = j;
            if (end < int(cps.size()) && cps[size_t(end)].c == U':'
                && (cps[size_t(end - 1)].c == U'u' || cps[size_t(end - 1)].c == U'U')
                && (end + 1 >= int(cps.size()) || !QChar::isLetter(cps[size_t(end + 1)].c)))
                ++end;
            tokens.push_back({Kind::Word, i, end - i});
            i = end;
        } else if (c == U'\n' || c == U'\r' || c == U'\u2028' || c == U'\u2029' || isBreakPunctuation(c)) {
            tokens.push_back({Kind::Break, i, 1});
            ++i;
        } else if (QChar::isSpace(c) || QChar::isPunct(c)) {
            ++i; // spaces, quotes and brackets only separate
        } else {
            tokens.push_back({Kind::Problem, i, 1});
            ++i;
        }
    }

    auto tokenText = [&](const Token &t) {
        const CodePoint &a = cps[size_t(t.first)];
        const CodePoint &b = cps[size_t(t.first + t.count - 1)];
        return text.mid(a.pos, b.pos + b.len - a.pos);
    };
    auto addProblem = [&](int cp, int count, const QString &reason) {
        const CodePoint &a = cps[size_t(cp)];
        const CodePoint &b = cps[size_t(cp + count - 1)];
        result.problems.append({a.pos, a.line, a.column, text.mid(a.pos, b.pos + b.len - a.pos), reason});
    };

    if (language == Language::Auto) {
        int words = 0, pinyinWords = 0;
        bool chinese = false;
        for (const Token &t : tokens) {
            if (t.kind == Kind::Han || t.kind == Kind::Zhuyin)
                chinese = true;
            if (t.kind == Kind::Word) {
                ++words;
                if (splitPinyinWord(tokenText(t)))
                    ++pinyinWords;
            }
        }
        language = chinese || (words > 0 && pinyinWords * 10 >= words * 9) ? Language::Mandarin : Language::English;
    }
    result.script.language = language;

    auto &syllables = result.script.syllables;
    for (const Token &t : tokens) {
        switch (t.kind) {
        case Kind::Break:
            if (!syllables.isEmpty())
                syllables.back().phraseBreakAfter = true;
            break;
        case Kind::Problem: addProblem(t.first, 1, ScriptText::tr("cannot be spoken")); break;
        case Kind::Han: {
            if (language == Language::English) {
                addProblem(t.first, t.count, ScriptText::tr("is not English"));
                break;
            }
            QString dictError;
            const auto dict = PinyinDictionary::shared(&dictError);
            if (!dict) {
                result.error = dictError;
                return result;
            }
            std::u32string run;
            for (int k = 0; k < t.count; ++k)
                run.push_back(cps[size_t(t.first + k)].c);
            const QVector<PinyinSyllable> readings = dict->readRun(run);
            for (int k = 0; k < t.count; ++k) {
                const CodePoint &cp = cps[size_t(t.first + k)];
                const PinyinSyllable &r = readings[k];
                if (r.pinyin.isEmpty()) {
                    addProblem(t.first + k, 1, ScriptText::tr("has no Mandarin reading in the dictionary"));
                    continue;
                }
                syllables.append({text.mid(cp.pos, cp.len), r.pinyin, r.tone, cp.pos, cp.len, false});
            }
            break;
        }
        case Kind::Zhuyin: {
            if (language == Language::English) {
                addProblem(t.first, t.count, ScriptText::tr("is not English"));
                break;
            }
            const QString run = tokenText(t);
            QVector<int> lengths;
            const auto sylls = zhuyinToPinyin(run, &lengths);
            if (!sylls) {
                addProblem(t.first, t.count, ScriptText::tr("is not valid Zhuyin"));
                break;
            }
            int offset = cps[size_t(t.first)].pos;
            for (int k = 0; k < sylls->size(); ++k) {
                syllables.append({run.mid(offset - cps[size_t(t.first)].pos, lengths[k]), sylls->at(k).pinyin,
                    sylls->at(k).tone, offset, lengths[k], false});
                offset += lengths[k];
            }
            break;
        }
        case Kind::Word: {
            const QString word = tokenText(t);
            const int pos = cps[size_t(t.first)].pos;
            if (language == Language::English) {
                syllables.append({word, QString(), 0, pos, int(word.size()), false});
                break;
            }
            QVector<QPair<int, int>> spans;
            const auto sylls = splitPinyinWord(word, &spans);
            if (!sylls) {
                bool number = true;
                for (const QChar ch : word)
                    number = number && ch.isDigit();
                addProblem(t.first, t.count,
                    number ? ScriptText::tr("is a number: write it in characters or pinyin")
                           : ScriptText::tr("is not Hanyu pinyin"));
                break;
            }
            for (int k = 0; k < sylls->size(); ++k)
                syllables.append({word.mid(spans[k].first, spans[k].second), sylls->at(k).pinyin, sylls->at(k).tone,
                    pos + spans[k].first, spans[k].second, false});
            break;
        }
        }
    }

    if (!result.problems.isEmpty()) {
        const ScriptProblem &p = result.problems.first();
        result.error = ScriptText::tr("line %1, column %2: '%3' %4")
                           .arg(QString::number(p.line), QString::number(p.column), p.text, p.reason);
        if (result.problems.size() > 1)
            result.error
                = ScriptText::tr("%1 (and %n more)", nullptr, int(result.problems.size() - 1)).arg(result.error);
    } else if (syllables.isEmpty()) {
        result.error = ScriptText::tr("the script holds nothing to speak");
    }
    return result;
}

ScriptParse readScriptFile(const QString &path, Language language, QString *textRead)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        ScriptParse r;
        r.error = ScriptText::tr("cannot read the script %1: %2").arg(path, f.errorString());
        return r;
    }
    const QByteArray bytes = f.readAll();
    QString text = QString::fromUtf8(bytes);
    if (text.contains(QChar::ReplacementCharacter) && !bytes.contains("\xEF\xBF\xBD")) {
        ScriptParse r;
        r.error = ScriptText::tr("the script %1 is not UTF-8 text").arg(path);
        return r;
    }
    if (text.startsWith(QChar(0xFEFF)))
        text[0] = QLatin1Char(' ');
    if (textRead)
        *textRead = text.trimmed();
    ScriptParse r = parseScript(text, language);
    if (!r.ok())
        r.error = withProblem(path, r.error);
    return r;
}

} // namespace toonface
