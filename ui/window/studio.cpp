#include "window/studio.h"

#include "playback/timereadout.h"

#include "capture/capturedialog.h"
#include "capture/importvideodialog.h"
#include "capture/livewindow.h"
#include "capture/videoview.h"
#include "dialogs/blinksdialog.h"
#include "dialogs/emotiondialog.h"
#include "dialogs/exportanimationdialog.h"
#include "dialogs/lipsyncdialog.h"
#include "dialogs/mouthshapesdialog.h"
#include "dialogs/preferencesdialog.h"
#include "dialogs/saytextdialog.h"
#include "document/companionfile.h"
#include "document/document.h"
#include "export/animationexport.h"
#include "playback/playbackcontroller.h"
#include "playback/playhead.h"
#include "playback/timereadout.h"
#include "timeline/timelineedits.h"
#include "timeline/timelineview.h"
#include "timeline/timelinewidget.h"
#include "views/previewview.h"
#include "views/themedicon.h"
#include "window/settings.h"

#include <QAction>
#include <QCoreApplication>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QIcon>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QScreen>
#include <QStandardPaths>
#include <QToolBar>

namespace toonface {

namespace {

constexpr double kEmotionFromPlayhead = 2.0; // seconds Add Emotion offers from the playhead
constexpr double kShortestEmotion = 0.5; // less than this before the end: the whole animation

} // namespace

Studio::Studio(Document *document, QMainWindow *window)
    : QObject(window)
    , m_document(document)
    , m_window(window)
    , m_playhead(new Playhead(this))
    , m_playback(new PlaybackController(document, m_playhead, this))
{
    connect(m_playback, &PlaybackController::message, this, &Studio::message);
    connect(m_document, &Document::changed, this, [this](ChangeFlags what) {
        if (what & (Change::Face | Change::Photo))
            updateEnabled();
    });
}

Studio::~Studio()
{
    delete m_liveWindow.data();
}

void Studio::install(PreviewView *preview, QAction *beforeMenu)
{
    m_timelineDock = new TimelineDock(m_document, m_playhead, m_window);
    // A few rows at least; the dock scrolls the others, so it never sets the window's height.
    m_timelineDock->widget()->setMinimumHeight(160);
    m_window->addDockWidget(Qt::BottomDockWidgetArea, m_timelineDock);

    m_lipSync = new QAction(themedIcon("audio-x-generic", "lip-sync.svg"), tr("&Lip Sync from Recording…"), this);
    m_lipSync->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_L));
    m_lipSync->setStatusTip(tr("Time the mouth to a speech recording and its script"));
    connect(m_lipSync, &QAction::triggered, this, [this] {
        m_playback->pause();
        QString outcome;
        if (LipSyncDialog::run(m_window, m_document, m_playhead->time(), &outcome))
            Q_EMIT message(outcome);
    });
    m_sayText = new QAction(themedIcon("insert-text", "say-text.svg"), tr("&Say Text…"), this);
    m_sayText->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_T));
    m_sayText->setStatusTip(tr("Speak a text with the built-in voice and lip-sync the face to it"));
    connect(m_sayText, &QAction::triggered, this, [this] {
        m_playback->pause();
        QString outcome;
        if (SayTextDialog::run(m_window, m_document, m_playhead->time(), &outcome))
            Q_EMIT message(outcome);
    });
    m_addBlinks = new QAction(QIcon(QStringLiteral(":/toonface/icons/timeline-blinks.svg")), tr("Add &Blinks…"), this);
    connect(m_addBlinks, &QAction::triggered, this, [this] { BlinksDialog::run(m_window, m_document); });
    m_addEmotion = new QAction(QIcon(QStringLiteral(":/toonface/icons/emotion-smile.svg")), tr("Add &Emotion…"), this);
    m_addEmotion->setObjectName(QStringLiteral("actionAddEmotion"));
    connect(m_addEmotion, &QAction::triggered, this, &Studio::addEmotion);
    m_mouthShapes = new QAction(tr("&Mouth Shapes…"), this);
    m_mouthShapes->setStatusTip(tr("Edit this character's nine mouth shapes"));
    connect(m_mouthShapes, &QAction::triggered, this, [this] { MouthShapesDialog::run(m_window, m_document); });
    m_exportAnimation
        = new QAction(themedIcon("document-export", "document-export.svg"), tr("Export &Animation…"), this);
    m_exportAnimation->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E));
    m_exportAnimation->setStatusTip(tr("Export the animation as SVG, HTML, MP4, GIF or PNG frames"));
    connect(m_exportAnimation, &QAction::triggered, this, &Studio::exportAnimation);

    m_animationMenu = new QMenu(tr("&Animation"), m_window);
    m_animationMenu->addAction(m_lipSync);
    m_animationMenu->addAction(m_sayText);
    m_animationMenu->addSeparator();
    m_animationMenu->addAction(m_addEmotion);
    m_animationMenu->addAction(m_addBlinks);
    m_animationMenu->addAction(preview->editPoseAction());
    m_animationMenu->addSeparator();
    m_animationMenu->addAction(m_mouthShapes);
    const TimelineActions &timeline = m_timelineDock->timeline()->timelineActions();
    QMenu *edit = m_animationMenu->addMenu(tr("&Timeline"));
    edit->addActions({timeline.copy, timeline.paste, timeline.deleteItems, timeline.selectAll});
    edit->addSeparator();
    edit->addActions({timeline.regenerateBlinks, timeline.addShake, timeline.addNod});
    edit->addSeparator();
    for (QAction *a : timeline.applyEmotion)
        edit->addAction(a);
    edit->addSeparator();
    edit->addActions({timeline.snap, timeline.zoomIn, timeline.zoomOut, timeline.zoomToFit});
    m_animationMenu->addSeparator();
    m_animationMenu->addAction(m_exportAnimation);
    installCapture();

    m_playbackMenu = new QMenu(tr("&Playback"), m_window);
    m_playbackMenu->addActions(m_playback->actions());
    m_window->menuBar()->insertMenu(beforeMenu, m_animationMenu);
    m_window->menuBar()->insertMenu(beforeMenu, m_playbackMenu);

    m_transport = m_window->addToolBar(tr("Transport"));
    m_transport->setObjectName(QStringLiteral("transportToolBar"));
    m_transport->addActions(m_playback->actions());
    m_transport->addWidget(new TimeReadout(m_document, m_playhead, m_transport));
    m_transport->addSeparator();
    m_transport->addAction(m_lipSync);
    m_transport->addAction(preview->editPoseAction());
    m_transport->addAction(m_exportAnimation);
    // The transport's shortcuts (Space, arrows, Home, End) work anywhere in the window.
    m_window->addActions(m_playback->actions());
    installVideo();
    installPreferences();
    updateEnabled();
}

