#include "anim/timeline.h"
#include "io/lipsyncformats.h"
#include "testmain.h"

#include <QFile>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace toonface;

Q_DECLARE_METATYPE(toonface::LipSyncFormat)
Q_DECLARE_METATYPE(toonface::LipSyncTrack)

namespace {

MouthCue cue(double start, double end, MouthShape shape)
{
    return {start, end, shape};
}

// Every shape once, back to back, at times off the 25 fps frame grid.
LipSyncTrack allShapesTrack()
{
    LipSyncTrack t;
    double time = 0.013;
    for (MouthShape s : kAllMouthShapes) {
        const double length = 0.09 + 0.031 * int(s);
        t.cues.append(cue(time, time + length, s));
        time += length;
    }
    t.duration = time;
    return t;
}

// Silence at the start, between phrases, and after the last cue (duration beyond it).
LipSyncTrack pausesTrack()
{
    LipSyncTrack t;
    t.cues = {cue(0.42, 0.61, MouthShape::A), cue(0.61, 0.77, MouthShape::U), cue(1.53, 1.71, MouthShape::O),
        cue(1.71, 1.79, MouthShape::N), cue(1.79, 2.2, MouthShape::M), cue(3.0, 3.33, MouthShape::F)};
    t.soundFile = QStringLiteral("voice.wav");
    t.duration = 4.5;
    return t;
}

// The shape a default mapping gives back for `shape` (the tables' documented non-bijective rows).
MouthShape backThrough(LipSyncFormat format, MouthShape shape)
{
    const bool rhubarb = format == LipSyncFormat::RhubarbTsv || format == LipSyncFormat::RhubarbJson;
    if (rhubarb && shape == MouthShape::H)
        return MouthShape::I;
    if (!rhubarb && shape == MouthShape::E)
        return MouthShape::I;
    return shape;
}

// How far a time may move through a format: JSON is exact, TSV keeps milliseconds, the
// frame-based formats round to the nearest frame.
double tolerance(LipSyncFormat format, double fps)
{
    switch (format) {
    case LipSyncFormat::RhubarbJson: return 1e-12;
    case LipSyncFormat::RhubarbTsv: return 0.0005 + 1e-9;
    case LipSyncFormat::Papagayo:
    case LipSyncFormat::MohoSwitch: return 0.5 / fps + 1e-9;
    }
    return 0;
}

void compareCues(const QVector<MouthCue> &got, const QVector<MouthCue> &want, double tol,
    const std::function<MouthShape(MouthShape)> &expectShape)
{
    QCOMPARE(got.size(), want.size());
    for (qsizetype i = 0; i < want.size(); ++i) {
        QVERIFY2(std::abs(got[i].start - want[i].start) <= tol,
            qPrintable(QStringLiteral("cue %1 start %2, expected %3").arg(i).arg(got[i].start).arg(want[i].start)));
        QVERIFY2(std::abs(got[i].end - want[i].end) <= tol,
            qPrintable(QStringLiteral("cue %1 end %2, expected %3").arg(i).arg(got[i].end).arg(want[i].end)));
        QCOMPARE(mouthShapeName(got[i].shape), mouthShapeName(expectShape(want[i].shape)));
    }
}

} // namespace

class TestLipSyncFormats : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void mappingTables_data();
    void mappingTables();
    void mappingBijectivePart_data();
    void mappingBijectivePart();
    void mappingCase();
    void mappingOverride();

    void roundTrip_data();
    void roundTrip();
    void roundTripThroughTimeline_data();
    void roundTripThroughTimeline();

    void writesRhubarbTsv();
    void writesMohoSwitch();
    void writesPapagayo();
    void readsRhubarbOutput();
    void readsPapagayoFile();
    void readsToonfaceJson();
    void readsPapagayoMohoExport();
    void acceptsCrLfAndBom();
    void openLastCueLastsOneFrame();

    void malformed_data();
    void malformed();

    void saveAndLoad();
    void loadErrorsNameTheFile();
};

