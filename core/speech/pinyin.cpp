#include "speech/pinyin.h"

#include <QSet>

#include <functional>

namespace toonface {

namespace {

const QChar kUmlautU(0x00FC); // ü
const QChar kCircumflexE(0x00EA); // ê

bool startsWithFront(const QString &final) // i- or ü- finals
{
    return final.startsWith(QLatin1Char('i')) || final.startsWith(kUmlautU);
}

const QSet<QString> &validFinals()
{
    static const QSet<QString> finals = [] {
        QSet<QString> s;
        for (const char *f :
            {"a", "o", "e", "ai", "ei", "ao", "ou", "an", "en", "ang", "eng", "ong", "er", "i", "ia", "io", "ie", "iao",
                "iou", "ian", "in", "iang", "ing", "iong", "u", "ua", "uo", "uai", "uei", "uan", "uen", "uang", "ueng"})
            s.insert(QString::fromLatin1(f));
        s.insert(QString(kCircumflexE));
        for (const char *f : {"", "e", "an", "en"})
            s.insert(QString(kUmlautU) + QString::fromLatin1(f));
        return s;
    }();
    return finals;
}

bool phonotacticallyValid(const QString &initial, const QString &final)
{
    static const QSet<QString> retroflexAndDental = {QStringLiteral("zh"), QStringLiteral("ch"), QStringLiteral("sh"),
        QStringLiteral("r"), QStringLiteral("z"), QStringLiteral("c"), QStringLiteral("s")};
    static const QSet<QString> velar = {QStringLiteral("g"), QStringLiteral("k"), QStringLiteral("h")};
    const bool front = startsWithFront(final);
    const bool umlaut = final.startsWith(kUmlautU);
    if (initial.isEmpty())
        return final != QLatin1String("ong");
    // er, ê, io and ueng stand alone (er, ê, yo, weng).
    if (final == QLatin1String("er") || final == QString(kCircumflexE) || final == QLatin1String("io")
        || final == QLatin1String("ueng"))
        return false;
    if (initial == QLatin1String("j") || initial == QLatin1String("q") || initial == QLatin1String("x"))
        return front;
    if (velar.contains(initial))
        return !front;
    if (retroflexAndDental.contains(initial))
        return !front || final == QLatin1String("i"); // the empty rime of zhi ... si
    if (umlaut)
        return initial == QLatin1String("n") || initial == QLatin1String("l");
    if (initial == QLatin1String("b") || initial == QLatin1String("p") || initial == QLatin1String("m")
        || initial == QLatin1String("f"))
        return final.size() == 1 || !final.startsWith(QLatin1Char('u'));
    return true; // d t n l
}

QChar toneVowel(const QString &s, int *index)
{
    // The mark goes on a or e; on the o of ou; otherwise on the last vowel.
    int i = s.indexOf(QLatin1Char('a'));
    if (i < 0)
        i = s.indexOf(QLatin1Char('e'));
    if (i < 0)
        i = s.indexOf(kCircumflexE);
    if (i < 0)
        i = s.indexOf(QLatin1String("ou"));
    if (i < 0) {
        for (int k = s.size() - 1; k >= 0; --k) {
            const QChar c = s.at(k);
            if (c == QLatin1Char('i') || c == QLatin1Char('o') || c == QLatin1Char('u') || c == kUmlautU) {
                i = k;
                break;
            }
        }
    }
    if (i < 0) { // syllabic nasals: the mark goes on the nasal
        i = s.indexOf(QLatin1Char('n'));
        if (i < 0)
            i = s.indexOf(QLatin1Char('m'));
    }
    *index = i;
    return i >= 0 ? s.at(i) : QChar();
}

} // namespace

std::optional<PinyinParts> splitPinyinSyllable(const QString &toneless)
{
    QString s = toneless;
    for (const char *nasal : {"m", "n", "ng", "hm", "hng"}) {
        if (s == QLatin1String(nasal))
            return PinyinParts {QString(), s, false};
    }
    bool erhua = false;
    if (s.size() > 2 && s.endsWith(QLatin1Char('r'))) {
        s.chop(1);
        erhua = true;
    }
    QString initial;
    for (const char *two : {"zh", "ch", "sh"}) {
        if (s.startsWith(QLatin1String(two)))
            initial = QString::fromLatin1(two);
    }
    if (initial.isEmpty() && !s.isEmpty() && QStringLiteral("bpmfdtnlgkhjqxrzcsyw").contains(s.at(0)))
        initial = s.left(1);
    QString rest = s.mid(initial.size());
    if (rest.isEmpty())
        return std::nullopt;

    if (initial == QLatin1String("y")) {
        if (rest.startsWith(QLatin1Char('u')) || rest.startsWith(kUmlautU))
            rest = QString(kUmlautU) + rest.mid(1);
        else if (!rest.startsWith(QLatin1Char('i')))
            rest.prepend(QLatin1Char('i'));
        initial.clear();
    } else if (initial == QLatin1String("w")) {
        if (!rest.startsWith(QLatin1Char('u')))
            rest.prepend(QLatin1Char('u'));
        initial.clear();
    } else if (initial == QLatin1String("j") || initial == QLatin1String("q") || initial == QLatin1String("x")) {
        if (rest.startsWith(QLatin1Char('u')))
            rest = QString(kUmlautU) + rest.mid(1);
    }
    if (rest == QLatin1String("iu"))
        rest = QStringLiteral("iou");
    else if (rest == QLatin1String("ui"))
        rest = QStringLiteral("uei");
    else if (rest == QLatin1String("un"))
        rest = QStringLiteral("uen");
    else if (rest == QString(kUmlautU) + QLatin1Char('n'))
        rest = QString(kUmlautU) + QLatin1String("en");

    if (!validFinals().contains(rest) || !phonotacticallyValid(initial, rest))
        return std::nullopt;
    if (erhua && rest == QLatin1String("er"))
        return std::nullopt;
    return PinyinParts {initial, rest, erhua};
}

std::optional<PinyinSyllable> parsePinyinSyllable(const QString &text)
{
    QString s = text.trimmed().toLower();
    if (s.isEmpty())
        return std::nullopt;
    int tone = 0;
    const QChar last = s.back();
    if (last >= QLatin1Char('0') && last <= QLatin1Char('5')) {
        tone = last == QLatin1Char('0') ? 5 : last.digitValue();
        s.chop(1);
    }
    s.replace(QLatin1String("u:"), QString(kUmlautU));
    s.replace(QLatin1Char('v'), kUmlautU);
    const QString d = s.normalized(QString::NormalizationForm_D);
    QString out;
    int markTone = 0;
    for (const QChar c : d) {
        switch (c.unicode()) {
        case 0x0304: markTone = 1; continue;
        case 0x0301: markTone = 2; continue;
        case 0x030C: markTone = 3; continue;
        case 0x0300: markTone = 4; continue;
        case 0x0308:
        case 0x0302: out.append(c); continue;
        default: break;
        }
        if (c < QLatin1Char('a') || c > QLatin1Char('z'))
            return std::nullopt;
        out.append(c);
    }
    out = out.normalized(QString::NormalizationForm_C);
    if (tone == 0)
        tone = markTone ? markTone : 5;
    // ü after j q x y is written u.
    if (out.size() > 1 && QStringLiteral("jqxy").contains(out.at(0)) && out.at(1) == kUmlautU)
        out[1] = QLatin1Char('u');
    if (!isMandarinSyllable(out))
        return std::nullopt;
    return PinyinSyllable {out, tone};
}

std::optional<QVector<PinyinSyllable>> splitPinyinWord(const QString &word, QVector<QPair<int, int>> *spans)
{
    QVector<PinyinSyllable> result;
    QVector<QPair<int, int>> where;
    // Pieces between separators (' ’ -) and after tone digits, each with its offset.
    QVector<QPair<int, QString>> pieces;
    QString cur;
    int curStart = 0;
    auto flush = [&](int next) {
        if (!cur.isEmpty())
            pieces.append({curStart, cur});
        cur.clear();
        curStart = next;
    };
    for (int i = 0; i < word.size(); ++i) {
        const QChar c = word.at(i);
        if (c == QLatin1Char('\'') || c == QChar(0x2019) || c == QLatin1Char('-')) {
            flush(i + 1);
            continue;
        }
        cur.append(c);
        if (c.isDigit())
            flush(i + 1);
    }
    flush(int(word.size()));

    for (const auto &entry : pieces) {
        // Named, not bound: clang before 16 cannot capture structured bindings in a lambda.
        const int offset = entry.first;
        const QString &piece = entry.second;
        // Longest valid first syllable whose rest also splits (depth-first).
        std::function<bool(int)> split = [&](int from) {
            if (from == piece.size())
                return true;
            for (int len = std::min<int>(int(piece.size()) - from, 8); len >= 1; --len) {
                int end = from + len;
                // A tone digit belongs to the syllable before it.
                if (end < piece.size() && piece.at(end).isDigit())
                    ++end;
                const auto syl = parsePinyinSyllable(piece.mid(from, end - from));
                if (!syl)
                    continue;
                result.append(*syl);
                where.append({offset + from, end - from});
                if (split(end))
                    return true;
                result.removeLast();
                where.removeLast();
            }
            return false;
        };
        if (!split(0))
            return std::nullopt;
    }
    if (result.isEmpty())
        return std::nullopt;
    if (spans)
        *spans = where;
    return result;
}

QString toneNumberSpelling(const PinyinSyllable &syllable)
{
    QString s = syllable.pinyin;
    s.replace(kUmlautU, QLatin1Char('v'));
    return s + QString::number(syllable.tone);
}

QString toneMarkSpelling(const PinyinSyllable &syllable)
{
    if (syllable.tone < 1 || syllable.tone > 4)
        return syllable.pinyin;
    int i = -1;
    toneVowel(syllable.pinyin, &i);
    if (i < 0)
        return syllable.pinyin;
    static const char16_t marks[] = {0x0304, 0x0301, 0x030C, 0x0300};
    QString d = syllable.pinyin.normalized(QString::NormalizationForm_D);
    // Positions shift by one after ü/ê decomposition; find the vowel again in the D form.
    int di = 0;
    for (int k = 0, seen = 0; k < d.size(); ++k) {
        if (d.at(k).category() == QChar::Mark_NonSpacing)
            continue;
        if (seen == i) {
            di = k;
            break;
        }
        ++seen;
    }
    int insertAt = di + 1;
    while (insertAt < d.size() && d.at(insertAt).category() == QChar::Mark_NonSpacing)
        ++insertAt;
    d.insert(insertAt, QChar(marks[syllable.tone - 1]));
    return d.normalized(QString::NormalizationForm_C);
}

} // namespace toonface
