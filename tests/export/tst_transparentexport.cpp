#include "animationfixture.h"
#include "testmain.h"

#include "export/animationexport.h"
#include "export/exportpreset.h"
#include "export/keptframes.h"
#include "media/mediareader.h"
#include "render/style.h"

#include <QDir>
#include <QFile>
#include <QImageReader>
#include <QTemporaryDir>
#include <QtTest>

#include <webp/demux.h>

using namespace toonface;

Q_DECLARE_METATYPE(toonface::AnimationFormat)

namespace {

// A short talking timeline with a head shake: 2 s at 10 fps, with a tone's sound when given.
Timeline talkingTimeline(const QString &audioPath = {}, double length = 2.0)
{
    Timeline t;
    t.setFrameRate(10);
    t.addMouthCues({{0.1, 0.5, MouthShape::A}, {0.6, 0.9, MouthShape::O}, {1.0, 1.5, MouthShape::I}});
    t.addBlink({0.7, 0.15});
    t.addShake(0.2, 1.4, 12.0, 2.0);
    t.setAudioClips({AudioClip {audioPath, 0.0, length}});
    return t;
}

ExportRequest request(AnimationFormat format, const QString &out, const QString &audioPath = {})
{
    ExportRequest r;
    r.format = format;
    r.outputPath = out;
    r.size = 128;
    r.face = test::animationFace();
    r.style = Style::preset(QStringLiteral("normal"));
    r.timeline = talkingTimeline(audioPath);
    return r;
}

QString outputName(AnimationFormat format)
{
    return format == AnimationFormat::PngSequence ? QStringLiteral("frames/")
                                                  : QStringLiteral("out.") + animationFormatSuffix(format);
}

QStringList entries(const QString &dir)
{
    return QDir(dir).entryList(QDir::AllEntries | QDir::Hidden | QDir::System | QDir::NoDotAndDotDot, QDir::Name);
}

struct WebpFrame
{
    QImage image;
    int endMs; // when it gives way to the next
};

// Every frame of an animated WebP, decoded by libwebp (FFmpeg 5.1 reads no animated WebP).
// libwebp merges a frame that repeats the last into it, lengthening it.
QVector<WebpFrame> webpFrames(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    const QByteArray data = f.readAll();
    WebPData webp {reinterpret_cast<const uint8_t *>(data.constData()), size_t(data.size())};
    WebPAnimDecoderOptions options;
    WebPAnimDecoderOptionsInit(&options);
    options.color_mode = MODE_BGRA; // QImage::Format_ARGB32 on little-endian machines
    WebPAnimDecoder *decoder = WebPAnimDecoderNew(&webp, &options);
    if (!decoder)
        return {};
    WebPAnimInfo info;
    WebPAnimDecoderGetInfo(decoder, &info);
    QVector<WebpFrame> frames;
    while (WebPAnimDecoderHasMoreFrames(decoder)) {
        uint8_t *pixels = nullptr;
        int timestamp = 0;
        if (!WebPAnimDecoderGetNext(decoder, &pixels, &timestamp))
            break;
        frames << WebpFrame {
            QImage(pixels, int(info.canvas_width), int(info.canvas_height), QImage::Format_ARGB32).copy(), timestamp};
    }
    WebPAnimDecoderDelete(decoder);
    return frames;
}

// Frame `index` of an export decoded as its users' programs would, alpha kept.
std::optional<QImage> decodedFrame(AnimationFormat format, const QString &path, int index, QString *error)
{
    switch (format) {
    case AnimationFormat::PngSequence: {
        const QImage image(QDir(path).filePath(QStringLiteral("frame_%1.png").arg(index + 1, 5, 10, QLatin1Char('0'))));
        if (image.isNull())
            return std::nullopt;
        return image.convertToFormat(QImage::Format_ARGB32);
    }
    case AnimationFormat::WebP: { // the frame showing at frame `index`'s time (10 fps)
        for (const WebpFrame &frame : webpFrames(path)) {
            if (frame.endMs > index * 100)
                return frame.image;
        }
        *error = QStringLiteral("%1: libwebp decoded no frame %2").arg(path).arg(index);
        return std::nullopt;
    }
    case AnimationFormat::Gif: {
        // Qt's reader composes frames as browsers do (disposal methods included).
        QImageReader reader(path);
        QImage image;
        for (int i = 0; i <= index; ++i)
            image = reader.read();
        if (image.isNull()) {
            *error = QStringLiteral("%1: %2").arg(path, reader.errorString());
            return std::nullopt;
        }
        return image.convertToFormat(QImage::Format_ARGB32);
    }
    default: return readVideoFrame(path, index, error);
    }
}

// The export's own frame drawn with a transparent background: where it is fully transparent,
// and where fully opaque.
QImage expectedFrame(const ExportRequest &r, int index)
{
    ExportRequest frames = r;
    frames.format = AnimationFormat::PngSequence;
    frames.background = ExportBackground::transparent();
    static QTemporaryDir dir;
    const QString out = dir.filePath(QStringLiteral("expected%1/").arg(qHash(r.outputPath)));
    if (!QFileInfo::exists(out + QStringLiteral("frame_00001.png"))) {
        frames.outputPath = out;
        if (!exportAnimation(frames).ok())
            return {};
    }
    return QImage(QDir(out).filePath(QStringLiteral("frame_%1.png").arg(index + 1, 5, 10, QLatin1Char('0'))))
        .convertToFormat(QImage::Format_ARGB32);
}

} // namespace

