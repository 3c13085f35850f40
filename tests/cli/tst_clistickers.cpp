#include "shareddata.h"
#include "testmain.h"

#include "media/mediareader.h"

#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

using namespace toonface;

// toonface-cli animate with transparent outputs, --background and --preset: the limits met on
// real photos, and a clear error with no file where they cannot be.
namespace {

const QString kPortrait = QStringLiteral("/usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg");
// More than 3 s of speech: a sticker takes a 3-second stretch of it.
const QString kSpeech = QStringLiteral("Hello there, this is a talking sticker made from one photo of my face.");

struct Run
{
    int code = -1;
    QByteArray err;
};

Run cli(const QStringList &args)
{
    QProcess p;
    p.start(QStringLiteral(TOONFACE_CLI_PATH), args);
    if (!p.waitForFinished(300000))
        return {};
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, p.readAllStandardError()};
}

bool isOneErrorLine(const QByteArray &err)
{
    static const QRegularExpression re(QStringLiteral("^toonface-cli: error: [^\\n]+\\n$"));
    return re.match(QString::fromUtf8(err)).hasMatch();
}

QStringList entries(const QString &dir)
{
    return QDir(dir).entryList(QDir::AllEntries | QDir::Hidden | QDir::System | QDir::NoDotAndDotDot, QDir::Name);
}

// The sticker of `photo` under `preset` meets its limits: size, side, length, rate, no sound,
// alpha 0 in the corners and an opaque face in the middle.
void checkSticker(const QString &path, int side, qint64 maxBytes)
{
    QVERIFY2(QFileInfo(path).size() <= maxBytes, qPrintable(QString::number(QFileInfo(path).size())));
    QString error;
    const std::optional<MediaInfo> info = probeMedia(path, &error);
    QVERIFY2(info, qPrintable(error));
    QCOMPARE(info->container, u"matroska,webm"_qs);
    QCOMPARE(info->videoCodec, u"vp9"_qs);
    QCOMPARE(QSize(info->width, info->height), QSize(side, side));
    QVERIFY2(info->videoDurationS <= 3.0 + 1e-6 && info->videoDurationS > 2.9,
        qPrintable(QString::number(info->videoDurationS)));
    QVERIFY(info->fps <= 30);
    QVERIFY(!info->hasAudio);
    QVERIFY(info->hasAlpha);
    for (int index : {0, info->frameCount / 2, info->frameCount - 1}) {
        const std::optional<QImage> frame = readVideoFrame(path, index, &error);
        QVERIFY2(frame, qPrintable(error));
        QCOMPARE(qAlpha(frame->pixel(0, 0)), 0);
        QCOMPARE(qAlpha(frame->pixel(side - 1, side - 1)), 0);
        QCOMPARE(qAlpha(frame->pixel(side / 2, side / 2)), 255);
    }
}

} // namespace

