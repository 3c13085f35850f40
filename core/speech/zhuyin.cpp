#include "speech/zhuyin.h"

#include <QHash>

namespace toonface {

namespace {

const QHash<char16_t, const char *> &initials()
{
    static const QHash<char16_t, const char *> m
        = {{u'ㄅ', "b"}, {u'ㄆ', "p"}, {u'ㄇ', "m"}, {u'ㄈ', "f"}, {u'ㄉ', "d"}, {u'ㄊ', "t"}, {u'ㄋ', "n"},
            {u'ㄌ', "l"}, {u'ㄍ', "g"}, {u'ㄎ', "k"}, {u'ㄏ', "h"}, {u'ㄐ', "j"}, {u'ㄑ', "q"}, {u'ㄒ', "x"},
            {u'ㄓ', "zh"}, {u'ㄔ', "ch"}, {u'ㄕ', "sh"}, {u'ㄖ', "r"}, {u'ㄗ', "z"}, {u'ㄘ', "c"}, {u'ㄙ', "s"}};
    return m;
}

const QHash<char16_t, const char *> &medials()
{
    static const QHash<char16_t, const char *> m = {{u'ㄧ', "i"}, {u'ㄨ', "u"}, {u'ㄩ', "v"}};
    return m;
}

const QHash<char16_t, const char *> &rimes()
{
    static const QHash<char16_t, const char *> m
        = {{u'ㄚ', "a"}, {u'ㄛ', "o"}, {u'ㄜ', "e"}, {u'ㄝ', "ê"}, {u'ㄞ', "ai"}, {u'ㄟ', "ei"}, {u'ㄠ', "ao"},
            {u'ㄡ', "ou"}, {u'ㄢ', "an"}, {u'ㄣ', "en"}, {u'ㄤ', "ang"}, {u'ㄥ', "eng"}, {u'ㄦ', "er"}};
    return m;
}

int toneOf(QChar c)
{
    switch (c.unicode()) {
    case 0x02C9: return 1; // ˉ
    case 0x02CA: return 2; // ˊ
    case 0x02C7: return 3; // ˇ
    case 0x02CB: return 4; // ˋ
    case 0x02D9: return 5; // ˙
    default: return 0;
    }
}

// Initial + medial + rime (any may be empty) → written pinyin, by pinyin's spelling rules.
QString spell(const QString &ini, const QString &med, QString rime)
{
    if (med.isEmpty()) {
        if (rime.isEmpty())
            return ini + QStringLiteral("i"); // zhi chi shi ri zi ci si
        return ini + rime;
    }
    if (med == QLatin1String("i")) {
        static const QHash<QString, QString> f = {{QString(), QStringLiteral("i")},
            {QStringLiteral("ê"), QStringLiteral("ie")}, {QStringLiteral("ou"), QStringLiteral("iu")},
            {QStringLiteral("en"), QStringLiteral("in")}, {QStringLiteral("eng"), QStringLiteral("ing")}};
        QString fin = f.value(rime, QStringLiteral("i") + rime);
        if (!ini.isEmpty())
            return ini + fin;
        if (fin == QLatin1String("i") || fin == QLatin1String("in") || fin == QLatin1String("ing"))
            return QStringLiteral("y") + fin;
        if (fin == QLatin1String("iu"))
            return QStringLiteral("you");
        return QStringLiteral("y") + fin.mid(1);
    }
    if (med == QLatin1String("u")) {
        static const QHash<QString, QString> f
            = {{QString(), QStringLiteral("u")}, {QStringLiteral("ei"), QStringLiteral("ui")},
                {QStringLiteral("en"), QStringLiteral("un")}, {QStringLiteral("eng"), QStringLiteral("ong")}};
        const QString fin = f.value(rime, QStringLiteral("u") + rime);
        if (!ini.isEmpty())
            return ini + fin;
        if (fin == QLatin1String("u"))
            return QStringLiteral("wu");
        if (rime == QLatin1String("eng"))
            return QStringLiteral("weng");
        if (rime == QLatin1String("ei"))
            return QStringLiteral("wei");
        if (rime == QLatin1String("en"))
            return QStringLiteral("wen");
        return QStringLiteral("w") + fin.mid(1);
    }
    // ü
    if (rime == QLatin1String("eng"))
        return ini.isEmpty() ? QStringLiteral("yong") : ini + QStringLiteral("iong");
    static const QHash<QString, QString> f
        = {{QString(), QStringLiteral("v")}, {QStringLiteral("ê"), QStringLiteral("ve")},
            {QStringLiteral("an"), QStringLiteral("van")}, {QStringLiteral("en"), QStringLiteral("vn")}};
    const QString fin = f.value(rime);
    if (fin.isEmpty())
        return QString();
    return (ini.isEmpty() ? QStringLiteral("y") : ini) + fin;
}

} // namespace

bool isZhuyinChar(char32_t c)
{
    return (c >= 0x3105 && c <= 0x312F) || (c >= 0x31A0 && c <= 0x31BF) || c == 0x02C9 || c == 0x02CA || c == 0x02C7
        || c == 0x02CB || c == 0x02D9;
}

std::optional<QVector<PinyinSyllable>> zhuyinToPinyin(const QString &run, QVector<int> *lengths)
{
    QVector<PinyinSyllable> out;
    if (lengths)
        lengths->clear();
    qsizetype i = 0;
    const qsizetype n = run.size();
    while (i < n) {
        const qsizetype start = i;
        int tone = 0;
        if (toneOf(run.at(i)) == 5) { // a leading ˙ marks the neutral tone
            tone = 5;
            ++i;
        }
        QString ini, med, rime;
        if (i < n && initials().contains(run.at(i).unicode()))
            ini = QString::fromUtf8(initials().value(run.at(i++).unicode()));
        if (i < n && medials().contains(run.at(i).unicode()))
            med = QString::fromUtf8(medials().value(run.at(i++).unicode()));
        if (i < n && rimes().contains(run.at(i).unicode()))
            rime = QString::fromUtf8(rimes().value(run.at(i++).unicode()));
        if (i < n && toneOf(run.at(i)) != 0) {
            tone = toneOf(run.at(i));
            ++i;
        }
        if (ini.isEmpty() && med.isEmpty() && rime.isEmpty())
            return std::nullopt;
        const QString written = spell(ini, med, rime);
        auto syl = parsePinyinSyllable(written);
        if (written.isEmpty() || !syl)
            return std::nullopt;
        syl->tone = tone ? tone : 1;
        out.append(*syl);
        if (lengths)
            lengths->append(int(i - start));
    }
    if (out.isEmpty())
        return std::nullopt;
    return out;
}

} // namespace toonface
