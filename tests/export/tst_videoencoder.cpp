#include "export/videoencoder.h"
#include "imagedifference.h"
#include "media/mediareader.h"
#include "testmain.h"

#include <QDataStream>
#include <QDir>
#include <QFile>
#include <QPainter>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <numbers>

#ifdef Q_OS_UNIX
#include <unistd.h>
#endif

using namespace toonface;
using testing::meanDifference;

Q_DECLARE_METATYPE(toonface::VideoFormat)

namespace {

// A yellow disc moving left to right over a blue background, a red bar whose height counts
// the frames: every frame differs, and the colours are far apart.
QImage movingShape(int i, QSize size)
{
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.fill(QColor(40, 70, 160));
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(250, 210, 40));
    const double r = size.height() / 5.0;
    p.drawEllipse(QPointF(r + (size.width() - 2 * r) * (i % 50) / 49.0, size.height() / 2.0), r, r);
    p.setBrush(QColor(220, 30, 30));
    p.drawRect(QRectF(0, size.height() - 2 - i % 50, 8, 2 + i % 50));
    return image;
}

QVector<float> sine(double seconds, int rate, double hz = 440)
{
    QVector<float> s(qsizetype(std::llround(seconds * rate)));
    for (qsizetype i = 0; i < s.size(); ++i)
        s[i] = float(0.5 * std::sin(2 * std::numbers::pi * hz * double(i) / rate));
    return s;
}

// A 16-bit PCM WAV file.
bool writeWav(const QString &path, const QVector<float> &mono, int rate, int channels)
{
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        return false;
    QDataStream out(&f);
    out.setByteOrder(QDataStream::LittleEndian);
    const quint32 dataBytes = quint32(mono.size() * channels * 2);
    out.writeRawData("RIFF", 4);
    out << quint32(36 + dataBytes);
    out.writeRawData("WAVEfmt ", 8);
    out << quint32(16) << quint16(1) << quint16(channels) << quint32(rate) << quint32(rate * channels * 2)
        << quint16(channels * 2) << quint16(16);
    out.writeRawData("data", 4);
    out << dataBytes;
    for (float v : mono)
        for (int c = 0; c < channels; ++c)
            out << qint16(std::lround(v * 32767));
    return out.status() == QDataStream::Ok;
}

QStringList allEntries(const QString &dir)
{
    return QDir(dir).entryList(QDir::AllEntries | QDir::Hidden | QDir::System | QDir::NoDotAndDotDot);
}

// The top-level MP4 boxes in file order.
QStringList mp4Boxes(const QString &path)
{
    QFile f(path);
    QStringList boxes;
    if (!f.open(QIODevice::ReadOnly))
        return boxes;
    while (!f.atEnd()) {
        const QByteArray header = f.read(8);
        if (header.size() < 8)
            break;
        quint64 size = (quint32(quint8(header[0])) << 24) | (quint32(quint8(header[1])) << 16)
            | (quint32(quint8(header[2])) << 8) | quint32(quint8(header[3]));
        qint64 headerSize = 8;
        if (size == 1) {
            const QByteArray large = f.read(8);
            size = 0;
            for (char c : large)
                size = (size << 8) | quint8(c);
            headerSize = 16;
        }
        boxes.append(QString::fromLatin1(header.mid(4, 4)));
        if (size < quint64(headerSize) || !f.seek(f.pos() - headerSize + qint64(size)))
            break;
    }
    return boxes;
}

// Where a tone first exceeds a threshold, in seconds.
double onset(const QVector<float> &samples, int rate, float threshold = 0.1f)
{
    for (qsizetype i = 0; i < samples.size(); ++i)
        if (std::abs(samples[i]) > threshold)
            return double(i) / rate;
    return -1;
}

bool writeFrames(const QString &path, VideoFormat format, QSize size, double fps, int frames, const AudioSource &audio,
    QString *error, const VideoOptions &options = {})
{
    return writeVideo(
        path, format, size, fps, frames, [size](int i) { return movingShape(i, size); }, audio, error, options);
}

} // namespace

class TestVideoEncoder : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void formatForPath_data();
    void formatForPath();

    void mp4WithSound();
    void mp4FramesLookRight();
    void mp4AudioLengthFollowsVideo_data();
    void mp4AudioLengthFollowsVideo();
    void mp4AudioOffsetKeepsSync_data();
    void mp4AudioOffsetKeepsSync();
    void mp4AudioFromFile();
    void mp4OddSizeIsPadded();
    void mp4FractionalFrameRate();
    void transparentFramesGetTheBackground_data();
    void transparentFramesGetTheBackground();

    void gif_data();
    void gif();
    void gifColours();
    void gifPaletteSamples();

    void pngSequence();
    void pngSequenceRemovesStaleFrames();

    void cancelLeavesNothing_data();
    void cancelLeavesNothing();
    void cancelKeepsTheOldFile();
    void destroyedWriterLeavesNothing();
    void outputPermissions();
    void progressIsReported();

    void errors_data();
    void errors();
    void unreadableAudio();
    void frameOfTheWrongSize();
    void noFrames_data();
    void noFrames();
    void unwritableFolder();
    void probeErrors();
};

