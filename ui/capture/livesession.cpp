#include "capture/livesession.h"

#include "capture/cameraframesource.h"
#include "document/document.h"
#include "render/svgface.h"
#include "views/previewrenderer.h"

#include <QMetaObject>

#include <chrono>
#include <future>

#include <algorithm>
#include <cmath>

namespace toonface {

namespace {

// How often a frame is tried for the rest pose while none is found (a detection costs far
// more than a frame).
constexpr double kRestPoseRetryS = 0.5;

} // namespace

// What the worker draws with; immutable, replaced as a whole when the document changes.
struct LiveSession::Scene
{
    std::shared_ptr<const SvgFace> face;
    QRectF frame;
    FaceModel model;
    MouthShapeSet shapes;
};

LiveSession::LiveSession(Document *document, QObject *parent)
    : QObject(parent)
    , m_document(document)
    , m_mouth(std::make_unique<AudioMouth>())
    , m_tracker(std::make_unique<Tracker>())
{
    m_clock.start();
    rebuildScene();
    connect(m_document, &Document::changed, this, [this](ChangeFlags what) {
        if (what & (Change::Face | Change::Points | Change::Style | Change::Photo | Change::MouthShapes))
            rebuildScene();
    });
}

LiveSession::~LiveSession()
{
    stop();
}

void LiveSession::rebuildScene()
{
    std::shared_ptr<Scene> scene;
    if (m_document->hasFace()) {
        scene = std::make_shared<Scene>();
        scene->model = m_document->face();
        scene->shapes = m_document->mouthShapes();
        scene->frame = headFrame(scene->model, 0.0);
        auto face = std::make_shared<SvgFace>(scene->model, m_document->style());
        face->setFrame(scene->frame);
        scene->face = std::move(face);
    }
    std::lock_guard lock(m_lock);
    m_scene = std::move(scene);
}

void LiveSession::start(std::unique_ptr<FrameSource> source, Audio clipAudio, bool keepRestPose)
{
    stop();
    if (!source)
        return;
    if (!keepRestPose) {
        m_tracker = std::make_unique<Tracker>();
        m_hasRestPose = false;
    } else {
        m_tracker->restart();
    }
    {
        std::lock_guard lock(m_lock);
        m_figures = {};
        m_latest.reset();
        m_clipAudio = std::move(clipAudio);
        m_clipFed = 0;
    }
    {
        std::lock_guard lock(m_soundLock);
        m_mouth = std::make_unique<AudioMouth>(m_clipAudio.isEmpty() ? kSpeechSampleRate : m_clipAudio.sampleRate);
    }
    m_source = std::move(source);
    m_running = true;
    ++m_generation;
    m_worker = std::thread([this, s = m_source.get(), generation = m_generation] { run(s, generation); });
}

void LiveSession::stop()
{
    if (m_source)
        m_source->stop();
    if (m_worker.joinable())
        m_worker.join();
    m_source.reset();
    m_running = false;
}

void LiveSession::setImageSize(QSize size)
{
    std::lock_guard lock(m_lock);
    m_imageSize = size.expandedTo(QSize(16, 16));
}

QImage LiveSession::restCartoon() const
{
    std::shared_ptr<const Scene> scene;
    QSize size;
    {
        std::lock_guard lock(m_lock);
        scene = m_scene;
        size = m_imageSize;
    }
    if (!scene)
        return {};
    return PreviewRenderer::renderPose(
        *scene->face, scene->frame, size, livePose(TrackedFrame {}, scene->model, scene->shapes, std::nullopt));
}

QSize LiveSession::imageSize() const
{
    std::lock_guard lock(m_lock);
    return m_imageSize;
}

void LiveSession::setMouthMode(LiveMouth mode)
{
    std::lock_guard lock(m_lock);
    m_mouthMode = mode;
}

LiveMouth LiveSession::mouthMode() const
{
    std::lock_guard lock(m_lock);
    return m_mouthMode;
}

void LiveSession::setRestPose()
{
    m_restRequested = true;
}

void LiveSession::pushAudio(const float *samples, qsizetype count, int sampleRate)
{
    {
        std::lock_guard lock(m_soundLock);
        if (m_mouth->sampleRate() != sampleRate)
            m_mouth = std::make_unique<AudioMouth>(sampleRate);
    }
    feedSound(samples, count);
}

void LiveSession::feedSound(const float *samples, qsizetype count)
{
    std::lock_guard lock(m_soundLock);
    const QVector<AudioMouthFrame> hops = m_mouth->push(samples, count);
    if (!m_recording)
        return;
    m_recordedRate = m_mouth->sampleRate();
    if (m_clipAudio.isEmpty())
        m_recordedSound.append(QVector<float>(samples, samples + count));
    m_recordedMouth += hops;
}

void LiveSession::startRecording()
{
    {
        std::lock_guard lock(m_lock);
        m_recordedFrames.clear();
        m_recordStart.reset();
        m_recordedSpan = 0;
    }
    {
        std::lock_guard lock(m_soundLock);
        m_recordedSound.clear();
        m_recordedMouth.clear();
    }
    m_recording = true;
}

LiveTake LiveSession::stopRecording()
{
    LiveTake take;
    m_recording = false;
    double start = 0;
    {
        std::lock_guard lock(m_lock);
        take.frames = std::exchange(m_recordedFrames, {});
        take.mouthMode = m_mouthMode;
        start = m_recordStart.value_or(0.0);
        const double rate = m_source ? m_source->frameRate() : 0.0;
        if (rate > 0)
            take.fps = rate;
        else if (take.frames.size() > 1)
            take.fps = (take.frames.size() - 1) / std::max(1e-3, take.frames.last().time - take.frames.first().time);
        if (!take.frames.isEmpty())
            take.duration = take.frames.last().time + (take.fps > 0 ? 1.0 / take.fps : 0.0);
        take.duration = std::max(take.duration, m_recordedSpan); // the frames heard only count too
        if (take.frames.isEmpty() && take.duration > 0)
            take.mouthMode = LiveMouth::Microphone; // heard only: the sound was the mouth
        if (!m_clipAudio.isEmpty() && m_recordStart) {
            // The clip's own sound over the take.
            const qsizetype from = std::clamp<qsizetype>(
                qsizetype(std::lround(start * m_clipAudio.sampleRate)), 0, m_clipAudio.samples.size());
            const qsizetype to
                = std::clamp<qsizetype>(qsizetype(std::lround((start + take.duration) * m_clipAudio.sampleRate)), from,
                    m_clipAudio.samples.size());
            take.audio = Audio {m_clipAudio.samples.mid(from, to - from), m_clipAudio.sampleRate};
        }
        m_recordStart.reset();
    }
    std::lock_guard lock(m_soundLock);
    if (take.audio.isEmpty() && !m_recordedSound.isEmpty())
        take.audio = Audio {std::exchange(m_recordedSound, {}), m_recordedRate};
    take.mouth = std::exchange(m_recordedMouth, {});
    // The mouth's hops are timed from the first sound: from the take's start instead.
    const double mouthStart = take.mouth.isEmpty() ? 0.0 : take.mouth.first().time - m_mouth->options().hopMs / 1000.0;
    for (AudioMouthFrame &f : take.mouth)
        f.time -= mouthStart;
    return take;
}

LiveFigures LiveSession::figures() const
{
    std::lock_guard lock(m_lock);
    return m_figures;
}

void LiveSession::post(std::function<void()> call)
{
    QMetaObject::invokeMethod(this, std::move(call), Qt::QueuedConnection);
}

void LiveSession::run(FrameSource *source, quint64 generation)
{
    auto *camera = dynamic_cast<CameraFrameSource *>(source);
    double lastRestTry = -1e9;
    struct RestPose
    {
        std::unique_ptr<Tracker> tracker; // null when no face was found
        QString error;
        bool asked = false;
    };
    std::future<RestPose> restJob;
    auto takeRestPose = [&] {
        RestPose rest = restJob.get();
        if (rest.tracker) {
            m_tracker = std::move(rest.tracker);
            m_hasRestPose = true;
            post([this, method = m_tracker->methodName()] {
                Q_EMIT status(tr("Rest pose set (tracking by %1)").arg(method));
            });
        } else if (rest.asked || !m_tracker->hasNeutral()) {
            post([this, error = rest.error] { Q_EMIT status(tr("No face for the rest pose: %1").arg(error)); });
        }
    };
    while (std::optional<VideoFrame> frame = source->next()) {
        // A camera's frame may have waited for the worker: its arrival is when it was pushed.
        const double arrival = camera ? now() - (camera->now() - camera->lastArrival()) : now();

        // The clip's sound up to this frame, as a microphone would have heard it.
        const float *sound = nullptr;
        qsizetype soundCount = 0;
        std::shared_ptr<const Scene> scene;
        QSize size;
        LiveMouth mode;
        {
            std::lock_guard lock(m_lock);
            if (!m_clipAudio.isEmpty()) {
                const qsizetype upTo = std::min<qsizetype>(m_clipAudio.samples.size(),
                    qsizetype(std::lround(
                        (frame->time + 1.0 / std::max(1.0, source->frameRate())) * m_clipAudio.sampleRate)));
                if (upTo > m_clipFed) {
                    sound = m_clipAudio.samples.constData() + m_clipFed;
                    soundCount = upTo - m_clipFed;
                    m_clipFed = upTo;
                }
            }
            scene = m_scene;
            size = m_imageSize;
            mode = m_mouthMode;
        }
        if (soundCount > 0)
            feedSound(sound, soundCount);

        // A frame with no picture (ClockSource: the performer is only heard) is the cartoon at
        // rest with the sound's mouth.
        const bool heardOnly = frame->image.isNull();
        if (heardOnly)
            mode = LiveMouth::Microphone;

        // The rest pose is detected beside the frames (a detection costs many frames), which
        // go on showing meanwhile; the tracker is swapped in when it is ready.
        if (restJob.valid() && restJob.wait_for(std::chrono::seconds(0)) == std::future_status::ready)
            takeRestPose();
        const double t = now();
        if (!heardOnly && !restJob.valid()
            && (m_restRequested || (!m_tracker->hasNeutral() && t - lastRestTry > kRestPoseRetryS))) {
            lastRestTry = t;
            restJob = std::async(std::launch::async,
                [options = m_tracker->options(), image = frame->image, asked = m_restRequested.exchange(false)] {
                    RestPose rest;
                    rest.asked = asked;
                    auto tracker = std::make_unique<Tracker>(options);
                    if (tracker->setNeutral(image, &rest.error))
                        rest.tracker = std::move(tracker);
                    return rest;
                });
        }

        LiveFrame out;
        out.source = frame->image;
        out.index = frame->index;
        out.arrival = arrival;
        if (!heardOnly && m_tracker->hasNeutral()) {
            out.tracked = m_tracker->track(*frame);
            out.hasTrack = true;
        }
        {
            std::lock_guard lock(m_soundLock);
            out.sound = soundShape(m_mouth->current());
        }
        const bool faceMissing = !out.hasTrack || out.tracked.lost;
        const std::optional<WeightedShape> mouth = chooseMouth(mode, faceMissing, out.sound);
        out.soundDrivesMouth = mouth.has_value();
        if (scene) {
            out.pose = livePose(out.hasTrack ? out.tracked : TrackedFrame {}, scene->model, scene->shapes, mouth);
            out.cartoon = PreviewRenderer::renderPose(*scene->face, scene->frame, size, out.pose);
        }
        out.ready = now();

        {
            std::lock_guard lock(m_lock);
            if (out.hasTrack && out.tracked.lost)
                ++m_figures.lost;
            if (m_recording && (out.hasTrack || heardOnly)) {
                if (!m_recordStart)
                    m_recordStart = frame->time;
                const double at = frame->time - *m_recordStart;
                m_recordedSpan = at + 1.0 / std::max(1.0, source->frameRate());
                if (out.hasTrack) {
                    TrackedFrame recorded = out.tracked;
                    recorded.time = at;
                    m_recordedFrames.append(recorded);
                }
            }
        }
        publish(std::move(out));
    }
    // A detection still running when the source ended is waited for, and said.
    if (restJob.valid())
        takeRestPose();
    const QString error = source->error();
    post([this, error, generation] {
        if (generation != m_generation)
            return; // a source started since
        m_running = false;
        Q_EMIT finished(error);
    });
}

void LiveSession::publish(LiveFrame frame)
{
    std::lock_guard lock(m_lock);
    ++m_figures.delivered;
    ++m_figures.rendered;
    m_figures.readyMs.append((frame.ready - frame.arrival) * 1000.0);
    m_figures.newestIndex = frame.index;
    if (m_latest)
        ++m_figures.replaced;
    m_latest = std::move(frame);
    if (!m_posted) {
        m_posted = true;
        post([this] { deliver(); });
    }
}

void LiveSession::deliver()
{
    {
        std::lock_guard lock(m_lock);
        m_posted = false;
        if (!m_latest)
            return;
        m_current = std::move(*m_latest);
        m_latest.reset();
        ++m_figures.shown;
        m_figures.shownMs.append((now() - m_current.arrival) * 1000.0);
    }
    Q_EMIT frameReady();
}

} // namespace toonface
