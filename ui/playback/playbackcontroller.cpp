#include "playback/playbackcontroller.h"

#include "playback/audiotrack.h"
#include "playback/mediaaudiotrack.h"
#include "playback/playhead.h"
#include "views/themedicon.h"

#include <QAction>
#include <QAudioDevice>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QMediaDevices>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <cmath>

namespace toonface {

namespace {

// The frame timer ticks several times a frame, so a frame is shown within a few milliseconds of
// its time however the timer's phase falls.
constexpr int kTicksPerFrame = 4;
constexpr int kMinTickMs = 4;
constexpr int kMaxTickMs = 10;

} // namespace

PlaybackController::PlaybackController(Document *document, Playhead *playhead, QObject *parent)
    : QObject(parent)
    , m_document(document)
    , m_playhead(playhead)
{
    m_elapsed.start();
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &PlaybackController::tick);
    createActions();
    connect(m_document, &Document::changed, this, &PlaybackController::onDocumentChanged);
    connect(m_playhead, &Playhead::timeChanged, this, &PlaybackController::onPlayheadMoved);
    connect(m_playhead, &Playhead::scrubbingChanged, this, &PlaybackController::onScrubbing);
    m_clips = m_document->timeline().audioClips();
    if (!QMediaDevices::audioOutputs().isEmpty())
        setAudioTrack(std::make_unique<MediaAudioTrack>());
    else
        openSound();
    updateActions();
}

PlaybackController::~PlaybackController()
{
    cancelMix();
    if (m_playing && m_playhead)
        m_playhead->setPlaying(false);
}

void PlaybackController::createActions()
{
    auto make = [this](const char *theme, const char *bundled, const QString &text, const char *name) {
        auto *action = new QAction(themedIcon(theme, bundled), text, this);
        action->setObjectName(QString::fromLatin1(name));
        return action;
    };
    m_playPause = make("media-playback-start", "play.svg", tr("&Play"), "playPauseAction");
    m_playPause->setShortcut(Qt::Key_Space);
    connect(m_playPause, &QAction::triggered, this, &PlaybackController::togglePlay);

    m_stop = make("media-playback-stop", "stop.svg", tr("&Stop"), "stopAction");
    m_stop->setToolTip(tr("Stop and return to the first frame"));
    connect(m_stop, &QAction::triggered, this, &PlaybackController::stop);

    m_loop = make("media-playlist-repeat", "loop.svg", tr("&Loop"), "loopAction");
    m_loop->setCheckable(true);
    m_loop->setToolTip(tr("Loop: play from the start again at the end"));

    m_first = make("media-skip-backward", "first-frame.svg", tr("&First Frame"), "firstFrameAction");
    m_first->setShortcut(Qt::Key_Home);
    connect(m_first, &QAction::triggered, this, &PlaybackController::goToFirstFrame);

    m_previous = make("go-previous", "previous-frame.svg", tr("Pre&vious Frame"), "previousFrameAction");
    m_previous->setShortcut(Qt::Key_Left);
    m_previous->setAutoRepeat(true);
    connect(m_previous, &QAction::triggered, this, [this] { stepFrames(-1); });

    m_next = make("go-next", "next-frame.svg", tr("&Next Frame"), "nextFrameAction");
    m_next->setShortcut(Qt::Key_Right);
    m_next->setAutoRepeat(true);
    connect(m_next, &QAction::triggered, this, [this] { stepFrames(1); });

    m_last = make("media-skip-forward", "last-frame.svg", tr("&Last Frame"), "lastFrameAction");
    m_last->setShortcut(Qt::Key_End);
    connect(m_last, &QAction::triggered, this, &PlaybackController::goToLastFrame);

    for (QAction *action : actions()) {
        if (!action->shortcut().isEmpty())
            action->setToolTip(QStringLiteral("%1 (%2)").arg(
                action->text().remove(QLatin1Char('&')), action->shortcut().toString(QKeySequence::NativeText)));
    }
}

QList<QAction *> PlaybackController::actions() const
{
    return {m_first, m_previous, m_playPause, m_next, m_last, m_stop, m_loop};
}

void PlaybackController::updateActions()
{
    const bool any = m_document->timeline().frameCount() > 0;
    for (QAction *action : actions())
        action->setEnabled(any || action == m_loop);
    m_playPause->setIcon(
        m_playing ? themedIcon("media-playback-pause", "pause.svg") : themedIcon("media-playback-start", "play.svg"));
    m_playPause->setText(m_playing ? tr("&Pause") : tr("&Play"));
    m_playPause->setToolTip(QStringLiteral("%1 (%2)").arg(
        m_playPause->text().remove(QLatin1Char('&')), m_playPause->shortcut().toString(QKeySequence::NativeText)));
}

