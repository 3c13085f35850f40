#pragma once

#include <QObject>

class QAction;
class QMainWindow;
class QMenu;
class QToolBar;

namespace toonface {

class Document;
class Playhead;
class PlaybackController;
class PreviewView;
class TimelineDock;

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

    Playhead *playhead() const { return m_playhead; }
    PlaybackController *playback() const { return m_playback; }
    TimelineDock *timelineDock() const { return m_timelineDock; }
    QAction *exportAnimationAction() const { return m_exportAnimation; }
    QAction *lipSyncAction() const { return m_lipSync; }
    QAction *sayTextAction() const { return m_sayText; }
    QMenu *animationMenu() const { return m_animationMenu; }
    QMenu *playbackMenu() const { return m_playbackMenu; }

    // Adds the timeline dock, the menus (before `beforeMenu`, e.g. Help; null appends) and the
    // transport tool bar to the window; the preview's Edit Pose action joins the Animation menu.
    void install(PreviewView *preview, QAction *beforeMenu);

    // The file an export is offered under: beside the project (or the photo), named after it.
    QString defaultExportPath(const QString &suffix) const;

Q_SIGNALS:
    // Something for the status bar.
    void message(const QString &text);

private:
    void exportAnimation();
    void addEmotion();
    void updateEnabled();

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
};

} // namespace toonface
