#include "export/videoencoder.h"
#include "speech/audio.h"
#include "talkingface.h"
#include "testmain.h"
#include "track/neutralchoice.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>

using namespace toonface;

namespace {

const QString kPortrait = QStringLiteral("/usr/lib/python3/dist-packages/skimage/data/astronaut.png");
const QString kGrid = QStringLiteral(TOONFACE_SHARED_DATA "/video/bbaf2n.mpg");

struct Run
{
    int code = -1;
    QByteArray out;
    QByteArray err;
};

Run cli(const QStringList &args)
{
    QProcess p;
    p.start(QStringLiteral(TOONFACE_CLI_PATH), args);
    if (!p.waitForFinished(300000))
        return {};
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, p.readAllStandardOutput(),
        p.readAllStandardError()};
}

bool isOneErrorLine(const QByteArray &err)
{
    static const QRegularExpression re(QStringLiteral("^toonface-cli: error: [^\\n]+\\n$"));
    return re.match(QString::fromUtf8(err)).hasMatch();
}

// A silent clip: `frames` from `frame(i)`.
template<class Frame>
QString writeClip(const QString &path, int frames, Frame frame)
{
    VideoWriter writer;
    QString error;
    const QImage first = frame(0);
    if (!writer.open(path, VideoFormat::Mp4, first.size(), 25, AudioSource {}, &error))
        return error;
    for (int i = 0; i < frames; ++i) {
        if (!writer.addFrame(i == 0 ? first : frame(i), &error))
            return error;
    }
    return writer.finish(&error) ? QString() : error;
}

} // namespace

