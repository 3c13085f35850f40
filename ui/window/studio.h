#pragma once

#include "anim/timeline.h"

#include <QObject>
#include <QPointer>

#include <optional>

class QAction;
class QMainWindow;
class QMenu;
class QToolBar;

namespace toonface {

class Document;
class LiveWindow;
class Playhead;
class PlaybackController;
class PreviewView;
class TimelineDock;
class VideoDock;

// The animation studio in the main window: the shared playhead, the playback transport, the
// timeline dock, and the Animation and Playback menus with their dialogs (lip sync, say text,
// blinks, emotion, mouth shapes, export). Wiring only: every piece is its own class.
//
// Create it before the preview (which follows playhead()), then install() it.
class Studio : public QObject
{
    Q_OBJECT

public:
    Studio(Document *document, QMainWindow *window);
    ~Studio() override;

    Playhead *playhead() const { return m_playhead; }
    PlaybackController *playback() const { return m_playback; }
    TimelineDock *timelineDock() const { return m_timelineDock; }
    QAction *exportAnimationAction() const { return m_exportAnimation; }
    // Import Video (issue 11): the action and the dock showing the clip beside the cartoon.
    QAction *importVideoAction() const { return m_importVideo; }
    VideoDock *videoDock() const { return m_videoDock; }
    QAction *lipSyncAction() const { return m_lipSync; }
    QAction *sayTextAction() const { return m_sayText; }
    QMenu *animationMenu() const { return m_animationMenu; }
    QMenu *playbackMenu() const { return m_playbackMenu; }

    // Adds the timeline dock, the menus (before `beforeMenu`, e.g. Help; null appends) and the
    // transport tool bar to the window; the preview's Edit Pose action joins the Animation menu.
    void install(PreviewView *preview, QAction *beforeMenu);

    // The file an export is offered under: beside the project (or the photo), named after it.
    QString defaultExportPath(const QString &suffix) const;

    // --- Camera capture and live mode (issue 11) ---
    // File ▸ Capture from Camera… and Animation ▸ Live Mode…, added to those menus by install().
    QAction *captureCameraAction() const { return m_captureCamera; }
    QAction *liveModeAction() const { return m_liveMode; }
    // Edit ▸ Preferences… (the interface's language), added to the Edit menu by install().
    QAction *preferencesAction() const { return m_preferences; }
    // The live mode window once opened (it is kept, hidden, when closed); null before. A
    // top-level window of its own: the window manager keeps it neither above the main window
    // nor on its task-bar entry, and it opens where it was last closed.
    LiveWindow *liveWindow() const;
    // Closes Live Mode (stopping its source and committing a recording) before the main window
    // closes, so that the question about unsaved changes covers the take.
    void closeLiveMode();
    // --- end of camera capture and live mode ---

Q_SIGNALS:
    // Something for the status bar.
    void message(const QString &text);
    // A camera snapshot was saved as `path`: the editor opens it as the new photo (the main
    // window connects this to its openFile()).
    void photoCaptured(const QString &path);

private:
    void exportAnimation();
    void addEmotion();
    void updateEnabled();
    void installVideo();
    // Camera capture and live mode.
    void installCapture();
    void captureFromCamera();
    void showLiveMode();
    void installPreferences();
    // The main window's menu titled `title` (its source text, e.g. "&View"), or null.
    QMenu *windowMenu(const char *title) const;

    Document *m_document;
    QMainWindow *m_window;
    Playhead *m_playhead;
    PlaybackController *m_playback;
    TimelineDock *m_timelineDock = nullptr;
    QMenu *m_animationMenu = nullptr;
    QMenu *m_playbackMenu = nullptr;
    QToolBar *m_transport = nullptr;
    QAction *m_lipSync = nullptr;
    QAction *m_sayText = nullptr;
    QAction *m_addBlinks = nullptr;
    QAction *m_addEmotion = nullptr;
    QAction *m_mouthShapes = nullptr;
    QAction *m_exportAnimation = nullptr;
    // Import Video.
    QAction *m_importVideo = nullptr;
    VideoDock *m_videoDock = nullptr;
    // Camera capture and live mode.
    QAction *m_captureCamera = nullptr;
    QAction *m_liveMode = nullptr;
    QPointer<LiveWindow> m_liveWindow; // top-level: deleted by ~Studio()
    QAction *m_preferences = nullptr;
};

} // namespace toonface