// --- Import Video and the video dock (issue 11) ---------------------------------------------
// Animation ▸ Import Video… tracks a clip onto the timeline; the Video dock beside the preview
// shows the clip at the playhead. The dock's toggle joins View (else the Animation menu).
void Studio::installVideo()
{
    m_importVideo = new QAction(themedIcon("video-x-generic", "import-video.svg"), tr("Import &Video…"), this);
    m_importVideo->setObjectName(QStringLiteral("importVideo"));
    m_importVideo->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_V));
    m_importVideo->setStatusTip(tr("Track a clip of a person speaking and put the motion on the timeline"));
    connect(m_importVideo, &QAction::triggered, this, [this] {
        m_playback->pause();
        const qsizetype before = m_document->timeline().audioClips().size();
        ImportVideoDialog dialog(m_document, m_playhead->time(), m_window);
        if (dialog.exec() != QDialog::Accepted)
            return;
        m_videoDock->show();
        m_videoDock->raise(); // its tab in front: the clip just imported
        const QString name = QFileInfo(m_document->timeline().video()->path).fileName();
        const QString imported = m_document->timeline().audioClips().size() > before
            ? tr("Imported %1 with its sound as a clip on the audio track").arg(name)
            : tr("Imported %1").arg(name);
        Q_EMIT message(
            dialog.warnings().isEmpty() ? imported : imported + QStringLiteral(" — ") + dialog.warnings().join(u' '));
    });
    const QList<QAction *> animationActions = m_animationMenu->actions();
    m_animationMenu->insertAction(animationActions.value(2), m_importVideo);

    m_videoDock = new VideoDock(m_document, m_playhead, m_window);
    m_window->addDockWidget(Qt::RightDockWidgetArea, m_videoDock);
    // A tab beside the docks already on the right: a column of its own would leave the photo
    // and the cartoon a sliver on a laptop's screen. It comes to the front when a clip arrives.
    for (QDockWidget *other : m_window->findChildren<QDockWidget *>()) {
        if (other != m_videoDock && other->parentWidget() == m_window
            && m_window->dockWidgetArea(other) == Qt::RightDockWidgetArea && !other->isFloating()) {
            m_window->tabifyDockWidget(other, m_videoDock);
            break;
        }
    }
    connect(m_videoDock, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible)
            m_videoDock->raise();
    });
    QAction *toggle = m_videoDock->toggleViewAction();
    toggle->setObjectName(QStringLiteral("showVideo"));
    toggle->setStatusTip(tr("Show the imported clip beside the cartoon"));
    QMenu *view = windowMenu("&View");
    (view ? view : m_animationMenu)->addAction(toggle);
    m_transport->insertAction(m_exportAnimation, m_importVideo);
}
// --- end of Import Video ---------------------------------------------------------------------

