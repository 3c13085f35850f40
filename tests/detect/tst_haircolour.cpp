#include "detect/agegroup.h"
#include "detect/appearance.h"
#include "detect/detector.h"
#include "detect/haircolour.h"
#include "detect/headparse.h"
#include "detect/labcolour.h"
#include "detect/photocolours.h"
#include "drawnface.h"
#include "render/style.h"
#include "sampledfaces.h"
#include "shareddata.h"
#include "testmain.h"

#include <QDir>
#include <QFile>
#include <QRandomGenerator>
#include <QTest>
#include <QTextStream>

#include <cmath>
#include <map>

using namespace toonface;
using testing::DrawnFaceOptions;

namespace {

const QColor kSkin(222, 178, 150);

// `n` pixels of `c`, each channel jittered by up to `spread` levels either way (as strands and
// JPEG noise vary).
std::vector<QRgb> pixelsNear(const QColor &c, int n, int spread, quint32 seed)
{
    QRandomGenerator rng(seed);
    std::vector<QRgb> out;
    for (int i = 0; i < n; ++i) {
        auto jitter = [&](int v) { return std::clamp(v + rng.bounded(-spread, spread + 1), 0, 255); };
        out.push_back(qRgb(jitter(c.red()), jitter(c.green()), jitter(c.blue())));
    }
    return out;
}

double labDistance(const LabColour &a, const LabColour &b)
{
    return std::hypot(a.l - b.l, a.a - b.a, a.b - b.b);
}

HairShade shadeOfColour(const QColor &c, const QColor &skin)
{
    HairColourReading r;
    r.valid = true;
    r.hair = labOf(c);
    r.skin = labOf(skin);
    return classifyHair(r).shade;
}

QString name(HairShade s)
{
    return hairShadeName(s);
}

} // namespace