bool PlaybackController::isLooping() const
{
    return m_loop->isChecked();
}

void PlaybackController::setLooping(bool loop)
{
    m_loop->setChecked(loop);
}

double PlaybackController::frameRate() const
{
    const double fps = m_document->timeline().frameRate();
    return fps > 0 ? fps : 25.0;
}

double PlaybackController::lastFrameTime() const
{
    return std::max(0, m_document->timeline().frameCount() - 1) / frameRate();
}

int PlaybackController::frameAt(double time) const
{
    return int(std::floor(time * frameRate() + 1e-9));
}

qint64 PlaybackController::now() const
{
    return m_wallClock ? m_wallClock() : m_elapsed.nsecsElapsed();
}

void PlaybackController::setWallClock(std::function<qint64()> nowNs)
{
    m_wallClock = std::move(nowNs);
}

void PlaybackController::setAudioTrack(std::unique_ptr<AudioTrack> track)
{
    if (m_track) {
        stopSound();
        m_track->disconnect(this);
    }
    cancelMix();
    m_track = std::move(track);
    m_soundPath.clear();
    m_soundOpen = false;
    if (m_track) {
        connect(m_track.get(), &AudioTrack::failed, this, [this](const QString &problem) {
            m_soundOpen = false;
            m_soundProblem = tr("%1 Playing without sound.").arg(problem);
            if (m_sound == Sound::Playing)
                m_sound = Sound::Done;
            Q_EMIT message(m_soundProblem);
        });
    }
    openSound();
}

bool PlaybackController::hasSound() const
{
    return m_track && m_soundOpen && m_heard.has_value();
}

void PlaybackController::openSound()
{
    const QVector<AudioClip> clips = soundingClips(m_document->timeline().audioClips());
    if (clips.isEmpty()) {
        m_heard.reset();
        m_soundProblem.clear();
        return;
    }
    for (const AudioClip &clip : clips) {
        if (!QFileInfo(clip.path).isFile()) {
            m_soundOpen = false;
            m_soundPath.clear();
            m_heard.reset();
            m_soundProblem
                = tr("The audio file %1 is missing: playing without sound.").arg(QDir::toNativeSeparators(clip.path));
            return;
        }
    }
    if (!m_track) {
        m_soundProblem = tr("No audio output device: playing without sound.");
        return;
    }
    if (m_soundOpen && m_heard && clips == m_openedClips)
        return;
    // The track as one file: a clip's own, or the clips mixed (media/audiomix.h). A mix is made
    // off the GUI thread (a long track takes seconds to decode and sum): the picture plays at
    // once and the sound joins it when the mix is ready.
    if (!m_mixFolder)
        m_mixFolder = std::make_unique<QTemporaryDir>();
    if (!m_mixFolder->isValid()) {
        m_openedClips = clips;
        useSound(clips, std::nullopt, tr("%1 Playing without sound.").arg(m_mixFolder->errorString()));
        return;
    }
    const bool whole = clips.size() == 1 && clips.first().trimIn == 0 && clips.first().trimOut == 0;
    const QString name = QStringLiteral("mix-%1.wav").arg(++m_mixCount);
    if (whole) {
        QString error;
        const std::optional<TrackSound> sound = trackSoundFile(clips, m_mixFolder->path(), name, &error);
        useSound(clips, sound, sound ? QString() : tr("%1 Playing without sound.").arg(error));
        return;
    }
    if (m_mixing && clips == m_mixingClips)
        return; // already being mixed
    cancelMix();
    m_mixCancel = std::make_shared<std::atomic_bool>(false);
    m_mixing = true;
    m_mixingClips = clips;
    const int generation = ++m_mixGeneration;
    auto *watcher = new QFutureWatcher<MixOutcome>(this);
    connect(watcher, &QFutureWatcher<MixOutcome>::finished, this, [this, watcher, generation, clips] {
        watcher->deleteLater();
        const MixOutcome outcome = watcher->result();
        if (generation != m_mixGeneration) {
            if (outcome.sound && outcome.sound->mixed)
                QFile::remove(outcome.sound->path); // an older track's mix
            return;
        }
        m_mixing = false;
        useSound(clips, outcome.sound,
            outcome.sound || outcome.error.isEmpty() ? QString() : tr("%1 Playing without sound.").arg(outcome.error));
        if (!m_soundProblem.isEmpty())
            Q_EMIT message(m_soundProblem);
        if (m_playing && !m_suspended)
            startSound(m_clock.time(now()));
        Q_EMIT soundReady();
    });
    watcher->setFuture(QtConcurrent::run([clips, folder = m_mixFolder->path(), name, cancel = m_mixCancel] {
        MixOutcome outcome;
        outcome.sound = trackSoundFile(clips, folder, name, &outcome.error, cancel.get());
        return outcome;
    }));
}

