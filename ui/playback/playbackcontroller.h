#pragma once

#include "document/document.h"
#include "media/audiomix.h"
#include "playback/playbackclock.h"

#include <QElapsedTimer>
#include <QList>
#include <QObject>
#include <QPointer>
#include <QTemporaryDir>
#include <QTimer>

#include <atomic>
#include <functional>
#include <memory>
#include <optional>

class QAction;

namespace toonface {

class AudioTrack;
class Playhead;

// Plays the document's animation: advances the Playhead frame by frame and sounds the timeline's
// audio track through an AudioTrack: the file of its only clip, or its clips mixed into one
// (trackSoundFile, made again when the track has changed and it plays).
//
// The picture follows the audio clock: while the sound plays, every tick reads its position and
// re-syncs the PlaybackClock to it (see there), so picture and sound stay within a frame of each
// other however long it plays. The picture never runs away from the sound and never steps back
// for it: until the sound starts flowing (an output can take a second to start) and while it
// stalls (its position stands still) the picture waits, at most kMaxAheadOfSound ahead of the
// sound's last position (up to kSoundGrace seconds; a sound silent for longer no longer holds
// the picture); when the sound turns out behind the picture, the picture holds until the
// sound catches up. Without sound (no clip, its file missing, no audio output device:
// QMediaDevices::audioOutputs() empty) it runs on the wall clock (QElapsedTimer).
//
// The track's sound starts `offset` seconds into the animation (silence before it: a lead-in) and
// lasts `duration` seconds; the animation goes on silently past it. Playback ends at the last
// frame, or with loop on wraps to the start. The playhead shows frame times (frame / fps).
//
// Transport actions (icons, shortcuts: Space, Left/Right, Home, End) are for the window's
// toolbar and menus; their shortcuts work once they are added to a widget of the window.
//
// Lives on the GUI thread.
class PlaybackController : public QObject
{
    Q_OBJECT

public:
    PlaybackController(Document *document, Playhead *playhead, QObject *parent = nullptr);
    ~PlaybackController() override;

    QAction *playPauseAction() const { return m_playPause; }
    QAction *stopAction() const { return m_stop; }
    QAction *loopAction() const { return m_loop; }
    QAction *firstFrameAction() const { return m_first; }
    QAction *previousFrameAction() const { return m_previous; }
    QAction *nextFrameAction() const { return m_next; }
    QAction *lastFrameAction() const { return m_last; }
    // The transport in toolbar order: first, previous, play/pause, next, last, stop, loop.
    QList<QAction *> actions() const;

    bool isPlaying() const { return m_playing; }
    bool isLooping() const;
    void setLooping(bool loop);
    // The timeline's frame rate and its last frame's time.
    double frameRate() const;
    double lastFrameTime() const;

    // Whether the sound is heard while playing (a clip, its file opened, an output device).
    bool hasSound() const;
    // Whether the clips are being mixed to one file in the background (soundReady() follows).
    bool isMixing() const { return m_mixing; }
    // Why there is no sound, for the status bar (empty when there is, or no clip to play).
    QString soundProblem() const { return m_soundProblem; }
    // Frames the playhead was moved to while playing, and the re-syncs to the audio clock that
    // jumped (a seek, a stall); for tests and a status display.
    int framesPlayed() const { return m_framesPlayed; }
    int audioResyncs() const { return m_resyncs; }
    // The largest |audio - picture clock| seen before a correction since play() (seconds).
    double maxAudioError() const { return m_maxAudioError; }

