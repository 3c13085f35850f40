// The read-aloud book's page videos (issue 29): each distinct pose drawn once and reused, the
// frames those of the page's timeline, the sound the page's stretch, cancel and bad input.
#include "animationfixture.h"
#include "testmain.h"

#include "anim/timeline.h"
#include "anim/timelineevaluator.h"
#include "export/bookvideo.h"
#include "face/pose.h"
#include "media/mediareader.h"
#include "render/svgface.h"
#include "speech/audio.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <utility>

using namespace toonface;

namespace {

// The mean difference of two pictures' channels (0..255): H.264 at the pages' quality keeps
// a cartoon within a few levels.
double meanDifference(const QImage &a, const QImage &b)
{
    const QImage x = a.convertToFormat(QImage::Format_RGB32);
    const QImage y = b.convertToFormat(QImage::Format_RGB32);
    if (x.size() != y.size())
        return 255;
    double sum = 0;
    for (int row = 0; row < x.height(); ++row) {
        const QRgb *p = reinterpret_cast<const QRgb *>(x.constScanLine(row));
        const QRgb *q = reinterpret_cast<const QRgb *>(y.constScanLine(row));
        for (int col = 0; col < x.width(); ++col)
            sum += std::abs(qRed(p[col]) - qRed(q[col])) + std::abs(qGreen(p[col]) - qGreen(q[col]))
                + std::abs(qBlue(p[col]) - qBlue(q[col]));
    }
    return sum / (3.0 * x.width() * x.height());
}

// A tone a step louder every second (0.05 in the first, 0.1 in the next, ...): a page's
// loudness tells which stretch of the sound it holds.
double stepAmplitude(double t)
{
    return 0.05 * (1 + std::floor(t));
}

Audio tone(double seconds)
{
    Audio a;
    a.sampleRate = 24000;
    a.samples.resize(qsizetype(seconds * a.sampleRate));
    for (qsizetype i = 0; i < a.samples.size(); ++i) {
        const double t = double(i) / a.sampleRate;
        a.samples[i] = float(stepAmplitude(t) * std::sin(2 * M_PI * 220.0 * t));
    }
    return a;
}

// The amplitude of a sine in samples [from, to) at `rate` (its RMS times the square root of 2).
double amplitude(const QVector<float> &samples, int rate, double from, double to)
{
    double sum = 0;
    const qsizetype a = qsizetype(from * rate), b = qsizetype(to * rate);
    for (qsizetype i = a; i < b; ++i)
        sum += double(samples[i]) * samples[i];
    return std::sqrt(2 * sum / double(b - a));
}

// A page as the book times it: sentences of mouth shapes with pauses between them, and blinks.
Timeline pageTimeline()
{
    Timeline t;
    t.setFrameRate(25);
    const MouthShape shapes[] = {MouthShape::A, MouthShape::M, MouthShape::O, MouthShape::E, MouthShape::U,
        MouthShape::I, MouthShape::F, MouthShape::N};
    const double lengths[] = {0.12, 0.2, 0.08, 0.15, 0.25, 0.1, 0.18};
    QVector<MouthCue> cues;
    int k = 0;
    for (const auto &[start, end] : {std::pair {0.3, 2.6}, std::pair {3.4, 6.1}, std::pair {7.0, 9.2}}) {
        for (double s = start; s < end; ++k) {
            const double length = lengths[k % std::size(lengths)];
            cues.append({s, s + length, shapes[k % std::size(shapes)]});
            s += length;
        }
    }
    t.addMouthCues(cues);
    t.generateBlinks(7, 10.0);
    return t;
}

} // namespace