QMenu *Studio::windowMenu(const char *title) const
{
    // The main window's titles, translated in its context as it shows them.
    const QString text = QCoreApplication::translate("toonface::MainWindow", title);
    for (QAction *a : m_window->menuBar()->actions()) {
        if (a->menu() && a->text() == text)
            return a->menu();
    }
    return nullptr;
}

// Edit ▸ Preferences…: the interface's language.
void Studio::installPreferences()
{
    m_preferences = new QAction(tr("Pre&ferences…"), this);
    m_preferences->setObjectName(QStringLiteral("preferences"));
    m_preferences->setShortcut(QKeySequence::Preferences);
    m_preferences->setMenuRole(QAction::PreferencesRole);
    m_preferences->setStatusTip(tr("Choose the language of the interface"));
    connect(m_preferences, &QAction::triggered, this, [this] { PreferencesDialog::run(m_window); });
    if (QMenu *edit = windowMenu("&Edit")) {
        edit->addSeparator();
        edit->addAction(m_preferences);
    } else {
        m_window->addAction(m_preferences);
    }
}

QString Studio::defaultExportPath(const QString &suffix) const
{
    return exportFile(*m_document, suffix, QStringLiteral("animation"),
        QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation));
}

void Studio::exportAnimation()
{
    m_playback->pause();
    ExportRequest base = exportRequestFor(m_document->project());
    base.outputPath = defaultExportPath(QStringLiteral("mp4"));
    const QString written = ExportAnimationDialog::run(m_window, base);
    if (!written.isEmpty())
        Q_EMIT message(tr("Exported %1").arg(QDir::toNativeSeparators(written)));
}

void Studio::addEmotion()
{
    // Over the timeline's selected range; else two seconds from the playhead; else (at the
    // end, or an empty animation) the whole of it.
    const TimelineView *view = m_timelineDock->timeline()->view();
    const std::optional<Span> selected = selectionRange(m_document->animation(), view->selection());
    const double duration = m_document->timeline().duration();
    const double at = m_playhead->time();
    if (selected && selected->end > selected->start)
        EmotionDialog::run(m_window, m_document, selected->start, selected->end);
    else if (at + kShortestEmotion <= duration)
        EmotionDialog::run(m_window, m_document, at, std::min(at + kEmotionFromPlayhead, duration));
    else
        EmotionDialog::run(m_window, m_document);
}