    // Replaces the sound's player (taking ownership); null plays silently. By default a
    // MediaAudioTrack when an output device exists. For tests and for a chosen device.
    void setAudioTrack(std::unique_ptr<AudioTrack> track);
    // Replaces the wall clock (nanoseconds, monotonic); for tests that simulate long playbacks.
    void setWallClock(std::function<qint64()> nowNs);

public Q_SLOTS:
    void play();
    void pause();
    void togglePlay();
    // Pauses and returns to the first frame.
    void stop();
    // Pauses and moves by `frames` frames, within the timeline.
    void stepFrames(int frames);
    void goToFirstFrame();
    void goToLastFrame();
    // Advances playback to the clock's time now (the frame timer calls it).
    void tick();

Q_SIGNALS:
    void playingChanged(bool playing);
    // Something the user should know, for the status bar (e.g. "playing without sound: ...").
    void message(const QString &text);
    // A mix made in the background is open (or failed: soundProblem() says why).
    void soundReady();

private:
    enum class Sound { Off, Waiting, Playing, Done };

    // How far the picture may run ahead of the sound's last told position: more than the steps
    // sound systems tell the position in (PulseAudio: 128-256 ms).
    static constexpr double kMaxAheadOfSound = 0.5;
    // How long a sound that has not started, or stands still, holds the picture.
    static constexpr double kSoundGrace = 2.0;

    void createActions();
    void updateActions();
    void onDocumentChanged(ChangeFlags what);
    void onPlayheadMoved(double time);
    void onScrubbing(bool scrubbing);
    void openSound();
    // Opens `sound` (the track `clips` as one file) in the player, or says `problem`.
    void useSound(const QVector<AudioClip> &clips, const std::optional<TrackSound> &sound, const QString &problem);
    // Drops the mix being made (the track changed): its result, when it comes, is not used.
    void cancelMix();
    // Starts the clock and the sound at animation time `time`.
    void startAt(double time);
    void startSound(double time);
    void stopSound();
    void updateSound(double time);
    // Holds the clock back to where the sound is, while the sound is late or stands still.
    void holdForSound(qint64 wall);
    void setPlayheadFrame(int frame);
    int frameAt(double time) const;
    qint64 now() const;

    Document *m_document;
    QPointer<Playhead> m_playhead;
    std::unique_ptr<AudioTrack> m_track;
    std::function<qint64()> m_wallClock;
    QElapsedTimer m_elapsed;
    PlaybackClock m_clock;
    QTimer m_timer;

    bool m_playing = false;
    bool m_suspended = false; // while the user scrubs
    bool m_settingTime = false;
    int m_frame = 0; // the frame the playhead shows
    Sound m_sound = Sound::Off;
    bool m_soundFlowed = false; // the track has told a position since it was started
    std::optional<double> m_lastAudioPosition; // the track's position as last told, since it was started
    double m_soundHoldTime = 0; // animation time the clock may not pass while the sound is held up
    qint64 m_soundNewsNs = 0; // when the sound last moved (or started)
    QVector<AudioClip> m_clips; // the audio track as last seen, to notice edits of it
    QVector<AudioClip> m_openedClips; // the track m_track has open
    std::optional<AudioClip> m_heard; // the file m_track plays, where it starts and how long it sounds
    std::unique_ptr<QTemporaryDir> m_mixFolder; // where the clips are mixed to one file
    QString m_mixPath; // the mix m_track has open, or empty
    int m_mixCount = 0;
    struct MixOutcome
    {
        std::optional<TrackSound> sound;
        QString error;
    };
    bool m_mixing = false; // a mix of m_mixingClips is being made
    QVector<AudioClip> m_mixingClips;
    int m_mixGeneration = 0; // the mix that counts; an older one finishing is dropped
    std::shared_ptr<std::atomic_bool> m_mixCancel; // stops the mix that no longer counts
    QString m_soundPath; // the file m_track has open
    bool m_soundOpen = false;
    QString m_soundProblem;
    int m_framesPlayed = 0;
    int m_resyncs = 0;
    double m_maxAudioError = 0;

    QAction *m_playPause = nullptr;
    QAction *m_stop = nullptr;
    QAction *m_loop = nullptr;
    QAction *m_first = nullptr;
    QAction *m_previous = nullptr;
    QAction *m_next = nullptr;
    QAction *m_last = nullptr;
};

} // namespace toonface
