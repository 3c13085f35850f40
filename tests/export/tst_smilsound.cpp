#include "smilfixture.h"
#include "testmain.h"

#include <QTest>

using namespace toonface;
using namespace toonface::smiltest;

// The SMIL SVG export's sound (embedded, compressed or referenced) and its HTML player.
class TestSmilSound : public SmilExportFixture
{
    Q_OBJECT

private Q_SLOTS:
    void init() { animationCache().clear(); }

    void initTestCase() { QVERIFY(prepare()); }

    void soundIsEmbedded()
    {
        AnimationExportOptions o;
        o.audio = ExportAudio::Embed;
        o.compressAudio = false;
        const QByteArray svg = exported(o);
        const Node doc = document(svg);
        const QList<const Node *> audio = all(doc, "tf:audio");
        QCOMPARE(audio.size(), 1);
        const QString href = audio.first()->attribute(QStringLiteral("href"));
        QVERIFY(href.startsWith(QStringLiteral("data:audio/wav;base64,")));
        // The sound decoded and written anew as WAV: the same samples, not the file's bytes.
        QTemporaryDir dir;
        const QString embedded = dir.filePath(QStringLiteral("embedded.wav"));
        QFile copy(embedded);
        QVERIFY(copy.open(QIODevice::WriteOnly));
        copy.write(QByteArray::fromBase64(href.mid(href.indexOf(QLatin1Char(',')) + 1).toLatin1()));
        copy.close();
        QString error;
        const std::optional<QVector<float>> original = readAudio(m_wav, 16000, &error);
        const std::optional<QVector<float>> decoded = readAudio(embedded, 16000, &error);
        QVERIFY2(original && decoded, qPrintable(error));
        QCOMPARE(decoded->size(), original->size());
        double worst = 0;
        for (qsizetype i = 0; i < original->size(); ++i)
            worst = std::max(worst, double(std::abs((*decoded)[i] - (*original)[i])));
        QVERIFY2(worst < 1e-3, qPrintable(QString::number(worst)));
        QCOMPARE(audio.first()->attribute(QStringLiteral("offset")).toDouble(), 0.0);
        QCOMPARE(audio.first()->attribute(QStringLiteral("duration")).toDouble(), 10.0);
        // The player: a play button and the script that starts the sound with the animation and
        // keeps the animation on the audio clock.
        QVERIFY(findId(doc, QStringLiteral("tf-play")));
        const QList<const Node *> scripts = all(doc, "script");
        QCOMPARE(scripts.size(), 1);
        for (const char *needle : {"pauseAnimations", "unpauseAnimations", "setCurrentTime", "currentTime", "play()"})
            QVERIFY2(svg.contains(needle), needle);
    }