void TestVideoEncoder::formatForPath_data()
{
    QTest::addColumn<QString>("path");
    QTest::addColumn<int>("format"); // -1: none
    QTest::newRow("mp4") << u"out/a.mp4"_qs << int(VideoFormat::Mp4);
    QTest::newRow("MP4") << u"A.MP4"_qs << int(VideoFormat::Mp4);
    QTest::newRow("gif") << u"a.gif"_qs << int(VideoFormat::Gif);
    QTest::newRow("folder") << u"frames/"_qs << int(VideoFormat::PngSequence);
    QTest::newRow("existing folder") << QDir::tempPath() << int(VideoFormat::PngSequence);
    QTest::newRow("svg") << u"a.svg"_qs << -1;
    QTest::newRow("none") << u"a"_qs << -1;
}

void TestVideoEncoder::formatForPath()
{
    QFETCH(QString, path);
    QFETCH(int, format);
    const auto f = videoFormatForPath(path);
    QCOMPARE(f ? int(*f) : -1, format);
}

// The check: 50 frames at 25 fps with a 2 s tone.
void TestVideoEncoder::mp4WithSound()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(u"talk.mp4"_qs);
    QString error;
    QVERIFY2(writeFrames(path, VideoFormat::Mp4, QSize(256, 256), 25, 50,
                 AudioSource::fromSamples(sine(2.0, 16000), 16000), &error),
        qPrintable(error));
    const auto info = probeMedia(path, &error);
    QVERIFY2(info, qPrintable(error));
    QCOMPARE(info->frameCount, 50);
    QCOMPARE(info->fps, 25.0);
    QVERIFY2(std::abs(info->videoDurationS - 2.0) < 1e-6, qPrintable(QString::number(info->videoDurationS)));
    QVERIFY(info->hasAudio);
    QVERIFY2(std::abs(info->audioDurationS - 2.0) <= 0.05, qPrintable(QString::number(info->audioDurationS)));
    QCOMPARE(info->width, 256);
    QCOMPARE(info->height, 256);
    QCOMPARE(info->videoCodec, u"h264"_qs);
    QCOMPARE(info->pixelFormat, u"yuv420p"_qs);
    QCOMPARE(info->audioCodec, u"aac"_qs);
    QCOMPARE(info->audioChannels, 1);
    QCOMPARE(info->audioSampleRate, 48000);
    // +faststart: the index comes before the media data, so players start before the download ends.
    const QStringList boxes = mp4Boxes(path);
    QVERIFY2(boxes.contains(u"moov"_qs) && boxes.contains(u"mdat"_qs), qPrintable(boxes.join(u' ')));
    QVERIFY2(boxes.indexOf(u"moov"_qs) < boxes.indexOf(u"mdat"_qs), qPrintable(boxes.join(u' ')));
    // The tone is there: 440 Hz at amplitude 0.5 has an RMS near 0.35.
    const auto sound = readAudio(path, 16000, &error);
    QVERIFY2(sound, qPrintable(error));
    double sum = 0;
    for (qsizetype i = 8000; i < 24000; ++i)
        sum += double((*sound)[i]) * (*sound)[i];
    QVERIFY2(std::abs(std::sqrt(sum / 16000) - 0.354) < 0.03, qPrintable(QString::number(std::sqrt(sum / 16000))));
}

// Colours and positions survive the encoding (no swapped channels, no shifted frames).
void TestVideoEncoder::mp4FramesLookRight()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(u"look.mp4"_qs);
    const QSize size(320, 240);
    QString error;
    QVERIFY2(writeFrames(path, VideoFormat::Mp4, size, 25, 30, {}, &error), qPrintable(error));
    for (int i : {0, 13, 29}) {
        const auto frame = readVideoFrame(path, i, &error);
        QVERIFY2(frame, qPrintable(error));
        const QImage want = movingShape(i, size);
        const double diff = meanDifference(*frame, want);
        QVERIFY2(diff < 3.0, qPrintable(QStringLiteral("frame %1: mean difference %2").arg(i).arg(diff)));
        // The neighbouring frame is clearly further away: frames are not shifted.
        QVERIFY(meanDifference(*frame, movingShape(i + 1, size)) > diff + 0.5);
        const QRgb centreOfBlue = frame->pixel(size.width() - 4, 4);
        QVERIFY2(std::abs(qRed(centreOfBlue) - 40) < 6 && std::abs(qGreen(centreOfBlue) - 70) < 6
                && std::abs(qBlue(centreOfBlue) - 160) < 6,
            qPrintable(QColor(centreOfBlue).name()));
    }
    const auto info = probeMedia(path, &error);
    QVERIFY2(info, qPrintable(error));
    QVERIFY(!info->hasAudio);
    QCOMPARE(info->frameCount, 30);
}