void TestLipSyncFormats::mappingTables_data()
{
    QTest::addColumn<bool>("rhubarb");
    QTest::addColumn<QString>("shape");
    QTest::addColumn<QString>("exported");
    QTest::addColumn<QString>("importedBack");

    // The tables documented in lipsyncformats.h.
    const char *rhubarb[][3] = {{"m", "A", "m"}, {"f", "G", "f"}, {"h", "B", "i"}, {"a", "D", "a"}, {"i", "B", "i"},
        {"u", "F", "u"}, {"e", "C", "e"}, {"o", "E", "o"}, {"n", "H", "n"}};
    for (const auto &row : rhubarb)
        QTest::addRow("rhubarb %s", row[0])
            << true << QString::fromLatin1(row[0]) << QString::fromLatin1(row[1]) << QString::fromLatin1(row[2]);
    const char *blair[][3] = {{"m", "MBP", "m"}, {"f", "FV", "f"}, {"h", "etc", "h"}, {"a", "AI", "a"}, {"i", "E", "i"},
        {"u", "U", "u"}, {"e", "E", "i"}, {"o", "O", "o"}, {"n", "L", "n"}};
    for (const auto &row : blair)
        QTest::addRow("preston blair %s", row[0])
            << false << QString::fromLatin1(row[0]) << QString::fromLatin1(row[1]) << QString::fromLatin1(row[2]);
}

void TestLipSyncFormats::mappingTables()
{
    QFETCH(bool, rhubarb);
    QFETCH(QString, shape);
    QFETCH(QString, exported);
    QFETCH(QString, importedBack);
    const ShapeMapping m = rhubarb ? ShapeMapping::rhubarb() : ShapeMapping::prestonBlair();
    const MouthShape s = *mouthShapeFromName(shape);
    QCOMPARE(m.exportName(s), exported);
    MouthShape back = MouthShape::M;
    QCOMPARE(m.importName(exported, &back), ShapeMapping::Match::Shape);
    QCOMPARE(mouthShapeName(back), importedBack);
}

void TestLipSyncFormats::mappingBijectivePart_data()
{
    QTest::addColumn<bool>("rhubarb");
    QTest::addColumn<QStringList>("shapes");
    QTest::addColumn<QStringList>("names");
    QTest::newRow("rhubarb") << true
                             << QStringList {u"m"_qs, u"f"_qs, u"a"_qs, u"i"_qs, u"u"_qs, u"e"_qs, u"o"_qs, u"n"_qs}
                             << QStringList {u"A"_qs, u"G"_qs, u"D"_qs, u"B"_qs, u"F"_qs, u"C"_qs, u"E"_qs, u"H"_qs};
    QTest::newRow("preston blair") << false
                                   << QStringList {u"m"_qs, u"f"_qs, u"h"_qs, u"a"_qs, u"i"_qs, u"u"_qs, u"o"_qs,
                                          u"n"_qs}
                                   << QStringList {
                                          u"MBP"_qs, u"FV"_qs, u"etc"_qs, u"AI"_qs, u"E"_qs, u"U"_qs, u"O"_qs, u"L"_qs};
}

// Where a table claims a bijection, both compositions are the identity and no two shapes
// share a name.
void TestLipSyncFormats::mappingBijectivePart()
{
    QFETCH(bool, rhubarb);
    QFETCH(QStringList, shapes);
    QFETCH(QStringList, names);
    const ShapeMapping m = rhubarb ? ShapeMapping::rhubarb() : ShapeMapping::prestonBlair();
    QSet<QString> seen;
    for (const QString &name : shapes) {
        const MouthShape s = *mouthShapeFromName(name);
        const QString ext = m.exportName(s);
        QVERIFY2(!seen.contains(ext), qPrintable(ext));
        seen.insert(ext);
        MouthShape back = MouthShape::M;
        QCOMPARE(m.importName(ext, &back), ShapeMapping::Match::Shape);
        QCOMPARE(mouthShapeName(back), name);
    }
    QCOMPARE(seen, QSet<QString>(names.cbegin(), names.cend()));
    for (const QString &ext : names) {
        MouthShape s = MouthShape::M;
        QCOMPARE(m.importName(ext, &s), ShapeMapping::Match::Shape);
        QCOMPARE(m.exportName(s), ext);
    }
    MouthShape unused = MouthShape::M;
    QCOMPARE(m.importName(m.restName(), &unused), ShapeMapping::Match::Rest);
    QCOMPARE(m.restName(), rhubarb ? u"X"_qs : u"rest"_qs);
    // Every shape is written as a name that reads back.
    for (MouthShape s : kAllMouthShapes)
        QCOMPARE(m.importName(m.exportName(s), &unused), ShapeMapping::Match::Shape);
}