    // Sound is embedded as AAC, whatever its format (never the file's own bytes): far smaller
    // than uncompressed sound, as long, and in time (a burst that starts at 1 s still starts
    // there: the encoder's priming is accounted for).
    void embeddedSoundIsCompressed_data()
    {
        QTest::addColumn<QString>("suffix");
        QTest::addColumn<QString>("mime");
        QTest::newRow("wav 44.1 kHz") << QStringLiteral("wav") << QStringLiteral("audio/mp4");
        QTest::newRow("flac") << QStringLiteral("flac") << QStringLiteral("audio/mp4");
        QTest::newRow("mp3") << QStringLiteral("mp3") << QStringLiteral("audio/mp4");
    }
    void embeddedSoundIsCompressed()
    {
        QFETCH(QString, suffix);
        QFETCH(QString, mime);
        // Silence, then a 440 Hz burst from 1 s to 2 s, then silence to 3 s.
        Audio sound;
        sound.sampleRate = 44100;
        sound.samples.resize(3 * sound.sampleRate);
        for (int i = sound.sampleRate; i < 2 * sound.sampleRate; ++i)
            sound.samples[i] = 0.5f * float(std::sin(2 * std::numbers::pi * 440.0 * i / sound.sampleRate));
        QTemporaryDir dir;
        const QString source = dir.filePath(QStringLiteral("burst.") + suffix);
        QString error;
        QVERIFY2(writeAudio(source, sound, &error), qPrintable(error));
        Timeline t = timeline();
        t.setAudioClips({AudioClip {source, 0.0, 3.0}});
        AnimationExportOptions o;
        o.audio = ExportAudio::Embed;
        QByteArray svg = exportSmilSvg(m_face, Style(), t, m_shapes, o, &error);
        QVERIFY2(!svg.isEmpty(), qPrintable(error));
        const QString href = all(document(svg), "tf:audio").first()->attribute(QStringLiteral("href"));
        QVERIFY2(
            href.startsWith(QStringLiteral("data:") + mime + QStringLiteral(";base64,")), qPrintable(href.left(40)));
        const QByteArray bytes = QByteArray::fromBase64(href.mid(href.indexOf(QLatin1Char(',')) + 1).toLatin1());
        QFile in(source);
        QVERIFY(in.open(QIODevice::ReadOnly));
        const QByteArray original = in.readAll();
        QVERIFY2(suffix == QLatin1StringView("mp3") || bytes.size() * 2 < original.size(),
            qPrintable(QStringLiteral("%1 of %2 bytes").arg(bytes.size()).arg(original.size())));
        const QString embedded = dir.filePath(QStringLiteral("embedded.m4a"));
        QFile out(embedded);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(bytes);
        out.close();
        const std::optional<MediaInfo> info = probeMedia(embedded, &error);
        QVERIFY2(info, qPrintable(error));
        QCOMPARE(info->audioCodec, QStringLiteral("aac"));
        QCOMPARE(info->audioChannels, 1);
        QVERIFY2(std::abs(info->audioDurationS - 3.0) < 0.03, qPrintable(QString::number(info->audioDurationS)));
        // The burst's start: the first 1 ms window whose level passes half the burst's.
        const int rate = 16000;
        const std::optional<QVector<float>> decoded = readAudio(embedded, rate, &error);
        QVERIFY2(decoded, qPrintable(error));
        double onset = -1;
        for (qsizetype i = 0; i + rate / 1000 <= decoded->size(); i += rate / 1000) {
            double peak = 0;
            for (qsizetype k = i; k < i + rate / 1000; ++k)
                peak = std::max(peak, double(std::abs((*decoded)[k])));
            if (peak > 0.25) {
                onset = double(i) / rate;
                break;
            }
        }
        qInfo("%s: %lld bytes as %lld bytes of AAC, burst at %.4f s", qPrintable(suffix), qlonglong(original.size()),
            qlonglong(bytes.size()), onset);
        QVERIFY(std::abs(onset - 1.0) <= 0.005);
    }

    void soundIsReferenced()
    {
        QTemporaryDir out;
        QVERIFY(QDir().mkpath(out.filePath(QStringLiteral("clips"))));
        AnimationExportOptions o;
        o.audio = ExportAudio::Reference;
        o.outputDir = out.filePath(QStringLiteral("clips"));
        const QString wav = out.filePath(QStringLiteral("sound files/voice one.wav"));
        QVERIFY(QDir().mkpath(QFileInfo(wav).absolutePath()));
        QVERIFY(QFile::copy(m_wav, wav));
        o.audioPath = wav;
        const Node doc = document(exported(o));
        const QList<const Node *> audio = all(doc, "tf:audio");
        QCOMPARE(audio.size(), 1);
        QCOMPARE(audio.first()->attribute(QStringLiteral("href")), QStringLiteral("../sound%20files/voice%20one.wav"));
    }

    // A referenced sound is checked without being decoded; a copy cut short (its header promises
    // more than it holds) or a file that is no sound is still refused, naming the file.
    void damagedReferencedSoundIsRefused_data()
    {
        QTest::addColumn<bool>("cutShort");
        QTest::newRow("cut short") << true;
        QTest::newRow("not a sound") << false;
    }