void TestVideoEncoder::mp4AudioLengthFollowsVideo_data()
{
    QTest::addColumn<double>("audioSeconds");
    QTest::addColumn<int>("rate");
    QTest::addColumn<double>("offset");
    QTest::newRow("longer sound is cut") << 3.0 << 44100 << 0.0;
    QTest::newRow("shorter sound is padded") << 0.7 << 22050 << 0.0;
    QTest::newRow("late sound") << 1.0 << 48000 << 0.6;
    QTest::newRow("early sound") << 3.0 << 8000 << -0.5;
}

void TestVideoEncoder::mp4AudioLengthFollowsVideo()
{
    QFETCH(double, audioSeconds);
    QFETCH(int, rate);
    QFETCH(double, offset);
    QTemporaryDir dir;
    const QString path = dir.filePath(u"len.mp4"_qs);
    QString error;
    QVERIFY2(writeFrames(path, VideoFormat::Mp4, QSize(64, 48), 25, 40,
                 AudioSource::fromSamples(sine(audioSeconds, rate), rate, offset), &error),
        qPrintable(error));
    const auto info = probeMedia(path, &error);
    QVERIFY2(info, qPrintable(error));
    QCOMPARE(info->frameCount, 40);
    QVERIFY2(std::abs(info->videoDurationS - 1.6) < 1e-6, qPrintable(QString::number(info->videoDurationS)));
    QVERIFY2(std::abs(info->audioDurationS - 1.6) <= 0.05, qPrintable(QString::number(info->audioDurationS)));
    QCOMPARE(info->audioSampleRate, rate % 11025 == 0 ? 44100 : 48000);
}

void TestVideoEncoder::mp4AudioOffsetKeepsSync_data()
{
    QTest::addColumn<double>("offset");
    QTest::newRow("none") << 0.0;
    QTest::newRow("later") << 0.5;
    QTest::newRow("earlier") << -0.3;
}

// A tone that starts 1 s into the recording is heard at 1 s + offset in the video.
void TestVideoEncoder::mp4AudioOffsetKeepsSync()
{
    QFETCH(double, offset);
    const int rate = 16000;
    QVector<float> samples(2 * rate, 0.0f);
    const QVector<float> tone = sine(1.0, rate, 1000);
    std::copy(tone.begin(), tone.end(), samples.begin() + rate);
    QTemporaryDir dir;
    const QString path = dir.filePath(u"sync.mp4"_qs);
    QString error;
    QVERIFY2(writeFrames(path, VideoFormat::Mp4, QSize(64, 48), 25, 75, AudioSource::fromSamples(samples, rate, offset),
                 &error),
        qPrintable(error));
    const auto sound = readAudio(path, rate, &error);
    QVERIFY2(sound, qPrintable(error));
    const double heard = onset(*sound, rate);
    QVERIFY2(std::abs(heard - (1.0 + offset)) < 0.01,
        qPrintable(QStringLiteral("tone heard at %1 s, expected %2 s").arg(heard).arg(1.0 + offset)));
}

// A stereo WAV file decoded by FFmpeg, mixed down to mono.
void TestVideoEncoder::mp4AudioFromFile()
{
    QTemporaryDir dir;
    const QString wav = dir.filePath(u"voice.wav"_qs);
    QVERIFY(writeWav(wav, sine(2.5, 44100), 44100, 2));
    QString error;
    const auto decoded = readAudio(wav, 44100, &error);
    QVERIFY2(decoded, qPrintable(error));
    QCOMPARE(decoded->size(), qsizetype(2.5 * 44100));
    const auto wavInfo = probeMedia(wav, &error);
    QVERIFY2(wavInfo, qPrintable(error));
    QVERIFY(wavInfo->hasAudio);
    QCOMPARE(wavInfo->audioChannels, 2);
    QCOMPARE(wavInfo->audioDurationS, 2.5);
    QCOMPARE(wavInfo->frameCount, 0);

    const QString path = dir.filePath(u"file.mp4"_qs);
    QVERIFY2(writeFrames(path, VideoFormat::Mp4, QSize(64, 64), 25, 50, AudioSource::fromFile(wav), &error),
        qPrintable(error));
    const auto info = probeMedia(path, &error);
    QVERIFY2(info, qPrintable(error));
    QCOMPARE(info->audioSampleRate, 44100);
    QCOMPARE(info->audioChannels, 1);
    QVERIFY2(std::abs(info->audioDurationS - 2.0) <= 0.05, qPrintable(QString::number(info->audioDurationS)));
}

