#include "export/videoencoder.h"
#include "imagedifference.h"
#include "numberedclip.h"
#include "testmain.h"
#include "track/videofilesource.h"

#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace toonface;
using testing::meanDifference;

namespace {

// A clip of `frames` frames at `fps`: frame i is grey level 10 * i (so frames can be told apart).
QString writeClip(const QTemporaryDir &dir, int frames, double fps)
{
    const QString path = dir.filePath(QStringLiteral("grey.mp4"));
    VideoWriter writer;
    QString error;
    if (!writer.open(path, VideoFormat::Mp4, QSize(64, 48), fps, AudioSource {}, &error))
        return {};
    for (int i = 0; i < frames; ++i) {
        QImage image(64, 48, QImage::Format_RGB32);
        image.fill(QColor(10 * i, 10 * i, 10 * i));
        if (!writer.addFrame(image, &error))
            return {};
    }
    return writer.finish(&error) ? path : QString();
}

} // namespace

class TestVideoFileSource : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void decodesEveryFrameInOrder()
    {
        QTemporaryDir dir;
        const QString path = writeClip(dir, 20, 25);
        QVERIFY(!path.isEmpty());
        VideoFileSource source;
        QString error;
        QVERIFY2(source.open(path, &error), qPrintable(error));
        QCOMPARE(source.frameSize(), QSize(64, 48));
        QCOMPARE(source.frameRate(), 25.0);
        QCOMPARE(source.frameCount(), 20);
        QVERIFY(!source.hasAudio());
        int n = 0;
        while (std::optional<VideoFrame> f = source.next()) {
            QCOMPARE(f->index, n);
            QVERIFY(std::abs(f->time - n / 25.0) < 1e-6);
            QCOMPARE(f->image.size(), QSize(64, 48));
            QVERIFY(std::abs(qGray(f->image.pixel(32, 24)) - 10 * n) <= 3);
            ++n;
        }
        QCOMPARE(n, 20);
        QVERIFY(source.error().isEmpty());
        QVERIFY(!source.next()); // stays at the end
    }

    void badFilesNameTheFileAndTheProblem()
    {
        QTemporaryDir dir;
        VideoFileSource source;
        QString error;
        const QString missing = dir.filePath(QStringLiteral("missing.mp4"));
        QVERIFY(!source.open(missing, &error));
        QVERIFY(error.startsWith(missing + QStringLiteral(": ")));
        QVERIFY(!source.next());

        const QString garbage = dir.filePath(QStringLiteral("garbage.mp4"));
        QFile f(garbage);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QByteArray(5000, 'x'));
        f.close();
        QVERIFY(!source.open(garbage, &error));
        QVERIFY2(error.startsWith(garbage + QStringLiteral(": ")), qPrintable(error));
    }

    void truncatedFileEndsEarlyWithoutCrashing()
    {
        QTemporaryDir dir;
        const QString path = writeClip(dir, 50, 25);
        QVERIFY(!path.isEmpty());
        QFile in(path);
        QVERIFY(in.open(QIODevice::ReadOnly));
        const QByteArray all = in.readAll();
        // MP4 keeps its index at the end (no faststart): a cut file cannot be opened at all.
        const QString cut = dir.filePath(QStringLiteral("cut.mp4"));
        QFile out(cut);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(all.left(all.size() / 2));
        out.close();
        VideoFileSource source;
        QString error;
        if (source.open(cut, &error)) {
            int n = 0;
            while (source.next())
                ++n;
            QVERIFY(n < 50);
        } else {
            QVERIFY2(error.startsWith(cut + QStringLiteral(": ")), qPrintable(error));
        }
        const QString grid = QStringLiteral(TOONFACE_SHARED_DATA "/video/bbaf2n.mpg");
        QFile clip(grid);
        if (!clip.open(QIODevice::ReadOnly))
            QSKIP("the GRID clips of shared/data/video are absent");
        const QByteArray mpg = clip.readAll();
        const QString cutMpg = dir.filePath(QStringLiteral("cut.mpg"));
        QFile outMpg(cutMpg);
        QVERIFY(outMpg.open(QIODevice::WriteOnly));
        outMpg.write(mpg.left(mpg.size() * 4 / 10));
        outMpg.close();
        QVERIFY2(source.open(cutMpg, &error), qPrintable(error));
        int n = 0;
        while (source.next())
            ++n;
        QVERIFY2(n > 10 && n < 75, qPrintable(QString::number(n))); // the frames before the cut
    }

    // A jump back or far ahead in a long clip lands on the key frame before the frame asked
    // for, with the indices and times reading from the start gives, so reading on reaches the
    // frame after at most a key-frame interval (2 s here), not the whole clip.
    void seeksBackAndFarAhead()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("numbered.mp4"));
        const int frames = 1500; // a minute at 25 fps
        const QString written = numberedclip::write(path, frames, 25);
        QVERIFY2(written.isEmpty(), qPrintable(written));
        VideoFileSource source;
        QString error;
        QVERIFY2(source.open(path, &error), qPrintable(error));
        for (int i = 0; i < 5; ++i)
            QVERIFY(source.next());
        for (const int target : {1200, 300, frames - 1, 0, 760, 761, 20}) {
            QVERIFY2(source.seek(target), qPrintable(QString::number(target)));
            int readBefore = 0;
            std::optional<VideoFrame> f;
            while ((f = source.next()) && f->index < target) {
                QCOMPARE(numberedclip::indexOf(f->image), f->index);
                ++readBefore;
            }
            QVERIFY(f);
            QCOMPARE(f->index, target);
            QCOMPARE(numberedclip::indexOf(f->image), target);
            QVERIFY(std::abs(f->time - target / 25.0) < 1e-6);
            QVERIFY2(readBefore < 50, qPrintable(QStringLiteral("%1: %2 read").arg(target).arg(readBefore)));
            // Reading on after a seek goes frame by frame.
            if (target + 1 < frames) {
                const std::optional<VideoFrame> after = source.next();
                QVERIFY(after);
                QCOMPARE(after->index, target + 1);
                QCOMPARE(numberedclip::indexOf(after->image), target + 1);
            }
        }
        QVERIFY(!source.seek(frames)); // past the end
        QVERIFY(!source.seek(-1));

        // A fresh source seeks before reading anything; a paced one does not seek.
        VideoFileSource fresh;
        QVERIFY2(fresh.open(path, &error), qPrintable(error));
        QVERIFY(fresh.seek(999));
        std::optional<VideoFrame> f;
        while ((f = fresh.next()) && f->index < 999) { }
        QVERIFY(f && numberedclip::indexOf(f->image) == 999);
        VideoFileSource paced;
        VideoFileSource::Options options;
        options.paced = true;
        QVERIFY2(paced.open(path, options, &error), qPrintable(error));
        QVERIFY(!paced.seek(100));
    }

    // An MPEG program stream (the GRID clips) seeks by byte position: the frame reached after a
    // jump is the one reading from the start gives.
    void seeksInAProgramStream()
    {
        const QString grid = QStringLiteral(TOONFACE_SHARED_DATA "/video/bbaf2n.mpg");
        if (!QFile::exists(grid))
            QSKIP("the GRID clips of shared/data/video are absent");
        VideoFileSource source;
        QString error;
        QVERIFY2(source.open(grid, &error), qPrintable(error));
        std::vector<QImage> all;
        while (std::optional<VideoFrame> f = source.next())
            all.push_back(f->image);
        QVERIFY(all.size() >= 70);
        QVERIFY2(source.open(grid, &error), qPrintable(error));
        for (const int target : {60, 12, 70, 0, 45}) {
            QVERIFY2(source.seek(target), qPrintable(QString::number(target)));
            std::optional<VideoFrame> f;
            while ((f = source.next()) && f->index < target) { }
            QVERIFY(f);
            QCOMPARE(f->index, target);
            QVERIFY(std::abs(f->time - target / 25.0) < 1e-3);
            QVERIFY2(meanDifference(f->image, all[size_t(target)]) < 2.0, qPrintable(QString::number(target)));
        }
    }

    void pacedSourceKeepsTimeAndStops()
    {
        QTemporaryDir dir;
        const QString path = writeClip(dir, 20, 25);
        QVERIFY(!path.isEmpty());
        VideoFileSource source;
        QString error;
        VideoFileSource::Options options;
        options.paced = true;
        options.speed = 2.0;
        QVERIFY2(source.open(path, options, &error), qPrintable(error));
        QElapsedTimer timer;
        timer.start();
        int n = 0;
        while (n < 10 && source.next())
            ++n;
        // Ten frames at twice 25 fps: frame 9 is due 0.18 s after frame 0, not before.
        QVERIFY(timer.elapsed() >= 170);
        QCOMPARE(n + source.droppedFrames(), 10);
        source.stop();
        QVERIFY(!source.next());
    }

    void pacedSourceDropsLateFrames()
    {
        QTemporaryDir dir;
        const QString path = writeClip(dir, 20, 25);
        QVERIFY(!path.isEmpty());
        VideoFileSource source;
        QString error;
        VideoFileSource::Options options;
        options.paced = true;
        QVERIFY2(source.open(path, options, &error), qPrintable(error));
        QVERIFY(source.next()); // starts the clock
        QTest::qSleep(300); // a reader that falls 7 frames behind
        const std::optional<VideoFrame> f = source.next();
        QVERIFY(f);
        QVERIFY2(f->index >= 5, qPrintable(QString::number(f->index))); // late frames were skipped
        QCOMPARE(source.droppedFrames(), f->index - 1);
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestVideoFileSource)
#include "tst_videofilesource.moc"
