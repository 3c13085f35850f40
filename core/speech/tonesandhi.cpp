#include "speech/tonesandhi.h"

namespace toonface {

namespace {

bool isDigit(const QString &text)
{
    static const QString digits = QStringLiteral("〇零一二三四五六七八九十两百千万亿");
    return text.size() == 1 && digits.contains(text.front());
}

} // namespace

QVector<int> spokenTones(const Script &script)
{
    const QVector<ScriptSyllable> &s = script.syllables;
    QVector<int> tones(s.size());
    for (qsizetype k = 0; k < s.size(); ++k)
        tones[k] = s[k].tone;
    if (script.language == Language::English)
        return tones;
    // The neighbour within the same phrase, or nullptr.
    auto next = [&](qsizetype k) { return k + 1 < s.size() && !s[k].phraseBreakAfter ? &s[k + 1] : nullptr; };
    auto previous = [&](qsizetype k) { return k > 0 && !s[k - 1].phraseBreakAfter ? &s[k - 1] : nullptr; };
    auto between = [&](qsizetype k) {
        const ScriptSyllable *p = previous(k), *n = next(k);
        return p && n && p->text == n->text && p->pinyin == n->pinyin;
    };

    // 一 and 不 first: their spoken tone decides the third-tone runs around them.
    for (qsizetype k = 0; k < s.size(); ++k) {
        const ScriptSyllable *n = next(k), *p = previous(k);
        if (s[k].text == QStringLiteral("一") && s[k].pinyin == QLatin1String("yi")) {
            if (between(k))
                tones[k] = 5;
            else if (!n || isDigit(n->text) || (p && (isDigit(p->text) || p->text == QStringLiteral("第"))))
                tones[k] = 1;
            else
                tones[k] = n->tone == 4 || n->tone == 5 ? 2 : 4;
        } else if (s[k].text == QStringLiteral("不") && s[k].pinyin == QLatin1String("bu")) {
            if (between(k))
                tones[k] = 5;
            else if (n && n->tone == 4)
                tones[k] = 2;
        }
    }
    // Runs of 3rd tones (as written, after the sandhi above) within a phrase.
    for (qsizetype k = 0; k + 1 < s.size(); ++k) {
        if (tones[k] == 3 && !s[k].phraseBreakAfter && tones[k + 1] == 3)
            tones[k] = 2;
    }
    return tones;
}

} // namespace toonface
