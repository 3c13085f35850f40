#include "speech/englishshapes.h"

#include <QHash>

namespace toonface {

namespace {

using S = MouthShape;

const QHash<QString, QVector<MouthShape>> &table()
{
    static const QHash<QString, QVector<MouthShape>> t = [] {
        QHash<QString, QVector<MouthShape>> m;
        auto put = [&](std::initializer_list<const char *> names, QVector<MouthShape> shapes) {
            for (const char *n : names)
                m.insert(QString::fromLatin1(n), shapes);
        };
        put({"p", "b", "m"}, {S::M});
        put({"f", "v"}, {S::F});
        put({"w", "r", "r-", "u:", "U", "U@", "S", "Z", "tS", "dZ"}, {S::U});
        put({"0", "O:", "O", "O@", "o@"}, {S::O});
        put({"oU", "@U", "o"}, {S::O, S::U});
        put({"OI"}, {S::O, S::I});
        put({"a", "aa", "A:", "A", "V", "A@", "a#"}, {S::A});
        put({"aI", "aI@", "aI3"}, {S::A, S::I});
        put({"aU", "aU@"}, {S::A, S::U});
        put({"E", "e@", "3:", "3", "e"}, {S::E});
        put({"eI"}, {S::E, S::I});
        put({"I", "i", "i:", "j", "I@", "i@", "i@3", "I2", "I#"}, {S::I});
        put({"n", "N", "l", "n-", "l/", "@L", "@N"}, {S::N});
        put({"@", "@2", "@5", "@r"}, {S::H});
        return m;
    }();
    return t;
}

bool isVowelShape(MouthShape s)
{
    return s == S::A || s == S::E || s == S::I || s == S::O || s == S::U;
}

} // namespace

QVector<MouthShape> englishPhonemeShapes(const QString &mnemonic, bool *hPrime)
{
    if (hPrime)
        *hPrime = false;
    if (mnemonic.isEmpty() || mnemonic.startsWith(QLatin1Char('_')))
        return {};
    QString key = mnemonic;
    key.remove(QLatin1Char('\'')).remove(QLatin1Char(','));
    const auto it = table().constFind(key);
    if (it != table().cend())
        return *it;
    // Other vowels by their first letter; other consonants open the mouth as h'.
    const QChar c = key.isEmpty() ? QChar() : key.at(0);
    if (QStringLiteral("aAV").contains(c))
        return {S::A};
    if (QStringLiteral("eE3").contains(c))
        return {S::E};
    if (QStringLiteral("iI").contains(c))
        return {S::I};
    if (QStringLiteral("oO0").contains(c))
        return {S::O};
    if (QStringLiteral("uU").contains(c))
        return {S::U};
    if (c == QLatin1Char('@'))
        return {S::H};
    if (hPrime)
        *hPrime = true;
    return {S::H};
}

QVector<ShapeKey> englishWordKeys(const QVector<TtsPhoneme> &phonemes, double start, double end)
{
    struct Key
    {
        MouthShape shape;
        double start;
        bool hPrime;
    };
    QVector<Key> keys;
    for (int p = 0; p < phonemes.size(); ++p) {
        bool hPrime = false;
        const QVector<MouthShape> shapes = englishPhonemeShapes(phonemes[p].name, &hPrime);
        if (shapes.isEmpty())
            continue;
        const double t0 = std::clamp(phonemes[p].start, start, end);
        const double t1 = p + 1 < phonemes.size() ? std::clamp(phonemes[p + 1].start, t0, end) : end;
        for (int k = 0; k < shapes.size(); ++k)
            keys.append({shapes[k], t0 + (t1 - t0) * 0.5 * k, hPrime});
    }
    QVector<ShapeKey> out;
    for (int k = 0; k < keys.size(); ++k) {
        if (keys[k].hPrime && k + 1 < keys.size() && isVowelShape(keys[k + 1].shape))
            continue;
        if (!out.isEmpty() && out.back().shape == keys[k].shape)
            continue;
        out.append({keys[k].shape, keys[k].start});
    }
    if (out.isEmpty())
        out.append({S::H, start});
    out.first().start = start; // the word's mouth starts with the word
    return out;
}

} // namespace toonface