class TestHairColour : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // A sample that is partly the skin (a parting, skin between thin strands) and partly the
    // room (wisps over the wall) reads as the hair, not as their blend.
    void readsTheStrandsNotTheSkinOrTheRoom()
    {
        const QColor grey(168, 168, 165), room(70, 90, 120);
        std::vector<QRgb> sample = pixelsNear(kSkin, 400, 4, 1);
        const auto wall = pixelsNear(room, 300, 4, 2);
        const auto hair = pixelsNear(grey, 300, 6, 3);
        sample.insert(sample.end(), wall.begin(), wall.end());
        sample.insert(sample.end(), hair.begin(), hair.end());
        const HairColourReading r = readHairColour(sample, kSkin, room);
        QVERIFY(r.valid);
        QVERIFY2(labDistance(r.hair, labOf(grey)) < 4.0, qPrintable(r.colour().name()));
        QVERIFY(r.kept < 0.5);
        QCOMPARE(classifyHair(r).shade, HairShade::Grey);
    }

    // The shadows between strands and a shine on them do not decide the hair's lightness.
    void shadowsAndShineLeftOut()
    {
        const QColor blond(200, 165, 105);
        std::vector<QRgb> sample = pixelsNear(blond, 500, 8, 4);
        const auto shadow = pixelsNear(QColor(45, 35, 25), 120, 4, 5);
        const auto shine = pixelsNear(QColor(250, 248, 240), 80, 3, 6);
        sample.insert(sample.end(), shadow.begin(), shadow.end());
        sample.insert(sample.end(), shine.begin(), shine.end());
        const HairColourReading r = readHairColour(sample, kSkin);
        QVERIFY(r.valid);
        QVERIFY2(std::abs(r.hair.l - labOf(blond).l) < 5.0, qPrintable(r.colour().name()));
    }

    void tooFewPixelsReadNothing()
    {
        QVERIFY(!readHairColour(pixelsNear(QColor(30, 30, 30), 5, 2, 7), kSkin).valid);
        QVERIFY(!readHairColour(pixelsNear(QColor(30, 30, 30), 100, 2, 7), QColor()).valid);
    }

    // Hair of each shade, as a photo shows it lit, is told as that shade.
    void shadesOfHair_data()
    {
        QTest::addColumn<QColor>("hair");
        QTest::addColumn<int>("shade");
        QTest::newRow("black") << QColor(28, 24, 22) << int(HairShade::Black);
        QTest::newRow("dark brown") << QColor(75, 52, 38) << int(HairShade::Brown);
        QTest::newRow("brown") << QColor(105, 75, 52) << int(HairShade::Brown);
        QTest::newRow("auburn") << QColor(140, 62, 35) << int(HairShade::Red);
        QTest::newRow("copper") << QColor(185, 95, 45) << int(HairShade::Red);
        QTest::newRow("blond") << QColor(205, 170, 110) << int(HairShade::Blond);
        QTest::newRow("grey") << QColor(150, 150, 148) << int(HairShade::Grey);
        QTest::newRow("white") << QColor(232, 232, 228) << int(HairShade::Grey);
    }
    void shadesOfHair()
    {
        QFETCH(QColor, hair);
        QFETCH(int, shade);
        QCOMPARE(name(shadeOfColour(hair, kSkin)), name(HairShade(shade)));
    }

    // The drawn colour is not muted toward brown: grey loses its colour, red keeps its chroma,
    // blond its lightness; a brown stays as read.
    void drawnColourKeepsItsShade_data()
    {
        QTest::addColumn<QColor>("hair");
        QTest::newRow("warm grey") << QColor(160, 155, 148);
        QTest::newRow("copper") << QColor(170, 90, 50);
        QTest::newRow("blond") << QColor(200, 168, 115);
        QTest::newRow("black") << QColor(35, 30, 28);
        QTest::newRow("brown") << QColor(100, 72, 50);
    }
    void drawnColourKeepsItsShade()
    {
        QFETCH(QColor, hair);
        const HairColourReading r = readHairColour(pixelsNear(hair, 200, 3, 8), kSkin);
        QVERIFY(r.valid);
        const HairShadeCall call = classifyHair(r);
        const QColor drawn = drawnHairColour(r, call);
        QCOMPARE(name(shadeOfColour(drawn, kSkin)), name(call.shade));
        const LabColour d = labOf(drawn);
        const double chroma = std::hypot(d.a, d.b);
        switch (call.shade) {
        case HairShade::Grey: QVERIFY2(chroma < r.chroma(), qPrintable(drawn.name())); break;
        case HairShade::Red:
        case HairShade::Blond:
            QVERIFY2(chroma >= r.chroma() - 1.0 && d.l >= r.hair.l - 1.0, qPrintable(drawn.name()));
            break;
        case HairShade::Black: QVERIFY2(d.l <= r.hair.l + 1.0, qPrintable(drawn.name())); break;
        case HairShade::Brown: QVERIFY2(labDistance(d, r.hair) < 2.0, qPrintable(drawn.name())); break;
        }
    }

    // Hair is never violet, blue or green: strands read so carry the room's colour (a grey head
    // before a mauve wall, black hair under a blue light). Such a reading is not red hair, and is
    // drawn without that colour, at the lightness read.
    void roomColouredStrandsAreDrawnWithoutTheirColour_data()
    {
        QTest::addColumn<QColor>("hair");
        QTest::newRow("mauve-grey") << QColor(190, 160, 200);
        QTest::newRow("blue-grey") << QColor(140, 160, 205);
        QTest::newRow("violet-black") << QColor(48, 20, 60);
        QTest::newRow("olive-grey") << QColor(150, 160, 100);
        QTest::newRow("teal-black") << QColor(20, 60, 60);
    }
    void roomColouredStrandsAreDrawnWithoutTheirColour()
    {
        QFETCH(QColor, hair);
        const HairColourReading r = readHairColour(pixelsNear(hair, 200, 3, 9), kSkin);
        QVERIFY(r.valid);
        QVERIFY2(r.chroma() > 10.0, qPrintable(r.colour().name()));
        const HairShadeCall call = classifyHair(r);
        QVERIFY2(call.shade != HairShade::Red, qPrintable(r.colour().name()));
        const LabColour d = labOf(drawnHairColour(r, call));
        QVERIFY2(std::hypot(d.a, d.b) < 4.0, qPrintable(colourOfLab(d).name()));
    }

    void labRoundTrip()
    {
        for (const QColor &c : {QColor(10, 10, 10), QColor(200, 120, 60), QColor(240, 240, 235), QColor(60, 90, 160)}) {
            const QColor back = colourOfLab(labOf(c));
            QVERIFY2(std::abs(back.red() - c.red()) <= 2 && std::abs(back.green() - c.green()) <= 2
                    && std::abs(back.blue() - c.blue()) <= 2,
                qPrintable(c.name() + QLatin1Char(' ') + back.name()));
        }
    }

    // Drawn heads of every hair shade on a mid and a dark background, on a light and a dark
    // skin: the cartoon's hair comes out in the hair's shade.
    void drawnHeadsKeepTheirShade_data()
    {
        QTest::addColumn<QColor>("hair");
        QTest::addColumn<QColor>("background");
        QTest::addColumn<QColor>("skin");
        QTest::addColumn<int>("shade");
        const std::pair<const char *, QColor> hairs[]
            = {{"white", QColor(232, 230, 226)}, {"grey", QColor(160, 160, 158)}, {"red", QColor(165, 72, 38)},
                {"blond", QColor(212, 178, 118)}, {"black", QColor(26, 23, 22)}};
        const int shades[] = {int(HairShade::Grey), int(HairShade::Grey), int(HairShade::Red), int(HairShade::Blond),
            int(HairShade::Black)};
        const std::pair<const char *, QColor> rooms[] = {{"mid", QColor(120, 122, 125)}, {"dark", QColor(38, 40, 46)}};
        const std::pair<const char *, QColor> skins[]
            = {{"light", QColor(232, 195, 172)}, {"dark", QColor(110, 74, 54)}};
        for (size_t h = 0; h < std::size(hairs); ++h)
            for (const auto &[roomName, room] : rooms)
                for (const auto &[skinName, skin] : skins) {
                    // (Blond hair on a dark skin is taken for a shine on a bald scalp by the
                    // head's cover, not by the colour: tst_headcover's hairIsNoHat says so.)
                    if (shades[h] == int(HairShade::Blond) && skin.lightness() < 100)
                        continue;
                    QTest::addRow("%s hair, %s room, %s skin", hairs[h].first, roomName, skinName)
                        << hairs[h].second << room << skin << shades[h];
                }
    }
    void drawnHeadsKeepTheirShade()
    {
        QFETCH(QColor, hair);
        QFETCH(QColor, background);
        QFETCH(QColor, skin);
        QFETCH(int, shade);
        DrawnFaceOptions o;
        o.hair = hair;
        o.background = background;
        o.skin = skin;
        Style style = Style::preset(QStringLiteral("normal"));
        AppearanceFindings f;
        sampleColours(testing::drawnFace(o), testing::drawnFaceModel(), &style, &f);
        const QColor drawn = style.components.value(QStringLiteral("hair")).fill;
        QVERIFY2(!style.appearance.bald && !style.appearance.hat, "drawn bald or hatted");
        QCOMPARE(name(shadeOfColour(drawn, skin)), name(HairShade(shade)));
    }

    // A white beard is drawn grey or white, under white hair and under dark hair alike.
    void whiteBeardDrawnWhite_data()
    {
        QTest::addColumn<QColor>("hair");
        QTest::addColumn<QColor>("background");
        QTest::newRow("white hair, mid room") << QColor(230, 230, 226) << QColor(120, 122, 125);
        QTest::newRow("white hair, dark room") << QColor(230, 230, 226) << QColor(38, 40, 46);
        QTest::newRow("dark hair, mid room") << QColor(60, 45, 35) << QColor(120, 122, 125);
        QTest::newRow("dark hair, dark room") << QColor(60, 45, 35) << QColor(38, 40, 46);
    }
    void whiteBeardDrawnWhite()
    {
        QFETCH(QColor, hair);
        QFETCH(QColor, background);
        DrawnFaceOptions o;
        o.hair = hair;
        o.background = background;
        o.beard = true;
        o.moustache = true;
        o.beardColour = QColor(228, 228, 224);
        Style style = Style::preset(QStringLiteral("normal"));
        sampleColours(testing::drawnFace(o), testing::drawnFaceModel(), &style);
        QVERIFY2(
            style.appearance.beard || style.appearance.moustache || style.appearance.goatee, "no facial hair found");
        const QColor drawn = style.components.value(QStringLiteral("beard")).fill;
        QCOMPARE(name(shadeOfColour(drawn, o.skin)), name(HairShade::Grey));
    }

    // A beard's grey strands read with the skin's warmth between them (chroma above the grey
    // shade's): on a face decided elderly they are drawn grey, and never see-through; on a
    // younger face the same reading keeps its fair shade. Dark stubble over medium skin reads
    // mid-grey: on a young face it is drawn dark (photocolours.h, drawnFacialHair).
    void beardGreyAsksTheAge_data()
    {
        QTest::addColumn<double>("l");
        QTest::addColumn<double>("a");
        QTest::addColumn<double>("b");
        QTest::addColumn<int>("group");
        QTest::addColumn<double>("elderly"); // the age model's chance of elderly
        QTest::addColumn<bool>("grey");
        // Chroma 18 over a skin of chroma 29: grey strands with the skin between them, as read.
        QTest::newRow("warm grey, elderly") << 60.0 << 6.0 << 17.0 << int(AgeGroup::Elderly) << 0.8 << true;
        QTest::newRow("warm grey, adult") << 60.0 << 6.0 << 17.0 << int(AgeGroup::Adult) << 0.1 << false;
        QTest::newRow("warm grey, child") << 60.0 << 6.0 << 17.0 << int(AgeGroup::Child) << 0.0 << false;
        // Chroma 5, L* 40: grey by the shade's rules.
        QTest::newRow("mid grey, elderly") << 40.0 << 2.0 << 4.5 << int(AgeGroup::Elderly) << 0.8 << true;
        QTest::newRow("mid grey, young") << 40.0 << 2.0 << 4.5 << int(AgeGroup::Adult) << 0.05 << false;
        QTest::newRow("white, young") << 80.0 << 1.0 << 3.0 << int(AgeGroup::Adult) << 0.05 << true;
    }
    void beardGreyAsksTheAge()
    {
        QFETCH(double, l);
        QFETCH(double, a);
        QFETCH(double, b);
        QFETCH(int, group);
        QFETCH(double, elderly);
        QFETCH(bool, grey);
        HairColourReading reading;
        reading.valid = true;
        reading.hair = {l, a, b};
        reading.skin = {62.0, 16.0, 24.0}; // chroma 29
        reading.kept = 0.6;
        reading.pixels = 200;
        AgeDecision age;
        age.group = AgeGroup(group);
        age.elderly = elderly;
        const QColor brows(60, 42, 30);
        bool drawnGrey = false;
        const LabColour drawn = labOf(drawnFacialHair(reading, QColor(), age, brows, &drawnGrey));
        QCOMPARE(drawnGrey, grey);
        // Grey: light and of little colour; else a fair shade or dark hair, as read.
        const bool looksGrey = drawn.l >= 50.0 && std::hypot(drawn.a, drawn.b) < 10.0;
        QVERIFY2(looksGrey == grey,
            qPrintable(QStringLiteral("drawn L* %1 a* %2 b* %3").arg(drawn.l).arg(drawn.a).arg(drawn.b)));
    }

    // On the labelled faces (faces-attributes, research data read only here) of elderly men with
    // grey hair and a beard found, the beard is drawn grey (light, of little colour, not
    // see-through) on at least half: they were drawn fair, light brown or see-through stubble.
    // The faces' age decision and the colour's thresholds are in-sample here.
    void elderlyGreyBeardsAreDrawnGrey()
    {
        TOONFACE_SAMPLED_FACES(sampled);
        int beards = 0, drawnGrey = 0;
        QStringList other;
        for (const testing::SampledFace &face : sampled.faces) {
            const testing::LabelledFace &row = face.row;
            if (row["age_group"] != QLatin1String("elderly") || row["hair_colour"] != QLatin1String("grey")
                || !row.flag("beard"))
                continue;
            const Style &style = face.style;
            if (!style.appearance.beard && !style.appearance.goatee && !style.appearance.moustache)
                continue;
            const QColor fill = style.components.value(QStringLiteral("beard")).fill;
            const LabColour drawn = labOf(fill);
            const bool grey = drawn.l >= 50.0 && std::hypot(drawn.a, drawn.b) < 15.0 && fill.alpha() == 255;
            ++beards;
            drawnGrey += grey;
            if (!grey)
                other << QStringLiteral("%1 %2").arg(row["file"], fill.name(QColor::HexArgb));
        }
        qInfo("grey-haired elderly men's beards drawn grey: %d of %d (not: %s)", drawnGrey, beards,
            qPrintable(other.join(QLatin1String(", "))));
        QVERIFY(beards > 0);
        QVERIFY2(2 * drawnGrey >= beards, qPrintable(other.join(QLatin1String(", "))));
    }

    // On the labelled faces (faces-attributes, research data read only here) whose hair is red,
    // blond or grey, and as many black-haired ones, the drawn hair shows the label's shade on at
    // least half of each: the rules were fitted on this set, so these are in-sample figures (the
    // held-out ones are toonface-bench likeness.attributes').
    void labelledFacesByShade()
    {
        TOONFACE_SAMPLED_FACES(sampled);
        std::map<QString, std::pair<int, int>> byShade; // label: (right, drawn)
        for (const testing::SampledFace &face : sampled.faces) {
            const QString label = face.row["hair_colour"];
            if (label != QLatin1String("red") && label != QLatin1String("blond") && label != QLatin1String("grey")
                && !(label == QLatin1String("black") && byShade[label].second < 12))
                continue;
            const Style &style = face.style;
            if (style.appearance.bald || style.appearance.hat)
                continue;
            const HairShade drawn = shadeOfColour(style.components.value(QStringLiteral("hair")).fill,
                style.components.value(QStringLiteral("face")).fill);
            byShade[label].first += hairShadeName(drawn) == label;
            ++byShade[label].second;
        }
        for (const auto &[label, counts] : byShade) {
            qInfo("%s hair drawn as such on %d of %d", qPrintable(label), counts.first, counts.second);
            QVERIFY2(2 * counts.first >= counts.second, qPrintable(label));
        }
    }

    // Grey-haired elderly people are drawn grey: grey strands over a dark room read taupe, near
    // the colour's thresholds, and were drawn so (a brown) unless the face's age says grey.
    // Drawn grey as in youngDarkHeadsAreNotDrawnGrey. In-sample (the labelled faces): 6 of 15
    // before, 8 after.
    void elderlyGreyHeadsAreDrawnGrey()
    {
        TOONFACE_SAMPLED_FACES(sampled);
        int heads = 0, drawnGrey = 0;
        QStringList other;
        for (const testing::SampledFace &face : sampled.faces) {
            const testing::LabelledFace &row = face.row;
            if (row["age_group"] != QLatin1String("elderly") || row["hair_colour"] != QLatin1String("grey"))
                continue;
            const Style &style = face.style;
            if (style.appearance.bald || style.appearance.hat)
                continue;
            const LabColour drawn = labOf(style.components.value(QStringLiteral("hair")).fill);
            const bool grey = drawn.l >= 50.0 && std::hypot(drawn.a, drawn.b) < 15.0;
            ++heads;
            drawnGrey += grey;
            if (!grey)
                other << row["file"];
        }
        qInfo("grey-haired elderly drawn grey: %d of %d (not: %s)", drawnGrey, heads,
            qPrintable(other.join(QLatin1String(", "))));
        QVERIFY(heads > 0);
        QVERIFY2(2 * drawnGrey >= heads, qPrintable(other.join(QLatin1String(", "))));
    }

    // Grey hair seen only beside the temples (a tight crop) is far lighter than the cheeks, as the
    // room beside a short-haired head is, most of all on dark skin: on a face the age models take
    // for an elderly person's it is drawn grey, not dark (fa_s146's white hair on dark skin was
    // drawn dark brown before). In-sample: the labelled grey heads so sampled, 4 of 5 drawn grey
    // before, all after.
    void greyHairBesideTheTemplesIsDrawnGrey()
    {
        TOONFACE_SAMPLED_FACES(sampled);
        int heads = 0;
        QStringList dark;
        for (const testing::SampledFace &face : sampled.faces) {
            const testing::LabelledFace &row = face.row;
            if (row["hair_colour"] != QLatin1String("grey"))
                continue;
            const Style &style = face.style;
            const AppearanceFindings &found = face.found;
            if (!found.templeHairSeen || found.templeLighter <= kRoomLighter || style.appearance.bald
                || style.appearance.hat)
                continue;
            ++heads;
            const LabColour drawn = labOf(style.components.value(QStringLiteral("hair")).fill);
            if (drawn.l < 50.0 || std::hypot(drawn.a, drawn.b) >= 15.0)
                dark << row["file"];
        }
        qInfo("grey heads seen beside the temples: %d, drawn dark: %s", heads,
            qPrintable(dark.join(QLatin1String(", "))));
        QVERIFY(heads > 0);
        QVERIFY2(dark.isEmpty(), qPrintable(dark.join(QLatin1String(", "))));
    }

    // No dark-haired child is drawn grey- or white-haired, and few young people: the strands of
    // their dark hair read grey (a shine, the wall through it) and were drawn grey on 1 of the 14
    // labelled dark-haired children and 3 of the 47 young people before the age was asked
    // (in-sample: the rule was fitted on these faces). Drawn grey here is what a viewer takes for grey: lighter than L*
    // 50 and of little colour (a dark taupe is dark hair).
    void youngDarkHeadsAreNotDrawnGrey()
    {
        TOONFACE_SAMPLED_FACES(sampled);
        int children = 0, young = 0, greyChildren = 0, greyYoung = 0;
        QStringList grey;
        for (const testing::SampledFace &face : sampled.faces) {
            const testing::LabelledFace &row = face.row;
            const QString age = row["age_group"], hair = row["hair_colour"];
            if ((age != QLatin1String("child") && age != QLatin1String("young"))
                || (hair != QLatin1String("black") && hair != QLatin1String("brown") && hair != QLatin1String("red")))
                continue;
            const Style &style = face.style;
            const LabColour drawn = labOf(style.components.value(QStringLiteral("hair")).fill);
            const bool drawnGrey = !style.appearance.bald && !style.appearance.hat && drawn.l >= 50.0
                && std::hypot(drawn.a, drawn.b) < 15.0;
            const bool child = age == QLatin1String("child");
            (child ? children : young)++;
            (child ? greyChildren : greyYoung) += drawnGrey;
            if (drawnGrey)
                grey << row["file"];
        }
        qInfo("drawn grey: %d of %d dark-haired children, %d of %d young (%s)", greyChildren, children, greyYoung,
            young, qPrintable(grey.join(QLatin1String(", "))));
        QCOMPARE(greyChildren, 0);
        QVERIFY2(greyYoung * 20 <= young, qPrintable(grey.join(QLatin1String(", "))));
    }
};

TOONFACE_TEST_MAIN(TestHairColour)
#include "tst_haircolour.moc"