class TestTransparentExport : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    QString m_tone;

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
        m_tone = m_dir.filePath(QStringLiteral("tone.wav"));
        QVERIFY(test::writeToneWav(m_tone, 2.0));
    }

    void backgroundsFromText()
    {
        QString error;
        QCOMPARE(parseExportBackground(QStringLiteral("transparent"), &error), ExportBackground::transparent());
        QCOMPARE(parseExportBackground(QStringLiteral("auto"), &error), ExportBackground {});
        QCOMPARE(parseExportBackground(QStringLiteral("#336699"), &error),
            ExportBackground::ofColour(QColor(0x33, 0x66, 0x99)));
        QCOMPARE(parseExportBackground(QStringLiteral("#fff"), &error), ExportBackground::ofColour(Qt::white));
        QCOMPARE(parseExportBackground(QStringLiteral("green"), &error), ExportBackground::ofColour(QColor("green")));
        QCOMPARE(parseExportBackground(m_tone, &error), ExportBackground::ofPhoto(m_tone));
        for (const QString &bad : {u"notacolour"_qs, u"#12345"_qs, u"#80ff0000"_qs, u""_qs, u"/no/such.png"_qs}) {
            error.clear();
            QVERIFY2(!parseExportBackground(bad, &error), qPrintable(bad));
            QVERIFY2(error.contains(QLatin1Char('\'') + bad + QLatin1Char('\'')), qPrintable(error));
            QVERIFY(error.contains(u"transparent"));
        }
    }

    void defaultsPerFormat()
    {
        for (AnimationFormat f : kAllAnimationFormats) {
            const ExportRequest r = request(f, QStringLiteral("x"));
            const ExportBackground b = effectiveBackground(r);
            const bool alpha = f == AnimationFormat::WebM || f == AnimationFormat::Mov || f == AnimationFormat::Apng
                || f == AnimationFormat::WebP || f == AnimationFormat::PngSequence;
            QCOMPARE(animationFormatHasAlpha(f), alpha);
            if (alpha || !isRasterFormat(f))
                QCOMPARE(b.kind, ExportBackground::Kind::Transparent);
            else
                QCOMPARE(b, ExportBackground::ofColour(Qt::white));
        }
        QCOMPARE(animationFormatForPath(QStringLiteral("a.WEBM")), AnimationFormat::WebM);
        QCOMPARE(animationFormatForPath(QStringLiteral("a.mov")), AnimationFormat::Mov);
        QCOMPARE(animationFormatForPath(QStringLiteral("a.apng")), AnimationFormat::Apng);
        QCOMPARE(animationFormatForPath(QStringLiteral("a.webp")), AnimationFormat::WebP);
    }

    void alphaInEveryFormat_data()
    {
        QTest::addColumn<AnimationFormat>("format");
        QTest::newRow("webm") << AnimationFormat::WebM;
        QTest::newRow("mov") << AnimationFormat::Mov;
        QTest::newRow("apng") << AnimationFormat::Apng;
        QTest::newRow("webp") << AnimationFormat::WebP;
        QTest::newRow("png frames") << AnimationFormat::PngSequence;
        QTest::newRow("gif") << AnimationFormat::Gif;
    }

    // Decoded, the background is alpha 0 and the face opaque, frame after frame as the head
    // moves (a GIF must not leave the last frame's face behind).
    void alphaInEveryFormat()
    {
        QFETCH(AnimationFormat, format);
        const QString dir = newFolder(QStringLiteral("alpha-") + animationFormatSuffix(format));
        ExportRequest r = request(format, QDir(dir).filePath(outputName(format)), m_tone);
        if (format == AnimationFormat::Gif)
            r.background = ExportBackground::transparent(); // GIF is opaque unless asked
        const ExportResult result = exportAnimation(r);
        QVERIFY2(result.ok(), qPrintable(result.error));
        QString error;
        if (format == AnimationFormat::WebP) { // FFmpeg 5.1 reads no animated WebP
            const QVector<WebpFrame> frames = webpFrames(r.outputPath);
            QVERIFY(frames.size() > 10);
            QCOMPARE(frames.last().endMs, 2000);
        } else {
            const std::optional<MediaInfo> info = probeMedia(r.outputPath, &error);
            QVERIFY2(info, qPrintable(error));
            QCOMPARE(info->frameCount, 20);
            if (format != AnimationFormat::PngSequence) // counted, not decoded
                QVERIFY2(info->hasAlpha, qPrintable(info->pixelFormat));
            if (format == AnimationFormat::WebM) {
                QCOMPARE(info->pixelFormat, u"yuva420p"_qs);
                QCOMPARE(info->audioCodec, u"opus"_qs);
            }
            if (format == AnimationFormat::Mov) {
                QVERIFY2(info->pixelFormat.startsWith(u"yuva444p"), qPrintable(info->pixelFormat));
                QCOMPARE(info->videoCodec, u"prores"_qs);
                QCOMPARE(info->audioCodec, u"pcm_s16le"_qs);
            }
            QCOMPARE(info->hasAudio, format == AnimationFormat::WebM || format == AnimationFormat::Mov);
        }

        for (int index : {0, 4, 8, 12, 19}) {
            const std::optional<QImage> frame = decodedFrame(format, r.outputPath, index, &error);
            QVERIFY2(frame, qPrintable(error));
            QCOMPARE(frame->size(), QSize(128, 128));
            QVERIFY(frame->hasAlphaChannel());
            const int w = frame->width() - 1;
            const int h = frame->height() - 1;
            for (QPoint corner : {QPoint(0, 0), QPoint(w, 0), QPoint(0, h), QPoint(w, h)})
                QCOMPARE(qAlpha(frame->pixel(corner)), 0);
            QCOMPARE(qAlpha(frame->pixel(frame->width() / 2, frame->height() / 2)), 255);
            // Pixel by pixel against the drawing: transparent where it is, opaque where it is
            // (a lossy format may blur a pixel or two along the edge).
            const QImage expected = expectedFrame(r, index);
            QVERIFY(!expected.isNull());
            int wrong = 0;
            int clear = 0;
            for (int y = 0; y < expected.height(); ++y) {
                for (int x = 0; x < expected.width(); ++x) {
                    const int want = qAlpha(expected.pixel(x, y));
                    const int got = qAlpha(frame->pixel(x, y));
                    clear += want == 0;
                    if ((want == 0 && got > 8) || (want == 255 && got < 247))
                        ++wrong;
                }
            }
            QVERIFY(clear > expected.width() * expected.height() / 10); // there is a background
            QVERIFY2(wrong <= expected.width() * expected.height() / 200,
                qPrintable(QStringLiteral("frame %1: %2 pixels of the wrong alpha").arg(index).arg(wrong)));
        }
    }

    void backgroundColourAndPhoto()
    {
        const QString dir = newFolder(QStringLiteral("backgrounds"));
        ExportRequest r = request(AnimationFormat::WebM, QDir(dir).filePath(QStringLiteral("green.webm")));
        r.background = ExportBackground::ofColour(QColor(0, 160, 0));
        ExportResult result = exportAnimation(r);
        QVERIFY2(result.ok(), qPrintable(result.error));
        QString error;
        std::optional<QImage> frame = readVideoFrame(r.outputPath, 3, &error);
        QVERIFY2(frame, qPrintable(error));
        QCOMPARE(qAlpha(frame->pixel(0, 0)), 255);
        QVERIFY(qGreen(frame->pixel(0, 0)) > 140 && qRed(frame->pixel(0, 0)) < 20);
        // Opaque frames: a plain VP9 stream, no alpha to decode.
        const std::optional<MediaInfo> opaque = probeMedia(r.outputPath, &error);
        QVERIFY2(opaque, qPrintable(error));
        QVERIFY(!opaque->hasAlpha);
        QCOMPARE(opaque->pixelFormat, u"yuv420p"_qs);

        // A photo of a red left half and a blue right half covers the frame.
        QImage photo(300, 200, QImage::Format_RGB32);
        photo.fill(Qt::blue);
        for (int y = 0; y < 200; ++y)
            for (int x = 0; x < 150; ++x)
                photo.setPixel(x, y, qRgb(255, 0, 0));
        const QString photoPath = QDir(dir).filePath(QStringLiteral("backdrop.png"));
        QVERIFY(photo.save(photoPath));
        r.outputPath = QDir(dir).filePath(QStringLiteral("photo.mp4"));
        r.format = AnimationFormat::Mp4;
        r.background = ExportBackground::ofPhoto(photoPath);
        result = exportAnimation(r);
        QVERIFY2(result.ok(), qPrintable(result.error));
        frame = readVideoFrame(r.outputPath, 3, &error);
        QVERIFY2(frame, qPrintable(error));
        QVERIFY(qRed(frame->pixel(2, 2)) > 200 && qBlue(frame->pixel(2, 2)) < 60);
        QVERIFY(qBlue(frame->pixel(125, 125)) > 200 && qRed(frame->pixel(125, 125)) < 60);

        r.outputPath = QDir(dir).filePath(QStringLiteral("nophoto.webm"));
        r.format = AnimationFormat::WebM;
        r.background = ExportBackground::ofPhoto(QDir(dir).filePath(QStringLiteral("missing.png")));
        result = exportAnimation(r);
        QCOMPARE(result.status, ExportStatus::BadInput);
        QVERIFY2(result.error.contains(u"missing.png"), qPrintable(result.error));
        QVERIFY(!QFileInfo::exists(r.outputPath));
    }

    void badBackgrounds()
    {
        const QString dir = newFolder(QStringLiteral("bad"));
        ExportRequest r = request(AnimationFormat::Mp4, QDir(dir).filePath(QStringLiteral("clear.mp4")));
        r.background = ExportBackground::transparent();
        ExportResult result = exportAnimation(r);
        QCOMPARE(result.status, ExportStatus::BadInput);
        QVERIFY2(result.error.contains(u"clear.mp4") && result.error.contains(u"MP4"), qPrintable(result.error));

        r.format = AnimationFormat::SmilSvg;
        r.outputPath = QDir(dir).filePath(QStringLiteral("green.svg"));
        r.background = ExportBackground::ofColour(Qt::green);
        result = exportAnimation(r);
        QCOMPARE(result.status, ExportStatus::BadInput);
        QVERIFY2(result.error.contains(u"green.svg"), qPrintable(result.error));
        QCOMPARE(entries(dir), QStringList());
    }

    // A stretch of the animation: its frames and its sound start there.
    void startAndDuration()
    {
        const QString dir = newFolder(QStringLiteral("trim"));
        ExportRequest r = request(AnimationFormat::WebM, QDir(dir).filePath(QStringLiteral("part.webm")), m_tone);
        r.start = 0.5;
        r.duration = 1.0;
        QCOMPARE(exportFrameCount(r), 10);
        QCOMPARE(exportDuration(r), 1.0);
        const ExportResult result = exportAnimation(r);
        QVERIFY2(result.ok(), qPrintable(result.error));
        QString error;
        const std::optional<MediaInfo> info = probeMedia(r.outputPath, &error);
        QVERIFY2(info, qPrintable(error));
        QCOMPARE(info->frameCount, 10);
        QVERIFY2(std::abs(info->audioDurationS - 1.0) < 0.03, qPrintable(QString::number(info->audioDurationS)));
        // Its first frame is the animation's frame 5.
        const std::optional<QImage> first = readVideoFrame(r.outputPath, 0, &error);
        QVERIFY2(first, qPrintable(error));
        const QImage expected = expectedFrame(request(AnimationFormat::WebM, QStringLiteral("whole.webm")), 5);
        const QImage other = expectedFrame(request(AnimationFormat::WebM, QStringLiteral("whole.webm")), 0);
        int nearExpected = 0;
        int nearOther = 0;
        for (int y = 0; y < 128; y += 2) {
            for (int x = 0; x < 128; x += 2) {
                nearExpected += std::abs(qAlpha(first->pixel(x, y)) - qAlpha(expected.pixel(x, y))) > 128;
                nearOther += std::abs(qAlpha(first->pixel(x, y)) - qAlpha(other.pixel(x, y))) > 128;
            }
        }
        QVERIFY2(nearExpected < nearOther, qPrintable(QStringLiteral("%1 vs %2").arg(nearExpected).arg(nearOther)));

        r.start = 5.0;
        r.outputPath = QDir(dir).filePath(QStringLiteral("late.webm"));
        const ExportResult late = exportAnimation(r);
        QCOMPARE(late.status, ExportStatus::BadInput);
        QVERIFY2(late.error.contains(u"late.webm"), qPrintable(late.error));
        QVERIFY(!QFileInfo::exists(r.outputPath));
    }

    void presetsByName()
    {
        QCOMPARE(exportPresetNames(), (QStringList {u"telegram-sticker"_qs, u"emoji"_qs, u"slide-overlay"_qs}));
        QVERIFY(!exportPresetNamed(QStringLiteral("tiktok")));
        const ExportRequest r = withPreset(request(AnimationFormat::Mp4, QStringLiteral("s.webm")),
            *exportPresetNamed(QStringLiteral("telegram-sticker")));
        QCOMPARE(r.format, AnimationFormat::WebM);
        QCOMPARE(exportFrameSize(r), QSize(512, 512));
        QVERIFY(r.silent);
        QCOMPARE(r.background.kind, ExportBackground::Kind::Transparent);
        QCOMPARE(exportFrameSize(withPreset(r, *exportPresetNamed(QStringLiteral("emoji")))), QSize(100, 100));
        const ExportRequest slide = withPreset(r, *exportPresetNamed(QStringLiteral("slide-overlay")));
        QCOMPARE(exportFrameSize(slide), QSize(1080, 1080));
    }

    void presetsMeetTheirLimits_data()
    {
        QTest::addColumn<QString>("name");
        QTest::newRow("telegram-sticker") << u"telegram-sticker"_qs;
        QTest::newRow("emoji") << u"emoji"_qs;
    }

    // A 3-second clip at the timeline's 40 frames a second: the rate is capped, the sound
    // left out, the file within its size.
    void presetsMeetTheirLimits()
    {
        QFETCH(QString, name);
        const ExportPreset preset = *exportPresetNamed(name);
        const QString dir = newFolder(QStringLiteral("preset-") + name);
        ExportRequest r = request(AnimationFormat::WebM, QDir(dir).filePath(QStringLiteral("sticker.webm")), m_tone);
        r.timeline = test::animationTimeline(m_tone);
        r.timeline.setFrameRate(40);
        r.duration = 3.0;
        const ExportResult result = exportWithPreset(r, preset);
        QVERIFY2(result.ok(), qPrintable(result.error));
        QVERIFY(QFileInfo(r.outputPath).size() <= preset.maxBytes);
        QString error;
        const std::optional<MediaInfo> info = probeMedia(r.outputPath, &error);
        QVERIFY2(info, qPrintable(error));
        QCOMPARE(QSize(info->width, info->height), QSize(preset.side, preset.side));
        QVERIFY(info->fps <= preset.maxFps);
        QVERIFY(info->videoDurationS <= preset.maxSeconds + 1e-6);
        QVERIFY(!info->hasAudio);
        QVERIFY(info->hasAlpha);
        QCOMPARE(entries(dir), QStringList {u"sticker.webm"_qs});
    }

    // Too long a clip: which limit, by how much, and no file (an older file is kept).
    void presetRefusesALongClip()
    {
        const QString dir = newFolder(QStringLiteral("long"));
        const QString out = QDir(dir).filePath(QStringLiteral("sticker.webm"));
        QFile old(out);
        QVERIFY(old.open(QIODevice::WriteOnly) && old.write("old") == 3);
        old.close();
        ExportRequest r = request(AnimationFormat::WebM, out);
        r.timeline = test::animationTimeline();
        r.duration = 5.2;
        const ExportResult result = exportWithPreset(r, *exportPresetNamed(QStringLiteral("telegram-sticker")));
        QCOMPARE(result.status, ExportStatus::OverLimit);
        QVERIFY2(result.error.contains(u"5.2 s") && result.error.contains(u"3 s") && result.error.contains(u"2.2 s"),
            qPrintable(result.error));
        QCOMPARE(entries(dir), QStringList {u"sticker.webm"_qs});
        QCOMPARE(QFileInfo(out).size(), 3);
    }

    // Over the limit at the first quality: encoded again at lower quality until it fits.
    void presetLowersTheQualityToFit()
    {
        const QString dir = newFolder(QStringLiteral("fit"));
        ExportPreset preset = *exportPresetNamed(QStringLiteral("telegram-sticker"));
        ExportRequest first
            = withPreset(request(AnimationFormat::WebM, QDir(dir).filePath(QStringLiteral("first.webm"))), preset);
        first.vp9Crf = 30; // the preset's first try
        const ExportResult firstResult = exportAnimation(first);
        QVERIFY2(firstResult.ok(), qPrintable(firstResult.error));
        const qint64 firstBytes = QFileInfo(first.outputPath).size();
        QVERIFY(QFile::remove(first.outputPath));
        preset.maxBytes = firstBytes * 6 / 10;
        ExportRequest r = request(AnimationFormat::WebM, QDir(dir).filePath(QStringLiteral("fits.webm")));
        const ExportResult result = exportWithPreset(r, preset);
        QVERIFY2(result.ok(), qPrintable(result.error));
        const qint64 bytes = QFileInfo(r.outputPath).size();
        QVERIFY2(bytes <= preset.maxBytes && bytes > 0,
            qPrintable(QStringLiteral("%1 of %2 (first try %3)").arg(bytes).arg(preset.maxBytes).arg(firstBytes)));
        QCOMPARE(entries(dir), QStringList {u"fits.webm"_qs});
        // Encoded more than once, drawn once.
        QVERIFY2(result.encodings >= 2, qPrintable(QString::number(result.encodings)));
        QCOMPARE(result.framesDrawn, exportFrameCount(withPreset(r, preset)));
        QString error;
        const std::optional<MediaInfo> info = probeMedia(r.outputPath, &error);
        QVERIFY2(info && info->hasAlpha, qPrintable(error));
        QCOMPARE(info->frameCount, exportFrameCount(withPreset(r, preset)));
    }

    // Frames kept by one export are encoded by the next without being drawn again, pixel for
    // pixel the same; a request of another size draws them anew.
    void keptFramesAreEncodedAgain()
    {
        const QString dir = newFolder(QStringLiteral("kept"));
        ExportRequest r = request(AnimationFormat::PngSequence, QDir(dir).filePath(QStringLiteral("drawn/")));
        r.keptFrames = std::make_shared<KeptFrames>();
        const ExportResult drawn = exportAnimation(r);
        QVERIFY2(drawn.ok(), qPrintable(drawn.error));
        const int frames = exportFrameCount(r);
        QCOMPARE(drawn.framesDrawn, frames);
        QCOMPARE(r.keptFrames->count(), frames);
        // Compressed well below the raw pictures.
        const qint64 raw = qint64(frames) * exportFrameSize(r).width() * exportFrameSize(r).height() * 4;
        QVERIFY2(r.keptFrames->bytes() < raw / 4,
            qPrintable(QStringLiteral("%1 of %2").arg(r.keptFrames->bytes()).arg(raw)));

        r.outputPath = QDir(dir).filePath(QStringLiteral("again/"));
        const ExportResult again = exportAnimation(r);
        QVERIFY2(again.ok(), qPrintable(again.error));
        QCOMPARE(again.framesDrawn, 0);
        const QStringList names = entries(QDir(dir).filePath(QStringLiteral("drawn")));
        QCOMPARE(names.size(), frames);
        QCOMPARE(entries(QDir(dir).filePath(QStringLiteral("again"))), names);
        for (const QString &name : names) {
            const QImage a(QDir(dir).filePath(QStringLiteral("drawn/") + name));
            const QImage b(QDir(dir).filePath(QStringLiteral("again/") + name));
            QVERIFY(!a.isNull() && a.hasAlphaChannel());
            QCOMPARE(b, a);
        }

        r.size = 64;
        r.outputPath = QDir(dir).filePath(QStringLiteral("smaller/"));
        const ExportResult smaller = exportAnimation(r);
        QVERIFY2(smaller.ok(), qPrintable(smaller.error));
        QCOMPARE(smaller.framesDrawn, frames);
        QCOMPARE(QImage(QDir(dir).filePath(QStringLiteral("smaller/") + names.first())).size(), exportFrameSize(r));
    }

    // A size no quality reaches: the quality is lowered first, then the export gives up
    // saying by how much the smallest file is over.
    void presetGivesUpOnSize()
    {
        const QString dir = newFolder(QStringLiteral("tiny"));
        ExportPreset tiny = *exportPresetNamed(QStringLiteral("telegram-sticker"));
        tiny.maxBytes = 2048;
        ExportRequest r = request(AnimationFormat::WebM, QDir(dir).filePath(QStringLiteral("tiny.webm")));
        std::vector<double> reported;
        const ExportResult result = exportWithPreset(r, tiny, [&](double f) { reported.push_back(f); });
        QCOMPARE(result.status, ExportStatus::OverLimit);
        QVERIFY2(result.error.contains(u"lowest quality") && result.error.contains(u"2.0 KB")
                && result.error.contains(u"tiny.webm"),
            qPrintable(result.error));
        QVERIFY(std::is_sorted(reported.begin(), reported.end()));
        QCOMPARE(entries(dir), QStringList());
        QVERIFY(result.encodings >= 2);
        QCOMPARE(result.framesDrawn, exportFrameCount(withPreset(r, tiny)));

        // The wrong output type for the preset.
        r.outputPath = QDir(dir).filePath(QStringLiteral("sticker.gif"));
        const ExportResult gif = exportWithPreset(r, tiny);
        QCOMPARE(gif.status, ExportStatus::OverLimit);
        QVERIFY2(gif.error.contains(u".webm"), qPrintable(gif.error));
        QCOMPARE(entries(dir), QStringList());
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestTransparentExport)
#include "tst_transparentexport.moc"
