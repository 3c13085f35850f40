#include "face/averageface.h"
#include "render/style.h"
#include "render/svgface.h"
#include "render/svglayer.h"
#include "testmain.h"

#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <QXmlStreamReader>

#include <sys/stat.h>

using namespace toonface;

namespace {

const QByteArray kOpen = "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" "
                         "xmlns:h=\"http://www.w3.org/1999/xhtml\" viewBox=\"0 0 10 10\">";

// What would make a browser fetch or navigate, in any form a layer could carry it.
const char *const kReachingOut[] = {"127.0.0.1", "http:", "srcset", "poster", "refresh", "@import", "image-set", "\\75",
    "\\69", "<p", "<img", "<video", "<link", "<meta", "<iframe", "<script", "xhtml", "javascript"};

QString fragmentOf(const QByteArray &body, QString *error = nullptr)
{
    LayerDrawing drawing;
    QString why;
    if (!readLayerSvg(kOpen + body + "</svg>", QStringLiteral("p-"), &drawing, &why)) {
        if (error)
            *error = why;
        return QStringLiteral("<refused>");
    }
    return QString::fromUtf8(drawing.fragment);
}

// Every element and attribute of `svg` (a whole document) lies in the SVG, XLink or XML
// namespace; *problem names the first one that does not.
bool onlySvg(const QByteArray &svg, QString *problem)
{
    QXmlStreamReader reader(svg);
    const QStringList allowed = {QStringLiteral("http://www.w3.org/2000/svg"),
        QStringLiteral("http://www.w3.org/1999/xlink"), QStringLiteral("http://www.w3.org/XML/1998/namespace")};
    while (!reader.atEnd()) {
        if (reader.readNext() != QXmlStreamReader::StartElement)
            continue;
        if (reader.namespaceUri() != allowed.first()) {
            *problem = reader.qualifiedName().toString();
            return false;
        }
        for (const QXmlStreamAttribute &a : reader.attributes()) {
            if (!a.namespaceUri().isEmpty() && !allowed.contains(a.namespaceUri().toString())) {
                *problem = a.qualifiedName().toString();
                return false;
            }
        }
    }
    *problem = reader.errorString();
    return !reader.hasError();
}

} // namespace