void TestVideoEncoder::mp4OddSizeIsPadded()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(u"odd.mp4"_qs);
    const QSize size(101, 77);
    VideoWriter writer;
    QString error;
    QVERIFY2(writer.open(path, VideoFormat::Mp4, size, 25, {}, &error), qPrintable(error));
    QCOMPARE(writer.encodedSize(), QSize(102, 78));
    for (int i = 0; i < 10; ++i)
        QVERIFY2(writer.addFrame(movingShape(i, size), &error), qPrintable(error));
    QVERIFY2(writer.finish(&error), qPrintable(error));
    const auto info = probeMedia(path, &error);
    QVERIFY2(info, qPrintable(error));
    QCOMPARE(info->frameCount, 10);
    QCOMPARE(QSize(info->width, info->height), QSize(102, 78));
    const auto frame = readVideoFrame(path, 5, &error);
    QVERIFY2(frame, qPrintable(error));
    const double diff = meanDifference(*frame, movingShape(5, size), QRect(0, 0, 101, 77));
    QVERIFY2(diff < 4.0, qPrintable(QString::number(diff)));
    // The padding repeats the edge: no black or white border.
    QVERIFY(meanDifference(frame->copy(101, 0, 1, 78), frame->copy(100, 0, 1, 78)) < 6.0);
    QVERIFY(meanDifference(frame->copy(0, 77, 102, 1), frame->copy(0, 76, 102, 1)) < 6.0);
}

void TestVideoEncoder::mp4FractionalFrameRate()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(u"ntsc.mp4"_qs);
    const double fps = 30000.0 / 1001.0;
    QString error;
    QVERIFY2(writeFrames(path, VideoFormat::Mp4, QSize(64, 48), fps, 60,
                 AudioSource::fromSamples(sine(3, 48000), 48000), &error),
        qPrintable(error));
    const auto info = probeMedia(path, &error);
    QVERIFY2(info, qPrintable(error));
    QCOMPARE(info->frameCount, 60);
    QVERIFY2(std::abs(info->fps - fps) < 1e-3, qPrintable(QString::number(info->fps)));
    QVERIFY(std::abs(info->videoDurationS - 60 / fps) < 1e-3);
    QVERIFY(std::abs(info->audioDurationS - 60 / fps) <= 0.05);
}

void TestVideoEncoder::transparentFramesGetTheBackground_data()
{
    QTest::addColumn<VideoFormat>("format");
    QTest::newRow("mp4") << VideoFormat::Mp4;
    QTest::newRow("gif") << VideoFormat::Gif;
}

void TestVideoEncoder::transparentFramesGetTheBackground()
{
    QFETCH(VideoFormat, format);
    QTemporaryDir dir;
    const QString path = dir.filePath(format == VideoFormat::Mp4 ? u"t.mp4"_qs : u"t.gif"_qs);
    VideoOptions options;
    options.background = QColor(0, 200, 0);
    QString error;
    QVERIFY2(writeVideo(
                 path, format, QSize(64, 64), 25, 3,
                 [](int) {
                     QImage image(64, 64, QImage::Format_ARGB32_Premultiplied);
                     image.fill(Qt::transparent);
                     return image;
                 },
                 {}, &error, options),
        qPrintable(error));
    const auto frame = readVideoFrame(path, 1, &error);
    QVERIFY2(frame, qPrintable(error));
    const QColor c = frame->pixelColor(32, 32);
    QVERIFY2(c.red() < 8 && std::abs(c.green() - 200) < 8 && c.blue() < 8, qPrintable(c.name()));
}

void TestVideoEncoder::gif_data()
{
    QTest::addColumn<double>("fps");
    QTest::addColumn<int>("frames");
    QTest::addColumn<int>("expectedFrames");
    QTest::addColumn<double>("expectedFps");
    QTest::newRow("25 kept") << 25.0 << 50 << 50 << 25.0;
    QTest::newRow("50 halved") << 50.0 << 50 << 25 << 25.0;
    QTest::newRow("30 to 15") << 30.0 << 45 << 23 << 15.0;
    QTest::newRow("10 kept") << 10.0 << 12 << 12 << 10.0;
}

