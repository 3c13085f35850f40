#include "detect/appearance.h"
#include "detect/detector.h"
#include "detect/headparse.h"
#include "detect/photocolours.h"
#include "drawnface.h"
#include "face/pointtable.h"
#include "render/style.h"
#include "shareddata.h"
#include "testmain.h"

#include <QDir>
#include <QFile>
#include <QPainter>
#include <QRadialGradient>
#include <QTest>
#include <QTextStream>

using namespace toonface;
using testing::DrawnFaceOptions;

namespace {

const QColor kSkins[] = {QColor(240, 205, 185), QColor(196, 140, 105), QColor(105, 70, 50)};

// The label at a photo point.
HeadParse::Label labelAt(const HeadParse &parse, QPointF photoPoint)
{
    const QPointF w = parse.toWork.map(photoPoint);
    return parse.at(int(w.x()), int(w.y()));
}

QString describe(const HeadParse &p)
{
    return QStringLiteral("crown cut %1, top cut %2, head %3, reach %4")
        .arg(p.crownCut)
        .arg(p.topCut)
        .arg(p.headHeight, 0, 'f', 2)
        .arg(p.scalpReach, 0, 'f', 2);
}

// A shine on a bald crown: a soft light spot, the skin lit toward white.
void shine(QImage *photo, QPointF at, double r, const QColor &skin)
{
    QPainter p(photo);
    p.setRenderHint(QPainter::Antialiasing);
    QColor light = QColor::fromRgbF(0.5 * (skin.redF() + 1.0), 0.5 * (skin.greenF() + 1.0), 0.5 * (skin.blueF() + 1.0));
    QRadialGradient g(at, r);
    g.setColorAt(0, light);
    light.setAlpha(0);
    g.setColorAt(1, light);
    p.setPen(Qt::NoPen);
    p.setBrush(g);
    p.drawEllipse(at, r, r);
}

} // namespace

