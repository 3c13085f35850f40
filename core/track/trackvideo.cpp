#include "track/trackvideo.h"

#include "i18n/coretext.h"
#include "io/facejson.h"
#include "media/mediareader.h"
#include "track/clipsilence.h"
#include "track/mouthrange.h"
#include "track/videofilesource.h"

#include <QElapsedTimer>
#include <QJsonArray>

#include <algorithm>
#include <condition_variable>
#include <ctime>
#include <deque>
#include <mutex>
#include <thread>

namespace toonface {

namespace {

// Decodes a source on a thread of its own into a short queue, so that decoding and tracking
// overlap. The queue holds at most kDepth frames.
class DecodeAhead
{
public:
    explicit DecodeAhead(FrameSource &source)
        : m_source(source)
        , m_thread([this] { run(); })
    { }
    ~DecodeAhead()
    {
        {
            std::lock_guard lock(m_mutex);
            m_stop = true;
        }
        m_changed.notify_all();
        m_thread.join();
    }

    std::optional<VideoFrame> next()
    {
        std::unique_lock lock(m_mutex);
        m_changed.wait(lock, [this] { return !m_queue.empty() || m_done; });
        if (m_queue.empty())
            return std::nullopt;
        VideoFrame f = std::move(m_queue.front());
        m_queue.pop_front();
        m_changed.notify_all();
        return f;
    }

private:
    static constexpr size_t kDepth = 8;

    void run()
    {
        for (;;) {
            std::optional<VideoFrame> f = m_source.next();
            std::unique_lock lock(m_mutex);
            if (!f || m_stop) {
                m_done = true;
                m_changed.notify_all();
                return;
            }
            m_changed.wait(lock, [this] { return m_queue.size() < kDepth || m_stop; });
            m_queue.push_back(std::move(*f));
            m_changed.notify_all();
        }
    }

