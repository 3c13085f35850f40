#pragma once

#include "track/livepose.h"

#include <QPointer>
#include <QString>
#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QTimer;

namespace toonface {

class CameraFeed;
class Document;
class FramePane;
class LiveSession;
class Microphone;
class Playhead;

// Live Mode: the cartoon follows a performer in real time. The source is a camera (picked by
// description) or a video file played at its own pace (the clip's sound standing in for the
// microphone); the cartoon fills the window, the source's frame with the face's box shows
// small beside it. Set Rest Pose takes the current frame as the neutral face; Record/Stop puts
// the performance on the timeline at the playhead as one undo step (with the microphone's or
// the clip's sound as a WAV beside the project, or motion only when there is none). The mouth
// follows the camera, the microphone, or both (the microphone when the lips are lost); with the
// source "Microphone only" no camera is needed: the voice alone moves the mouth.
class LiveWindow : public QWidget
{
    Q_OBJECT

public:
    // With no parent it is a top-level window of its own (as the studio opens it).
    LiveWindow(Document *document, Playhead *playhead, QWidget *parent = nullptr);
    ~LiveWindow() override;

    // Where Live Mode opens: its own window of `wanted` size (shrunk to the screen), beside the
    // main window's frame `mainFrame` when the screen `available` has room on the right (else
    // the left), otherwise at the screen's right edge, level with the main window's top, so
    // that the main window's photo and menus stay in sight. Always inside `available`.
    static QRect placement(const QRect &mainFrame, QSize wanted, const QRect &available);

    // Plays the clip at `path` as the live source (false with the message in the status line).
    bool startClip(const QString &path);
    // Starts the camera described so (empty: the default); false, with the no-camera message
    // shown, when there is none.
    bool startCamera(const QString &description);
    // The microphone alone drives the cartoon (its mouth; the face at rest): for a performer
    // only heard. False, with the microphone's message shown, when there is none.
    bool startMicrophoneOnly();
    // Stops the source (and a recording, committing it).
    void stopSource();

    void setMouthMode(LiveMouth mode);
    void setLooping(bool loop);

    LiveSession *session() const { return m_session; }
    FramePane *cartoonPane() const { return m_cartoon; }
    FramePane *sourcePane() const { return m_source; }
    QPushButton *recordButton() const { return m_record; }
    QPushButton *restPoseButton() const { return m_restPose; }
    QString statusText() const;
    // The figures line ("shown 90 of 90 frames, 30.0 fps, latency ...").
    QString figuresText() const;

Q_SIGNALS:
    // For the main window's status bar.
    void message(const QString &text);
    // The window was closed (its source stopped, a recording committed).
    void closed();

protected:
    void closeEvent(QCloseEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;

private:
    void fillSources();
    void onSourceChosen(int index);
    void onFrame();
    void onFinished(const QString &error);
    void toggleRecording(bool on);
    void finishRecording();
    void updateFigures();
    void setStatus(const QString &text);
    void applyMouthMode();

    Document *m_document;
    QPointer<Playhead> m_playhead;
    LiveSession *m_session;
    CameraFeed *m_feed;
    Microphone *m_microphone;
    FramePane *m_cartoon;
    FramePane *m_source;
    QComboBox *m_sources;
    QComboBox *m_mouth;
    QCheckBox *m_loop;
    QPushButton *m_restPose;
    QPushButton *m_record;
    QLabel *m_figures;
    QLabel *m_status;
    QTimer *m_figuresTimer;
    QString m_clip; // the clip playing, empty for a camera
    double m_recordAt = 0;
    bool m_clipHasSound = false;
};

} // namespace toonface
