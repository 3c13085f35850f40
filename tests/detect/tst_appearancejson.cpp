#include "detect/appearance.h"
#include "detect/photocolours.h"
#include "drawnface.h"
#include "io/appearancejson.h"
#include "render/style.h"
#include "testmain.h"

#include <QJsonArray>
#include <QRegularExpression>
#include <QTest>

using namespace toonface;
using testing::DrawnFaceOptions;

Q_DECLARE_METATYPE(toonface::testing::DrawnFaceOptions)

namespace {

// The "appearance" object's schema: every key, of its type, in its range.
QString schemaProblem(const QJsonObject &a)
{
    const QRegularExpression colour(QStringLiteral("^#[0-9a-f]{6}$"));
    if (!colour.match(a.value(QLatin1StringView("skin")).toString()).hasMatch())
        return QStringLiteral("skin: expected #rrggbb");
    const QJsonValue hair = a.value(QLatin1StringView("hair"));
    if (!hair.isNull() && !colour.match(hair.toString()).hasMatch())
        return QStringLiteral("hair: expected #rrggbb or null");
    const QStringList lengths {
        QStringLiteral("none"), QStringLiteral("short"), QStringLiteral("medium"), QStringLiteral("long")};
    if (!lengths.contains(a.value(QLatin1StringView("hairLength")).toString()))
        return QStringLiteral("hairLength: expected none, short, medium or long");
    for (const char *key : {"bald", "headwear", "moustache", "beard", "goatee"})
        if (!a.value(QLatin1StringView(key)).isBool())
            return QStringLiteral("%1: expected a boolean").arg(QLatin1StringView(key));
    const QStringList glasses {
        QStringLiteral("none"), QStringLiteral("round"), QStringLiteral("rectangular"), QStringLiteral("rimless")};
    if (!glasses.contains(a.value(QLatin1StringView("glasses")).toString()))
        return QStringLiteral("glasses: expected none or its kind");
    const QStringList ages {QStringLiteral("adult"), QStringLiteral("child"), QStringLiteral("elderly")};
    if (!ages.contains(a.value(QLatin1StringView("ageGroup")).toString()))
        return QStringLiteral("ageGroup: expected adult, child or elderly");
    const QJsonObject confidence = a.value(QLatin1StringView("confidence")).toObject();
    for (const char *key : {"hairLength", "bald", "headwear", "moustache", "beard", "goatee", "glasses", "ageGroup"}) {
        const QJsonValue c = confidence.value(QLatin1StringView(key));
        if (!c.isDouble() || c.toDouble() < 0 || c.toDouble() > 1)
            return QStringLiteral("confidence.%1: expected a number in 0..1").arg(QLatin1StringView(key));
    }
    const QJsonValue kind = a.value(QLatin1StringView("headwearKind"));
    if (a.value(QLatin1StringView("headwear")).toBool()
            ? kind.toString() != QLatin1StringView("hat") && kind.toString() != QLatin1StringView("wrap")
            : !kind.isNull())
        return QStringLiteral("headwearKind: expected hat or wrap with headwear, null without");
    if (a.size() != 12 || confidence.size() != 8)
        return QStringLiteral("unexpected keys");
    return {};
}

} // namespace

class TestAppearanceJson : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void schema_data()
    {
        QTest::addColumn<DrawnFaceOptions>("options");
        DrawnFaceOptions o;
        QTest::newRow("plain") << o;
        o.glasses = o.moustache = o.beard = true;
        QTest::newRow("glasses, moustache, beard") << o;
        o = DrawnFaceOptions();
        o.bald = true;
        QTest::newRow("bald") << o;
        o = DrawnFaceOptions();
        o.hat = true;
        QTest::newRow("hat") << o;
    }

    // The object follows its schema and says what the drawing draws.
    void schema()
    {
        QFETCH(DrawnFaceOptions, options);
        Style style = Style::preset(QStringLiteral("normal"));
        AppearanceFindings findings;
        sampleColours(testing::drawnFace(options), testing::drawnFaceModel(), &style, &findings);
        const QJsonObject a = appearanceToJson(style, findings);
        const QString problem = schemaProblem(a);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        QCOMPARE(a.value(QLatin1StringView("bald")).toBool(), style.appearance.bald);
        QCOMPARE(a.value(QLatin1StringView("headwear")).toBool(), style.appearance.hat);
        QCOMPARE(a.value(QLatin1StringView("moustache")).toBool(), style.appearance.moustache);
        QCOMPARE(a.value(QLatin1StringView("beard")).toBool(), style.appearance.beard);
        QCOMPARE(a.value(QLatin1StringView("goatee")).toBool(), style.appearance.goatee);
        QCOMPARE(a.value(QLatin1StringView("glasses")).toString(), glassesShapeName(style.appearance.glasses));
        QCOMPARE(
            a.value(QLatin1StringView("skin")).toString(), style.components.value(QStringLiteral("face")).fill.name());
        // What was drawn is what was there.
        QCOMPARE(a.value(QLatin1StringView("glasses")).toString() != QLatin1StringView("none"), options.glasses);
        QCOMPARE(a.value(QLatin1StringView("moustache")).toBool(), options.moustache);
        QCOMPARE(a.value(QLatin1StringView("bald")).toBool(), options.bald);
        QCOMPARE(a.value(QLatin1StringView("headwear")).toBool(), options.hat);
        // A bald head has no hair colour and no length.
        if (options.bald) {
            QVERIFY(a.value(QLatin1StringView("hair")).isNull());
            QCOMPARE(a.value(QLatin1StringView("hairLength")).toString(), QStringLiteral("none"));
        } else {
            QVERIFY(a.value(QLatin1StringView("hair")).isString());
        }
    }

    // A decision far past its threshold is surer than one near it.
    void confidenceGrowsWithTheEvidence()
    {
        AppearanceFindings near, far;
        near.evidence.lipDL = -AppearanceFindings::kLipDarker - 1;
        far.evidence.lipDL = -AppearanceFindings::kLipDarker - 20;
        const FaceModel face = testing::drawnFaceModel();
        rateAppearance(face, &near);
        rateAppearance(face, &far);
        QVERIFY(near.confidence.moustache > 0.5);
        QVERIFY(far.confidence.moustache > near.confidence.moustache);
        QVERIFY(far.confidence.moustache <= 1.0);
    }
};

TOONFACE_TEST_MAIN(TestAppearanceJson)
#include "tst_appearancejson.moc"
