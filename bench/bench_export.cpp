#include "benchmark.h"

#include "anim/timeline.h"
#include "export/framerenderer.h"
#include "export/smilexport.h"
#include "export/videoencoder.h"
#include "face/averageface.h"
#include "face/mouthshape.h"
#include "io/project.h"
#include "media/mediareader.h"
#include "render/svgface.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QTemporaryDir>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <random>

using namespace toonface;

namespace {

// Frequent Mandarin syllables with their mouth shapes by face-model.md's rules (initials b p m
// give m, f gives f, other initials nothing before a vowel; ao -> a u, ong -> o n h, ...), most
// frequent first.
struct Syllable
{
    const char *pinyin;
    const char *shapes;
};
constexpr Syllable kSyllables[] = {{"de", "e"}, {"shi", "ih"}, {"yi", "i"}, {"bu", "mu"}, {"le", "e"}, {"zai", "ai"},
    {"ren", "en"}, {"wo", "uo"}, {"you", "iou"}, {"ta", "a"}, {"zhe", "e"}, {"ge", "e"}, {"men", "men"}, {"lai", "ai"},
    {"shang", "anh"}, {"guo", "uo"}, {"dao", "au"}, {"shuo", "uo"}, {"dui", "uei"}, {"da", "a"}, {"zhong", "onh"},
    {"sheng", "enh"}, {"hui", "uei"}, {"ke", "e"}, {"ni", "i"}, {"hao", "au"}, {"jiu", "iou"}, {"ye", "ie"},
    {"mei", "mei"}, {"xiang", "ianh"}, {"kan", "an"}, {"zhi", "ih"}, {"qu", "u"}, {"xue", "ue"}, {"nian", "ian"},
    {"tian", "ian"}, {"fa", "fa"}, {"fen", "fen"}, {"ma", "ma"}, {"na", "a"}, {"li", "i"}, {"xie", "ie"},
    {"gong", "onh"}, {"wen", "uen"}, {"er", "eh"}, {"yu", "u"}, {"dian", "ian"}, {"jia", "ia"}, {"bing", "minh"},
    {"hen", "en"}, {"dou", "ou"}, {"qi", "i"}, {"jian", "ian"}, {"lao", "au"}, {"bei", "mei"}, {"neng", "enh"},
    {"xian", "ian"}, {"hou", "ou"}, {"zi", "ih"}, {"yao", "iau"}, {"dong", "onh"}, {"fang", "fanh"}, {"gei", "ei"},
    {"yong", "ionh"}, {"chu", "u"}, {"mian", "mian"}, {"qian", "ian"}, {"wei", "uei"}, {"zuo", "uo"}, {"jin", "in"},
    {"ming", "minh"}, {"kai", "ai"}, {"huan", "uan"}, {"tong", "onh"}, {"ben", "men"}, {"xing", "inh"}, {"yue", "ue"},
    {"yuan", "uan"}, {"yun", "uen"}};

// Ten minutes of Mandarin-like speech as lip sync would give it: syllables drawn by a Zipf
// law from the list above, `shortest`-`longest` s each, their shapes starting at the thesis'
// fractions of the syllable (ch. 5.3); phrases of 6-14 syllables with 0.3-0.9 s pauses and a
// longer breath every fifth phrase. A smile and a surprise, random blinks, a few gaze moves,
// head shakes and nods.
Timeline tenMinutesOfSpeech(double shortest, double longest, double length = 600.0)
{
    static const double fractions[4][4] = {{0}, {0, 0.8095}, {0, 0.4337, 0.8312}, {0, 0.245, 0.4565, 0.7153}};
    std::mt19937 rng(5);
    auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    std::vector<double> weights;
    for (size_t k = 0; k < std::size(kSyllables); ++k)
        weights.push_back(1.0 / std::pow(k + 1.0, 0.8));
    std::discrete_distribution<size_t> pick(weights.begin(), weights.end());

    QVector<MouthCue> cues;
    double t = 0.5;
    int phrase = 0;
    while (t < length - 2.0) {
        const int syllables = 6 + int(rng() % 9);
        for (int s = 0; s < syllables && t < length - 1.0; ++s) {
            const QByteArray shapes(kSyllables[pick(rng)].shapes);
            const double duration = uniform(shortest, longest);
            const int n = int(shapes.size());
            for (int k = 0; k < n; ++k) {
                const double start = t + fractions[n - 1][k] * duration;
                const double end = k + 1 < n ? t + fractions[n - 1][k + 1] * duration : t + duration;
                const auto shape = mouthShapeFromName(QString(QLatin1Char(shapes[k])));
                if (!cues.isEmpty() && cues.last().shape == *shape && cues.last().end == start)
                    cues.last().end = end; // consecutive equal shapes merge
                else
                    cues.append({start, end, *shape});
            }
            t += duration;
        }
        t += ++phrase % 5 == 0 ? uniform(1.0, 2.0) : uniform(0.3, 0.9);
    }
    Timeline timeline;
    timeline.addMouthCues(cues);
    // Placed for ten minutes, scaled to a shorter length.
    const double k = length / 600.0;
    timeline.addEmotionClip({60.0 * k, 180.0 * k, Emotion::Smile, 0.8, 0.5, 0.5});
    timeline.addEmotionClip({300.0 * k, 320.0 * k, Emotion::Surprise, 0.7, 0.3, 0.5});
    timeline.generateBlinks(7, length);
    for (double s = 0; s < length; s += 40.0)
        timeline.addGazeKey({s, {uniform(-0.05, 0.05), uniform(-0.02, 0.02)}});
    for (double s : {30.0, 150.0, 400.0})
        timeline.addShake(s * k, s * k + 1.0);
    for (double s : {90.0, 250.0, 500.0})
        timeline.addNod(s * k, s * k + 1.0);
    timeline.setAudioClips({AudioClip {QStringLiteral("speech.wav"), 0.0, length}});
    return timeline;
}

// A CPU clock (CLOCK_PROCESS_CPUTIME_ID: all threads; CLOCK_THREAD_CPUTIME_ID: this one), ms.
double clockMs(clockid_t clock)
{
    timespec t {};
    clock_gettime(clock, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) / 1e6;
}

// Export of ten minutes at a speaker's pace (syllables of 0.14-0.30 s, about 4.5 a second).
// `fast`: syllables of 0.08-0.18 s, about 10 mouth cues a second over the whole ten minutes.
QJsonObject benchExport(bool fast)
{
    const FaceModel face = averageFace(QRectF(100, 100, 300, 360), QSize(512, 512));
    const MouthShapeSet shapes;
    const Style style = Style::preset(QStringLiteral("normal"));
    const Timeline timeline = fast ? tenMinutesOfSpeech(0.08, 0.18) : tenMinutesOfSpeech(0.14, 0.30);
    AnimationExportOptions options;
    options.audio = ExportAudio::None; // the figures are the drawing's; the sound adds its own size

    // The process's CPU time over the three writes (all threads), a third of it a write.
    auto cpuMs = [] { return clockMs(CLOCK_PROCESS_CPUTIME_ID); };
    QByteArray smil;
    const double cpuBefore = cpuMs();
    const double smilMs = bench::medianMs([&] { smil = exportSmilSvg(face, style, timeline, shapes, options); }, 3, 0);
    const double smilCpuMs = (cpuMs() - cpuBefore) / 3;
    // The same without dropping keys: what the reduction saves.
    AnimationExportOptions allKeys = options;
    allKeys.reduction = 0;
    const qsizetype allKeysBytes = exportSmilSvg(face, style, timeline, shapes, allKeys).size();
    // TOONFACE_BENCH_OUT=DIR keeps the file for a look at what it holds.
    if (const QString dir = qEnvironmentVariable("TOONFACE_BENCH_OUT"); !dir.isEmpty()) {
        QFile out(
            QDir(dir).filePath(fast ? QStringLiteral("ten-minutes-fast.svg") : QStringLiteral("ten-minutes.svg")));
        if (out.open(QIODevice::WriteOnly))
            out.write(smil);
    }
    // What the bytes are spent on.
    qsizetype keys = 0, animations = 0, keyTimesBytes = 0, keySplinesBytes = 0, valuesBytes = 0;
    static const QRegularExpression attribute(QStringLiteral("(keyTimes|keySplines|values)=\"([^\"]*)\""));
    const QString text = QString::fromLatin1(smil);
    for (auto it = attribute.globalMatch(text); it.hasNext();) {
        const auto m = it.next();
        const qsizetype size = m.capturedLength(2);
        if (m.captured(1) == QLatin1StringView("keyTimes")) {
            keyTimesBytes += size;
            keys += m.captured(2).count(QLatin1Char(';')) + 1;
            ++animations;
        } else if (m.captured(1) == QLatin1StringView("keySplines")) {
            keySplinesBytes += size;
        } else {
            valuesBytes += size;
        }
    }

    // The largest animations: the element's id and attribute, and their bytes.
    QVector<std::pair<qsizetype, QString>> elements;
    static const QRegularExpression animation(
        QStringLiteral("<(?:animate|animateTransform) attributeName=\"(\\w+)\"[^>]*/>|\\bid=\"([^\"]+)\""));
    QString owner;
    for (auto it = animation.globalMatch(text); it.hasNext();) {
        const auto m = it.next();
        if (m.hasCaptured(2))
            owner = m.captured(2);
        else
            elements.append({m.capturedLength(0), owner + QLatin1Char(' ') + m.captured(1)});
    }
    std::sort(elements.begin(), elements.end(), [](const auto &a, const auto &b) { return a.first > b.first; });
    QJsonObject largest;
    for (qsizetype i = 0; i < std::min<qsizetype>(8, elements.size()); ++i)
        largest.insert(elements[i].second, elements[i].first);

    AnimationExportOptions frameOptions = options;
    frameOptions.mode = AnimationExportOptions::Mode::Frames;
    QByteArray frames;
    const double framesMs
        = bench::medianMs([&] { frames = exportSmilSvg(face, style, timeline, shapes, frameOptions); }, 1, 0);

    QJsonObject r = bench::loadAverage();
    r.insert(QStringLiteral("durationS"), timeline.duration());
    r.insert(QStringLiteral("mouthCues"), timeline.mouthKeys().size());
    r.insert(QStringLiteral("mouthCuesPerSecond"), timeline.mouthKeys().size() / timeline.duration());
    r.insert(QStringLiteral("blinks"), timeline.blinks().size());
    r.insert(QStringLiteral("smilMs"), smilMs);
    r.insert(QStringLiteral("smilCpuMs"), std::round(smilCpuMs));
    r.insert(QStringLiteral("smilBytes"), smil.size());
    r.insert(QStringLiteral("smilBytesAllKeys"), allKeysBytes);
    r.insert(QStringLiteral("smilReductionPx"), options.reduction);
    r.insert(QStringLiteral("smilAnimations"), animations);
    r.insert(QStringLiteral("smilKeys"), keys);
    r.insert(QStringLiteral("smilKeyTimesBytes"), keyTimesBytes);
    r.insert(QStringLiteral("smilKeySplinesBytes"), keySplinesBytes);
    r.insert(QStringLiteral("smilValuesBytes"), valuesBytes);
    r.insert(QStringLiteral("smilLargestAnimationsBytes"), largest);
    r.insert(QStringLiteral("framesMs"), framesMs);
    r.insert(QStringLiteral("framesBytes"), frames.size());
    r.insert(QStringLiteral("frames"), timeline.frameCount());
    // Issue 28's targets for ten minutes without the sound.
    r.insert(QStringLiteral("targetSmilBytes"), 2'000'000);
    r.insert(QStringLiteral("targetSmilMs"), 1000);
    return r;
}

// Frames rendered for video: the first 20 s at 512x512, in parallel, delivered in order. Then
// a frame's CPU time on one thread, drawn as video export draws it (the under pass reused,
// svgface.h: svgPasses()) and plainly (its whole SVG rasterized), over the first 200 frames.
QJsonObject benchFrames()
{
    const FaceModel face = averageFace(QRectF(100, 100, 300, 360), QSize(512, 512));
    const Timeline timeline = tenMinutesOfSpeech(0.14, 0.30);
    const FrameRenderer renderer(
        SvgFace(face, Style::preset(QStringLiteral("normal"))), timeline, MouthShapeSet(), QSize(512, 512));
    FrameRenderOptions options;
    options.count = 500;
    qint64 checksum = 0;
    const double ms = bench::medianMs(
        [&] {
            renderFrames(
                renderer,
                [&](int, const QImage &image) {
                    checksum += image.pixel(256, 256);
                    return true;
                },
                options);
        },
        3, 0);
    constexpr int kFrames = 200;
    const double before = clockMs(CLOCK_THREAD_CPUTIME_ID);
    for (int i = 0; i < kFrames; ++i)
        checksum += renderer.render(i).pixel(256, 256);
    const double reusedMs = (clockMs(CLOCK_THREAD_CPUTIME_ID) - before) / kFrames;
    const double plainBefore = clockMs(CLOCK_THREAD_CPUTIME_ID);
    for (int i = 0; i < kFrames; ++i)
        checksum += rasterizeSvg(renderer.svgAt(renderer.frameTime(i)), QSize(512, 512)).pixel(256, 256);
    const double plainMs = (clockMs(CLOCK_THREAD_CPUTIME_ID) - plainBefore) / kFrames;
    QJsonObject r = bench::loadAverage();
    r.insert(QStringLiteral("frames"), options.count);
    r.insert(QStringLiteral("ms"), ms);
    r.insert(QStringLiteral("framesPerSecond"), options.count * 1000.0 / ms);
    r.insert(QStringLiteral("timesRealTime"), options.count / renderer.frameRate() * 1000.0 / ms);
    r.insert(QStringLiteral("cpuMsPerFrame"), reusedMs);
    r.insert(QStringLiteral("cpuMsPerFramePlain"), plainMs);
    r.insert(QStringLiteral("checksum"), checksum != 0);
    return r;
}

// x264's speed presets on the same 5 s of frames (512x512, the normal style, crf 20): the
// encoding's CPU time per minute of video, the file's size, and how close the decoded pictures
// stay to the drawn ones (PSNR over RGB of every 10th frame, and the largest channel difference).
QJsonObject benchMp4Presets()
{
    const FaceModel face = averageFace(QRectF(100, 100, 300, 360), QSize(512, 512));
    const Timeline timeline = tenMinutesOfSpeech(0.14, 0.30, 60.0);
    const FrameRenderer renderer(
        SvgFace(face, Style::preset(QStringLiteral("normal"))), timeline, MouthShapeSet(), QSize(512, 512));
    FrameRenderOptions frameOptions;
    frameOptions.count = 125;
    QVector<QImage> frames;
    renderFrames(
        renderer,
        [&](int, const QImage &image) {
            frames.append(image.convertToFormat(QImage::Format_RGB32));
            return true;
        },
        frameOptions);
    QTemporaryDir dir;
    QJsonObject r = bench::loadAverage();
    for (const char *preset : {"veryfast", "superfast", "ultrafast"}) {
        VideoOptions options;
        options.preset = QLatin1StringView(preset);
        const QString path = dir.filePath(QLatin1StringView(preset) + QStringLiteral(".mp4"));
        QString error;
        const double before = clockMs(CLOCK_PROCESS_CPUTIME_ID);
        const bool ok = writeVideo(
            path, VideoFormat::Mp4, QSize(512, 512), renderer.frameRate(), int(frames.size()),
            [&](int i) { return frames[i]; }, {}, &error, options);
        const double cpuMs = clockMs(CLOCK_PROCESS_CPUTIME_ID) - before;
        if (!ok)
            return {{QStringLiteral("error"), error}};
        double squared = 0;
        qint64 samples = 0;
        int largest = 0;
        for (int i = 0; i < frames.size(); i += 10) {
            const std::optional<QImage> decoded = readVideoFrame(path, i, &error);
            if (!decoded)
                return {{QStringLiteral("error"), error}};
            for (int y = 0; y < 512; ++y) {
                const QRgb *a = reinterpret_cast<const QRgb *>(frames[i].constScanLine(y));
                const QRgb *b = reinterpret_cast<const QRgb *>(decoded->constScanLine(y));
                for (int x = 0; x < 512; ++x) {
                    for (int d : {qRed(a[x]) - qRed(b[x]), qGreen(a[x]) - qGreen(b[x]), qBlue(a[x]) - qBlue(b[x])}) {
                        squared += d * d;
                        largest = std::max(largest, std::abs(d));
                    }
                    samples += 3;
                }
            }
        }
        const double seconds = frames.size() / renderer.frameRate();
        r.insert(QLatin1StringView(preset),
            QJsonObject {{QStringLiteral("encodeCpuSecondsPerMinute"), cpuMs / 1000.0 * 60.0 / seconds},
                {QStringLiteral("bytesPerMinute"), QFileInfo(path).size() * 60.0 / seconds},
                {QStringLiteral("psnrDb"), 10 * std::log10(255.0 * 255.0 / (squared / double(samples)))},
                {QStringLiteral("largestDifference"), largest}});
    }
    return r;
}

// The whole process a user runs: toonface-cli animate of a project holding a minute of speech
// (the normal style, 512x512, 25 fps, no sound) to MP4 and to GIF; wall and CPU time as
// multiples of real time, and peak memory.
QJsonObject benchVideoFromProject()
{
    QTemporaryDir dir;
    Project project;
    project.face = averageFace(QRectF(100, 100, 300, 360), QSize(512, 512));
    project.style = Style::preset(QStringLiteral("normal"));
    // A real person's drawing (hair, clothes, her colours) when the Debian package's portrait
    // is here: the CLI makes her project, whose timeline is then replaced.
    const QString portrait = QStringLiteral("/usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg");
    const QString made = dir.filePath(QStringLiteral("grace.toonface"));
    QString drawing = QStringLiteral("the average face");
    if (QFileInfo::exists(portrait)
        && bench::runMeasured(QStringLiteral(TOONFACE_CLI_PATH),
            {QStringLiteral("animate"), portrait, QStringLiteral("--say"), QStringLiteral("ni3 hao3"),
                QStringLiteral("--project"), made, QStringLiteral("-o"), dir.filePath(QStringLiteral("grace.svg"))},
            {QStringLiteral("QT_QPA_PLATFORM=offscreen")})
               .ok) {
        QString error;
        if (const auto loaded = loadProject(made, &error)) {
            project = *loaded;
            drawing = QFileInfo(portrait).fileName();
        }
    }
    project.timeline = tenMinutesOfSpeech(0.14, 0.30, 60.0);
    project.timeline.setAudioClips({});
    const QString path = dir.filePath(QStringLiteral("minute.toonface"));
    QString error;
    if (!saveProject(project, path, &error))
        return {{QStringLiteral("error"), error}};
    const double seconds = project.timeline.frameCount() / project.timeline.frameRate();
    QJsonObject r = bench::loadAverage();
    for (const char *suffix : {"mp4", "gif"}) {
        const QString out = dir.filePath(QStringLiteral("minute.") + QLatin1StringView(suffix));
        const bench::ChildRun run = bench::runMeasured(QStringLiteral(TOONFACE_CLI_PATH),
            {QStringLiteral("animate"), path, QStringLiteral("-o"), out}, {QStringLiteral("QT_QPA_PLATFORM=offscreen")},
            true);
        if (!run.ok)
            return {{QStringLiteral("error"), QString::fromUtf8(run.stderrText)}};
        r.insert(QLatin1StringView(suffix),
            QJsonObject {{QStringLiteral("seconds"), seconds}, {QStringLiteral("wallMs"), qRound(run.wallMs)},
                {QStringLiteral("timesRealTime"), seconds * 1000.0 / run.wallMs},
                {QStringLiteral("cpuSecondsPerMinute"), run.cpuMs / 1000.0 * 60.0 / seconds},
                // Seconds of video per CPU-second: the multiple of real time one idle core gives,
                // which a loaded machine's wall time cannot show.
                {QStringLiteral("timesRealTimePerCore"), seconds * 1000.0 / std::max(1.0, run.cpuMs)},
                {QStringLiteral("peakMb"), qRound(run.peakMb)}, {QStringLiteral("bytes"), QFileInfo(out).size()}});
    }
    r.insert(QStringLiteral("drawing"), drawing);
    r.insert(QStringLiteral("targetMp4TimesRealTime"), 10);
    r.insert(QStringLiteral("targetGifTimesRealTime"), 5);
    return r;
}

} // namespace

TOONFACE_BENCHMARK("export.videoFromProject", benchVideoFromProject);
TOONFACE_BENCHMARK("export.tenMinutes", [] { return benchExport(false); });
TOONFACE_BENCHMARK("export.tenMinutesFast", [] { return benchExport(true); });
TOONFACE_BENCHMARK("export.frames512", benchFrames);
TOONFACE_BENCHMARK("export.mp4Presets", benchMp4Presets);