void TestLipSyncFormats::mappingCase()
{
    const ShapeMapping r = ShapeMapping::rhubarb();
    MouthShape s = MouthShape::N;
    // Rhubarb's A (closed) and Toonface's a (open) differ only in case.
    QCOMPARE(r.importName(u"A"_qs, &s), ShapeMapping::Match::Shape);
    QCOMPARE(s, MouthShape::M);
    QCOMPARE(r.importName(u"a"_qs, &s), ShapeMapping::Match::Shape);
    QCOMPARE(s, MouthShape::A);
    QCOMPARE(r.importName(u"x"_qs, &s), ShapeMapping::Match::Unknown);
    QCOMPARE(r.importName(u"Q"_qs, &s), ShapeMapping::Match::Unknown);

    const ShapeMapping p = ShapeMapping::prestonBlair();
    QCOMPARE(p.importName(u"mbp"_qs, &s), ShapeMapping::Match::Shape);
    QCOMPARE(s, MouthShape::M);
    QCOMPARE(p.importName(u"ETC"_qs, &s), ShapeMapping::Match::Shape);
    QCOMPARE(s, MouthShape::H);
    QCOMPARE(p.importName(u"wq"_qs, &s), ShapeMapping::Match::Shape);
    QCOMPARE(s, MouthShape::U);
    QCOMPARE(p.importName(u"REST"_qs, &s), ShapeMapping::Match::Rest);
    QCOMPARE(p.importName(u"X"_qs, &s), ShapeMapping::Match::Unknown);
}

// An override gives the shapes the defaults merge their own names, and the round trip
// becomes exact for all nine.
void TestLipSyncFormats::mappingOverride()
{
    ShapeMapping m = ShapeMapping::rhubarb();
    m.setExportName(MouthShape::H, u"K"_qs);
    m.setImportShape(u"K"_qs, MouthShape::H);
    m.setRestName(u"Z"_qs);
    LipSyncOptions options;
    options.mapping = m;
    const LipSyncTrack track = allShapesTrack();
    const QByteArray tsv = writeLipSync(track, LipSyncFormat::RhubarbTsv, options);
    QVERIFY(tsv.contains("\tK\n"));
    QVERIFY(tsv.endsWith("\tZ\n"));
    QString error;
    const auto back = parseLipSync(tsv, LipSyncFormat::RhubarbTsv, u"o.tsv"_qs, options, &error);
    QVERIFY2(back, qPrintable(error));
    compareCues(back->cues, track.cues, tolerance(LipSyncFormat::RhubarbTsv, 25), [](MouthShape s) { return s; });

    ShapeMapping p = ShapeMapping::prestonBlair();
    p.setImportShape(u"WQ"_qs, MouthShape::O);
    p.setImportShape(u"shh"_qs, std::nullopt);
    MouthShape s = MouthShape::M;
    QCOMPARE(p.importName(u"wq"_qs, &s), ShapeMapping::Match::Shape);
    QCOMPARE(s, MouthShape::O);
    QCOMPARE(p.importName(u"SHH"_qs, &s), ShapeMapping::Match::Rest);
}

void TestLipSyncFormats::roundTrip_data()
{
    QTest::addColumn<LipSyncFormat>("format");
    QTest::addColumn<double>("fps");
    QTest::addColumn<LipSyncTrack>("track");

    const std::array<std::pair<LipSyncFormat, const char *>, 4> formats = {{{LipSyncFormat::RhubarbTsv, "tsv"},
        {LipSyncFormat::RhubarbJson, "json"}, {LipSyncFormat::Papagayo, "pgo"}, {LipSyncFormat::MohoSwitch, "dat"}}};
    for (const auto &[format, name] : formats) {
        QTest::addRow("%s all shapes 25", name) << format << 25.0 << allShapesTrack();
        QTest::addRow("%s all shapes 24", name) << format << 24.0 << allShapesTrack();
        QTest::addRow("%s pauses 30", name) << format << 30.0 << pausesTrack();
        QTest::addRow("%s empty", name) << format << 25.0 << LipSyncTrack {};
    }
}

