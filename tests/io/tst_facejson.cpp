#include "detect/detector.h"
#include "face/averageface.h"
#include "face/fapu.h"
#include "io/facejson.h"
#include "testmain.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QRegularExpression>
#include <QTest>

using namespace toonface;

namespace {

FaceModel testFace()
{
    FaceModel face = averageFace(QRectF(101.3, 150.7, 203.1, 241.9), QSize(640, 800));
    face.setPoint(12, QPointF(1.0 / 3.0, 200.0 / 7.0), true);
    face.setHandPlaced(pt::idx("8.9"), true);
    return face;
}

// Replaces (or, with an undefined value, removes) the value at a path like "points[12].x".
QJsonValue patched(const QJsonValue &root, QStringView path, const QJsonValue &value)
{
    if (path.isEmpty())
        return value;
    static const QRegularExpression head(QStringLiteral("^(?:\\[(\\d+)\\]|\\.?([^.\\[]+))"));
    const auto m = head.match(path.toString());
    Q_ASSERT(m.hasMatch());
    const QStringView rest = path.mid(m.capturedLength());
    if (m.capturedLength(1) > 0) {
        QJsonArray a = root.toArray();
        const int i = m.captured(1).toInt();
        if (rest.isEmpty() && value.isUndefined())
            a.removeAt(i);
        else
            a[i] = patched(a.at(i), rest, value);
        return a;
    }
    QJsonObject o = root.toObject();
    const QString key = m.captured(2);
    if (rest.isEmpty() && value.isUndefined())
        o.remove(key);
    else
        o.insert(key, patched(o.value(key), rest, value));
    return o;
}

// A detection of `face` with its regions and the geometric part of its tracking seed.
DetectionResult seededDetection(const FaceModel &face)
{
    DetectionResult d;
    d.status = DetectStatus::Ok;
    d.regions = regionsFromPoints(face);
    d.tracking.valid = true;
    seedGeometryFromPoints(face, &d.tracking);
    return d;
}

} // namespace