void TestVideoEncoder::gif()
{
    QFETCH(double, fps);
    QFETCH(int, frames);
    QFETCH(int, expectedFrames);
    QFETCH(double, expectedFps);
    QTemporaryDir dir;
    const QString path = dir.filePath(u"anim.gif"_qs);
    VideoWriter writer;
    QString error;
    const QSize size(120, 90);
    QVERIFY2(writer.open(path, VideoFormat::Gif, size, fps, AudioSource::fromSamples(sine(1, 8000), 8000), &error),
        qPrintable(error));
    QCOMPARE(writer.outputFps(), expectedFps);
    for (int i = 0; i < frames; ++i)
        QVERIFY2(writer.addFrame(movingShape(i, size), &error), qPrintable(error));
    QVERIFY2(writer.finish(&error), qPrintable(error));
    const auto info = probeMedia(path, &error);
    QVERIFY2(info, qPrintable(error));
    QCOMPARE(info->videoCodec, u"gif"_qs);
    QCOMPARE(info->frameCount, expectedFrames);
    QCOMPARE(QSize(info->width, info->height), size);
    QVERIFY2(std::abs(info->videoDurationS - expectedFrames / expectedFps) < 0.011,
        qPrintable(QString::number(info->videoDurationS)));
    QVERIFY(!info->hasAudio);
}

// The palette reproduces flat cartoon colours closely, also in later frames.
void TestVideoEncoder::gifColours()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(u"colours.gif"_qs);
    const QSize size(160, 120);
    QString error;
    QVERIFY2(writeFrames(path, VideoFormat::Gif, size, 25, 30, {}, &error), qPrintable(error));
    for (int i : {0, 17, 29}) {
        const auto frame = readVideoFrame(path, i, &error);
        QVERIFY2(frame, qPrintable(error));
        const double diff = meanDifference(*frame, movingShape(i, size));
        QVERIFY2(diff < 2.0, qPrintable(QStringLiteral("frame %1: mean difference %2").arg(i).arg(diff)));
    }
}

// A colour that shows only from frame 5 on is exact when a palette sample holds it.
void TestVideoEncoder::gifPaletteSamples()
{
    const QSize size(96, 64);
    auto frameAt = [size](int i) {
        QImage image = movingShape(i, size);
        if (i >= 5) {
            QPainter p(&image);
            p.fillRect(QRect(60, 8, 30, 30), QColor(0, 160, 90));
        }
        return image;
    };
    QTemporaryDir dir;
    QString error;
    const QRect square(60, 8, 30, 30);
    double diff[2] = {0, 0};
    for (int withSample : {0, 1}) {
        const QString path = dir.filePath(QStringLiteral("s%1.gif").arg(withSample));
        VideoOptions options;
        if (withSample)
            options.paletteSamples = {frameAt(9)};
        QVERIFY2(writeVideo(path, VideoFormat::Gif, size, 25, 10, frameAt, {}, &error, options), qPrintable(error));
        const auto frame = readVideoFrame(path, 7, &error);
        QVERIFY2(frame, qPrintable(error));
        diff[withSample] = meanDifference(*frame, frameAt(7), square);
    }
    QVERIFY2(diff[1] < 1.0, qPrintable(QString::number(diff[1])));
    QVERIFY2(diff[0] > diff[1] + 5, qPrintable(QStringLiteral("%1 %2").arg(diff[0]).arg(diff[1])));
}

void TestVideoEncoder::pngSequence()
{
    QTemporaryDir dir;
    const QString folder = dir.filePath(u"frames/sub"_qs); // created on the way
    const QSize size(48, 32);
    QString error;
    QVERIFY2(writeVideo(
                 folder, VideoFormat::PngSequence, size, 25, 12,
                 [size](int i) {
                     QImage image = movingShape(i, size);
                     image.setPixelColor(0, 0, QColor(1, 2, 3, 128)); // alpha is kept
                     return image;
                 },
                 {}, &error),
        qPrintable(error));
    QStringList want;
    for (int i = 1; i <= 12; ++i)
        want.append(QStringLiteral("frame_%1.png").arg(i, 5, 10, QLatin1Char('0')));
    QCOMPARE(allEntries(folder), want);
    for (int i : {0, 5, 11}) {
        QImage expected = movingShape(i, size);
        expected.setPixelColor(0, 0, QColor(1, 2, 3, 128));
        const QImage got(QDir(folder).filePath(want[i]));
        QCOMPARE(got.convertToFormat(QImage::Format_ARGB32), expected.convertToFormat(QImage::Format_ARGB32));
    }
    const auto info = probeMedia(folder, &error);
    QVERIFY2(info, qPrintable(error));
    QCOMPARE(info->frameCount, 12);
    QCOMPARE(QSize(info->width, info->height), size);
}

void TestVideoEncoder::pngSequenceRemovesStaleFrames()
{
    QTemporaryDir dir;
    const QString folder = dir.path();
    QString error;
    QVERIFY2(writeFrames(folder, VideoFormat::PngSequence, QSize(16, 16), 25, 8, {}, &error), qPrintable(error));
    QFile other(dir.filePath(u"notes.txt"_qs));
    QVERIFY(other.open(QIODevice::WriteOnly));
    other.close();
    QVERIFY2(writeFrames(folder, VideoFormat::PngSequence, QSize(16, 16), 25, 3, {}, &error), qPrintable(error));
    QCOMPARE(allEntries(folder),
        (QStringList {u"frame_00001.png"_qs, u"frame_00002.png"_qs, u"frame_00003.png"_qs, u"notes.txt"_qs}));
}