void TestLipSyncFormats::roundTrip()
{
    QFETCH(LipSyncFormat, format);
    QFETCH(double, fps);
    QFETCH(LipSyncTrack, track);
    LipSyncOptions options;
    options.fps = fps;
    const QByteArray data = writeLipSync(track, format, options);
    QString error;
    const auto back = parseLipSync(data, format, u"roundtrip"_qs, options, &error);
    QVERIFY2(back, qPrintable(error));
    const double tol = tolerance(format, fps);
    compareCues(back->cues, track.cues, tol, [format](MouthShape s) { return backThrough(format, s); });
    if (format == LipSyncFormat::RhubarbJson || format == LipSyncFormat::Papagayo) {
        QCOMPARE(back->soundFile, track.soundFile);
        const double lastEnd = track.cues.isEmpty() ? 0.0 : track.cues.last().end;
        const double duration = std::max(track.duration, lastEnd);
        // Papagayo rounds the duration up to whole frames.
        QVERIFY2(std::abs(back->duration - duration) <= (format == LipSyncFormat::Papagayo ? 1.0 / fps : 1e-12),
            qPrintable(QString::number(back->duration)));
    }
}

void TestLipSyncFormats::roundTripThroughTimeline_data()
{
    QTest::addColumn<LipSyncFormat>("format");
    QTest::newRow("tsv") << LipSyncFormat::RhubarbTsv;
    QTest::newRow("json") << LipSyncFormat::RhubarbJson;
    QTest::newRow("pgo") << LipSyncFormat::Papagayo;
    QTest::newRow("dat") << LipSyncFormat::MohoSwitch;
}

// The mouth track of a timeline, exported and imported onto another timeline, gives the same
// keys (shapes the mapping merges aside).
void TestLipSyncFormats::roundTripThroughTimeline()
{
    QFETCH(LipSyncFormat, format);
    Timeline original;
    original.addMouthCues(pausesTrack().cues);
    LipSyncTrack track;
    track.cues = original.mouthCues();
    const QByteArray data = writeLipSync(track, format);
    QString error;
    const auto back = parseLipSync(data, format, u"timeline"_qs, {}, &error);
    QVERIFY2(back, qPrintable(error));
    Timeline imported;
    imported.addMouthCues(back->cues);
    const QVector<MouthKey> want = original.mouthKeys();
    const QVector<MouthKey> got = imported.mouthKeys();
    QCOMPARE(got.size(), want.size());
    const double tol = tolerance(format, 25);
    for (qsizetype i = 0; i < want.size(); ++i) {
        QVERIFY(std::abs(got[i].time - want[i].time) <= tol);
        QCOMPARE(got[i].shape, backThrough(format, want[i].shape));
        QVERIFY(got[i].duration && want[i].duration);
        QVERIFY(std::abs(*got[i].duration - *want[i].duration) <= 2 * tol);
    }
}

void TestLipSyncFormats::writesRhubarbTsv()
{
    LipSyncTrack t;
    t.cues = {cue(0.1, 0.3, MouthShape::A), cue(0.3, 0.5, MouthShape::M), cue(0.8, 1.0, MouthShape::O)};
    QCOMPARE(writeLipSync(t, LipSyncFormat::RhubarbTsv),
        QByteArray("0.000\tX\n0.100\tD\n0.300\tA\n0.500\tX\n0.800\tE\n1.000\tX\n"));
}

void TestLipSyncFormats::writesMohoSwitch()
{
    LipSyncTrack t;
    t.cues = {cue(0.2, 0.4, MouthShape::A), cue(0.4, 0.6, MouthShape::F), cue(1.0, 1.2, MouthShape::H)};
    LipSyncOptions o;
    o.fps = 25;
    // Frames 5-9 AI, 10-14 FV, 15-24 rest, 25-29 etc; Moho numbers frames from 1.
    QCOMPARE(writeLipSync(t, LipSyncFormat::MohoSwitch, o),
        QByteArray("MohoSwitch1\n1 rest\n6 AI\n11 FV\n16 rest\n26 etc\n31 rest\n"));
}

