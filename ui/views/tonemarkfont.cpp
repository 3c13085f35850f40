#include "views/tonemarkfont.h"

#include <QApplication>
#include <QFontDatabase>
#include <QFontInfo>
#include <QPainterPath>
#include <QRawFont>

namespace toonface {

namespace {

// Every vowel pinyin marks, with all four tones.
const QString &toneVowels()
{
    static const QString vowels = QStringLiteral("āáǎàēéěèīíǐìōóǒòūúǔùǖǘǚǜ");
    return vowels;
}

// 1 when the family draws every vowel, 0 when it lacks some, -1 when it claims one and draws
// nothing.
int coverage(const QFont &font)
{
    const QRawFont raw = QRawFont::fromFont(font, QFontDatabase::Latin);
    if (!raw.isValid())
        return 0;
    const QList<quint32> glyphs = raw.glyphIndexesForString(toneVowels());
    int result = 1;
    for (quint32 glyph : glyphs) {
        if (glyph == 0)
            result = 0;
        else if (raw.pathForGlyph(glyph).isEmpty())
            return -1;
    }
    return result;
}

// A family that draws every vowel, preferring one of the same kind (sans serif or not,
// proportional or not) as `font`; empty when none is installed.
QString toneMarkFamily(const QFont &font)
{
    const bool fixed = QFontInfo(font).fixedPitch();
    const bool serif = font.styleHint() == QFont::Serif;
    QString best;
    int bestScore = -1;
    for (const QString &family : QFontDatabase::families(QFontDatabase::Latin)) {
        if (QFontDatabase::isPrivateFamily(family) || !QFontDatabase::isSmoothlyScalable(family))
            continue;
        QFont candidate(family);
        candidate.setPointSizeF(font.pointSizeF() > 0 ? font.pointSizeF() : 10);
        if (coverage(candidate) != 1)
            continue;
        const bool sans = family.contains(QLatin1StringView("Sans"), Qt::CaseInsensitive);
        const int score = (QFontDatabase::isFixedPitch(family) == fixed ? 2 : 0) + (sans != serif ? 1 : 0);
        if (score > bestScore) {
            best = family;
            bestScore = score;
        }
    }
    return best;
}

} // namespace

bool drawsToneMarks(const QFont &font)
{
    return coverage(font) >= 0;
}

QFont withToneMarks(const QFont &font)
{
    if (drawsToneMarks(font))
        return font;
    const QString family = toneMarkFamily(font);
    if (family.isEmpty())
        return font;
    QFont fixed = font;
    QStringList families = font.families();
    if (families.isEmpty())
        families.append(font.family());
    families.prepend(family);
    fixed.setFamilies(families);
    return fixed;
}

void ensureToneMarks()
{
    QApplication::setFont(withToneMarks(QApplication::font()));
}

} // namespace toonface