    FrameSource &m_source;
    std::mutex m_mutex;
    std::condition_variable m_changed;
    std::deque<VideoFrame> m_queue;
    bool m_done = false;
    bool m_stop = false;
    std::thread m_thread; // last: started once the members it uses exist
};

double processCpuMs()
{
    timespec t {};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

TrackStatus statusOf(DetectStatus s)
{
    switch (s) {
    case DetectStatus::ModelMissing: return TrackStatus::ModelMissing;
    case DetectStatus::Cancelled: return TrackStatus::Cancelled;
    case DetectStatus::BadImage: return TrackStatus::BadVideo;
    default: return TrackStatus::NoFace;
    }
}

} // namespace

TrackResult trackVideo(const QString &path, const TrackVideoOptions &options,
    const std::function<void(int, int)> &progress, const std::atomic_bool *cancel)
{
    TrackResult result;
    result.videoPath = path;
    result.neutralFrame = options.neutralFrame;
    auto cancelled = [&] {
        if (cancel && cancel->load()) {
            result.status = TrackStatus::Cancelled;
            result.error = VideoText::tr("%1: tracking was cancelled").arg(path);
            return true;
        }
        return false;
    };
    if (options.neutralFrame < 0) {
        result.error = VideoText::tr("%1: the neutral frame must be 0 or later").arg(path);
        return result;
    }

    // The neutral frame first.
    VideoFileSource source;
    QString error;
    if (!source.open(path, &error)) {
        result.error = error;
        return result;
    }
    result.size = source.frameSize();
    result.fps = source.frameRate();
    result.hasAudio = source.hasAudio();
    std::optional<VideoFrame> neutral;
    int seen = 0;
    while (!neutral && !cancelled()) {
        std::optional<VideoFrame> f = source.next();
        if (!f)
            break;
        if (seen++ == options.neutralFrame)
            neutral = std::move(f);
    }
    if (result.status == TrackStatus::Cancelled)
        return result;
    if (!neutral) {
        result.error = !source.error().isEmpty() ? source.error()
            : seen == 0                          ? VideoText::tr("%1: no video frame could be decoded").arg(path)
                        : VideoText::tr("%1: the neutral frame %2 is past the video's end (it has %3 frames)")
                              .arg(path, QString::number(options.neutralFrame), QString::number(seen));
        return result;
    }
    // A snapped mouth is snapped over the whole clip once it is tracked (track/mouthrange.h): the
    // tracker measures it as it is.
    TrackerOptions trackerOptions = options.tracker;
    trackerOptions.snapMouth = false;
    Tracker tracker(trackerOptions);
    DetectStatus status = DetectStatus::NoFace;
    if (!tracker.setNeutral(neutral->image, &error, &status)) {
        result.status = statusOf(status);
        result.error = VideoText::tr("%1: frame %2: %3").arg(path, QString::number(options.neutralFrame), error);
        return result;
    }
    result.method = tracker.methodName();
    result.neutral = tracker.neutralDetection();
    result.neutralImage = neutral->image;
    result.neutralEs0 = tracker.neutralEs0();

    // Every frame from the first.
    QElapsedTimer timer;
    timer.start();
    const double cpuStart = processCpuMs();
    if (options.neutralFrame > 0 && !source.open(path, &error)) {
        result.error = error;
        return result;
    }
    const int total = source.frameCount();
    {
        DecodeAhead ahead(source);
        if (options.neutralFrame == 0)
            result.frames.append(tracker.track(*neutral));
        while (!cancelled()) {
            std::optional<VideoFrame> f = ahead.next();
            if (!f)
                break;
            if (options.neutralFrame == 0 && f->index == 0)
                continue;
            result.frames.append(tracker.track(*f));
            if (progress)
                progress(int(result.frames.size()), total);
        }
    }
    result.trackingMs = timer.nsecsElapsed() / 1e6;
    result.trackingCpuMs = processCpuMs() - cpuStart;
    if (result.status == TrackStatus::Cancelled)
        return result;
    if (options.tracker.snapMouth) {
        result.mouthRange = measureMouthRange(result.frames, widestMouthOpeningEs0(tracker));
        if (result.hasAudio) {
            QString soundError;
            const std::optional<QVector<float>> sound = readAudio(path, kSilenceSampleRate, &soundError);
            if (sound) {
                result.silentFrames
                    = silentFrames(result.frames, *sound, kSilenceSampleRate, result.fps > 0 ? 1.0 / result.fps : 0.04);
            } else {
                result.warnings << VideoText::tr("%1: its sound could not be read (%2): the mouth is not closed "
                                                 "in its silences")
                                       .arg(path, soundError);
            }
        }
        snapClipMouth(&result.frames, tracker, *result.mouthRange, result.silentFrames);
    }
    if (!source.error().isEmpty())
        result.warnings << VideoText::tr("%1 (tracked the %2 frames before)")
                               .arg(source.error(), QString::number(result.frames.size()));
    if (source.damagedPackets() > 0)
        result.warnings << VideoText::tr("%1: %2 damaged packets were skipped; the frames around them may be wrong")
                               .arg(path, QString::number(source.damagedPackets()));
    int lost = 0;
    for (const TrackedFrame &f : std::as_const(result.frames))
        lost += f.lost;
    if (lost > 0)
        result.warnings << VideoText::tr("%1: the face was lost in %2 of %3 frames (they hold the last pose)")
                               .arg(path, QString::number(lost), QString::number(result.frames.size()));
    result.status = TrackStatus::Ok;
    return result;
}

QJsonObject trackToJson(const TrackResult &track)
{
    // To `decimals` places, so that the JSON shows them and no more (0.9526, not 0.9526000000000001).
    auto round = [](double v, int decimals) {
        const double scale = std::pow(10.0, decimals);
        return std::round(v * scale) / scale;
    };
    QJsonObject json;
    json.insert(QStringLiteral("format"), QString::fromLatin1(kTrackFormat));
    QJsonObject video;
    video.insert(QStringLiteral("path"), track.videoPath);
    video.insert(QStringLiteral("width"), track.size.width());
    video.insert(QStringLiteral("height"), track.size.height());
    video.insert(QStringLiteral("fps"), track.fps);
    video.insert(QStringLiteral("frames"), int(track.frames.size()));
    video.insert(QStringLiteral("hasAudio"), track.hasAudio);
    json.insert(QStringLiteral("video"), video);
    json.insert(QStringLiteral("neutralFrame"), track.neutralFrame);
    json.insert(QStringLiteral("method"), track.method);
    json.insert(QStringLiteral("neutral"), faceToJson(track.neutral.face, track.videoPath, &track.neutral));
    json.insert(QStringLiteral("units"), QStringLiteral("ES0"));
    json.insert(QStringLiteral("es0"), track.neutralEs0);
    if (track.mouthRange) {
        QJsonObject range;
        QJsonObject closed;
        for (int k = 0; k < 4; ++k) {
            const QPointF d = track.mouthRange->closedEs0[k];
            closed.insert(QString::fromLatin1(kMouthControlIds[k]), QJsonArray {round(d.x(), 5), round(d.y(), 5)});
        }
        range.insert(QStringLiteral("closed"), closed);
        range.insert(QStringLiteral("wideOpening"), round(track.mouthRange->wideOpeningEs0, 5));
        range.insert(QStringLiteral("gain"), round(track.mouthRange->gain, 4));
        range.insert(QStringLiteral("silentFrames"),
            int(std::count(track.silentFrames.cbegin(), track.silentFrames.cend(), true)));
        json.insert(QStringLiteral("mouthRange"), range);
    }

    // Points and displacements of the points that move: the control points and the mouth's
    // derived points.
    QVector<int> moving;
    for (int i = 0; i < kPointCount; ++i) {
        const PointInfo &p = pointTable()[i];
        if (p.control || p.group == PointGroup::Mouth)
            moving.append(i);
    }
    QJsonArray frames;
    for (const TrackedFrame &f : track.frames) {
        QJsonObject o;
        o.insert(QStringLiteral("time"), round(f.time, 6));
        o.insert(QStringLiteral("lost"), f.lost);
        o.insert(QStringLiteral("confidence"), round(f.confidence, 4));
        QJsonArray points;
        QJsonObject displacements;
        for (int i : std::as_const(moving)) {
            QJsonObject p;
            p.insert(QStringLiteral("id"), pointId(i));
            p.insert(QStringLiteral("x"), round(f.points[i].x(), 3));
            p.insert(QStringLiteral("y"), round(f.points[i].y(), 3));
            points.append(p);
            const QPointF d = f.motion.displacementEs0[i];
            displacements.insert(pointId(i), QJsonArray {round(d.x(), 5), round(d.y(), 5)});
        }
        o.insert(QStringLiteral("points"), points);
        o.insert(QStringLiteral("displacements"), displacements);
        QJsonObject eyes;
        eyes.insert(QStringLiteral("left"), round(f.motion.leftEyeOpen, 4));
        eyes.insert(QStringLiteral("right"), round(f.motion.rightEyeOpen, 4));
        o.insert(QStringLiteral("eyes"), eyes);
        QJsonObject head;
        head.insert(QStringLiteral("rotation"), round(f.motion.rotationDeg, 3));
        head.insert(QStringLiteral("x"), round(f.motion.translationEs0.x(), 5));
        head.insert(QStringLiteral("y"), round(f.motion.translationEs0.y(), 5));
        head.insert(QStringLiteral("scale"), round(f.motion.scale, 5));
        o.insert(QStringLiteral("head"), head);
        o.insert(QStringLiteral("gaze"), QJsonArray {round(f.motion.gazeEs0.x(), 5), round(f.motion.gazeEs0.y(), 5)});
        o.insert(QStringLiteral("mouthOpen"), round(f.motion.mouthOpenEs0, 5));
        if (f.mouthShape)
            o.insert(QStringLiteral("mouthShape"), mouthShapeName(*f.mouthShape));
        frames.append(o);
    }
    json.insert(QStringLiteral("frames"), frames);
    return json;
}

} // namespace toonface
