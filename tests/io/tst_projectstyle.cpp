#include "face/averageface.h"
#include "io/project.h"
#include "render/svglayer.h"
#include "testmain.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QTest>

using namespace toonface;

namespace {

const QString kData = QStringLiteral(TOONFACE_TEST_DATA "/io");

Project projectWith(const Style &style)
{
    Project p;
    p.face = averageFace(QRectF(100, 120, 200, 240), QSize(400, 500));
    p.style = style;
    return p;
}

} // namespace

// The style's caricature factor and appearance in the project file (the rest of the format is
// tst_project's).
class TestProjectStyle : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void roundTrips_data()
    {
        QTest::addColumn<double>("caricature");
        QTest::addColumn<int>("glasses");
        QTest::addColumn<bool>("flags");
        QTest::newRow("default") << kDefaultCaricature << int(GlassesShape::None) << false;
        QTest::newRow("exact, round glasses, all worn") << 0.0 << int(GlassesShape::Round) << true;
        QTest::newRow("strong, rimless") << 0.9 << int(GlassesShape::Rimless) << false;
        QTest::newRow("rectangular, bald") << 0.5 << int(GlassesShape::Rectangular) << true;
    }

    void roundTrips()
    {
        QFETCH(double, caricature);
        QFETCH(int, glasses);
        QFETCH(bool, flags);
        Style style = Style::preset(QStringLiteral("bold"));
        style.caricature = caricature;
        style.appearance = {GlassesShape(glasses), flags, flags, flags, flags, flags, {}};
        if (flags)
            style.appearance.lens = {0.46, 0.31, 0.04, 0.12};
        // The age group the user chose (or the photo's) is kept.
        style.appearance.age = flags ? AgeGroup::Child : caricature > 0.8 ? AgeGroup::Elderly : AgeGroup::Adult;
        // A layer that follows the head (or not) keeps doing so.
        StyleLayer layer;
        layer.name = QStringLiteral("hat.svg");
        layer.svg
            = "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 10 10\"><rect width=\"10\" height=\"4\"/></svg>";
        // The project holds a layer's cleaned copy (issue 24): one already clean round-trips.
        QString cleaning;
        QVERIFY2(cleanLayerSvg(QByteArray(layer.svg), &layer.svg, &cleaning), qPrintable(cleaning));
        layer.followsHead = flags;
        style.layers = {layer};
        style.components[QStringLiteral("glasses")].stroke = QColor(0x80, 0x20, 0x20);
        style.components[QStringLiteral("hat")].visible = false;
        QTemporaryDir tmp;
        const QString file = tmp.filePath(QStringLiteral("p.toonface"));
        QString error;
        QVERIFY2(saveProject(projectWith(style), file, &error), qPrintable(error));
        const auto loaded = loadProject(file, &error);
        QVERIFY2(loaded, qPrintable(error));
        QCOMPARE(loaded->style.caricature, caricature);
        QCOMPARE(loaded->style.appearance, style.appearance);
        QVERIFY(loaded->style == style);
    }

    // Files from before keep their drawing: no exaggeration, nothing worn.
    void oldFilesLoadUnchanged()
    {
        QString error;
        const auto p = loadProject(kData + QStringLiteral("/v1/project.toonface"), &error);
        QVERIFY2(p, qPrintable(error));
        QCOMPARE(p->style.caricature, 0.0);
        QCOMPARE(p->style.appearance, Appearance());
    }

    void badValuesNameTheField_data()
    {
        QTest::addColumn<QString>("key");
        QTest::addColumn<QByteArray>("value");
        QTest::addColumn<QString>("expected");
        QTest::newRow("caricature too big") << QStringLiteral("caricature") << QByteArray("5")
                                            << QStringLiteral("style.caricature: expected a number from 0 to 1");
        QTest::newRow("caricature negative") << QStringLiteral("caricature") << QByteArray("-0.1")
                                             << QStringLiteral("style.caricature: expected a number from 0 to 1");
        QTest::newRow("caricature string") << QStringLiteral("caricature") << QByteArray("\"mild\"")
                                           << QStringLiteral("style.caricature: expected a number");
        QTest::newRow("glasses shape")
            << QStringLiteral("appearance")
            << QByteArray(R"({"glasses":"square","moustache":false,"beard":false,"hat":false,"bald":false})")
            << QStringLiteral("style.appearance.glasses: expected one of \"none\"");
        QTest::newRow("beard number") << QStringLiteral(
            "appearance") << QByteArray(R"({"glasses":"none","moustache":false,"beard":1,"hat":false,"bald":false})")
                                      << QStringLiteral("style.appearance.beard: expected true or false");
        QTest::newRow("lens too big")
            << QStringLiteral("appearance")
            << QByteArray(R"({"glasses":"round","moustache":false,"beard":false,"hat":false,"bald":false,)"
                          R"("lens":{"halfWidth":9,"halfHeight":0.3,"outward":0,"down":0}})")
            << QStringLiteral("style.appearance.lens: expected lens half sizes above 0 and at most 2");
        QTest::newRow("lens without its height")
            << QStringLiteral("appearance")
            << QByteArray(R"({"glasses":"round","moustache":false,"beard":false,"hat":false,"bald":false,)"
                          R"("lens":{"halfWidth":0.4,"outward":0,"down":0}})")
            << QStringLiteral("style.appearance.lens.halfHeight: ");
        QTest::newRow("age group")
            << QStringLiteral("appearance")
            << QByteArray(R"({"glasses":"none","moustache":false,"beard":false,"hat":false,"bald":false,"age":"teen"})")
            << QStringLiteral("style.appearance.age: expected one of \"adult\"");
        QTest::newRow("appearance array") << QStringLiteral("appearance") << QByteArray("[]")
                                          << QStringLiteral("style.appearance: expected an object");
    }

    void badValuesNameTheField()
    {
        QFETCH(QString, key);
        QFETCH(QByteArray, value);
        QFETCH(QString, expected);
        QTemporaryDir tmp;
        QJsonObject json = projectToJson(projectWith(Style()), tmp.path());
        QJsonObject style = json.value(QStringLiteral("style")).toObject();
        style.insert(key, QJsonDocument::fromJson("[" + value + "]").array().at(0));
        json.insert(QStringLiteral("style"), style);
        QString error;
        QVERIFY(!projectFromJson(json, tmp.path(), &error));
        QVERIFY2(error.contains(expected), qPrintable(error));
    }
};

TOONFACE_TEST_APPLESS_MAIN(TestProjectStyle)
#include "tst_projectstyle.moc"
