#pragma once

#include "face/facemodel.h"
#include "face/mouthshape.h"
#include "face/pose.h"
#include "speech/audio.h"
#include "speech/audiomouth.h"
#include "track/framesource.h"
#include "track/livepose.h"
#include "track/tracker.h"

#include <QElapsedTimer>
#include <QImage>
#include <QObject>
#include <QRectF>
#include <QVector>

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>

namespace toonface {

class Document;
class SvgFace;

// The newest picture of a live session.
struct LiveFrame
{
    QImage cartoon; // the cartoon in the frame's pose, at the session's image size
    QImage source; // the frame it was tracked on
    Pose pose;
    TrackedFrame tracked; // meaningful when tracked: the face, its points and motion
    bool hasTrack = false; // false until a rest pose was found
    WeightedShape sound; // the sound's mouth then
    bool soundDrivesMouth = false;
    double arrival = 0; // seconds on the session's clock
    double ready = 0;
    int index = -1; // the source's frame index
};

// What a live session measured since start().
struct LiveFigures
{
    int delivered = 0; // frames the source delivered
    int rendered = 0; // pictures drawn: one per delivered frame
    int shown = 0; // pictures the GUI took
    int replaced = 0; // drawn pictures replaced by a newer one before the GUI took them
    int lost = 0; // frames with no face
    int newestIndex = -1; // the source's index of the newest picture drawn
    QVector<double> readyMs; // per drawn picture: from the frame's arrival to the picture drawn
    QVector<double> shownMs; // per shown picture: from the frame's arrival to the GUI taking it
};

// A recorded performance.
struct LiveTake
{
    QVector<TrackedFrame> frames; // times from the take's start
    double fps = 0;
    double duration = 0;
    Audio audio; // the sound over the take (empty without a microphone or clip sound)
    QVector<AudioMouthFrame> mouth; // the sound's mouth over the take, times from its start
    LiveMouth mouthMode = LiveMouth::Camera;
};

// Live puppeteering without widgets: a FrameSource -> a Tracker on a worker thread -> the
// cartoon of the document's face in each frame's pose, drawn on the worker too
// (PreviewRenderer::renderPose). Latest frame wins: the worker takes the source's newest frame
// (a camera source keeps only one; a paced file drops late ones), and the GUI takes the newest
// picture through one coalesced queued call — pictures are replaced, never queued.
//
// The first frame with a face becomes the rest pose (the neutral); setRestPose() makes the
// next frame the new one. The mouth follows the camera, the sound (pushAudio(): the
// microphone; or the clip's own sound given to start(), fed in step with its frames) or both
// (the sound while the face is lost). A source of frames without pictures (ClockSource) is a
// performer only heard: the cartoon at rest with the sound's mouth. Recording keeps the tracked
// frames, the sound and the sound's mouth until stopRecording().
//
// Lives on the GUI thread; pushAudio() may be called from any thread.
class LiveSession : public QObject
{
    Q_OBJECT

public:
    explicit LiveSession(Document *document, QObject *parent = nullptr);
    ~LiveSession() override; // stops the source and waits for the worker

    // Reads `source` on a worker thread (stopping the one before). `clipAudio` is the sound the
    // frames go with (a video file's), at any rate; empty for a camera. The rest pose is kept
    // with keepRestPose (the same performer, e.g. a clip replayed), else found anew.
    void start(std::unique_ptr<FrameSource> source, Audio clipAudio = {}, bool keepRestPose = false);
    // Stops the source and waits for the worker. Idempotent.
    void stop();
    bool isRunning() const { return m_running; }

    void setImageSize(QSize size);
    QSize imageSize() const;
    // The cartoon at rest (no track, closed mouth) at the image size, for before a source runs;
    // null without a face.
    QImage restCartoon() const;
    void setMouthMode(LiveMouth mode);
    LiveMouth mouthMode() const;
    // The next frame with a face becomes the rest pose.
    void setRestPose();
    bool hasRestPose() const { return m_hasRestPose; }

    // Sound from a microphone (mono, [-1, 1], at `sampleRate`); any thread.
    void pushAudio(const float *samples, qsizetype count, int sampleRate);

    void startRecording();
    bool isRecording() const { return m_recording; }
    LiveTake stopRecording();

    // The newest picture the GUI took (frameReady()).
    const LiveFrame &current() const { return m_current; }
    LiveFigures figures() const;
    // Seconds on the clock arrivals are measured on.
    double now() const { return m_clock.nsecsElapsed() / 1e9; }

Q_SIGNALS:
    void frameReady();
    // Something for the status line ("No face in view", the tracking method, ...).
    void status(const QString &text);
    // The source ended: `error` is empty at the end of a clip, else why it stopped.
    void finished(const QString &error);

private:
    struct Scene;
    void rebuildScene();
    void run(FrameSource *source, quint64 generation);
    void feedSound(const float *samples, qsizetype count);
    void publish(LiveFrame frame);
    void deliver();
    void post(std::function<void()> call);

    Document *m_document;
    QElapsedTimer m_clock;
    std::unique_ptr<FrameSource> m_source;
    std::thread m_worker;
    std::atomic_bool m_running {false};
    quint64 m_generation = 0; // GUI thread: which start() a worker's finished() belongs to

    mutable std::mutex m_lock; // everything below shared with the worker
    std::shared_ptr<const Scene> m_scene;
    QSize m_imageSize {480, 480};
    LiveMouth m_mouthMode = LiveMouth::Camera;
    std::optional<LiveFrame> m_latest;
    bool m_posted = false;
    LiveFigures m_figures;
    Audio m_clipAudio;
    qsizetype m_clipFed = 0;

    std::mutex m_soundLock; // the sound's mouth and the recorded sound
    std::unique_ptr<AudioMouth> m_mouth;
    QVector<float> m_recordedSound;
    QVector<AudioMouthFrame> m_recordedMouth;
    int m_recordedRate = kSpeechSampleRate;

    std::unique_ptr<Tracker> m_tracker; // the worker's
    std::atomic_bool m_restRequested {false};
    std::atomic_bool m_hasRestPose {false};
    std::atomic_bool m_recording {false};
    QVector<TrackedFrame> m_recordedFrames; // under m_lock
    std::optional<double> m_recordStart; // source time of the take's first frame, under m_lock
    double m_recordedSpan = 0; // seconds from it to the end of the newest frame recorded, under m_lock
    double m_lastFrameTime = 0;

    LiveFrame m_current;
};

// The mouth shape and weight the sound asks for now.
inline WeightedShape soundShape(const AudioMouthFrame &f)
{
    return {f.shape, f.weight};
}

} // namespace toonface