void TestLipSyncFormats::writesPapagayo()
{
    LipSyncTrack t;
    t.cues = {cue(0.2, 0.4, MouthShape::A), cue(0.4, 0.6, MouthShape::U), cue(1.0, 1.2, MouthShape::M)};
    t.soundFile = u"hello.wav"_qs;
    t.duration = 2.0;
    LipSyncOptions o;
    o.fps = 25;
    const QByteArray want = "lipsync version 1\n"
                            "hello.wav\n"
                            "25\n"
                            "50\n"
                            "1\n"
                            "\tVoice 1\n"
                            "\ta u|m\n"
                            "\t2\n"
                            "\t\ta u\n\t\t5\n\t\t14\n\t\t2\n"
                            "\t\t\ta 5 9 1\n\t\t\t\t5 AI\n"
                            "\t\t\tu 10 14 1\n\t\t\t\t10 U\n"
                            "\t\tm\n\t\t25\n\t\t29\n\t\t1\n"
                            "\t\t\tm 25 29 1\n\t\t\t\t25 MBP\n";
    QCOMPARE(writeLipSync(t, LipSyncFormat::Papagayo, o), want);
}

// Rhubarb's own output: X (idle) at the start, between words and at the end.
void TestLipSyncFormats::readsRhubarbOutput()
{
    const QByteArray tsv = "0.00\tX\n0.05\tD\n0.27\tC\n0.31\tB\n0.43\tX\n0.80\tG\n0.95\tX\n";
    QString error;
    const auto t = parseLipSync(tsv, LipSyncFormat::RhubarbTsv, u"r.tsv"_qs, {}, &error);
    QVERIFY2(t, qPrintable(error));
    const QVector<MouthCue> want = {cue(0.05, 0.27, MouthShape::A), cue(0.27, 0.31, MouthShape::E),
        cue(0.31, 0.43, MouthShape::I), cue(0.80, 0.95, MouthShape::F)};
    compareCues(t->cues, want, 1e-12, [](MouthShape s) { return s; });

    const QByteArray json = R"({
  "metadata": { "soundFile": "C:\\voice.wav", "duration": 1.20 },
  "mouthCues": [
    { "start": 0.00, "end": 0.05, "value": "X" },
    { "start": 0.05, "end": 0.27, "value": "D" },
    { "start": 0.27, "end": 0.31, "value": "H" },
    { "start": 0.31, "end": 1.20, "value": "X" }
  ]
})";
    const auto j = parseLipSync(json, LipSyncFormat::RhubarbJson, u"r.json"_qs, {}, &error);
    QVERIFY2(j, qPrintable(error));
    QCOMPARE(j->soundFile, u"C:\\voice.wav"_qs);
    QCOMPARE(j->duration, 1.2);
    compareCues(j->cues, {cue(0.05, 0.27, MouthShape::A), cue(0.27, 0.31, MouthShape::N)}, 1e-12,
        [](MouthShape s) { return s; });
}

// A file as Papagayo saves it: two phrases, words of several phonemes, a rest inside a word.
void TestLipSyncFormats::readsPapagayoFile()
{
    const QByteArray pgo = "lipsync version 1\n"
                           "sounds/hello.wav\n"
                           "24\n"
                           "72\n"
                           "1\n"
                           "\tVoice 1\n"
                           "\tHello world|Fine\n"
                           "\t2\n"
                           "\t\tHello world\n\t\t2\n\t\t20\n\t\t2\n"
                           "\t\t\tHello 2 9 4\n"
                           "\t\t\t\t2 etc\n\t\t\t\t4 E\n\t\t\t\t6 L\n\t\t\t\t8 O\n"
                           "\t\t\tworld 12 20 4\n"
                           "\t\t\t\t12 WQ\n\t\t\t\t15 rest\n\t\t\t\t17 L\n\t\t\t\t19 etc\n"
                           "\t\tFine\n\t\t40\n\t\t47\n\t\t1\n"
                           "\t\t\tFine 40 47 3\n"
                           "\t\t\t\t40 FV\n\t\t\t\t43 AI\n\t\t\t\t46 etc\n";
    QString error;
    const auto t = parseLipSync(pgo, LipSyncFormat::Papagayo, u"p.pgo"_qs, {}, &error);
    QVERIFY2(t, qPrintable(error));
    QCOMPARE(t->soundFile, u"sounds/hello.wav"_qs);
    QCOMPARE(t->duration, 3.0);
    const double f = 1.0 / 24;
    const QVector<MouthCue> want = {cue(2 * f, 4 * f, MouthShape::H), cue(4 * f, 6 * f, MouthShape::I),
        cue(6 * f, 8 * f, MouthShape::N), cue(8 * f, 10 * f, MouthShape::O), cue(12 * f, 15 * f, MouthShape::U),
        cue(17 * f, 19 * f, MouthShape::N), cue(19 * f, 21 * f, MouthShape::H), cue(40 * f, 43 * f, MouthShape::F),
        cue(43 * f, 46 * f, MouthShape::A), cue(46 * f, 48 * f, MouthShape::H)};
    compareCues(t->cues, want, 1e-12, [](MouthShape s) { return s; });
}