class TestBookVideo : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    QString m_sound; // 12 s
    BookRequest m_request;

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_sound = m_dir.filePath(QStringLiteral("book.wav"));
        QString error;
        QVERIFY2(writeAudio(m_sound, tone(12), &error), qPrintable(error));
        m_request.face = test::animationFace();
        m_request.outputPath = m_dir.filePath(QStringLiteral("book.epub"));
    }

    // A rounded pose is within half a step of the pose, rounds to itself, and draws almost the
    // same picture at the pages' size.
    void roundedPoseIsCloseAndStable()
    {
        const Timeline timeline = test::animationTimeline();
        const TimelineEvaluator evaluator(timeline, m_request.face, m_request.mouthShapes);
        const SvgFace face(m_request.face, m_request.style);
        const double step = 0.5;
        for (const double t : {0.5, 1.3, 2.55, 4.1, 6.9, 8.33}) {
            const Pose pose = evaluator.evaluate(t);
            const Pose rounded = roundedPose(pose, step);
            QCOMPARE(roundedPose(rounded, step), rounded);
            for (int i = 0; i < kPointCount; ++i) {
                QVERIFY(std::abs(rounded.offset[i].x() - pose.offset[i].x()) <= step / 2 + 1e-9);
                QVERIFY(std::abs(rounded.offset[i].y() - pose.offset[i].y()) <= step / 2 + 1e-9);
            }
            const double d = meanDifference(rasterizeSvg(face.svg(pose), PageVideoWriter::frameSize()),
                rasterizeSvg(face.svg(rounded), PageVideoWriter::frameSize()));
            QVERIFY2(d < 0.5, qPrintable(QStringLiteral("%1 s: %2").arg(t).arg(d)));
        }
    }

    // A page where the face holds still is drawn once however long it lasts.
    void stillPageDrawsOnePicture()
    {
        PageVideoWriter writer(m_request, m_dir.path());
        QString error;
        QVERIFY2(writer.openSound(m_sound, &error), qPrintable(error));
        Timeline still;
        ExportStatus status = ExportStatus::Failed;
        const QString video = writer.write(still, 0, 4000, nullptr, &status, &error);
        QVERIFY2(!video.isEmpty(), qPrintable(error));
        QCOMPARE(status, ExportStatus::Done);
        QCOMPARE(writer.framesWritten(), qint64(std::ceil(4 * PageVideoWriter::frameRate())));
        QCOMPARE(writer.framesDrawn(), qint64(1));
        const std::optional<MediaInfo> info = probeMedia(video, &error);
        QVERIFY2(info, qPrintable(error));
        QCOMPARE(info->frameCount, int(writer.framesWritten()));
        QVERIFY(info->hasAudio);
        // The speech keeps the rate it was made at (24 kHz), not resampled to 48 kHz.
        QCOMPARE(info->audioSampleRate, 24000);
    }

    // A talking page: fewer pictures drawn than frames (the pauses and held shapes reuse
    // theirs), and every frame, drawn or reused, shows its time's pose.
    void talkingPageShowsEachFramesPose()
    {
        PageVideoWriter writer(m_request, m_dir.path());
        QString error;
        QVERIFY2(writer.openSound(m_sound, &error), qPrintable(error));
        const Timeline timeline = pageTimeline();
        ExportStatus status = ExportStatus::Failed;
        const QString video = writer.write(timeline, 0, 10000, nullptr, &status, &error);
        QVERIFY2(!video.isEmpty(), qPrintable(error));
        const qint64 frames = qint64(std::ceil(10 * PageVideoWriter::frameRate()));
        QCOMPARE(writer.framesWritten(), frames);
        QVERIFY2(writer.framesDrawn() < frames && writer.framesDrawn() > 1,
            qPrintable(QStringLiteral("%1 of %2 drawn").arg(writer.framesDrawn()).arg(frames)));

        SvgFace face(m_request.face, m_request.style);
        face.setFrame(headFrame(m_request.face));
        const TimelineEvaluator evaluator(timeline, m_request.face, m_request.mouthShapes);
        QVector<int> sampled;
        QVector<QImage> expected;
        for (int frame = 0; frame < frames; frame += 5) {
            sampled.append(frame);
            expected.append(rasterizeSvg(
                face.svg(evaluator.evaluate(frame / PageVideoWriter::frameRate())), PageVideoWriter::frameSize()));
        }
        // Compared where the face moves (the mouth and eyes): there a pose differs from another by
        // far more than the encoder's loss.
        QRect moves;
        for (const QImage &e : expected) {
            for (int y = 0; y < e.height(); ++y)
                for (int x = 0; x < e.width(); ++x)
                    if (qGray(e.pixel(x, y)) != qGray(expected.first().pixel(x, y)))
                        moves |= QRect(x, y, 1, 1);
        }
        QVERIFY(!moves.isEmpty());
        int moving = 0;
        for (qsizetype k = 0; k < sampled.size(); ++k) {
            const std::optional<QImage> decoded = readVideoFrame(video, sampled[k], &error);
            QVERIFY2(decoded, qPrintable(error));
            // The encoder's loss there is about one level; poses differ by up to eight.
            const double d = meanDifference(decoded->copy(moves), expected[k].copy(moves));
            QVERIFY2(d < 2.0, qPrintable(QStringLiteral("frame %1: %2").arg(sampled[k]).arg(d)));
            const double apart = meanDifference(expected[k].copy(moves), expected.first().copy(moves));
            if (apart > 4.0) {
                ++moving;
                QVERIFY2(d < apart / 2,
                    qPrintable(
                        QStringLiteral("frame %1: %2 from its pose, %3 apart").arg(sampled[k]).arg(d).arg(apart)));
            }
        }
        QVERIFY(moving > 0); // the comparison can tell poses apart
    }

    // The pages cut the sound in order: the second page's sound follows the first's.
    void pagesCutTheSoundInOrder()
    {
        PageVideoWriter writer(m_request, m_dir.path());
        QString error;
        QVERIFY2(writer.openSound(m_sound, &error), qPrintable(error));
        ExportStatus status = ExportStatus::Failed;
        QVERIFY2(!writer.write(Timeline(), 0, 1000, nullptr, &status, &error).isEmpty(), qPrintable(error));
        const QString second = writer.write(Timeline(), 3000, 5000, nullptr, &status, &error);
        QVERIFY2(!second.isEmpty(), qPrintable(error));
        const std::optional<MediaInfo> info = probeMedia(second, &error);
        QVERIFY2(info, qPrintable(error));
        QVERIFY2(std::abs(info->audioDurationS - 2.0) < 0.1, qPrintable(QString::number(info->audioDurationS)));
        // Seconds 3 and 4 of the book's sound, in order.
        const std::optional<QVector<float>> sound = readAudio(second, 24000, &error);
        QVERIFY2(sound, qPrintable(error));
        for (const int s : {0, 1}) {
            const double a = amplitude(*sound, 24000, s + 0.2, s + 0.8);
            QVERIFY2(std::abs(a - stepAmplitude(3 + s)) < 0.02,
                qPrintable(QStringLiteral("second %1: %2, not %3").arg(3 + s).arg(a).arg(stepAmplitude(3 + s))));
        }
        QVERIFY2(std::abs(info->videoDurationS - 2.0) < 1.0 / PageVideoWriter::frameRate() + 1e-6,
            qPrintable(QString::number(info->videoDurationS)));
    }

    // Cancelled: no video, the Cancelled status.
    void cancelled()
    {
        PageVideoWriter writer(m_request, m_dir.path());
        QString error;
        QVERIFY2(writer.openSound(m_sound, &error), qPrintable(error));
        const std::atomic_bool cancel = true;
        ExportStatus status = ExportStatus::Failed;
        QVERIFY(writer.write(test::animationTimeline(), 0, 10000, &cancel, &status, &error).isEmpty());
        QCOMPARE(status, ExportStatus::Cancelled);
        QVERIFY(!QFileInfo::exists(m_dir.filePath(QStringLiteral("page.mp4"))) || writer.framesWritten() == 0);
    }

    // Bad input: no sound opened, a sound that is not one, a layer that does not parse.
    void badInput()
    {
        QString error;
        ExportStatus status = ExportStatus::Done;
        {
            PageVideoWriter writer(m_request, m_dir.path());
            QVERIFY(writer.write(Timeline(), 0, 1000, nullptr, &status, &error).isEmpty());
            QCOMPARE(status, ExportStatus::Failed);
            QVERIFY(error.contains(m_request.outputPath));
        }
        {
            PageVideoWriter writer(m_request, m_dir.path());
            const QString text = m_dir.filePath(QStringLiteral("notes.wav"));
            QFile f(text);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("not a sound at all");
            f.close();
            QVERIFY(!writer.openSound(text, &error));
            QVERIFY2(error.contains(text), qPrintable(error));
        }
        {
            BookRequest request = m_request;
            const QString layer = m_dir.filePath(QStringLiteral("layer.svg"));
            QFile f(layer);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("<svg");
            f.close();
            request.layerFiles = {layer};
            PageVideoWriter writer(request, m_dir.path());
            QVERIFY2(writer.openSound(m_sound, &error), qPrintable(error));
            QVERIFY(writer.write(Timeline(), 0, 1000, nullptr, &status, &error).isEmpty());
            QCOMPARE(status, ExportStatus::BadInput);
            QVERIFY2(error.contains(layer), qPrintable(error));
        }
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestBookVideo)
#include "tst_bookvideo.moc"
