// The user's SVG layers in the project file (Style::layers, io/layersjson.h): held inline, so a
// project opens with the layer files gone; bad layers are refused by their field.

#include "face/averageface.h"
#include "io/project.h"
#include "render/svglayer.h"
#include "testmain.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace toonface;

namespace {

const QByteArray kTie = "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 40 120\">"
                        "<path id=\"tie\" d=\"M20,0 L35,100 L20,120 L5,100 Z\" fill=\"#aa2233\"/></svg>";

Project projectWith(const QVector<StyleLayer> &layers)
{
    Project p;
    p.face = averageFace(QRectF(100, 120, 200, 240), QSize(400, 500));
    p.style = Style::preset(QStringLiteral("normal"));
    p.style.layers = layers;
    return p;
}

} // namespace

class TestProjectLayers : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void roundTripSelfContained()
    {
        QTemporaryDir tmp;
        const QString layerFile = tmp.filePath(QStringLiteral("tie.svg"));
        {
            QFile f(layerFile);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(kTie);
        }
        StyleLayer tie;
        QString error;
        QVERIFY2(loadLayerFile(layerFile, &tie, &error), qPrintable(error));
        QCOMPARE(tie.name, QStringLiteral("tie.svg"));
        // Held as its cleaned copy (issue 24): the same drawing, as a standalone document.
        QByteArray cleaned;
        QVERIFY2(cleanLayerSvg(kTie, &cleaned, &error), qPrintable(error));
        QCOMPARE(tie.svg, cleaned);
        QVERIFY(tie.svg.contains("<path id=\"tie\" d=\"M20,0 L35,100 L20,120 L5,100 Z\" fill=\"#aa2233\""));
        tie.offset = QPointF(0.05, 2.25);
        tie.width = 0.6;
        StyleLayer hidden = tie;
        hidden.name = QStringLiteral("behind, hidden");
        hidden.front = false;
        hidden.visible = false;
        const Project project = projectWith({tie, hidden});

        const QString file = tmp.filePath(QStringLiteral("p.toonface"));
        QVERIFY2(saveProject(project, file, &error), qPrintable(error));
        QVERIFY(QFile::remove(layerFile)); // the project holds the drawing itself
        const auto loaded = loadProject(file, &error);
        QVERIFY2(loaded, qPrintable(error));
        QCOMPARE(loaded->style.layers.size(), 2);
        QCOMPARE(loaded->style.layers[0], tie);
        QCOMPARE(loaded->style.layers[1], hidden);
        QVERIFY(loaded->style == project.style);
    }

    void noLayersNoField()
    {
        const QJsonObject json = projectToJson(projectWith({}), QDir::tempPath());
        QVERIFY(!json.value(QStringLiteral("style")).toObject().contains(QStringLiteral("layers")));
    }

    void badLayersNameTheField_data()
    {
        QTest::addColumn<QString>("key");
        QTest::addColumn<QJsonValue>("value");
        QTest::addColumn<QString>("expected");
        QTest::newRow("not svg") << QStringLiteral("svg") << QJsonValue(QStringLiteral("<html/>"))
                                 << QStringLiteral(
                                        "style.layers[0].svg: not an SVG drawing: the root element is <html>");
        QTest::newRow("not xml") << QStringLiteral("svg") << QJsonValue(QStringLiteral("<svg"))
                                 << QStringLiteral("style.layers[0].svg: not an SVG drawing: line 1");
        QTest::newRow("zero width") << QStringLiteral("width") << QJsonValue(0)
                                    << QStringLiteral("style.layers[0].width: expected a width more than 0");
        QTest::newRow("huge offset") << QStringLiteral("x") << QJsonValue(1e9) << QStringLiteral("style.layers[0].x");
        QTest::newRow("no name") << QStringLiteral("name") << QJsonValue() << QStringLiteral("style.layers[0].name");
    }

    void badLayersNameTheField()
    {
        QFETCH(QString, key);
        QFETCH(QJsonValue, value);
        QFETCH(QString, expected);
        StyleLayer layer;
        layer.name = QStringLiteral("tie.svg");
        layer.svg = kTie;
        QJsonObject json = projectToJson(projectWith({layer}), QDir::tempPath());
        QJsonObject style = json.value(QStringLiteral("style")).toObject();
        QJsonArray layers = style.value(QStringLiteral("layers")).toArray();
        QJsonObject first = layers.first().toObject();
        if (value.isNull())
            first.remove(key);
        else
            first.insert(key, value);
        layers.replace(0, first);
        style.insert(QStringLiteral("layers"), layers);
        json.insert(QStringLiteral("style"), style);
        QString error;
        QVERIFY(!projectFromJson(json, QDir::tempPath(), &error));
        QVERIFY2(error.startsWith(expected), qPrintable(error));
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestProjectLayers)
#include "tst_projectlayers.moc"