    void damagedReferencedSoundIsRefused()
    {
        QFETCH(bool, cutShort);
        QTemporaryDir out;
        const QString wav = out.filePath(QStringLiteral("damaged voice.wav"));
        QFile in(m_wav);
        QVERIFY(in.open(QIODevice::ReadOnly));
        const QByteArray whole = in.readAll();
        QFile damaged(wav);
        QVERIFY(damaged.open(QIODevice::WriteOnly));
        damaged.write(cutShort ? whole.left(whole.size() * 6 / 10) : QByteArray("these are words, not sound\n"));
        damaged.close();
        AnimationExportOptions o;
        o.audio = ExportAudio::Reference;
        o.outputDir = out.path();
        o.audioPath = wav;
        QString error;
        const QByteArray svg = exportSmilSvg(m_face, Style(), timeline(), m_shapes, o, &error);
        QVERIFY(svg.isEmpty());
        QVERIFY2(error.contains(QStringLiteral("damaged voice.wav")), qPrintable(error));
        QVERIFY2(!cutShort || error.contains(QStringLiteral("short")), qPrintable(error));
    }

    void silentExportHasNoPlayer()
    {
        const QByteArray svg = exported(silent());
        const Node doc = document(svg);
        QVERIFY(all(doc, "tf:audio").isEmpty());
        QVERIFY(all(doc, "script").isEmpty());
        QVERIFY(!findId(doc, QStringLiteral("tf-play")));
        const QList<const Node *> info = all(doc, "tf:animation");
        QCOMPARE(info.size(), 1);
        QCOMPARE(info.first()->attribute(QStringLiteral("duration")).toDouble(), 10.0);
        QCOMPARE(info.first()->attribute(QStringLiteral("fps")).toDouble(), 25.0);
    }

    void htmlPlayer_data()
    {
        QTest::addColumn<int>("audio");
        QTest::newRow("embedded") << int(ExportAudio::Embed);
        QTest::newRow("referenced") << int(ExportAudio::Reference);
        QTest::newRow("silent") << int(ExportAudio::None);
    }

    void htmlPlayer()
    {
        QFETCH(int, audio);
        AnimationExportOptions o;
        o.audio = ExportAudio(audio);
        o.outputDir = m_dir.path();
        QString error;
        const QByteArray html = exportHtmlPlayer(m_face, Style(), timeline(), m_shapes, o, &error);
        QVERIFY2(!html.isEmpty(), qPrintable(error));
        QVERIFY(html.startsWith("<!DOCTYPE html>"));
        // The SVG inline, animated, without its own player.
        const qsizetype from = html.indexOf("<svg");
        const qsizetype to = html.indexOf("</svg>");
        QVERIFY(from > 0 && to > from);
        const Node svg = document(html.mid(from, to + 6 - from));
        QVERIFY(all(svg, "animate").size() > 10);
        QVERIFY(all(svg, "script").isEmpty());
        QVERIFY(!findId(svg, QStringLiteral("tf-play")));
        // Its own controls in every case; the clock paused, set when seeking, corrected on
        // every animation frame (the browser test plays with them).
        for (const char *needle : {"pauseAnimations", "unpauseAnimations", "setCurrentTime", "requestAnimationFrame",
                 "id=\"tf-toggle\"", "id=\"tf-seek\"", "id=\"tf-time\""})
            QVERIFY2(html.contains(needle), needle);
        if (ExportAudio(audio) == ExportAudio::None) {
            QVERIFY(!html.contains("<audio"));
            return;
        }
        // The sound is hidden: the player's controls drive it.
        QVERIFY(html.contains("<audio id=\"tf-audio\" preload=\"auto\" src="));
        QVERIFY(!html.contains("controls src"));
        if (ExportAudio(audio) == ExportAudio::Embed)
            QVERIFY(html.contains("src=\"data:audio/mp4;base64,")); // the WAV compressed
        else
            QVERIFY(html.contains("src=\"voice.wav\""));
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestSmilSound)
#include "tst_smilsound.moc"