// Toonface's own lip-sync JSON names the shape `shape` and uses its own shape names.
void TestLipSyncFormats::readsToonfaceJson()
{
    const QByteArray json = R"({"format": "toonface.lipsync/1", "syllables": [],
        "mouthCues": [{"start": 0.1, "end": 0.2, "shape": "a"}, {"start": 0.2, "end": 0.35, "shape": "n"}]})";
    QString error;
    const auto t = parseLipSync(json, LipSyncFormat::RhubarbJson, u"t.json"_qs, {}, &error);
    QVERIFY2(t, qPrintable(error));
    compareCues(
        t->cues, {cue(0.1, 0.2, MouthShape::A), cue(0.2, 0.35, MouthShape::N)}, 1e-12, [](MouthShape s) { return s; });
}

// Papagayo's Moho export repeats "rest" on the frame before a pause ends, and leaves the last
// phoneme open.
void TestLipSyncFormats::readsPapagayoMohoExport()
{
    LipSyncOptions o;
    o.fps = 24;
    QString error;
    const auto m = parseLipSync("MohoSwitch1\n3 etc\n5 E\n9 rest\n14 rest\n15 MBP\n17 O\n", LipSyncFormat::MohoSwitch,
        u"papagayo.dat"_qs, o, &error);
    QVERIFY2(m, qPrintable(error));
    const double f = 1.0 / 24;
    compareCues(m->cues,
        {cue(2 * f, 4 * f, MouthShape::H), cue(4 * f, 8 * f, MouthShape::I), cue(14 * f, 16 * f, MouthShape::M),
            cue(16 * f, 17 * f, MouthShape::O)},
        1e-12, [](MouthShape s) { return s; });
}

void TestLipSyncFormats::acceptsCrLfAndBom()
{
    QString error;
    const auto t = parseLipSync("\xEF\xBB\xBF"
                                "0.00\tX\r\n0.10\tD\r\n0.20\tX\r\n",
        LipSyncFormat::RhubarbTsv, u"w.tsv"_qs, {}, &error);
    QVERIFY2(t, qPrintable(error));
    compareCues(t->cues, {cue(0.1, 0.2, MouthShape::A)}, 1e-12, [](MouthShape s) { return s; });
    const auto m = parseLipSync(
        "MohoSwitch1\r\n1 rest\r\n3 AI\r\n5 rest\r\n", LipSyncFormat::MohoSwitch, u"w.dat"_qs, {}, &error);
    QVERIFY2(m, qPrintable(error));
    compareCues(m->cues, {cue(2 / 25.0, 4 / 25.0, MouthShape::A)}, 1e-12, [](MouthShape s) { return s; });
}

// Papagayo's Moho export ends on the last phoneme, with no rest after it.
void TestLipSyncFormats::openLastCueLastsOneFrame()
{
    LipSyncOptions o;
    o.fps = 24;
    QString error;
    const auto m = parseLipSync("MohoSwitch1\n1 etc\n5 O\n", LipSyncFormat::MohoSwitch, u"o.dat"_qs, o, &error);
    QVERIFY2(m, qPrintable(error));
    compareCues(m->cues, {cue(0, 4 / 24.0, MouthShape::H), cue(4 / 24.0, 5 / 24.0, MouthShape::O)}, 1e-12,
        [](MouthShape s) { return s; });
    const auto t = parseLipSync("0.5\tD\n", LipSyncFormat::RhubarbTsv, u"o.tsv"_qs, o, &error);
    QVERIFY2(t, qPrintable(error));
    compareCues(t->cues, {cue(0.5, 0.5 + 1 / 24.0, MouthShape::A)}, 1e-12, [](MouthShape s) { return s; });
}