void TestVideoEncoder::cancelLeavesNothing_data()
{
    QTest::addColumn<VideoFormat>("format");
    QTest::addColumn<QString>("name");
    QTest::newRow("mp4") << VideoFormat::Mp4 << u"out.mp4"_qs;
    QTest::newRow("gif") << VideoFormat::Gif << u"out.gif"_qs;
    QTest::newRow("png") << VideoFormat::PngSequence << QString();
}

// Cancelled half way, an export leaves no file behind, not even a temporary one.
void TestVideoEncoder::cancelLeavesNothing()
{
    QFETCH(VideoFormat, format);
    QFETCH(QString, name);
    QTemporaryDir dir;
    const QString path = name.isEmpty() ? dir.path() : dir.filePath(name);
    std::atomic<bool> cancel = false;
    int rendered = 0;
    QString error;
    const bool ok = writeVideo(
        path, format, QSize(64, 64), 25, 50,
        [&](int i) {
            ++rendered;
            return movingShape(i, QSize(64, 64));
        },
        AudioSource::fromSamples(sine(2, 16000), 16000), &error, {},
        [&](int done, int) {
            if (done == 20)
                cancel = true;
        },
        &cancel);
    QVERIFY(!ok);
    QCOMPARE(error, QDir::toNativeSeparators(path) + u": cancelled"_qs);
    QCOMPARE(rendered, 20);
    QCOMPARE(allEntries(dir.path()), QStringList());
}

void TestVideoEncoder::cancelKeepsTheOldFile()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(u"keep.mp4"_qs);
    QFile old(path);
    QVERIFY(old.open(QIODevice::WriteOnly));
    old.write("the previous export");
    old.close();
    VideoWriter writer;
    QString error;
    QVERIFY2(writer.open(path, VideoFormat::Mp4, QSize(32, 32), 25, {}, &error), qPrintable(error));
    for (int i = 0; i < 5; ++i)
        QVERIFY(writer.addFrame(movingShape(i, QSize(32, 32)), &error));
    writer.cancel();
    QVERIFY(!writer.isOpen());
    QCOMPARE(allEntries(dir.path()), QStringList {u"keep.mp4"_qs});
    QVERIFY(old.open(QIODevice::ReadOnly));
    QCOMPARE(old.readAll(), QByteArray("the previous export"));
    old.close();
    // A finished export replaces it.
    QVERIFY2(writeFrames(path, VideoFormat::Mp4, QSize(32, 32), 25, 5, {}, &error), qPrintable(error));
    QCOMPARE(probeMedia(path, &error)->frameCount, 5);
    QCOMPARE(allEntries(dir.path()), QStringList {u"keep.mp4"_qs});
}

void TestVideoEncoder::destroyedWriterLeavesNothing()
{
    QTemporaryDir dir;
    QString error;
    {
        VideoWriter mp4;
        VideoWriter gif;
        VideoWriter png;
        QVERIFY(mp4.open(dir.filePath(u"a.mp4"_qs), VideoFormat::Mp4, QSize(32, 32), 25, {}, &error));
        QVERIFY(gif.open(dir.filePath(u"a.gif"_qs), VideoFormat::Gif, QSize(32, 32), 25, {}, &error));
        QVERIFY(png.open(dir.filePath(u"png"_qs), VideoFormat::PngSequence, QSize(32, 32), 25, {}, &error));
        for (int i = 0; i < 3; ++i) {
            QVERIFY(mp4.addFrame(movingShape(i, QSize(32, 32)), &error));
            QVERIFY(gif.addFrame(movingShape(i, QSize(32, 32)), &error));
            QVERIFY(png.addFrame(movingShape(i, QSize(32, 32)), &error));
        }
        QVERIFY(!allEntries(dir.path()).isEmpty());
    }
    // The PNG folder itself stays (it may have been there before); its frames go.
    QCOMPARE(allEntries(dir.path()), QStringList {u"png"_qs});
    QCOMPARE(allEntries(dir.filePath(u"png"_qs)), QStringList());
}

// A new export gets the permissions of any new file (not a temporary file's owner-only ones);
// a replaced file keeps its own.
void TestVideoEncoder::outputPermissions()
{
    QTemporaryDir dir;
    QFile plain(dir.filePath(u"plain"_qs));
    QVERIFY(plain.open(QIODevice::WriteOnly));
    plain.close();
    const QString path = dir.filePath(u"new.gif"_qs);
    QString error;
    QVERIFY2(writeFrames(path, VideoFormat::Gif, QSize(16, 16), 25, 2, {}, &error), qPrintable(error));
    QCOMPARE(QFile::permissions(path), QFile::permissions(plain.fileName()));

    const auto kept = QFile::ReadOwner | QFile::WriteOwner | QFile::ReadUser | QFile::WriteUser | QFile::ReadGroup;
    QVERIFY(QFile::setPermissions(path, kept));
    QVERIFY2(writeFrames(path, VideoFormat::Gif, QSize(16, 16), 25, 3, {}, &error), qPrintable(error));
    QCOMPARE(QFile::permissions(path), kept);
    QCOMPARE(probeMedia(path, &error)->frameCount, 3);
}

