// The audio track mixed into one sound (issue 26): what playback and every export hear.
#include "animationfixture.h"

#include "export/animationexport.h"
#include "media/audiomix.h"
#include "media/mediareader.h"
#include "render/style.h"
#include "speech/audio.h"
#include "testmain.h"

#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>

using namespace toonface;

namespace {

constexpr int kRate = 8000;

// A WAV of a steady tone of `amplitude` (0..1) and `hz`.
QString writeTone(const QString &path, double seconds, double amplitude, double hz)
{
    Audio a;
    a.sampleRate = kRate;
    a.samples.resize(qsizetype(seconds * kRate));
    for (qsizetype i = 0; i < a.samples.size(); ++i)
        a.samples[i] = float(amplitude * std::sin(2 * M_PI * hz * double(i) / kRate));
    QString error;
    return writeAudio(path, a, &error) ? path : QString();
}

// The peak of samples in [from, to) seconds.
double peakIn(const QVector<float> &samples, int rate, double from, double to)
{
    double peak = 0;
    for (qsizetype i = qsizetype(from * rate); i < std::min<qsizetype>(samples.size(), qsizetype(to * rate)); ++i)
        peak = std::max(peak, double(std::abs(samples[i])));
    return peak;
}

} // namespace

class TestAudioMix : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    QString m_a; // 1 s, 0.3 loud
    QString m_b; // 2 s, 0.5 loud

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_a = writeTone(m_dir.filePath(QStringLiteral("a.wav")), 1.0, 0.3, 440);
        m_b = writeTone(m_dir.filePath(QStringLiteral("b.wav")), 2.0, 0.5, 300);
        QVERIFY(!m_a.isEmpty() && !m_b.isEmpty());
    }

    void clipsSoundAtTheirOffsets()
    {
        AudioClip a {m_a, 0.5, 1.0};
        AudioClip b {m_b, 3.0, 2.0};
        b.trimIn = 0.5; // heard from 3.5 s
        b.trimOut = 0.5; // to 4.5 s
        QString error;
        const std::optional<MixedSound> mix = mixAudioClips({b, a}, kRate, &error);
        QVERIFY2(mix, qPrintable(error));
        QCOMPARE(mix->start, 0.5);
        QVERIFY(std::abs(mix->duration() - 4.0) < 2.0 / kRate); // 0.5 .. 4.5 s
        // Times in the mix are timeline times minus its start.
        const auto at = [&](double from, double to) { return peakIn(mix->samples, kRate, from - 0.5, to - 0.5); };
        QVERIFY(std::abs(at(0.55, 1.45) - 0.3) < 0.02); // a
        QVERIFY(at(1.55, 3.45) < 1e-3); // silence between, and b's trimmed start
        QVERIFY(std::abs(at(3.55, 4.45) - 0.5) < 0.02); // b
    }

    void overlapsDoNotClip()
    {
        // Three loud clips over each other: the sum would reach 2.4.
        const QString loud = writeTone(m_dir.filePath(QStringLiteral("loud.wav")), 1.0, 0.8, 200);
        QVERIFY(!loud.isEmpty());
        QString error;
        const std::optional<MixedSound> mix = mixAudioClips(
            {AudioClip {loud, 0, 1}, AudioClip {loud, 0.25, 1}, AudioClip {loud, 0.5, 1}}, kRate, &error);
        QVERIFY2(mix, qPrintable(error));
        const double peak = peakIn(mix->samples, kRate, 0, mix->duration());
        QVERIFY2(peak <= kMixCeiling + 1e-6, qPrintable(QString::number(peak)));
        QVERIFY(peak > 0.9); // limited, not silenced
        // Where one clip plays alone (the first quarter second, minus the limiter's attack) it is untouched.
        QVERIFY(std::abs(peakIn(mix->samples, kRate, 0.0, 0.2) - 0.8) < 0.01);
    }

    void aMissingFileIsNamed()
    {
        QString error;
        const QString missing = m_dir.filePath(QStringLiteral("gone.wav"));
        QVERIFY(!mixAudioClips({AudioClip {m_a, 0, 1}, AudioClip {missing, 2, 1}}, kRate, &error));
        QVERIFY2(error.contains(missing), qPrintable(error));
    }

    void oneWholeClipIsItsOwnFile()
    {
        QString error;
        const std::optional<TrackSound> one
            = trackSoundFile({AudioClip {m_a, 1.5, 1.0}}, m_dir.path(), QStringLiteral("one.wav"), &error);
        QVERIFY2(one, qPrintable(error));
        QCOMPARE(one->path, m_a);
        QCOMPARE(one->offset, 1.5);
        QVERIFY(!one->mixed);
        const std::optional<TrackSound> two = trackSoundFile(
            {AudioClip {m_a, 1.5, 1.0}, AudioClip {m_b, 4.0, 2.0}}, m_dir.path(), QStringLiteral("two.wav"), &error);
        QVERIFY2(two, qPrintable(error));
        QVERIFY(two->mixed);
        QCOMPARE(two->offset, 1.5);
        QVERIFY(std::abs(two->duration - 4.5) < 0.01);
        const std::optional<QVector<float>> samples = readAudio(two->path, kRate, &error);
        QVERIFY2(samples, qPrintable(error));
        QVERIFY(std::abs(peakIn(*samples, kRate, 2.6, 4.4) - 0.5) < 0.02); // b at 4.0 s of the timeline
    }

    // Every export with sound carries both recordings at their places.
    void exportsCarryEveryClip()
    {
        Timeline t;
        t.setFrameRate(10);
        t.addMouthCues({{0.1, 0.4, MouthShape::A}, {3.1, 3.5, MouthShape::O}});
        t.setAudioClips({AudioClip {m_a, 0.0, 1.0}, AudioClip {m_b, 3.0, 2.0}});
        ExportRequest r;
        r.format = AnimationFormat::Mp4;
        r.outputPath = m_dir.filePath(QStringLiteral("two.mp4"));
        r.size = 96;
        r.face = test::animationFace();
        r.style = Style::preset(QStringLiteral("normal"));
        r.timeline = t;
        const ExportResult result = exportAnimation(r);
        QVERIFY2(result.ok(), qPrintable(result.error));
        QString error;
        const std::optional<MediaInfo> info = probeMedia(r.outputPath, &error);
        QVERIFY2(info, qPrintable(error));
        QVERIFY(info->hasAudio);
        QVERIFY2(std::abs(info->videoDurationS - 5.0) < 0.15, qPrintable(QString::number(info->videoDurationS)));
        const std::optional<QVector<float>> heard = readAudio(r.outputPath, kRate, &error);
        QVERIFY2(heard, qPrintable(error));
        QVERIFY(peakIn(*heard, kRate, 0.1, 0.9) > 0.2); // a
        QVERIFY(peakIn(*heard, kRate, 1.3, 2.7) < 0.05); // the gap
        QVERIFY(peakIn(*heard, kRate, 3.2, 4.8) > 0.35); // b

        // SVG: the mix embedded, from the first clip's start, as long as both.
        r.format = AnimationFormat::SmilSvg;
        r.outputPath = m_dir.filePath(QStringLiteral("two.svg"));
        const ExportResult svg = exportAnimation(r);
        QVERIFY2(svg.ok(), qPrintable(svg.error));
        QFile f(r.outputPath);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray text = f.readAll();
        const QRegularExpressionMatch m
            = QRegularExpression(QStringLiteral("<tf:audio [^>]*offset=\"([0-9.]+)\" duration=\"([0-9.]+)\""))
                  .match(QString::fromUtf8(text));
        QVERIFY(m.hasMatch());
        QVERIFY(std::abs(m.captured(1).toDouble()) < 1e-6);
        QVERIFY2(std::abs(m.captured(2).toDouble() - 5.0) < 0.01, qPrintable(m.captured(2)));
        QVERIFY(text.contains("data:audio/mp4;base64,"));
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestAudioMix)
#include "tst_audiomix.moc"