void TestLipSyncFormats::malformed_data()
{
    QTest::addColumn<LipSyncFormat>("format");
    QTest::addColumn<QByteArray>("data");
    QTest::addColumn<QString>("expected"); // the error after "bad.x: "

    const auto tsv = LipSyncFormat::RhubarbTsv;
    QTest::newRow("tsv one field") << tsv << QByteArray("0.0\tX\n0.5\n") << u"line 2: expected 'start<TAB>shape'"_qs;
    QTest::newRow("tsv three fields") << tsv << QByteArray("0.0\tX\n\n0.5\tA\tB\n") << u"line 3: expected"_qs;
    QTest::newRow("tsv time") << tsv << QByteArray("abc\tA\n") << u"line 1: expected a start time"_qs;
    QTest::newRow("tsv negative") << tsv << QByteArray("0\tX\n-1\tA\n") << u"line 2: expected a start time"_qs;
    QTest::newRow("tsv nan") << tsv << QByteArray("nan\tA\n") << u"line 1: expected a start time"_qs;
    QTest::newRow("tsv backwards") << tsv << QByteArray("0.5\tA\n0.2\tB\n") << u"line 2: time 0.2 is before"_qs;
    QTest::newRow("tsv shape") << tsv << QByteArray("0\tX\n0.1\tD\n0.2\tQ\n") << u"line 3: unknown mouth shape 'Q'"_qs;

    const auto json = LipSyncFormat::RhubarbJson;
    QTest::newRow("json syntax") << json << QByteArray("{\n  \"mouthCues\": [\n    {\"start\": 0,, }\n  ]\n}")
                                 << u"line 3: not valid JSON"_qs;
    QTest::newRow("json no cues") << json << QByteArray("{\"metadata\": {}}") << u"mouthCues: expected"_qs;
    QTest::newRow("json value") << json << QByteArray(R"({"mouthCues": [{"start": 0, "end": 1, "value": "A"},
                                                                {"start": 1, "end": 2, "value": "Q"}]})")
                                << u"mouthCues[1].value: unknown mouth shape 'Q'"_qs;
    QTest::newRow("json end") << json << QByteArray(R"({"mouthCues": [{"start": 2, "end": 1, "value": "A"}]})")
                              << u"mouthCues[0].end: ends (1) before it starts (2)"_qs;
    QTest::newRow("json overlap") << json << QByteArray(R"({"mouthCues": [{"start": 0, "end": 1, "value": "A"},
                                                                  {"start": 0.5, "end": 2, "value": "B"}]})")
                                  << u"mouthCues[1].start: starts (0.5) before the previous cue ends (1)"_qs;
    QTest::newRow("json start type") << json << QByteArray(R"({"mouthCues": [{"start": "0", "end": 1, "value": "A"}]})")
                                     << u"mouthCues[0].start: expected a number"_qs;

    const auto pgo = LipSyncFormat::Papagayo;
    const QByteArray head = "lipsync version 1\nx.wav\n24\n48\n1\n\tVoice 1\n\thi\n\t1\n\t\thi\n\t\t0\n\t\t10\n\t\t1\n";
    QTest::newRow("pgo header") << pgo << QByteArray("lipsync version 2\n") << u"line 1: expected the header"_qs;
    QTest::newRow("pgo empty") << pgo << QByteArray() << u"line 1: unexpected end of file"_qs;
    QTest::newRow("pgo fps") << pgo << QByteArray("lipsync version 1\nx.wav\nfast\n")
                             << u"line 3: expected the frame rate"_qs;
    QTest::newRow("pgo zero fps") << pgo << QByteArray("lipsync version 1\nx.wav\n0\n")
                                  << u"line 3: expected the frame rate"_qs;
    QTest::newRow("pgo truncated") << pgo << QByteArray(head + "\t\t\thi 0 10 2\n\t\t\t\t0 etc\n")
                                   << u"line 15: unexpected end of file, expected phoneme 2 of 'hi'"_qs;
    QTest::newRow("pgo word") << pgo << QByteArray(head + "\t\t\thi 0 10\n")
                              << u"line 13: expected word 1 of phrase 1"_qs;
    QTest::newRow("pgo word frames") << pgo << QByteArray(head + "\t\t\thi 8 3 1\n\t\t\t\t8 AI\n")
                                     << u"line 13: word 'hi' ends (frame 3) before it starts (frame 8)"_qs;
    QTest::newRow("pgo phoneme") << pgo << QByteArray(head + "\t\t\thi 0 10 1\n\t\t\t\tAI\n")
                                 << u"line 14: expected phoneme 1 of 'hi'"_qs;
    QTest::newRow("pgo phoneme name") << pgo << QByteArray(head + "\t\t\thi 0 10 2\n\t\t\t\t0 etc\n\t\t\t\t4 ZZ\n")
                                      << u"line 15: unknown mouth shape 'ZZ'"_qs;
    QTest::newRow("pgo phoneme order") << pgo << QByteArray(head + "\t\t\thi 0 10 2\n\t\t\t\t5 etc\n\t\t\t\t4 AI\n")
                                       << u"line 15: phoneme frame 4 is before the previous phoneme's 5"_qs;

    const auto dat = LipSyncFormat::MohoSwitch;
    QTest::newRow("dat header") << dat << QByteArray("Moho\n1 rest\n")
                                << u"line 1: expected the header 'MohoSwitch1'"_qs;
    QTest::newRow("dat fields") << dat << QByteArray("MohoSwitch1\n1 rest\n5\n")
                                << u"line 3: expected 'frame shape'"_qs;
    QTest::newRow("dat frame") << dat << QByteArray("MohoSwitch1\n1.5 rest\n") << u"line 2: expected a frame number"_qs;
    QTest::newRow("dat order") << dat << QByteArray("MohoSwitch1\n1 rest\n9 AI\n4 O\n")
                               << u"line 4: frame 4 is before the previous line's frame 9"_qs;
    QTest::newRow("dat shape") << dat << QByteArray("MohoSwitch1\n1 rest\n3 D\n")
                               << u"line 3: unknown mouth shape 'D'"_qs;
}