void Studio::updateEnabled()
{
    const bool face = m_document->hasFace();
    for (QAction *a : {m_lipSync, m_sayText, m_addBlinks, m_addEmotion, m_mouthShapes, m_exportAnimation}) {
        if (a)
            a->setEnabled(face);
    }
}

// --- Camera capture and live mode (issue 11) ---

void Studio::installCapture()
{
    m_captureCamera = new QAction(themedIcon("camera-photo", "camera.svg"), tr("Capture from &Camera…"), this);
    m_captureCamera->setStatusTip(tr("Take the neutral photo with a camera"));
    connect(m_captureCamera, &QAction::triggered, this, &Studio::captureFromCamera);
    m_liveMode = new QAction(themedIcon("camera-web", "live-mode.svg"), tr("&Live Mode…"), this);
    m_liveMode->setObjectName(QStringLiteral("actionLiveMode"));
    m_liveMode->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_L));
    m_liveMode->setStatusTip(tr("Puppeteer the cartoon live from a camera or a video, and record the performance"));
    connect(m_liveMode, &QAction::triggered, this, &Studio::showLiveMode);

    // After Open in the File menu (the main window's first menu).
    if (QMenu *file = m_window->menuBar()->actions().constFirst()->menu()) {
        const QList<QAction *> items = file->actions();
        file->insertAction(items.value(1), m_captureCamera);
    }
    m_animationMenu->insertAction(m_mouthShapes, m_liveMode);
    m_animationMenu->insertSeparator(m_mouthShapes);
}

void Studio::captureFromCamera()
{
    m_playback->pause();
    CaptureDialog dialog(m_document, m_window);
    connect(&dialog, &CaptureDialog::photoTaken, this, [this](const QString &path) {
        Q_EMIT message(tr("Camera photo saved as %1").arg(QDir::toNativeSeparators(path)));
        Q_EMIT photoCaptured(path);
    });
    dialog.exec();
}

void Studio::showLiveMode()
{
    m_playback->pause();
    if (!m_liveWindow) {
        // A window of its own, not the main window's child (which the window manager keeps above
        // it); it never keeps the editor running alone: closeLiveMode() closes it with the main
        // window, and Qt quits when the main window closes.
        m_liveWindow = new LiveWindow(m_document, m_playhead);
        m_liveWindow->setAttribute(Qt::WA_QuitOnClose, false);
        connect(m_liveWindow, &LiveWindow::message, this, &Studio::message);
        connect(m_liveWindow, &LiveWindow::closed, this,
            [this] { Settings().setLiveWindowGeometry(m_liveWindow->saveGeometry()); });
        // Where it was last closed; the first time beside the main window (centred over it, it
        // would hide the photo).
        const QByteArray geometry = Settings().liveWindowGeometry();
        if (geometry.isEmpty() || !m_liveWindow->restoreGeometry(geometry)) {
            if (const QScreen *screen = m_window->screen()) {
                const QRect place = LiveWindow::placement(
                    m_window->frameGeometry(), m_liveWindow->size(), screen->availableGeometry());
                m_liveWindow->resize(place.size());
                m_liveWindow->move(place.topLeft());
            }
        }
    }
    m_liveWindow->show();
    m_liveWindow->raise();
    m_liveWindow->activateWindow();
}

LiveWindow *Studio::liveWindow() const
{
    return m_liveWindow.data();
}

void Studio::closeLiveMode()
{
    if (m_liveWindow && m_liveWindow->isVisible())
        m_liveWindow->close();
}

// --- end of camera capture and live mode ---

} // namespace toonface