void TestVideoEncoder::progressIsReported()
{
    QTemporaryDir dir;
    QVector<int> calls;
    QString error;
    QVERIFY(writeVideo(
        dir.filePath(u"p.gif"_qs), VideoFormat::Gif, QSize(16, 16), 25, 7,
        [](int i) { return movingShape(i, QSize(16, 16)); }, {}, &error, {},
        [&](int done, int total) { calls.append(done * 100 + total); }));
    QCOMPARE(calls, (QVector<int> {107, 207, 307, 407, 507, 607, 707}));
}

void TestVideoEncoder::errors_data()
{
    QTest::addColumn<VideoFormat>("format");
    QTest::addColumn<QSize>("size");
    QTest::addColumn<double>("fps");
    QTest::addColumn<QString>("problem");
    QTest::newRow("mp4 huge") << VideoFormat::Mp4 << QSize(10000, 100) << 25.0 << u"unsupported size 10000x100"_qs;
    QTest::newRow("mp4 tiny") << VideoFormat::Mp4 << QSize(1, 100) << 25.0 << u"unsupported size 1x100"_qs;
    QTest::newRow("empty") << VideoFormat::Gif << QSize(0, 10) << 25.0 << u"unsupported size 0x10"_qs;
    QTest::newRow("gif huge") << VideoFormat::Gif << QSize(70000, 10) << 25.0 << u"unsupported size 70000x10"_qs;
    QTest::newRow("zero fps") << VideoFormat::Mp4 << QSize(64, 64) << 0.0 << u"unsupported frame rate 0"_qs;
    QTest::newRow("nan fps") << VideoFormat::Gif << QSize(64, 64) << std::nan("") << u"unsupported frame rate"_qs;
    QTest::newRow("fast fps") << VideoFormat::PngSequence << QSize(64, 64) << 1000.0
                              << u"unsupported frame rate 1000"_qs;
}

void TestVideoEncoder::errors()
{
    QFETCH(VideoFormat, format);
    QFETCH(QSize, size);
    QFETCH(double, fps);
    QFETCH(QString, problem);
    QTemporaryDir dir;
    const QString path = dir.filePath(u"bad.out"_qs);
    VideoWriter writer;
    QString error;
    QVERIFY(!writer.open(path, format, size, fps, {}, &error));
    QVERIFY2(error.startsWith(QDir::toNativeSeparators(path) + u": "_qs + problem), qPrintable(error));
    QVERIFY(!writer.isOpen());
    QCOMPARE(allEntries(dir.path()), QStringList());
}

void TestVideoEncoder::unreadableAudio()
{
    QTemporaryDir dir;
    const QString missing = dir.filePath(u"missing.wav"_qs);
    QString error;
    VideoWriter writer;
    QVERIFY(!writer.open(
        dir.filePath(u"a.mp4"_qs), VideoFormat::Mp4, QSize(32, 32), 25, AudioSource::fromFile(missing), &error));
    QVERIFY2(error == missing + u": no such file"_qs, qPrintable(error)); // never handed to FFmpeg

    const QString text = dir.filePath(u"notes.wav"_qs);
    QFile f(text);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("this is not a sound file at all, just some text.\n");
    f.close();
    QVERIFY(!writer.open(
        dir.filePath(u"a.mp4"_qs), VideoFormat::Mp4, QSize(32, 32), 25, AudioSource::fromFile(text), &error));
    QVERIFY2(error.startsWith(text + u": cannot read the audio"_qs), qPrintable(error));
    QVERIFY(!writer.open(dir.filePath(u"a.mp4"_qs), VideoFormat::Mp4, QSize(32, 32), 25,
        AudioSource::fromSamples(sine(1, 8000), 0), &error));
    QVERIFY2(error.contains(u"invalid sample rate 0"_qs), qPrintable(error));
    QCOMPARE(allEntries(dir.path()), (QStringList {u"notes.wav"_qs}));
    QVERIFY(!readAudio(missing, 16000, &error));
    QVERIFY2(error.startsWith(missing + u": "_qs), qPrintable(error));
}