void PlaybackController::cancelMix()
{
    if (m_mixCancel)
        *m_mixCancel = true;
    m_mixCancel.reset();
    ++m_mixGeneration;
    m_mixing = false;
}

void PlaybackController::useSound(
    const QVector<AudioClip> &clips, const std::optional<TrackSound> &sound, const QString &problem)
{
    if (!m_mixPath.isEmpty())
        QFile::remove(m_mixPath);
    m_mixPath.clear();
    m_openedClips = clips;
    if (!sound || sound->path.isEmpty() || !m_track) {
        m_soundOpen = false;
        m_soundPath.clear();
        m_heard.reset();
        m_soundProblem = m_track ? problem : tr("No audio output device: playing without sound.");
        return;
    }
    if (sound->mixed)
        m_mixPath = sound->path;
    m_heard = AudioClip {sound->path, sound->offset, sound->duration > 0 ? sound->duration : Timeline::kMaxSeconds};
    QString error;
    m_soundOpen = m_track->open(sound->path, &error);
    m_soundPath = m_soundOpen ? sound->path : QString();
    m_soundProblem = m_soundOpen ? QString() : tr("%1 Playing without sound.").arg(error);
}

void PlaybackController::play()
{
    if (m_playing)
        return;
    if (m_document->timeline().frameCount() <= 0) {
        Q_EMIT message(tr("Nothing to play: the timeline is empty."));
        return;
    }
    openSound();
    if (!m_soundProblem.isEmpty())
        Q_EMIT message(m_soundProblem);
    double time = m_playhead->time();
    if (frameAt(time) >= frameAt(lastFrameTime()))
        time = 0; // from the end, play again from the start
    m_playing = true;
    m_framesPlayed = 0;
    m_resyncs = 0;
    m_maxAudioError = 0;
    m_frame = frameAt(time);
    startAt(time);
    const double frameMs = 1000.0 / frameRate();
    m_timer.start(std::clamp(int(frameMs / kTicksPerFrame), kMinTickMs, kMaxTickMs));
    m_playhead->setPlaying(true);
    updateActions();
    Q_EMIT playingChanged(true);
    if (time != m_playhead->time())
        setPlayheadFrame(m_frame);
}

void PlaybackController::pause()
{
    if (!m_playing)
        return;
    m_playing = false;
    m_suspended = false;
    m_timer.stop();
    stopSound();
    m_playhead->setPlaying(false);
    updateActions();
    Q_EMIT playingChanged(false);
}

void PlaybackController::togglePlay()
{
    if (m_playing)
        pause();
    else
        play();
}

void PlaybackController::stop()
{
    pause();
    goToFirstFrame();
}

void PlaybackController::stepFrames(int frames)
{
    pause();
    const int last = frameAt(lastFrameTime());
    const int frame = std::clamp(frameAt(m_playhead->time()) + frames, 0, last);
    m_playhead->setTime(frame / frameRate());
}

void PlaybackController::goToFirstFrame()
{
    m_playhead->setTime(0);
}

void PlaybackController::goToLastFrame()
{
    m_playhead->setTime(lastFrameTime());
}

void PlaybackController::startAt(double time)
{
    m_clock.start(time, now());
    startSound(time);
}

void PlaybackController::startSound(double time)
{
    stopSound();
    if (!hasSound())
        return;
    const AudioClip &clip = *m_heard;
    const double inFile = time - clip.offset;
    if (inFile < 0) {
        m_sound = Sound::Waiting; // the lead-in
    } else if (inFile < clip.duration) {
        m_track->play(inFile);
        m_sound = Sound::Playing;
        m_soundFlowed = false;
        m_lastAudioPosition.reset();
        m_soundHoldTime = time;
        m_soundNewsNs = now();
    } else {
        m_sound = Sound::Done;
    }
}

void PlaybackController::stopSound()
{
    if (m_track && m_sound == Sound::Playing)
        m_track->pause();
    m_sound = Sound::Off;
}