class TestCliTrack : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        if (!QFileInfo::exists(kPortrait))
            return;
        const testing::TalkingFace talking {QImage(kPortrait).scaled(320, 320)};
        QVERIFY(talking.isValid());
        m_drawn = m_dir.filePath(QStringLiteral("drawn.mp4"));
        const QString error = writeClip(m_drawn, 25,
            [&](int i) { return talking.frame(i >= 8 && i < 14 ? 1.0 : 0.0, i == 18 || i == 19 ? 0.0 : 1.0); });
        QVERIFY2(error.isEmpty(), qPrintable(error));
        // A clip that opens mid-word: the lips apart for its first 6 frames.
        m_openingMidWord = m_dir.filePath(QStringLiteral("midword.mp4"));
        const QString midWordError
            = writeClip(m_openingMidWord, 25, [&](int i) { return talking.frame(i < 6 ? 1.0 : 0.0, 1.0); });
        QVERIFY2(midWordError.isEmpty(), qPrintable(midWordError));
    }

    // By default the neutral frame is the one the editor's Import Video chooses, and stderr names
    // it; --neutral-frame N names another, and nothing is said of a frame the user named.
    void trackChoosesTheNeutralFrame_data()
    {
        QTest::addColumn<QString>("clip");
        QTest::addColumn<bool>("silent");
        QTest::newRow("opening mid-word") << m_openingMidWord << false;
        QTest::newRow("GRID") << kGrid << true;
    }

    void trackChoosesTheNeutralFrame()
    {
        QFETCH(QString, clip);
        QFETCH(bool, silent);
        if (m_openingMidWord.isEmpty())
            QSKIP("astronaut.png is not installed (package python3-skimage)");
        if (!QFileInfo::exists(clip))
            QSKIP("the GRID clips of shared/data/video are absent");
        const NeutralChoice choice = chooseNeutralFrame(clip);
        QVERIFY2(choice.found, qPrintable(choice.error));
        QCOMPARE(choice.silent, silent);
        if (clip == m_openingMidWord)
            QVERIFY2(choice.frame >= 6, qPrintable(QString::number(choice.frame))); // not a parted frame

        for (const QStringList &extra :
            {QStringList {}, QStringList {QStringLiteral("--neutral-frame"), QStringLiteral("auto")}}) {
            const Run r = cli(QStringList {QStringLiteral("track"), clip} + extra);
            QVERIFY2(r.code == 0, r.err.constData());
            QCOMPARE(
                QJsonDocument::fromJson(r.out).object().value(QStringLiteral("neutralFrame")).toInt(), choice.frame);
            const QString said = QStringLiteral("toonface-cli: %1: neutral frame %2 (").arg(clip).arg(choice.frame);
            QVERIFY2(QString::fromUtf8(r.err).contains(said), r.err.constData());
            QCOMPARE(r.err.contains("in a silence"), silent);
        }

        const Run named = cli({QStringLiteral("track"), clip, QStringLiteral("--neutral-frame"), QStringLiteral("0")});
        QVERIFY2(named.code == 0, named.err.constData());
        QCOMPARE(QJsonDocument::fromJson(named.out).object().value(QStringLiteral("neutralFrame")).toInt(), 0);
        QVERIFY2(!named.err.contains("neutral frame"), named.err.constData());
    }

    void trackWritesTheTrackJson()
    {
        if (m_drawn.isEmpty())
            QSKIP("astronaut.png is not installed (package python3-skimage)");
        const QString out = m_dir.filePath(QStringLiteral("drawn.json"));
        const Run r = cli({QStringLiteral("track"), m_drawn, QStringLiteral("-o"), out});
        QVERIFY2(r.code == 0, r.err.constData());
        QFile f(out);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray text = f.readAll();
        const QJsonObject json = QJsonDocument::fromJson(text).object();
        QCOMPARE(json.value(QStringLiteral("format")).toString(), QStringLiteral("toonface.track/1"));
        // Numbers to the places they are rounded to, not binary noise (0.9526000000000001).
        const QRegularExpression noise(QStringLiteral("\\d\\.\\d*(0{6,}|9{6,})[1-9]"));
        QVERIFY2(!noise.match(QString::fromUtf8(text)).hasMatch(),
            qPrintable(noise.match(QString::fromUtf8(text)).captured()));
        QCOMPARE(json.value(QStringLiteral("method")).toString(), QStringLiteral("landmarks"));
        const QJsonArray frames = json.value(QStringLiteral("frames")).toArray();
        QCOMPARE(frames.size(), 25);
        const auto open = [&](int i) { return frames[i].toObject().value(QStringLiteral("mouthOpen")).toDouble(); };
        QVERIFY(open(11) > open(3) + 0.1);
        QVERIFY(!frames[11].toObject().value(QStringLiteral("lost")).toBool());

        // Snapped, to stdout.
        const Run snapped = cli({QStringLiteral("track"), m_drawn, QStringLiteral("--snap-mouth"),
            QStringLiteral("--method"), QStringLiteral("landmarks")});
        QVERIFY2(snapped.code == 0, snapped.err.constData());
        const QJsonArray s = QJsonDocument::fromJson(snapped.out).object().value(QStringLiteral("frames")).toArray();
        QCOMPARE(s.size(), 25);
        QCOMPARE(s[2].toObject().value(QStringLiteral("mouthShape")).toString(), QStringLiteral("m"));
        QVERIFY(s[11].toObject().value(QStringLiteral("mouthShape")).toString() != QStringLiteral("m"));
    }

    void trackGridClip()
    {
        if (!QFileInfo::exists(kGrid))
            QSKIP("the GRID clips of shared/data/video are absent");
        const Run r = cli({QStringLiteral("track"), kGrid, QStringLiteral("--neutral-frame"), QStringLiteral("3")});
        QVERIFY2(r.code == 0, r.err.constData());
        const QJsonObject json = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(json.value(QStringLiteral("neutralFrame")).toInt(), 3);
        QCOMPARE(json.value(QStringLiteral("video")).toObject().value(QStringLiteral("frames")).toInt(), 75);
        QVERIFY(json.value(QStringLiteral("video")).toObject().value(QStringLiteral("hasAudio")).toBool());
    }

    void animateClipAloneIsSilentButMoves()
    {
        if (m_drawn.isEmpty())
            QSKIP("astronaut.png is not installed (package python3-skimage)");
        const QString out = m_dir.filePath(QStringLiteral("alone.svg"));
        const QString project = m_dir.filePath(QStringLiteral("alone.toonface"));
        const Run r = cli(
            {QStringLiteral("animate"), m_drawn, QStringLiteral("-o"), out, QStringLiteral("--project"), project});
        QVERIFY2(r.code == 0, r.err.constData());
        QVERIFY2(r.err.contains("no sound"), r.err.constData()); // said, not an error
        QFile svg(out);
        QVERIFY(svg.open(QIODevice::ReadOnly));
        const QByteArray text = svg.readAll();
        QVERIFY(text.contains("<animate"));
        QVERIFY(!text.contains("<audio"));
        QFile p(project);
        QVERIFY(p.open(QIODevice::ReadOnly));
        const QJsonObject timeline
            = QJsonDocument::fromJson(p.readAll()).object().value(QStringLiteral("timeline")).toObject();
        QCOMPARE(timeline.value(QStringLiteral("pose")).toArray().size(), 25);
        QCOMPARE(timeline.value(QStringLiteral("blink")).toArray().size(), 1);
        QVERIFY(QFileInfo::exists(m_dir.filePath(QStringLiteral("alone-neutral.png"))));
    }

    void animateAnotherFaceByAClipWithSound()
    {
        if (!QFileInfo::exists(kGrid) || !QFileInfo::exists(kPortrait))
            QSKIP("needs the GRID clips and astronaut.png");
        const QString out = m_dir.filePath(QStringLiteral("driven.html"));
        const Run r = cli({QStringLiteral("animate"), kPortrait, QStringLiteral("--video"), kGrid,
            QStringLiteral("--snap-mouth"), QStringLiteral("-o"), out});
        QVERIFY2(r.code == 0, r.err.constData());
        QVERIFY(QFileInfo(out).size() > 1000);
        // The clip's sound, copied a block at a time: what decoding it whole gives, to the
        // 16-bit WAV file's rounding and scale (written times 32767, read back over 32768).
        const AudioResult copied = loadAudio(m_dir.filePath(QStringLiteral("driven-sound.wav")));
        QVERIFY2(copied.ok(), qPrintable(copied.error));
        const AudioResult whole = loadAudio(kGrid);
        QVERIFY2(whole.ok(), qPrintable(whole.error));
        QCOMPARE(copied.audio.samples.size(), whole.audio.samples.size());
        // A WAV file holds [-1, 1]: louder samples are clipped.
        for (qsizetype i = 0; i < whole.audio.samples.size(); ++i) {
            const float expected = std::clamp(whole.audio.samples[i], -1.0f, 1.0f);
            QVERIFY2(std::abs(copied.audio.samples[i] - expected) <= 2.0f / 32768,
                qPrintable(QStringLiteral("sample %1: %2, not %3").arg(i).arg(copied.audio.samples[i]).arg(expected)));
        }
    }

    // PNG frames into a folder that does not exist yet: made, with the clip's sound beside them.
    void animateClipIntoANewFrameFolder()
    {
        if (!QFileInfo::exists(kGrid))
            QSKIP("needs the GRID clips of shared/data/video");
        const QString folder = m_dir.filePath(QStringLiteral("new/frames"));
        const Run r = cli({QStringLiteral("animate"), kGrid, QStringLiteral("--fps"), QStringLiteral("5"),
            QStringLiteral("-o"), folder + QLatin1Char('/')});
        QVERIFY2(r.code == 0, r.err.constData());
        QVERIFY(QFileInfo::exists(folder + QStringLiteral("/speech-sound.wav")));
        QVERIFY(QDir(folder).entryList({QStringLiteral("*.png")}, QDir::Files).size() >= 10);
    }

    void badClipsAndUsage_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<int>("code");
        QTest::addColumn<QString>("mention");
        const QString missing = m_dir.filePath(QStringLiteral("missing.mp4"));
        QTest::newRow("missing") << QStringList {QStringLiteral("track"), missing} << 3 << missing;
        QTest::newRow("garbage") << QStringList {QStringLiteral("track"), m_dir.filePath(QStringLiteral("garbage.mp4"))}
                                 << 3 << m_dir.filePath(QStringLiteral("garbage.mp4"));
        QTest::newRow("no face") << QStringList {QStringLiteral("track"), m_dir.filePath(QStringLiteral("wall.mp4"))}
                                 << 4 << m_dir.filePath(QStringLiteral("wall.mp4"));
        QTest::newRow("no face, animate") << QStringList {QStringLiteral("animate"),
            m_dir.filePath(QStringLiteral("wall.mp4")), QStringLiteral("-o"), m_dir.filePath(QStringLiteral("x.svg"))}
                                          << 4 << m_dir.filePath(QStringLiteral("wall.mp4"));
        QTest::newRow("past the end") << QStringList {QStringLiteral("track"),
            m_dir.filePath(QStringLiteral("wall.mp4")), QStringLiteral("--neutral-frame"), QStringLiteral("99")}
                                      << 3 << QStringLiteral("past the video's end");
        QTest::newRow("negative frame") << QStringList {QStringLiteral("track"), missing,
            QStringLiteral("--neutral-frame"), QStringLiteral("-1")}
                                        << 2 << QStringLiteral("--neutral-frame");
        QTest::newRow("neutral frame not a number")
            << QStringList {QStringLiteral("track"), missing, QStringLiteral("--neutral-frame"), QStringLiteral("rest")}
            << 2 << QStringLiteral("a frame number from 0 or auto, not 'rest'");
        QTest::newRow("method") << QStringList {QStringLiteral("track"), missing, QStringLiteral("--method"),
            QStringLiteral("magic")}
                                << 2 << QStringLiteral("magic");
        QTest::newRow("no video") << QStringList {QStringLiteral("track")} << 2 << QStringLiteral("VIDEO");
        // A recording whose header promises 2 s and which holds 1.25 s.
        const QString cutWav = m_dir.filePath(QStringLiteral("cut.wav"));
        QTest::newRow("cut recording") << QStringList {QStringLiteral("lipsync"), QStringLiteral("--audio"), cutWav,
            QStringLiteral("--script"), m_dir.filePath(QStringLiteral("hello.txt"))}
                                       << 3
                                       << cutWav
                + QStringLiteral(": cut short (its header promises 2.00 s, it holds 1.25 s)");
        if (QFileInfo::exists(kGrid)) {
            const QString cut = m_dir.filePath(QStringLiteral("cut.mpg"));
            QTest::newRow("cut clip") << QStringList {QStringLiteral("track"), cut} << 3
                                      << cut + QStringLiteral(": the file is cut short or damaged");
        }
    }

    void badClipsAndUsage()
    {
        QFETCH(QStringList, args);
        QFETCH(int, code);
        QFETCH(QString, mention);
        {
            QFile garbage(m_dir.filePath(QStringLiteral("garbage.mp4")));
            QVERIFY(garbage.open(QIODevice::WriteOnly));
            garbage.write(QByteArray(4000, '\x17'));
        }
        const QString wall = m_dir.filePath(QStringLiteral("wall.mp4"));
        if (!QFileInfo::exists(wall)) {
            const QString error = writeClip(wall, 8, [](int i) {
                QImage image(160, 120, QImage::Format_RGB32);
                image.fill(QColor(100 + 5 * i, 120, 140));
                return image;
            });
            QVERIFY2(error.isEmpty(), qPrintable(error));
        }
        const QString cutWav = m_dir.filePath(QStringLiteral("cut.wav"));
        if (!QFileInfo::exists(cutWav)) {
            Audio tone;
            tone.samples.resize(2 * tone.sampleRate);
            for (qsizetype i = 0; i < tone.samples.size(); ++i)
                tone.samples[i] = float(0.3 * std::sin(2 * M_PI * 300 * double(i) / tone.sampleRate));
            QString error;
            QVERIFY2(writeAudio(cutWav, tone, &error), qPrintable(error));
            QFile wav(cutWav);
            QVERIFY(wav.open(QIODevice::ReadWrite));
            const qsizetype header = wav.readAll().indexOf("data") + 8;
            QVERIFY(wav.resize(header + qsizetype(1.25 * tone.sampleRate) * 2));
        }
        QFile script(m_dir.filePath(QStringLiteral("hello.txt")));
        QVERIFY(script.open(QIODevice::WriteOnly));
        script.write("你好\n");
        script.close();
        const QString cutClip = m_dir.filePath(QStringLiteral("cut.mpg"));
        if (QFileInfo::exists(kGrid) && !QFileInfo::exists(cutClip)) {
            QFile grid(kGrid);
            QVERIFY(grid.open(QIODevice::ReadOnly));
            QFile cut(cutClip);
            QVERIFY(cut.open(QIODevice::WriteOnly));
            cut.write(grid.read(2000));
        }
        const Run r = cli(args);
        QCOMPARE(r.code, code);
        QVERIFY2(isOneErrorLine(r.err), r.err.constData());
        QVERIFY2(QString::fromUtf8(r.err).contains(mention), r.err.constData());
    }

private:
    QTemporaryDir m_dir;
    QString m_drawn;
    QString m_openingMidWord;
};

TOONFACE_TEST_GUILESS_MAIN(TestCliTrack)
#include "tst_clitrack.moc"