// A shared project's layers are cleaned by allow-lists: only SVG drawing is kept, and nothing
// in it can load from outside the file or take the page elsewhere, whatever escape, namespace or
// entity carries it; trees too deep or too large are refused by name.
class TestLayerSafety : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void reachingOutIsLeftOut_data()
    {
        QTest::addColumn<QByteArray>("body");
        QTest::newRow("css escape in url")
            << QByteArray("<rect width=\"1\" height=\"1\" style=\"fill:\\75 rl(http://127.0.0.1:9/a)\"/>");
        QTest::newRow("css escape in sheet")
            << QByteArray("<style>rect{fill:\\75 rl(http://127.0.0.1:9/b)}</style><rect width=\"1\" height=\"1\"/>");
        QTest::newRow("escaped import") << QByteArray("<style>@\\69mport 'http://127.0.0.1:9/c.css';</style>");
        QTest::newRow("image-set") << QByteArray(
            "<rect width=\"1\" height=\"1\" style=\"fill:image-set('http://127.0.0.1:9/d.png' 1x)\"/>");
        QTest::newRow("css comment in url")
            << QByteArray("<style>rect{fill:url(/**/http://127.0.0.1:9/e)}</style><rect width=\"1\" height=\"1\"/>");
        QTest::newRow("presentation attribute url")
            << QByteArray("<rect width=\"1\" height=\"1\" fill=\"url(http://127.0.0.1:9/f#x)\"/>");
        QTest::newRow("xhtml img srcset")
            << QByteArray("<h:img srcset=\"http://127.0.0.1:9/g.png 1x\"/><rect width=\"1\" height=\"1\"/>");
        QTest::newRow("xhtml meta refresh")
            << QByteArray("<h:meta http-equiv=\"refresh\" content=\"0;url=http://127.0.0.1:9/h\"/>");
        QTest::newRow("html breakout in svg namespace")
            << QByteArray("<p/><img srcset=\"http://127.0.0.1:9/i.png 1x\"/><video poster=\"http://127.0.0.1:9/j\"/>"
                          "<link imagesrcset=\"http://127.0.0.1:9/k\"/>"
                          "<meta http-equiv=\"refresh\" content=\"0;url=http://127.0.0.1:9/l\"/>");
        QTest::newRow("foreign object") << QByteArray(
            "<foreignObject><h:iframe src=\"http://127.0.0.1:9/m\"/></foreignObject>");
        QTest::newRow("script and handler")
            << QByteArray("<script>fetch('http://127.0.0.1:9/n')</script><rect onclick=\"javascript:x()\"/>");
        QTest::newRow("animated link") << QByteArray(
            "<a><set attributeName=\"href\" to=\"http://127.0.0.1:9/o\"/><rect width=\"1\" height=\"1\"/></a>");
        QTest::newRow("link to elsewhere")
            << QByteArray("<a xlink:href=\"http://127.0.0.1:9/p\"><rect width=\"1\" height=\"1\"/></a>");
        QTest::newRow("feImage outside") << QByteArray(
            "<filter id=\"f\"><feImage href=\"http://127.0.0.1:9/q.png\"/></filter>");
        QTest::newRow("cursor") << QByteArray(
            "<rect width=\"1\" height=\"1\" cursor=\"url(http://127.0.0.1:9/r.cur), auto\"/>");
        QTest::newRow("svg image of svg")
            << QByteArray("<image href=\"data:image/svg+xml;base64,PHN2Zz48L3N2Zz4=\" width=\"1\" height=\"1\"/>");
    }

    void reachingOutIsLeftOut()
    {
        QFETCH(QByteArray, body);
        QString error;
        const QString fragment = fragmentOf(body, &error);
        QVERIFY2(fragment != QLatin1StringView("<refused>"), qPrintable(error));
        for (const char *needle : kReachingOut)
            QVERIFY2(!fragment.contains(QLatin1StringView(needle), Qt::CaseInsensitive),
                qPrintable(QStringLiteral("%1 in %2").arg(QLatin1StringView(needle), fragment)));
        // A drawing beside the hostile part is kept.
        if (body.contains("<rect width=\"1\""))
            QVERIFY2(fragment.contains(QLatin1StringView("<rect")), qPrintable(fragment));
    }

    // The drawing a layer needs is kept whole: shapes, text, gradients, clipping, masks,
    // filters, styles that refer to its own elements, embedded raster pictures; a link keeps
    // its drawing as a group.
    void drawingIsKept()
    {
        const QByteArray body = "<defs><linearGradient id=\"g\"><stop offset=\"0\" stop-color=\"#f00\"/>"
                                "</linearGradient><clipPath id=\"c\"><circle r=\"4\"/></clipPath>"
                                "<filter id=\"b\"><feGaussianBlur stdDeviation=\"1\"/></filter></defs>"
                                "<style>.k{fill:url(#g);stroke:rgb(1,2,3)}</style>"
                                "<g clip-path=\"url(#c)\" filter=\"url(#b)\" transform=\"translate(1 2)\">"
                                "<path class=\"k\" d=\"M0 0L5 5Z\" style=\"fill:url('#g');opacity:.5\"/>"
                                "<text x=\"1\" y=\"2\" font-family=\"serif\">Hi<tspan dx=\"1\">!</tspan></text></g>"
                                "<a xlink:href=\"#g\"><rect id=\"r\" width=\"2\" height=\"2\"/></a>"
                                "<use xlink:href=\"#r\" x=\"3\"/>"
                                "<image href=\"data:image/png;base64,iVBORw0KGgo=\" width=\"1\" height=\"1\"/>";
        QString error;
        const QString f = fragmentOf(body, &error);
        for (const char *kept : {"<linearGradient id=\"p-g\"", "<stop offset=\"0\" stop-color=\"#f00\"",
                 "clip-path=\"url(#p-c)\"", "filter=\"url(#p-b)\"", "<feGaussianBlur stdDeviation=\"1\"",
                 ".k{fill:url(#p-g);stroke:rgb(1,2,3)}", "d=\"M0 0L5 5Z\"", "style=\"fill:url('#p-g');opacity:.5\"",
                 "<text x=\"1\" y=\"2\" font-family=\"serif\">Hi<tspan dx=\"1\">!</tspan></text>",
                 "<g><rect id=\"p-r\"", "xlink:href=\"#p-r\"", "data:image/png;base64,iVBORw0KGgo="})
            QVERIFY2(f.contains(QLatin1StringView(kept)),
                qPrintable(QStringLiteral("%1 not in %2").arg(QLatin1StringView(kept), f)));
    }

    // An SVG 1.1 file with its DOCTYPE and HTML's &nbsp; (as editors write them) is read, and
    // written back as well-formed XML with the character itself; an entity nobody defines is
    // refused by name; an external entity is never read.
    void doctypeAndEntities()
    {
        const QByteArray svg11 = "<?xml version=\"1.0\"?>\n<!DOCTYPE svg PUBLIC \"-//W3C//DTD SVG 1.1//EN\" "
                                 "\"http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd\">\n"
                                 "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 10 10\">"
                                 "<text>a&nbsp;b</text></svg>";
        QByteArray cleaned;
        QString error;
        QVERIFY2(cleanLayerSvg(svg11, &cleaned, &error), qPrintable(error));
        QVERIFY(!cleaned.contains("&nbsp;") && !cleaned.contains("DOCTYPE"));
        QVERIFY(QString::fromUtf8(cleaned).contains(QStringLiteral("a\u00a0b")));
        QString problem;
        QVERIFY2(onlySvg(cleaned, &problem), qPrintable(problem));
        // The preview draws it (QSvgRenderer reads the cleaned copy).
        const FaceModel face = averageFace(QRectF(100, 100, 200, 260), QSize(400, 480));
        SvgFace drawing(face, Style());
        drawing.addLayer(svg11);
        QVERIFY(drawing.svg().contains("layer-1-")
            || QString::fromUtf8(drawing.svg()).contains(QStringLiteral("a\u00a0b")));
        QXmlStreamReader whole(drawing.svg());
        while (!whole.atEnd())
            whole.readNext();
        QVERIFY2(!whole.hasError(), qPrintable(whole.errorString()));

        const QByteArray undefined = "<!DOCTYPE svg PUBLIC \"-//W3C//DTD SVG 1.1//EN\" \"svg11.dtd\">"
                                     "<svg xmlns=\"http://www.w3.org/2000/svg\"><text>&secret;</text></svg>";
        QVERIFY(!cleanLayerSvg(undefined, &cleaned, &error));
        QVERIFY2(error.contains(QStringLiteral("&secret;")), qPrintable(error));

        QTemporaryDir dir;
        QFile secret(dir.filePath(QStringLiteral("secret.txt")));
        QVERIFY(secret.open(QIODevice::WriteOnly));
        secret.write("PRIVATE-BYTES");
        secret.close();
        const QByteArray external = "<!DOCTYPE svg [<!ENTITY x SYSTEM \"file://" + secret.fileName().toUtf8()
            + "\">]><svg xmlns=\"http://www.w3.org/2000/svg\"><text>&x;</text></svg>";
        if (cleanLayerSvg(external, &cleaned, &error))
            QVERIFY(!cleaned.contains("PRIVATE-BYTES"));
    }

    void limits_data()
    {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QString>("problem");
        QByteArray deep = kOpen;
        for (int i = 0; i < 100000; ++i)
            deep += "<g>";
        for (int i = 0; i < 100000; ++i)
            deep += "</g>";
        deep += "</svg>";
        QTest::newRow("100,000 nested groups") << deep << QStringLiteral("nested more than 64 deep");
        QByteArray wide = kOpen;
        for (int i = 0; i < 100001; ++i)
            wide += "<g/>";
        wide += "</svg>";
        QTest::newRow("100,001 elements") << wide << QStringLiteral("more than 100000 elements");
    }

    void limits()
    {
        QFETCH(QByteArray, content);
        QFETCH(QString, problem);
        LayerDrawing drawing;
        QString error;
        QVERIFY(!readLayerSvg(content, QString(), &drawing, &error));
        QVERIFY2(error.contains(problem), qPrintable(error));
        // The face draws without the layer; nothing walks the deep tree.
        const FaceModel face = averageFace(QRectF(100, 100, 200, 260), QSize(400, 480));
        SvgFace svg(face, Style());
        svg.addLayer(content);
        QVERIFY(!svg.svg().contains("<g><g><g><g>"));
    }

    // Cleaning is done once, on the way in: a cleaned layer cleans to itself, and a layer file
    // is held (and so saved in the project) as its cleaned copy.
    void cleanedOnce()
    {
        const QByteArray hostile = kOpen
            + "<script>alert(1)</script><rect id=\"r\" width=\"2\" height=\"2\" onclick=\"x()\"/>"
              "<h:p>hi</h:p></svg>";
        QByteArray once, twice;
        QString error;
        QVERIFY2(cleanLayerSvg(hostile, &once, &error), qPrintable(error));
        QVERIFY2(cleanLayerSvg(once, &twice, &error), qPrintable(error));
        QCOMPARE(twice, once);
        QVERIFY(!once.contains("script") && !once.contains("onclick") && !once.contains("<h:p"));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("hat.svg"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(hostile);
        file.close();
        StyleLayer layer;
        QVERIFY2(loadLayerFile(path, &layer, &error), qPrintable(error));
        QCOMPARE(layer.svg, once);
    }

    // A layer that is not a regular file is refused before anything reads it: a device would
    // be read without end, a pipe would block.
    void devicesAndPipesRefused()
    {
        QTemporaryDir dir;
        const QString fifo = dir.filePath(QStringLiteral("pipe.svg"));
        QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
        const FaceModel face = averageFace(QRectF(100, 100, 200, 260), QSize(400, 480));
        for (const QString &path : {QStringLiteral("/dev/zero"), fifo, dir.path()}) {
            StyleLayer layer;
            QString error;
            QVERIFY(!loadLayerFile(path, &layer, &error));
            QVERIFY2(error.contains(path), qPrintable(error));
            SvgFace svg(face, Style());
            QVERIFY(!svg.addLayerFile(path, &error));
            QVERIFY2(error.contains(path) && (error.contains(QStringLiteral("not a file"))), qPrintable(error));
        }
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestLayerSafety)
#include "tst_layersafety.moc"