class TestFaceJson : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void layout()
    {
        const FaceModel face = testFace();
        const QJsonObject json = faceToJson(face, QStringLiteral("/photos/me.jpg"));
        QCOMPARE(json.value(QStringLiteral("format")).toString(), QStringLiteral("toonface.face/1"));
        const QJsonArray points = json.value(QStringLiteral("points")).toArray();
        QCOMPARE(points.size(), kPointCount);
        for (int i = 0; i < kPointCount; ++i) {
            const QJsonObject p = points.at(i).toObject();
            QCOMPARE(p.value(QStringLiteral("id")).toString(), pointId(i));
            QCOMPARE(p.value(QStringLiteral("x")).toDouble(), face.point(i).x());
            QCOMPARE(p.value(QStringLiteral("y")).toDouble(), face.point(i).y());
            QCOMPARE(p.value(QStringLiteral("group")).toString(), groupName(pointTable()[i].group));
            QCOMPARE(p.value(QStringLiteral("control")).toBool(), pointTable()[i].control);
            QCOMPARE(p.value(QStringLiteral("handPlaced")).toBool(), face.isHandPlaced(i));
        }
        const Fapu f = face.fapu();
        const QJsonObject fapu = json.value(QStringLiteral("fapu")).toObject();
        const std::pair<const char *, double> expected[]
            = {{"ES0", f.es0}, {"ENS0", f.ens0}, {"MNS0", f.mns0}, {"MW0", f.mw0}, {"LeftEyeH", f.leftEyeH},
                {"RightEyeH", f.rightEyeH}, {"UpperLipH", f.upperLipH}, {"LowerLipH", f.lowerLipH}, {"JawH", f.jawH}};
        QCOMPARE(fapu.size(), 9);
        for (const auto &[name, value] : expected) {
            QVERIFY2(fapu.contains(QLatin1StringView(name)), name);
            QCOMPARE(fapu.value(QLatin1StringView(name)).toDouble(), value);
            QVERIFY(value > 0);
        }
        const QJsonObject image = json.value(QStringLiteral("image")).toObject();
        QCOMPARE(image.value(QStringLiteral("path")).toString(), QStringLiteral("/photos/me.jpg"));
        QCOMPARE(image.value(QStringLiteral("width")).toInt(), 640);
        QCOMPARE(image.value(QStringLiteral("height")).toInt(), 800);
        // No detection: no detection figures.
        QCOMPARE(json.value(QStringLiteral("method")).toString(), QStringLiteral("none"));
        QVERIFY(!json.contains(QStringLiteral("timingMs")));
        QVERIFY(!json.contains(QStringLiteral("faceCount")));
    }

    void detectionFields()
    {
        DetectionResult d;
        d.status = DetectStatus::Ok;
        d.method = QStringLiteral("landmarks");
        d.faceCount = 2;
        d.faceBox = QRect(10, 20, 300, 320);
        d.timingMs
            = {{QStringLiteral("detect"), 12.5}, {QStringLiteral("landmarks"), 3.25}, {QStringLiteral("total"), 15.75}};
        d.groupConfidence = {{QStringLiteral("eyes"), 0.9}, {QStringLiteral("hair"), 0.4}};
        const QJsonObject json = faceToJson(testFace(), QStringLiteral("me.jpg"), &d);
        QCOMPARE(json.value(QStringLiteral("method")).toString(), QStringLiteral("landmarks"));
        QCOMPARE(json.value(QStringLiteral("faceCount")).toInt(), 2);
        const QJsonObject box = json.value(QStringLiteral("faceBox")).toObject();
        QCOMPARE(QRect(box.value(QStringLiteral("x")).toInt(), box.value(QStringLiteral("y")).toInt(),
                     box.value(QStringLiteral("width")).toInt(), box.value(QStringLiteral("height")).toInt()),
            d.faceBox);
        const QJsonObject timing = json.value(QStringLiteral("timingMs")).toObject();
        QCOMPARE(timing.size(), 3);
        QCOMPARE(timing.value(QStringLiteral("total")).toDouble(), 15.75);
        QCOMPARE(timing.value(QStringLiteral("detect")).toDouble(), 12.5);
        const QJsonObject conf = json.value(QStringLiteral("groupConfidence")).toObject();
        QCOMPARE(conf.size(), 2);
        QCOMPARE(conf.value(QStringLiteral("eyes")).toDouble(), 0.9);
    }

    void roundTripThroughText()
    {
        const FaceModel face = testFace();
        const QByteArray text = QJsonDocument(faceToJson(face, QStringLiteral("dir/me.jpg"))).toJson();
        QString error;
        QString imagePath;
        const auto back = faceFromJson(QJsonDocument::fromJson(text).object(), &error, &imagePath);
        QVERIFY2(back, qPrintable(error));
        QVERIFY(*back == face);
        QCOMPARE(back->point(12), QPointF(1.0 / 3.0, 200.0 / 7.0));
        QCOMPARE(back->handPlacedCount(), 2);
        QCOMPARE(imagePath, QStringLiteral("dir/me.jpg"));
    }

    // The regions and the tracking seed survive a trip through the JSON text exactly.
    void regionsRoundTrip()
    {
        const FaceModel face = testFace();
        DetectionResult d;
        d.status = DetectStatus::Ok;
        d.method = QStringLiteral("landmarks");
        d.regions = regionsFromPoints(face);
        d.regions.ears[1] = QRectF(); // an ear that was not found
        d.tracking.valid = true;
        d.tracking.rect = QRectF(120.5, 200.25, 80.125, 60.0);
        d.tracking.m1 = 151.3;
        d.tracking.s1 = 40.7;
        d.tracking.t1 = 110.6;
        d.tracking.m2 = 14.2;
        d.tracking.s2 = 6.1;
        seedGeometryFromPoints(face, &d.tracking);
        d.tracking.skin = {1234, 225.5, 180.25, 150.0, 9.75};
        d.tracking.hair = {56, 60.0, 40.0, 25.5, 4.0};
        d.tracking.edgeThresholds = {312.0, 248.5, 0.0, 1030.25};
        const QByteArray text = QJsonDocument(faceToJson(face, QStringLiteral("me.jpg"), &d)).toJson();
        const QJsonObject json = QJsonDocument::fromJson(text).object();
        QVERIFY(json.contains(QStringLiteral("regions")));
        QVERIFY(json.contains(QStringLiteral("tracking")));
        FaceRegions regions;
        TrackingSeed tracking;
        QString error;
        QVERIFY2(faceRegionsFromJson(json, &regions, &tracking, &error), qPrintable(error));
        QVERIFY(regions == d.regions);
        QCOMPARE(regions.hairOutline.size(), 19);
        QVERIFY(tracking == d.tracking);
        // The face itself reads back as before.
        const auto back = faceFromJson(json, &error);
        QVERIFY2(back, qPrintable(error));
        QVERIFY(*back == face);
    }

    // Files written before regions and tracking existed, or without a detection, read with
    // empty regions and an invalid seed.
    void regionsAbsent()
    {
        const QJsonObject json = faceToJson(testFace(), QStringLiteral("me.jpg"));
        QVERIFY(!json.contains(QStringLiteral("regions")));
        QVERIFY(!json.contains(QStringLiteral("tracking")));
        FaceRegions regions;
        regions.nose = QRectF(1, 2, 3, 4);
        TrackingSeed tracking;
        tracking.valid = true;
        QString error;
        QVERIFY2(faceRegionsFromJson(json, &regions, &tracking, &error), qPrintable(error));
        QVERIFY(regions == FaceRegions());
        QVERIFY(!tracking.valid);
    }

    void regionsValidation_data()
    {
        QTest::addColumn<QString>("path");
        QTest::addColumn<QJsonValue>("value");
        QTest::addColumn<QString>("expected");
        QTest::newRow("box not an object")
            << QStringLiteral("regions.nose") << QJsonValue(3) << QStringLiteral("regions.nose");
        QTest::newRow("negative width") << QStringLiteral("regions.mouth.width") << QJsonValue(-2)
                                        << QStringLiteral("regions.mouth");
        QTest::newRow("one ear") << QStringLiteral("regions.ears[1]") << QJsonValue(QJsonValue::Undefined)
                                 << QStringLiteral("regions.ears");
        QTest::newRow("outline point") << QStringLiteral("regions.hairOutline[3]") << QJsonValue(QJsonArray {1})
                                       << QStringLiteral("regions.hairOutline[3]");
        QTest::newRow("threshold text") << QStringLiteral("tracking.t1") << QJsonValue(QStringLiteral("x"))
                                        << QStringLiteral("tracking.t1");
        QTest::newRow("eyeball radius") << QStringLiteral("tracking.eyeballs[0].radius")
                                        << QJsonValue(QJsonValue::Undefined)
                                        << QStringLiteral("tracking.eyeballs[0].radius");
        QTest::newRow("hair samples") << QStringLiteral("tracking.hair.samples") << QJsonValue(1.5)
                                      << QStringLiteral("tracking.hair.samples");
        QTest::newRow("three edge thresholds")
            << QStringLiteral("tracking.edgeThresholds") << QJsonValue(QJsonArray {1, 2, 3})
            << QStringLiteral("tracking.edgeThresholds");
        QTest::newRow("edge threshold text")
            << QStringLiteral("tracking.edgeThresholds[2]") << QJsonValue(QStringLiteral("x"))
            << QStringLiteral("tracking.edgeThresholds[2]");
    }

    // A seed written before the edge thresholds were kept reads with them not measured (0).
    void trackingWithoutEdgeThresholds()
    {
        const FaceModel face = testFace();
        DetectionResult d = seededDetection(face);
        d.tracking.edgeThresholds = {10, 20, 30, 40};
        const QJsonValue old
            = patched(faceToJson(face, QString(), &d), u"tracking.edgeThresholds", QJsonValue::Undefined);
        QVERIFY(
            !old.toObject().value(QStringLiteral("tracking")).toObject().contains(QStringLiteral("edgeThresholds")));
        FaceRegions regions;
        TrackingSeed tracking;
        tracking.edgeThresholds = {1, 2, 3, 4};
        QString error;
        QVERIFY2(faceRegionsFromJson(old.toObject(), &regions, &tracking, &error), qPrintable(error));
        QVERIFY(tracking.valid);
        QVERIFY(tracking.edgeThresholds == (std::array<double, 4> {}));
        QCOMPARE(tracking.d, d.tracking.d);
    }

    void regionsValidation()
    {
        QFETCH(QString, path);
        QFETCH(QJsonValue, value);
        QFETCH(QString, expected);
        const FaceModel face = testFace();
        DetectionResult d = seededDetection(face);
        const QJsonValue bad = patched(faceToJson(face, QString(), &d), path, value);
        FaceRegions regions;
        TrackingSeed tracking;
        QString error;
        QVERIFY(!faceRegionsFromJson(bad.toObject(), &regions, &tracking, &error));
        QVERIFY2(error.startsWith(expected + QLatin1Char(':')), qPrintable(error));
    }

    void faceWithoutImageSizeRoundTrips()
    {
        FaceModel face = testFace();
        face.setImageSize(QSize());
        const QJsonObject json = faceToJson(face, QString());
        QVERIFY(!json.value(QStringLiteral("image")).toObject().contains(QStringLiteral("width")));
        QString error;
        const auto back = faceFromJson(json, &error);
        QVERIFY2(back, qPrintable(error));
        QVERIFY(*back == face);
    }

    void handPlacedIsOptional()
    {
        const QJsonValue json
            = patched(faceToJson(testFace(), QString()), u"points[12].handPlaced", QJsonValue::Undefined);
        QString error;
        const auto back = faceFromJson(json.toObject(), &error);
        QVERIFY2(back, qPrintable(error));
        QVERIFY(!back->isHandPlaced(12));
    }

    void validation_data()
    {
        QTest::addColumn<QString>("path");
        QTest::addColumn<QJsonValue>("value");
        QTest::addColumn<QString>("expected");
        const QJsonValue remove(QJsonValue::Undefined);
        auto row = [](const char *name, const char *path, const QJsonValue &value, const char *expected) {
            QTest::newRow(name) << QString::fromLatin1(path) << value << QString::fromUtf8(expected);
        };
        row("format missing", "format", remove, "format: expected a string, it is missing");
        row("format project", "format", QStringLiteral("toonface.project"),
            "format: expected \"toonface.face/1\", found the string \"toonface.project\"");
        row("format newer", "format", QStringLiteral("toonface.face/2"),
            "format: toonface.face/2 was made by a newer Toonface (this version reads toonface.face/1)");
        row("points missing", "points", remove, "points: expected an array, it is missing");
        row("points object", "points", QJsonObject(), "points: expected an array, found an object");
        row("71 points", "points[71]", remove, "points: expected 72 points, found 71");
        row("point not object", "points[4]", 3, "points[4]: expected an object, found 3");
        row("x string", "points[12].x", QStringLiteral("12"),
            "points[12].x: expected a number, found the string \"12\"");
        row("y missing", "points[70].y", remove, "points[70].y: expected a number, it is missing");
        row("y huge", "points[1].y", -2e7,
            "points[1].y: expected a number between -10000000 and 10000000, found -2e+07");
        row("wrong id", "points[0].id", QStringLiteral("h.2"), "points[0].id: expected \"h.1\"");
        row("id number", "points[0].id", 1, "points[0].id: expected a string, found 1");
        row("group mismatch", "points[19].group", QStringLiteral("hair"),
            "points[19].group: expected \"contour\", found the string \"hair\"");
        row("control mismatch", "points[0].control", true, "points[0].control: expected false, found true");
        row("control string", "points[0].control", QStringLiteral("no"), "points[0].control: expected true or false");
        row("handPlaced number", "points[3].handPlaced", 1, "points[3].handPlaced: expected true or false, found 1");
        row("image missing", "image", remove, "image: expected an object, it is missing");
        row("image path number", "image.path", 7, "image.path: expected a string, found 7");
        row("width negative", "image.width", -1, "image.width: expected an integer from 0 to 1000000, found -1");
        row("width fractional", "image.width", 640.5,
            "image.width: expected an integer from 0 to 1000000, found 640.5");
        row("height without width", "image.width", remove,
            "image.width: expected an integer from 0 to 1000000, it is missing");
    }

    void validation()
    {
        QFETCH(QString, path);
        QFETCH(QJsonValue, value);
        QFETCH(QString, expected);
        const QJsonObject good = faceToJson(testFace(), QStringLiteral("me.jpg"));
        QString error;
        QVERIFY2(faceFromJson(good, &error), qPrintable(error));
        const QJsonObject bad = patched(good, path, value).toObject();
        QVERIFY(bad != good);
        QVERIFY(!faceFromJson(bad, &error));
        QVERIFY2(error.startsWith(expected), qPrintable(error));
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestFaceJson)
#include "tst_facejson.moc"
