#include "detect/detector.h"
#include "detect/landmarkpredictor.h"
#include "madeupmodel.h"
#include "testmain.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <cstring>
#include <random>
#include <sstream>

using namespace toonface;
using toonface::testing::madeUpModel;
using toonface::testing::writeModel;

namespace {

bool sameBytes(const LandmarkPredictor &a, const LandmarkPredictor &b)
{
    return a.flat().size() == b.flat().size() && std::memcmp(a.flat().data(), b.flat().data(), a.flat().size()) == 0;
}

QByteArray contentsOf(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

void writeBytes(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    QCOMPARE(f.write(bytes), bytes.size());
}

// The model in dlib's old format, which wrote each float as text followed by a space (the
// integers as now): its parts taken from dlib's own serialisation of it.
QByteArray inOldTextFormat(const dlib::shape_predictor &model)
{
    std::ostringstream binary;
    dlib::serialize(model, binary);
    std::istringstream in(binary.str());
    int version = 0;
    dlib::matrix<float, 0, 1> initial;
    std::vector<std::vector<dlib::impl::regression_tree>> forests;
    std::vector<std::vector<unsigned long>> anchors;
    std::vector<std::vector<dlib::vector<float, 2>>> deltas;
    dlib::deserialize(version, in);
    dlib::deserialize(initial, in);
    dlib::deserialize(forests, in);
    dlib::deserialize(anchors, in);
    dlib::deserialize(deltas, in);

    std::ostringstream out;
    auto real = [&](float v) {
        char text[64];
        std::snprintf(text, sizeof text, "%.9g ", double(v));
        out << text;
    };
    auto column = [&](const dlib::matrix<float, 0, 1> &m) {
        dlib::serialize(-m.nr(), out);
        dlib::serialize(-m.nc(), out);
        for (long i = 0; i < m.size(); ++i)
            real(m(i));
    };
    auto count = [&](size_t n) { dlib::serialize(static_cast<unsigned long>(n), out); };
    dlib::serialize(version, out);
    column(initial);
    count(forests.size());
    for (const auto &forest : forests) {
        count(forest.size());
        for (const auto &tree : forest) {
            count(tree.splits.size());
            for (const auto &s : tree.splits) {
                dlib::serialize(s.idx1, out);
                dlib::serialize(s.idx2, out);
                real(s.thresh);
            }
            count(tree.leaf_values.size());
            for (const auto &leaf : tree.leaf_values)
                column(leaf);
        }
    }
    dlib::serialize(anchors, out);
    count(deltas.size());
    for (const auto &cascade : deltas) {
        count(cascade.size());
        for (const auto &d : cascade) {
            real(d.x());
            real(d.y());
        }
    }
    return QByteArray::fromStdString(out.str());
}

} // namespace

// The project's own reader of dlib's model file (shapemodelfile.h), held to dlib's reader:
// the same flat arrays, byte for byte; damaged, cut or foreign files refused by name.
class TestShapeModelFile : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init() { QVERIFY(m_dir.isValid()); }

    void madeUpModelsAsDlibReadsThem_data()
    {
        QTest::addColumn<unsigned>("seed");
        QTest::addColumn<int>("cascades");
        QTest::addColumn<int>("trees");
        QTest::addColumn<int>("depth");
        QTest::addColumn<bool>("special");
        QTest::newRow("small") << 1u << 3 << 40 << 3 << false;
        QTest::newRow("one stump cascade") << 2u << 1 << 1 << 0 << false;
        QTest::newRow("deep") << 3u << 2 << 20 << 6 << false;
        QTest::newRow("special values") << 4u << 4 << 30 << 4 << true;
    }

    void madeUpModelsAsDlibReadsThem()
    {
        QFETCH(unsigned, seed);
        QFETCH(int, cascades);
        QFETCH(int, trees);
        QFETCH(int, depth);
        QFETCH(bool, special);
        const QString path = m_dir.filePath(QStringLiteral("model-%1.dat").arg(seed));
        writeModel(path, madeUpModel(seed, cascades, trees, depth, 1, special));
        QString error;
        const auto ours = LandmarkPredictor::read(path, &error);
        QVERIFY2(ours, qPrintable(error));
        const auto dlibs = LandmarkPredictor::readThroughDlib(path, &error);
        QVERIFY2(dlibs, qPrintable(error));
        QVERIFY(sameBytes(*ours, *dlibs));
        QCOMPARE(ours->meanShape(), dlibs->meanShape());
    }

    // The model installed with dlib (100 MB): the same arrays as dlib's reader gives.
    void installedModelAsDlibReadsIt()
    {
        const QString path = landmarkModelPath();
        if (!QFile::exists(path))
            QSKIP("The landmark model is not installed (package libdlib-data).");
        QString error;
        const auto ours = LandmarkPredictor::read(path, &error);
        QVERIFY2(ours, qPrintable(error));
        const auto dlibs = LandmarkPredictor::readThroughDlib(path, &error);
        QVERIFY2(dlibs, qPrintable(error));
        QVERIFY(ours->flat().size() > 50'000'000);
        QVERIFY(sameBytes(*ours, *dlibs));
    }

