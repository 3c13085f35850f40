#include "render/agestyle.h"
#include "render/style.h"
#include "render/svgface.h"
#include "svgfacefixture.h"
#include "testmain.h"

#include <QTest>

using namespace toonface;
using namespace toonface::svgfacetest;

namespace {

// A style as a photo of an adult woman might leave it: painted lips, thick dark brows.
Style madeUp(AgeGroup age)
{
    Style s = preset("normal");
    s.components[QStringLiteral("lips")].fill = QColor(0xc8, 0x1e, 0x46);
    s.components[QStringLiteral("eyebrows")].stroke = QColor(0x20, 0x16, 0x10);
    s.components[QStringLiteral("eyebrows")].strokeWidth = 6.0;
    s.appearance.age = age;
    return s;
}

QColor paint(const QVector<FacePart> &parts, const char *id, const char *attribute)
{
    const FacePart *p = partById(parts, QLatin1StringView(id));
    return p ? QColor(p->paint.value(QLatin1StringView(attribute))) : QColor();
}

double strokeWidth(const QVector<FacePart> &parts, const char *id)
{
    const FacePart *p = partById(parts, QLatin1StringView(id));
    return p ? p->paint.value(QStringLiteral("stroke-width")).toDouble() : 0.0;
}

double hueDistance(const QColor &a, const QColor &b)
{
    const double d = std::abs(a.hsvHueF() - b.hsvHueF()) * 360.0;
    return std::min(d, 360.0 - d);
}

QStringList ageLineIds(const QVector<FacePart> &parts)
{
    QStringList ids;
    for (const FacePart &p : parts)
        if (p.id.startsWith(QLatin1StringView("age-")))
            ids << p.id;
    return ids;
}

} // namespace