void PlaybackController::updateSound(double time)
{
    if (m_sound != Sound::Waiting && m_sound != Sound::Playing)
        return;
    if (!hasSound()) {
        stopSound();
        return;
    }
    const AudioClip &clip = *m_heard;
    const double inFile = time - clip.offset;
    if (m_sound == Sound::Waiting && inFile >= 0) {
        startSound(time);
    } else if (m_sound == Sound::Playing && inFile >= clip.duration) {
        m_track->pause();
        m_sound = Sound::Done;
    } else if (m_sound == Sound::Playing && m_soundFlowed && !m_track->isPlaying()) {
        m_sound = Sound::Done; // the file is shorter than the clip: silence to the end
    }
}

void PlaybackController::tick()
{
    if (!m_playing || m_suspended)
        return;
    const qint64 wall = now();
    bool jumped = false;
    if (m_sound == Sound::Playing) {
        // Sound systems tell the position in steps (PulseAudio: every 128-256 ms, later when
        // busy): a position is news only when it changed, and the clock runs on between steps
        // instead of waiting at a stale one.
        const std::optional<double> position = m_track->position();
        if (position && position != m_lastAudioPosition) {
            // The first position tells how late the sound started: the clock locks on to it.
            const bool lockIn = !m_soundFlowed;
            m_soundFlowed = true;
            m_lastAudioPosition = position;
            const double heard = m_heard->offset + *position;
            m_soundHoldTime = heard + kMaxAheadOfSound;
            m_soundNewsNs = wall;
            // A re-sync moves the clock, never the picture back: a picture ahead of the sound
            // holds until the sound catches up (below), one behind it jumps forward.
            if (m_clock.syncToAudio(heard, wall)) {
                if (!lockIn)
                    ++m_resyncs;
            } else {
                m_maxAudioError = std::max(m_maxAudioError, std::abs(m_clock.lastError()));
            }
        }
    }
    holdForSound(wall);
    double time = m_clock.time(wall);
    const double end = m_document->timeline().duration();
    if (time >= end) {
        if (!isLooping() || end <= 0) {
            setPlayheadFrame(frameAt(lastFrameTime()));
            pause();
            return;
        }
        time = std::fmod(time, end);
        startAt(time);
        jumped = true;
    }
    updateSound(time);
    const int frame = frameAt(time);
    // Only a loop's wrap steps the picture back: corrections toward the sound never do.
    if (frame > m_frame || (jumped && frame != m_frame))
        setPlayheadFrame(frame);
}

void PlaybackController::holdForSound(qint64 wall)
{
    if (m_sound != Sound::Playing || double(wall - m_soundNewsNs) * 1e-9 > kSoundGrace)
        return;
    // Not started yet: the clock waits where the sound starts; standing still: it runs at most
    // kMaxAheadOfSound past the sound's last position. A sound held up for longer than the
    // grace no longer holds it: the clock goes on from there.
    if (m_clock.time(wall) > m_soundHoldTime)
        m_clock.start(m_soundHoldTime, wall);
}

void PlaybackController::setPlayheadFrame(int frame)
{
    m_frame = frame;
    m_settingTime = true;
    m_playhead->setTime(frame / frameRate());
    m_settingTime = false;
    if (m_playing)
        ++m_framesPlayed;
}

void PlaybackController::onPlayheadMoved(double time)
{
    if (m_settingTime || !m_playing || m_suspended)
        return;
    // Moved by someone else while playing (Home, End, a click on the ruler): play on from there.
    m_frame = frameAt(time);
    startAt(time);
}

void PlaybackController::onScrubbing(bool scrubbing)
{
    if (!m_playing)
        return;
    if (scrubbing) {
        m_suspended = true;
        stopSound();
    } else {
        m_suspended = false;
        m_frame = frameAt(m_playhead->time());
        startAt(m_playhead->time());
    }
}

void PlaybackController::onDocumentChanged(ChangeFlags what)
{
    if (what & Change::Photo)
        pause(); // another project
    if (what & (Change::Animation | Change::Photo)) {
        const QVector<AudioClip> &clips = m_document->timeline().audioClips();
        if (clips != m_clips) {
            m_clips = clips;
            cancelMix();
            stopSound();
            m_soundOpen = false;
            m_soundPath.clear();
            m_heard.reset();
            // A track that must be mixed is opened when it plays (a drag of a clip changes the
            // track at every step); one clip heard whole opens at once.
            const QVector<AudioClip> sounding = soundingClips(clips);
            const bool whole = sounding.size() == 1 && sounding.first().trimIn == 0 && sounding.first().trimOut == 0;
            if (whole || (m_playing && !m_suspended))
                openSound();
            if (m_playing && !m_suspended)
                startSound(m_clock.time(now()));
        }
        updateActions();
    }
}

} // namespace toonface