    // A file in dlib's old text form is handed to dlib's reader, and gives the same model.
    void oldTextFormatReadThroughDlib()
    {
        const dlib::shape_predictor model = madeUpModel(5, 2, 10, 2);
        const QString binary = m_dir.filePath(QStringLiteral("binary.dat"));
        const QString text = m_dir.filePath(QStringLiteral("text.dat"));
        writeModel(binary, model);
        writeBytes(text, inOldTextFormat(model));
        QString error;
        const auto fromText = LandmarkPredictor::read(text, &error);
        QVERIFY2(fromText, qPrintable(error));
        const auto fromBinary = LandmarkPredictor::read(binary, &error);
        QVERIFY2(fromBinary, qPrintable(error));
        QVERIFY(sameBytes(*fromText, *fromBinary));
    }

    // Cut anywhere, the file is refused, and the message names it.
    void cutShortRefusedByName()
    {
        const QString whole = m_dir.filePath(QStringLiteral("whole.dat"));
        writeModel(whole, madeUpModel(6, 2, 12, 3));
        const QByteArray bytes = contentsOf(whole);
        QVERIFY(bytes.size() > 10000);
        const QString cut = m_dir.filePath(QStringLiteral("cut.dat"));
        std::vector<qsizetype> lengths;
        for (qsizetype n = 0; n < 300; ++n)
            lengths.push_back(n);
        for (qsizetype n = 300; n < bytes.size(); n += 97)
            lengths.push_back(n);
        lengths.push_back(bytes.size() - 1);
        for (const qsizetype n : lengths) {
            writeBytes(cut, bytes.left(n));
            QString error;
            QVERIFY2(!LandmarkPredictor::read(cut, &error), qPrintable(QString::number(n)));
            QVERIFY2(error.contains(QDir::toNativeSeparators(cut)), qPrintable(error));
            QVERIFY2(error.contains(QStringLiteral("could not be read")), qPrintable(error));
        }
    }

    // Bytes overwritten here and there: each damaged file is refused by name or read as some
    // model, never a crash or a read outside the file.
    void damagedBytesNeverCrash()
    {
        const QString whole = m_dir.filePath(QStringLiteral("whole.dat"));
        writeModel(whole, madeUpModel(7, 2, 12, 3));
        const QByteArray bytes = contentsOf(whole);
        const QString damaged = m_dir.filePath(QStringLiteral("damaged.dat"));
        std::mt19937 random(7);
        int refused = 0;
        for (int trial = 0; trial < 300; ++trial) {
            QByteArray copy = bytes;
            // Early bytes hold the counts and sizes: the most telling damage, tried most.
            const qsizetype at = trial < 100 ? qsizetype(random() % 2000) : qsizetype(random() % bytes.size());
            copy[at] = char(random() & 0xff);
            writeBytes(damaged, copy);
            QString error;
            if (!LandmarkPredictor::read(damaged, &error)) {
                ++refused;
                QVERIFY2(error.contains(QDir::toNativeSeparators(damaged)), qPrintable(error));
            }
        }
        QVERIFY(refused > 0);
    }

    void foreignFilesRefusedByName_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("expected");
        QTest::newRow("empty") << QByteArray() << QStringLiteral("could not be read");
        QTest::newRow("text") << QByteArray("shape_predictor_68_face_landmarks, but not really\n")
                              << QStringLiteral("could not be read");
        QTest::newRow("png") << QByteArray("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16) << QStringLiteral("could not be read");
        std::ostringstream version2;
        dlib::serialize(2, version2);
        QTest::newRow("another version") << QByteArray::fromStdString(version2.str())
                                         << QStringLiteral("unknown format version");
        std::ostringstream five;
        dlib::serialize(1, five);
        dlib::matrix<float, 0, 1> initial(10);
        initial = 0.5f;
        dlib::serialize(initial, five);
        QTest::newRow("five points") << QByteArray::fromStdString(five.str()) << QStringLiteral("gives 5 points");
    }

    void foreignFilesRefusedByName()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(QString, expected);
        const QString path = m_dir.filePath(QStringLiteral("foreign.dat"));
        writeBytes(path, bytes);
        QString error;
        QVERIFY(!LandmarkPredictor::read(path, &error));
        QVERIFY2(error.contains(QDir::toNativeSeparators(path)), qPrintable(error));
        QVERIFY2(error.contains(expected), qPrintable(error));
    }

    void folderRefusedByName()
    {
        QString error;
        QVERIFY(!LandmarkPredictor::read(m_dir.path(), &error));
        QVERIFY2(error.contains(QDir::toNativeSeparators(m_dir.path())), qPrintable(error));
    }

private:
    QTemporaryDir m_dir;
};

TOONFACE_TEST_GUILESS_MAIN(TestShapeModelFile)
#include "tst_shapemodelfile.moc"