class TestHeadParse : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void skins_data()
    {
        QTest::addColumn<QColor>("skin");
        QTest::newRow("light") << kSkins[0];
        QTest::newRow("medium") << kSkins[1];
        QTest::newRow("dark") << kSkins[2];
    }

    // A haired head: the face is skin, the crown hair (the person, not skin), the photo's far
    // corners background; the crown is seen, covered by hair over the forehead's skin.
    void hairedHead_data() { skins_data(); }
    void hairedHead()
    {
        QFETCH(QColor, skin);
        DrawnFaceOptions o;
        o.skin = skin;
        const FaceModel face = testing::drawnFaceModel();
        const HeadParse p = parseHead(testing::drawnFace(o, face), face);
        QVERIFY(p.valid);
        QCOMPARE(labelAt(p, (face.point("9.15") + face.point("3.5")) / 2.0), HeadParse::Skin);
        // (The drawn hair is brown: on the dark skin it is as dark as the skin and of its hue, and
        // the label map calls it skin; the walk up the forehead still tells it from a scalp.)
        if (skin != kSkins[2])
            QCOMPARE(labelAt(p, face.point("h.10") + QPointF(0, 10)), HeadParse::Other);
        QCOMPARE(labelAt(p, QPointF(4, 4)), HeadParse::Background);
        QCOMPARE(labelAt(p, QPointF(face.imageSize().width() - 5, 4)), HeadParse::Background);
        QVERIFY2(!p.crownCut, qPrintable(describe(p)));
        QVERIFY2(p.scalpReach < AppearanceFindings::kScalpReach, qPrintable(describe(p)));
        // (The bald report's measure: hair over much of the forehead's middle above the brows.)
        if (skin != kSkins[2])
            QVERIFY2(p.crownSkin < 0.7, qPrintable(QString::number(p.crownSkin)));
        QVERIFY(!findAppearance(testing::drawnFace(o, face), face, skin).appearance.bald);
    }

    // A bald head is skin over the crown, also with a shine on it; it is decided bald.
    void baldHead_data() { skins_data(); }
    void baldHead()
    {
        QFETCH(QColor, skin);
        DrawnFaceOptions o;
        o.skin = skin;
        o.bald = true;
        const FaceModel face = testing::drawnFaceModel();
        for (const bool shiny : {false, true}) {
            QImage photo = testing::drawnFace(o, face);
            if (shiny) {
                const double es0 = QLineF(face.point("3.6"), face.point("3.5")).length();
                shine(&photo, face.point("h.10") + QPointF(0.2 * es0, 0.45 * es0), 0.35 * es0, skin);
            }
            const HeadParse p = parseHead(photo, face);
            QVERIFY2(!p.crownCut && p.scalpReach >= AppearanceFindings::kScalpReach
                    && p.headHeight >= AppearanceFindings::kMinHeadHeight,
                qPrintable(describe(p)));
            const AppearanceFindings f = findAppearance(photo, face, skin);
            QVERIFY2(f.appearance.bald, qPrintable(describe(p)));
            QVERIFY2(p.crownSkin > 0.8, qPrintable(QString::number(p.crownSkin)));
            QCOMPARE(f.crownSkin, p.crownSkin);
            QCOMPARE(f.scalpReach, p.scalpReach);
        }
    }

    // A crown the photo cuts off is not seen: the parse decides nothing about it.
    void crownCutOff()
    {
        DrawnFaceOptions o;
        o.bald = true;
        const FaceModel face = testing::drawnFaceModel();
        const QImage whole = testing::drawnFace(o, face);
        const int top = int(face.point("4.1").y() - 0.1 * QLineF(face.point("3.6"), face.point("3.5")).length());
        const QImage cropped = whole.copy(0, top, whole.width(), whole.height() - top);
        FaceModel moved = face;
        moved.setImageSize(cropped.size());
        for (int i = 0; i < kPointCount; ++i)
            moved.setPoint(i, face.point(i) - QPointF(0, top), false);
        const HeadParse p = parseHead(cropped, moved);
        QVERIFY(p.valid);
        QVERIFY2(p.crownCut, qPrintable(describe(p)));
        QCOMPARE(p.at(p.size.width() / 2, 0), HeadParse::Outside);
    }

    // Hair drawn down to the shoulders falls below the chin; hair cut above the ears does not.
    void hairFall()
    {
        const FaceModel face = testing::drawnFaceModel();
        const double es0 = QLineF(face.point("3.6"), face.point("3.5")).length();
        FaceModel longHaired = face;
        // The outline's three lowest points each side moved down to below the chin.
        const double chin = face.point("2.1").y();
        for (int k = 0; k < 3; ++k) {
            for (const int i : {pt::idx("h.1") + k, pt::idx("h.19") - k})
                longHaired.setPoint(
                    i, QPointF(face.point(i).x(), std::max(face.point(i).y(), chin + (1.0 - 0.45 * k) * es0)));
        }
        DrawnFaceOptions o;
        const HeadParse shortParse = parseHead(testing::drawnFace(o, face), face);
        const HeadParse longParse = parseHead(testing::drawnFace(o, longHaired), face);
        QVERIFY(shortParse.hairSeen && longParse.hairSeen);
        QVERIFY2(longParse.hairFall > 0.5, qPrintable(QString::number(longParse.hairFall)));
        QVERIFY2(shortParse.hairFall < 0, qPrintable(QString::number(shortParse.hairFall)));
        QVERIFY(!longParse.fallCut);
        // The hair length decided from it (the outline the detector would find is the drawn one).
        const QColor skin = o.skin;
        QCOMPARE(findAppearance(testing::drawnFace(o, longHaired), longHaired, skin).hairLength, HairLength::Long);
        QCOMPARE(findAppearance(testing::drawnFace(o, face), face, skin).hairLength, HairLength::Short);
    }

    // The outline's lower ends follow the fall where the outline stopped short: on the long-haired
    // drawing with the short outline, h.1 and h.19 move down below the chin; on a short-haired one
    // they stay above it; a point the user placed stays.
    void outlineFollowsTheFall()
    {
        const FaceModel face = testing::drawnFaceModel();
        const double es0 = QLineF(face.point("3.6"), face.point("3.5")).length();
        const double chin = face.point("2.1").y();
        FaceModel longHaired = face;
        for (int k = 0; k < 3; ++k)
            for (const int i : {pt::idx("h.1") + k, pt::idx("h.19") - k})
                longHaired.setPoint(
                    i, QPointF(face.point(i).x(), std::max(face.point(i).y(), chin + (1.0 - 0.45 * k) * es0)));
        DrawnFaceOptions o;
        const QImage photo = testing::drawnFace(o, longHaired);
        FaceModel outline = face; // the search's short outline over long hair
        QVERIFY(followHairFall(&outline, parseHead(photo, face)));
        QVERIFY2(outline.point("h.1").y() > chin && outline.point("h.19").y() > chin,
            qPrintable(QStringLiteral("%1 %2 chin %3")
                           .arg(outline.point("h.1").y())
                           .arg(outline.point("h.19").y())
                           .arg(chin)));
        for (int i = pt::idx("h.5"); i <= pt::idx("h.15"); ++i)
            QCOMPARE(outline.point(i), face.point(i));

        FaceModel placed = face;
        placed.setPoint(pt::idx("h.1"), face.point("h.1"), true);
        followHairFall(&placed, parseHead(photo, face));
        QCOMPARE(placed.point("h.1"), face.point("h.1"));

        // (The drawing's short hair is closed along the jaw: it goes down beside the cheeks to the
        // jaw's corners, and no lower.)
        FaceModel shortHaired = face;
        followHairFall(&shortHaired, parseHead(testing::drawnFace(o, face), face));
        QVERIFY(shortHaired.point("h.1").y() < chin && shortHaired.point("h.19").y() < chin);
    }

    // A tight crop (from a little over the brows to under the chin, the cheeks' width and a
    // little more) shows the hair's colour only beside the temples. Beside a short-haired head
    // against a white wall that is the wall: the fall of its colour is not taken for long hair
    // (roomFall), and the outline does not follow it. Long dark hair against the same wall still
    // falls below the chin.
    void tightCropRoom_data()
    {
        QTest::addColumn<bool>("longHair");
        QTest::addColumn<QColor>("wall");
        QTest::newRow("short hair, white wall") << false << QColor(250, 250, 250);
        QTest::newRow("long hair, white wall") << true << QColor(250, 250, 250);
        QTest::newRow("long hair, grey wall") << true << QColor(150, 150, 150);
    }
    void tightCropRoom()
    {
        QFETCH(bool, longHair);
        QFETCH(QColor, wall);
        FaceModel face = testing::drawnFaceModel();
        const double es0 = QLineF(face.point("3.6"), face.point("3.5")).length();
        const double chin = face.point("2.1").y();
        for (int k = 0; k < 6; ++k) {
            for (const int i : {pt::idx("h.1") + k, pt::idx("h.19") - k}) {
                const QPointF temple = face.point(i < pt::idx("h.10") ? "11.2" : "11.3");
                // Long: the three lowest points each side down below the chin; short: the sides
                // cut to the temples (hair on the crown only, which the crop leaves out).
                if (longHair && k < 3)
                    face.setPoint(
                        i, QPointF(face.point(i).x(), std::max(face.point(i).y(), chin + (1.0 - 0.45 * k) * es0)));
                else if (!longHair)
                    face.setPoint(i, temple);
            }
        }
        DrawnFaceOptions o;
        o.skin = kSkins[1];
        o.hair = QColor(40, 30, 25);
        o.background = wall;
        const QImage whole = testing::drawnFace(o, face);
        const QPointF mid = (face.point("3.6") + face.point("3.5")) / 2.0;
        // (As wide as the tight crops of faces-attributes, a little wider where the hair falls.)
        const double half = longHair ? 1.6 : 1.25;
        const QRect crop = QRectF(QPointF(mid.x() - half * es0, face.point("4.1").y() - 0.3 * es0),
            QPointF(mid.x() + half * es0, chin + 0.6 * es0))
                               .toAlignedRect()
                               .intersected(whole.rect());
        const QImage photo = whole.copy(crop);
        FaceModel moved = face;
        moved.setImageSize(photo.size());
        for (int i = 0; i < kPointCount; ++i)
            moved.setPoint(i, face.point(i) - QPointF(crop.topLeft()), false);
        const HeadParse p = parseHead(photo, moved);
        const QString seen = QStringLiteral("temple sample seen %1, lighter %2, fall %3 (measured %4)")
                                 .arg(p.templeHairSeen)
                                 .arg(p.templeLighter, 0, 'f', 1)
                                 .arg(p.hairFall, 0, 'f', 2)
                                 .arg(p.measuredFall, 0, 'f', 2);
        QVERIFY2(p.valid && p.templeHairSeen, qPrintable(seen));
        QCOMPARE(p.roomFall, !longHair);
        if (longHair) {
            QVERIFY2(p.hairFall > 0, qPrintable(seen));
            return;
        }
        QVERIFY2(p.hairFall < -1.0, qPrintable(seen));
        // The outline's ends (the drawn short hair's, beside the cheeks) stay where they are.
        FaceModel outline = moved;
        QVERIFY(!followHairFall(&outline, p));
        QCOMPARE(findAppearance(photo, moved, o.skin).hairLength, HairLength::Short);
    }

    void invalidInput()
    {
        QVERIFY(!parseHead(QImage(), testing::drawnFaceModel()).valid);
        QVERIFY(!parseHead(testing::drawnFace({}), FaceModel()).valid);
    }

    // Shared photos (research data, read only here): the bald man of bald_guys.jpg is drawn bald;
    // of the labelled faces whose forehead and crown the photo shows, nobody with hair is.
    void sharedPhotos()
    {
        const QString dir = testing::sharedDataDir();
        const QImage guys(QDir(dir).filePath(QStringLiteral("faces/bald_guys.jpg")));
        if (guys.isNull())
            QSKIP("the shared photos are not here (../shared/data/faces)");
        const DetectionResult r = detectFace(guys);
        if (r.status == DetectStatus::ModelMissing)
            QSKIP("the landmark model is not installed");
        QCOMPARE(r.status, DetectStatus::Ok);
        Style style = Style::preset(QStringLiteral("normal"));
        AppearanceFindings f;
        sampleColours(guys, r.face, &style, &f);
        QVERIFY2(style.appearance.bald, qPrintable(describe(parseHead(guys, r.face))));
        QVERIFY(!f.crownCut);

        const QDir labelled(QDir(dir).filePath(QStringLiteral("faces-attributes")));
        QFile tsv(labelled.filePath(QStringLiteral("labels.tsv")));
        if (!tsv.open(QIODevice::ReadOnly | QIODevice::Text))
            QSKIP("the labelled faces are not here (../shared/data/faces-attributes)");
        QTextStream in(&tsv);
        const QStringList header = in.readLine().split(QLatin1Char('\t'));
        int seen = 0;
        while (!in.atEnd()) {
            const QStringList c = in.readLine().split(QLatin1Char('\t'));
            if (c.size() < header.size() || c[header.indexOf(QLatin1String("bald"))] != QLatin1String("0"))
                continue;
            const QString file = c[header.indexOf(QLatin1String("file"))];
            const QImage photo(labelled.filePath(file));
            const DetectionResult d = detectFace(photo);
            if (d.status != DetectStatus::Ok)
                continue;
            Style s = Style::preset(QStringLiteral("normal"));
            AppearanceFindings found;
            sampleColours(photo, d.face, &s, &found);
            if (found.crownCut)
                continue;
            ++seen;
            QVERIFY2(!s.appearance.bald, qPrintable(file + QLatin1String(": ") + describe(parseHead(photo, d.face))));
        }
        QVERIFY2(seen >= 30, qPrintable(QString::number(seen)));
    }
};

TOONFACE_TEST_MAIN(TestHeadParse)
#include "tst_headparse.moc"