void TestLipSyncFormats::malformed()
{
    QFETCH(LipSyncFormat, format);
    QFETCH(QByteArray, data);
    QFETCH(QString, expected);
    QString error;
    const auto t = parseLipSync(data, format, u"bad.x"_qs, {}, &error);
    QVERIFY(!t);
    QVERIFY2(error.startsWith(u"bad.x: "_qs + expected), qPrintable(error));
}

void TestLipSyncFormats::saveAndLoad()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const LipSyncTrack track = pausesTrack();
    for (const char *ext : {"tsv", "json", "pgo", "dat"}) {
        const QString path = dir.filePath(u"track."_qs + QString::fromLatin1(ext));
        const LipSyncFormat format = *lipSyncFormatForPath(path);
        QString error;
        QVERIFY2(saveLipSync(track, path, format, {}, &error), qPrintable(error));
        const auto back = loadLipSync(path, std::nullopt, {}, &error);
        QVERIFY2(back, qPrintable(error));
        compareCues(
            back->cues, track.cues, tolerance(format, 25), [format](MouthShape s) { return backThrough(format, s); });
    }
    QCOMPARE(lipSyncFormatForPath(u"A.PGO"_qs), LipSyncFormat::Papagayo);
    QVERIFY(!lipSyncFormatForPath(u"a.txt"_qs));
}

void TestLipSyncFormats::loadErrorsNameTheFile()
{
    QTemporaryDir dir;
    QString error;
    const QString missing = dir.filePath(u"missing.tsv"_qs);
    QVERIFY(!loadLipSync(missing, std::nullopt, {}, &error));
    QVERIFY2(error.startsWith(missing + u": cannot read"_qs), qPrintable(error));

    const QString txt = dir.filePath(u"cues.txt"_qs);
    QVERIFY(!loadLipSync(txt, std::nullopt, {}, &error));
    QVERIFY2(error.startsWith(txt + u": unknown lip-sync format"_qs), qPrintable(error));

    const QString bad = dir.filePath(u"bad.dat"_qs);
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("MohoSwitch1\n1 rest\n2 Q\n");
    f.close();
    QVERIFY(!loadLipSync(bad, std::nullopt, {}, &error));
    QVERIFY2(error.startsWith(bad + u": line 3: unknown mouth shape 'Q'"_qs), qPrintable(error));

    const QString unwritable = dir.filePath(u"no/such/folder/out.tsv"_qs);
    QVERIFY(!saveLipSync(pausesTrack(), unwritable, LipSyncFormat::RhubarbTsv, {}, &error));
    QVERIFY2(error.startsWith(unwritable + u": not saved"_qs), qPrintable(error));
}

TOONFACE_TEST_GUILESS_MAIN(TestLipSyncFormats)
#include "tst_lipsyncformats.moc"
