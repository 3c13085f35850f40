#include "speech/syllableshapes.h"

#include "speech/pinyin.h"

#include <QStringList>

namespace toonface {

namespace {

// A shape while a syllable is being read: the nine shapes, plus h' (an initial's open mouth).
struct Token
{
    MouthShape shape;
    bool hPrime = false;
};

bool isVowel(MouthShape s)
{
    return s == MouthShape::A || s == MouthShape::E || s == MouthShape::I || s == MouthShape::O || s == MouthShape::U;
}

} // namespace

QVector<MouthShape> syllableShapes(const QString &pinyin)
{
    const auto parsed = parsePinyinSyllable(pinyin);
    if (!parsed)
        return {};
    const auto parts = splitPinyinSyllable(parsed->pinyin);
    if (!parts)
        return {};

    QVector<Token> tokens;
    const QString &ini = parts->initial;
    if (ini == QLatin1String("b") || ini == QLatin1String("p") || ini == QLatin1String("m"))
        tokens.append({MouthShape::M});
    else if (ini == QLatin1String("f"))
        tokens.append({MouthShape::F});
    else if (!ini.isEmpty())
        tokens.append({MouthShape::H, true});

    QString final = parts->final;
    // The empty rime of zhi chi shi ri zi ci si is spelled ih.
    static const QStringList emptyRime = {QStringLiteral("zh"), QStringLiteral("ch"), QStringLiteral("sh"),
        QStringLiteral("r"), QStringLiteral("z"), QStringLiteral("c"), QStringLiteral("s")};
    if (final == QLatin1String("i") && emptyRime.contains(ini))
        final = QStringLiteral("ih");
    // ao is pronounced toward u (also in iao).
    final.replace(QLatin1String("ao"), QLatin1String("au"));
    if (parts->erhua)
        final += QLatin1Char('r');

    for (int k = 0; k < final.size(); ++k) {
        switch (final.at(k).unicode()) {
        case 'a': tokens.append({MouthShape::A}); break;
        case 'e':
        case 0x00EA: tokens.append({MouthShape::E}); break; // ê
        case 'i': tokens.append({MouthShape::I}); break;
        case 'o': tokens.append({MouthShape::O}); break;
        case 'u':
        case 0x00FC: tokens.append({MouthShape::U}); break; // ü
        case 'n': tokens.append({MouthShape::N}); break;
        case 'm': tokens.append({MouthShape::M}); break; // syllabic m, hm
        case 'g': // the g of ng
        case 'r': // the r of er (and of erhua)
        case 'h': // the h of the empty rime ih, and of hm/hng
            tokens.append({MouthShape::H});
            break;
        default: return {};
        }
    }

    QVector<MouthShape> shapes;
    for (int k = 0; k < tokens.size(); ++k) {
        const Token &t = tokens.at(k);
        if (t.hPrime && k + 1 < tokens.size() && isVowel(tokens.at(k + 1).shape))
            continue;
        if (shapes.isEmpty() || shapes.back() != t.shape)
            shapes.append(t.shape);
    }
    return shapes;
}

QString shapeSpelling(const QVector<MouthShape> &shapes)
{
    QStringList names;
    for (MouthShape s : shapes)
        names.append(mouthShapeName(s));
    return names.join(QLatin1Char(' '));
}

double shapeStartFraction(int count, int k)
{
    static const double table[4][4] = {{0, 0, 0, 0}, {0, 0.8095, 0, 0}, {0, 0.4337, 0.4337 + 0.3975, 0},
        {0, 0.245, 0.245 + 0.2115, 0.245 + 0.2115 + 0.2588}};
    if (count <= 0 || k <= 0)
        return 0;
    if (count <= 4)
        return table[count - 1][std::min(k, count - 1)];
    // Beyond the table: the first four as for four shapes, the rest evenly in what remains.
    if (k < 4)
        return table[3][k];
    const double last = table[3][3];
    return last + (1.0 - last) * double(k - 3) / double(count - 3);
}

QVector<ShapeKey> syllableShapeKeys(const QVector<MouthShape> &shapes, double start, double duration)
{
    QVector<ShapeKey> keys;
    keys.reserve(shapes.size());
    for (int k = 0; k < shapes.size(); ++k)
        keys.append({shapes.at(k), start + shapeStartFraction(int(shapes.size()), k) * duration});
    return keys;
}

} // namespace toonface