class TestCliStickers : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    QString newFolder(const QString &name)
    {
        const QString path = m_dir.filePath(name);
        QDir(path).removeRecursively();
        QDir().mkpath(path);
        return path;
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        if (!QFileInfo::exists(kPortrait))
            QSKIP("the Grace Hopper photo (python-matplotlib-data) is not installed");
    }

    void presetsOnGraceHopper_data()
    {
        QTest::addColumn<QString>("preset");
        QTest::addColumn<int>("side");
        QTest::addColumn<qint64>("maxBytes");
        QTest::newRow("telegram-sticker") << u"telegram-sticker"_qs << 512 << qint64(256 * 1024);
        QTest::newRow("emoji") << u"emoji"_qs << 100 << qint64(64 * 1024);
    }

    void presetsOnGraceHopper()
    {
        QFETCH(QString, preset);
        QFETCH(int, side);
        QFETCH(qint64, maxBytes);
        const QString dir = newFolder(preset);
        const QString out = QDir(dir).filePath(QStringLiteral("sticker.webm"));
        const Run run
            = cli({QStringLiteral("animate"), kPortrait, QStringLiteral("--say"), kSpeech, QStringLiteral("--preset"),
                preset, QStringLiteral("--duration"), QStringLiteral("3"), QStringLiteral("-o"), out});
        QVERIFY2(run.code == 0, run.err.constData());
        checkSticker(out, side, maxBytes);
        if (QTest::currentTestFailed())
            return;
        QVERIFY(entries(dir).contains(u"sticker.webm"_qs));
    }

    // A slide overlay keeps its sound (Opus) and its alpha at 1080 pixels.
    void slideOverlay()
    {
        const QString dir = newFolder(QStringLiteral("slide"));
        const QString out = QDir(dir).filePath(QStringLiteral("overlay.webm"));
        const Run run = cli({QStringLiteral("animate"), kPortrait, QStringLiteral("--say"), kSpeech,
            QStringLiteral("--preset"), QStringLiteral("slide-overlay"), QStringLiteral("--duration"),
            QStringLiteral("1"), QStringLiteral("-o"), out});
        QVERIFY2(run.code == 0, run.err.constData());
        QString error;
        const std::optional<MediaInfo> info = probeMedia(out, &error);
        QVERIFY2(info, qPrintable(error));
        QCOMPARE(QSize(info->width, info->height), QSize(1080, 1080));
        QVERIFY(info->hasAlpha);
        QVERIFY(info->hasAudio);
        QCOMPARE(info->audioCodec, u"opus"_qs);
    }

    // The research photos (shared data): every face found makes a sticker within the limits.
    void telegramStickersOfSharedPhotos()
    {
        const QDir faces(testing::sharedFacesDir());
        const QStringList photos = faces.entryList({QStringLiteral("*.jpg"), QStringLiteral("*.png")}, QDir::Files);
        if (photos.isEmpty())
            QSKIP("the shared photos (/work/shared/data/faces) are absent");
        int made = 0;
        for (const QString &name : photos) {
            const QString dir = newFolder(QStringLiteral("shared-") + name);
            const QString out = QDir(dir).filePath(QStringLiteral("sticker.webm"));
            const Run run = cli({QStringLiteral("animate"), faces.filePath(name), QStringLiteral("--say"), kSpeech,
                QStringLiteral("--preset"), QStringLiteral("telegram-sticker"), QStringLiteral("--duration"),
                QStringLiteral("3"), QStringLiteral("-o"), out});
            if (run.code == 4) { // no face found: nothing to make a sticker of
                QVERIFY(entries(dir).isEmpty());
                continue;
            }
            QVERIFY2(run.code == 0, qPrintable(name + QStringLiteral(": ") + QString::fromUtf8(run.err)));
            checkSticker(out, 512, 256 * 1024);
            if (QTest::currentTestFailed())
                return;
            ++made;
        }
        QVERIFY2(made * 2 >= photos.size(), qPrintable(QStringLiteral("%1 of %2").arg(made).arg(photos.size())));
    }

    // Too long for the preset: which limit, by how much, how to trim, and no file.
    void presetRefusesALongClip()
    {
        const QString dir = newFolder(QStringLiteral("long"));
        const QString out = QDir(dir).filePath(QStringLiteral("sticker.webm"));
        const Run run = cli({QStringLiteral("animate"), kPortrait, QStringLiteral("--say"), kSpeech,
            QStringLiteral("--preset"), QStringLiteral("telegram-sticker"), QStringLiteral("-o"), out});
        QCOMPARE(run.code, 3);
        QVERIFY2(isOneErrorLine(run.err), run.err.constData());
        const QString err = QString::fromUtf8(run.err);
        QVERIFY2(err.contains(u"sticker.webm") && err.contains(u"allows 3 s") && err.contains(u"--duration")
                && err.contains(u"too long"),
            qPrintable(err));
        // The speech's own files are written beside the output; the sticker is not.
        QVERIFY(!entries(dir).contains(u"sticker.webm"_qs));
        for (const QString &name : entries(dir))
            QVERIFY2(!name.endsWith(u".part") && !name.endsWith(u".webm"), qPrintable(name));
    }

    void badInput_data()
    {
        QTest::addColumn<QStringList>("options");
        QTest::addColumn<QString>("output");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("unknown preset") << QStringList {u"--preset"_qs, u"tiktok"_qs} << u"a.webm"_qs << u"tiktok"_qs;
        QTest::newRow("preset of another format")
            << QStringList {u"--preset"_qs, u"telegram-sticker"_qs} << u"a.gif"_qs << u".webm"_qs;
        QTest::newRow("bad colour") << QStringList {u"--background"_qs, u"purpleish"_qs} << u"a.webm"_qs
                                    << u"purpleish"_qs;
        QTest::newRow("colour with alpha")
            << QStringList {u"--background"_qs, u"#80ff0000"_qs} << u"a.webm"_qs << u"#80ff0000"_qs;
        QTest::newRow("transparent mp4") << QStringList {u"--background"_qs, u"transparent"_qs} << u"a.mp4"_qs
                                         << u"MP4"_qs;
        QTest::newRow("svg over a colour") << QStringList {u"--background"_qs, u"white"_qs} << u"a.svg"_qs << u"SVG"_qs;
        QTest::newRow("negative start") << QStringList {u"--start"_qs, u"-1"_qs} << u"a.webm"_qs << u"--start"_qs;
        QTest::newRow("zero duration") << QStringList {u"--duration"_qs, u"0"_qs} << u"a.webm"_qs << u"--duration"_qs;
        QTest::newRow("png is ambiguous") << QStringList {} << u"a.png"_qs << u".apng"_qs;
    }

    void badInput()
    {
        QFETCH(QStringList, options);
        QFETCH(QString, output);
        QFETCH(QString, mentions);
        const QString dir = newFolder(QStringLiteral("bad"));
        const Run run = cli(QStringList {QStringLiteral("animate"), kPortrait, QStringLiteral("--say"),
                                QStringLiteral("hi"), QStringLiteral("-o"), QDir(dir).filePath(output)}
            + options);
        QCOMPARE(run.code, 2);
        QVERIFY2(isOneErrorLine(run.err), run.err.constData());
        QVERIFY2(QString::fromUtf8(run.err).contains(mentions), run.err.constData());
        QCOMPARE(entries(dir), QStringList());
    }

    // An opaque MP4 over the user's colour; WebP transparent by default.
    void backgroundsByOption()
    {
        const QString dir = newFolder(QStringLiteral("backgrounds"));
        const QString mp4 = QDir(dir).filePath(QStringLiteral("green.mp4"));
        Run run = cli({QStringLiteral("animate"), kPortrait, QStringLiteral("--say"), QStringLiteral("hi"),
            QStringLiteral("--background"), QStringLiteral("#00c000"), QStringLiteral("--fps"), QStringLiteral("10"),
            QStringLiteral("-o"), mp4});
        QVERIFY2(run.code == 0, run.err.constData());
        QString error;
        const std::optional<QImage> frame = readVideoFrame(mp4, 0, &error);
        QVERIFY2(frame, qPrintable(error));
        QVERIFY(qGreen(frame->pixel(1, 1)) > 170 && qRed(frame->pixel(1, 1)) < 40);

        const QString apng = QDir(dir).filePath(QStringLiteral("clear.apng"));
        run = cli({QStringLiteral("animate"), kPortrait, QStringLiteral("--say"), QStringLiteral("hi"),
            QStringLiteral("--fps"), QStringLiteral("10"), QStringLiteral("-o"), apng});
        QVERIFY2(run.code == 0, run.err.constData());
        const std::optional<QImage> clear = readVideoFrame(apng, 0, &error);
        QVERIFY2(clear, qPrintable(error));
        QVERIFY(clear->hasAlphaChannel());
        QCOMPARE(qAlpha(clear->pixel(0, 0)), 0);
        QCOMPARE(qAlpha(clear->pixel(clear->width() / 2, clear->height() / 2)), 255);
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestCliStickers)
#include "tst_clistickers.moc"