void TestVideoEncoder::frameOfTheWrongSize()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(u"w.mp4"_qs);
    VideoWriter writer;
    QString error;
    QVERIFY(writer.open(path, VideoFormat::Mp4, QSize(64, 64), 25, {}, &error));
    QVERIFY(writer.addFrame(movingShape(0, QSize(64, 64)), &error));
    QVERIFY(!writer.addFrame(movingShape(1, QSize(64, 48)), &error));
    QCOMPARE(error, path + u": frame 2 is 64x48, the video is 64x64"_qs);
    QCOMPARE(writer.framesAdded(), 1);
    QVERIFY(writer.finish(&error));
    QCOMPARE(probeMedia(path, &error)->frameCount, 1);
}

void TestVideoEncoder::noFrames_data()
{
    cancelLeavesNothing_data();
}

void TestVideoEncoder::noFrames()
{
    QFETCH(VideoFormat, format);
    QFETCH(QString, name);
    QTemporaryDir dir;
    const QString path = name.isEmpty() ? dir.path() : dir.filePath(name);
    QString error;
    QVERIFY(!writeFrames(path, format, QSize(32, 32), 25, 0, {}, &error));
    QCOMPARE(error, QDir::toNativeSeparators(path) + u": no frames to write"_qs);
    QCOMPARE(allEntries(dir.path()), QStringList());
}

void TestVideoEncoder::unwritableFolder()
{
    QTemporaryDir dir;
    QString error;
    VideoWriter writer;
    const QString missing = dir.filePath(u"no/such/folder/a.mp4"_qs);
    QVERIFY(!writer.open(missing, VideoFormat::Mp4, QSize(32, 32), 25, {}, &error));
    QVERIFY2(error.startsWith(missing + u": cannot write: the folder "_qs) && error.endsWith(u" does not exist"_qs),
        qPrintable(error));

    // A file stands where the folder should be.
    const QString file = dir.filePath(u"file"_qs);
    QFile f(file);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.close();
    QVERIFY(!writer.open(file + u"/a.gif"_qs, VideoFormat::Gif, QSize(32, 32), 25, {}, &error));
    QVERIFY2(error.startsWith(file + u"/a.gif: cannot write"_qs), qPrintable(error));
    QVERIFY(!writer.open(file, VideoFormat::PngSequence, QSize(32, 32), 25, {}, &error));
    QVERIFY2(error.startsWith(file + u": cannot write PNG frames"_qs), qPrintable(error));
    QVERIFY(!writer.open(file + u"/frames"_qs, VideoFormat::PngSequence, QSize(32, 32), 25, {}, &error));
    QVERIFY2(error.startsWith(file + u"/frames: cannot create the folder"_qs), qPrintable(error));
    QVERIFY(!writer.open(dir.path(), VideoFormat::Mp4, QSize(32, 32), 25, {}, &error));
    QVERIFY2(error.startsWith(dir.path() + u": cannot write: it is a folder"_qs), qPrintable(error));

#ifdef Q_OS_UNIX
    if (geteuid() == 0)
        QSKIP("running as root: a read-only folder is writable");
    const QString readOnly = dir.filePath(u"ro"_qs);
    QVERIFY(QDir().mkdir(readOnly));
    QVERIFY(QFile::setPermissions(readOnly, QFile::ReadOwner | QFile::ExeOwner));
    QVERIFY(!writer.open(readOnly + u"/a.mp4"_qs, VideoFormat::Mp4, QSize(32, 32), 25, {}, &error));
    QVERIFY2(error.startsWith(readOnly + u"/a.mp4: cannot write in the folder"_qs), qPrintable(error));
    QVERIFY(!writeFrames(readOnly, VideoFormat::PngSequence, QSize(32, 32), 25, 2, {}, &error));
    QVERIFY2(error.startsWith(readOnly + u": cannot write frame_00001.png"_qs), qPrintable(error));
    QFile::setPermissions(readOnly, QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
#endif
}

void TestVideoEncoder::probeErrors()
{
    QTemporaryDir dir;
    QString error;
    const QString missing = dir.filePath(u"none.mp4"_qs);
    QVERIFY(!probeMedia(missing, &error));
    QVERIFY2(error == missing + u": no such file"_qs, qPrintable(error));
    QVERIFY(!probeMedia(dir.path(), &error));
    QVERIFY2(error.startsWith(dir.path() + u": no frame_NNNNN.png files"_qs), qPrintable(error));
    QVERIFY(!readVideoFrame(missing, 0, &error));
    QVERIFY2(error == missing + u": no such file"_qs, qPrintable(error));
    const QString path = dir.filePath(u"short.gif"_qs);
    QVERIFY(writeFrames(path, VideoFormat::Gif, QSize(16, 16), 25, 3, {}, &error));
    QVERIFY(!readVideoFrame(path, 3, &error));
    QCOMPARE(error, path + u": has no frame 3 (it has 3)"_qs);
}

TOONFACE_TEST_GUILESS_MAIN(TestVideoEncoder)
#include "tst_videoencoder.moc"