// How a face's age group changes its drawing (render/agestyle.h).
class TestAgeStyle : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void skins_data()
    {
        QTest::addColumn<QColor>("skin");
        QTest::newRow("pale") << QColor(0xf3, 0xd6, 0xc2);
        QTest::newRow("medium") << QColor(0xc6, 0x8c, 0x69);
        QTest::newRow("dark") << QColor(0x69, 0x46, 0x32);
    }

    // A child's lips are of the skin's own colour (no lipstick) and its brows thin and light.
    void skins()
    {
        QFETCH(QColor, skin);
        const FaceModel face = testFace();
        Style adult = madeUp(AgeGroup::Adult), child = madeUp(AgeGroup::Child);
        for (Style *s : {&adult, &child})
            for (const char *key : {"face", "jaw"})
                s->components[QLatin1StringView(key)].fill = skin;
        const QVector<FacePart> a = SvgFace(face, adult).parts(), c = SvgFace(face, child).parts();
        const QColor lips = paint(c, "mouth-upper-lip", "fill");
        QVERIFY(lips.isValid());
        QCOMPARE(paint(a, "mouth-upper-lip", "fill"), QColor(0xc8, 0x1e, 0x46));
        QVERIFY2(hueDistance(lips, skin) < 12.0, qPrintable(lips.name() + QLatin1Char(' ') + skin.name()));
        QVERIFY(lips.valueF() < skin.valueF()); // still reads as lips: a little deeper than the skin
        QVERIFY(colourDistance(lips, skin) < 60);
        QCOMPARE(paint(c, "mouth-lower-lip", "fill"), lips);
        // Thin brows, between their colour and the skin's.
        QVERIFY(strokeWidth(c, "eyebrow-left") < 0.5 * strokeWidth(a, "eyebrow-left"));
        const QColor brow = paint(c, "eyebrow-left", "stroke");
        QVERIFY(colourDistance(brow, skin) < colourDistance(QColor(0x20, 0x16, 0x10), skin));
    }

    // A child's face is drawn rounder with larger eyes; less so than the cute preset.
    void childProportions()
    {
        const FaceModel face = testFace();
        const QVector<FacePart> a = SvgFace(face, madeUp(AgeGroup::Adult)).parts();
        const QVector<FacePart> c = SvgFace(face, madeUp(AgeGroup::Child)).parts();
        const QVector<FacePart> cute = SvgFace(face, preset("cute")).parts();
        auto radius = [](const QVector<FacePart> &parts) {
            return partById(parts, QStringLiteral("eyeball-left"))->geometry.value(QStringLiteral("r")).toDouble();
        };
        auto bottom = [](const QVector<FacePart> &parts) {
            return pathPoints(partById(parts, QStringLiteral("jaw"))->geometry.value(QStringLiteral("d")))
                .boundingRect()
                .bottom();
        };
        QVERIFY(radius(c) > 1.25 * radius(a)); // a third larger: a fifth larger read as middle-aged
        QVERIFY(radius(c) < radius(cute));
        QVERIFY(bottom(c) < bottom(a) - 0.05 * face.fapu().jawH);
        QVERIFY(bottom(c) > bottom(cute));
    }

    // The elderly get fine age lines in the creases' muted colour; nobody else does.
    void elderlyLines()
    {
        const FaceModel face = testFace();
        const QStringList expected {QStringLiteral("age-nasolabial-left"), QStringLiteral("age-nasolabial-right"),
            QStringLiteral("age-forehead-1"), QStringLiteral("age-forehead-2"), QStringLiteral("age-crow-left"),
            QStringLiteral("age-crow-right")};
        const QVector<FacePart> old = SvgFace(face, madeUp(AgeGroup::Elderly)).parts();
        QCOMPARE(ageLineIds(old), expected);
        for (const QString &id : expected) {
            const FacePart *p = partById(old, id);
            QCOMPARE(p->styleKey, QStringLiteral("creases"));
            // Inside the face, and fine: on average thinner than 0.02 ES0 along its length.
            const QRectF box = pathPoints(p->geometry.value(QStringLiteral("d"))).boundingRect();
            QVERIFY2(face.bounds().adjusted(-2, -2, 2, 2).contains(box), qPrintable(id));
            const double length = std::max(box.width(), box.height());
            QVERIFY2(area(painterPath(p->geometry.value(QStringLiteral("d")))) < 0.02 * face.fapu().es0 * length,
                qPrintable(id));
        }
        QVERIFY(ageLineIds(SvgFace(face, madeUp(AgeGroup::Adult)).parts()).isEmpty());
        QVERIFY(ageLineIds(SvgFace(face, madeUp(AgeGroup::Child)).parts()).isEmpty());
        // The SVG holds them under their ids.
        QVERIFY(SvgFace(face, madeUp(AgeGroup::Elderly)).svg().contains("id=\"age-forehead-1\""));
    }

    // The user's choice (the style's appearance, as the Appearance dock sets it) decides, and the
    // style given is kept as given: the age's changes are made only where the face is drawn.
    void theChoiceWins()
    {
        const FaceModel face = testFace();
        Style s = madeUp(AgeGroup::Child);
        const SvgFace child(face, s);
        QCOMPARE(child.style(), s);
        s.appearance.age = AgeGroup::Adult; // the user says: an adult
        const QVector<FacePart> adult = SvgFace(face, s).parts();
        QCOMPARE(paint(adult, "mouth-upper-lip", "fill"), QColor(0xc8, 0x1e, 0x46));
        QCOMPARE(strokeWidth(adult, "eyebrow-left"),
            strokeWidth(SvgFace(face, madeUp(AgeGroup::Adult)).parts(), "eyebrow-left"));
        QVERIFY(strokeWidth(child.parts(), "eyebrow-left") < strokeWidth(adult, "eyebrow-left"));
        // A child with thick brows chosen is drawn with a line brow.
        Style thick = madeUp(AgeGroup::Child);
        thick.eyebrows = EyebrowVariant::Thick;
        QCOMPARE(agedStyle(thick).eyebrows, EyebrowVariant::Bezier);
        QCOMPARE(agedStyle(madeUp(AgeGroup::Adult)), madeUp(AgeGroup::Adult));
    }
};

TOONFACE_TEST_MAIN(TestAgeStyle)
#include "tst_agestyle.moc"
