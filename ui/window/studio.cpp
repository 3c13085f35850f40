#include "window/studio.h"

#include "dialogs/blinksdialog.h"
#include "dialogs/emotiondialog.h"
#include "dialogs/exportanimationdialog.h"
#include "dialogs/lipsyncdialog.h"
#include "dialogs/mouthshapesdialog.h"
#include "dialogs/saytextdialog.h"
#include "document/document.h"
#include "export/animationexport.h"
#include "playback/playbackcontroller.h"
#include "playback/playhead.h"
#include "timeline/timelineedits.h"
#include "timeline/timelineview.h"
#include "timeline/timelinewidget.h"
#include "views/previewview.h"
#include "views/themedicon.h"

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QIcon>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
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

void Studio::install(PreviewView *preview, QAction *beforeMenu)
{
    m_timelineDock = new TimelineDock(m_document, m_playhead, m_window);
    // A few rows at least; the dock scrolls the others, so it never sets the window's height.
    m_timelineDock->widget()->setMinimumHeight(160);
    m_window->addDockWidget(Qt::BottomDockWidgetArea, m_timelineDock);

    m_lipSync = new QAction(themedIcon("audio-x-generic", "lip-sync.svg"), tr("&Lip Sync from Recording…"), this);
    m_lipSync->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_L));
    m_lipSync->setStatusTip(tr("Time the mouth to a speech recording and its script"));
    connect(m_lipSync, &QAction::triggered, this, [this] { LipSyncDialog::run(m_window, m_document); });
    m_sayText = new QAction(themedIcon("insert-text", "say-text.svg"), tr("&Say Text…"), this);
    m_sayText->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_T));
    m_sayText->setStatusTip(tr("Speak a text with the built-in voice and lip-sync the face to it"));
    connect(m_sayText, &QAction::triggered, this, [this] { SayTextDialog::run(m_window, m_document); });
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

    m_playbackMenu = new QMenu(tr("&Playback"), m_window);
    m_playbackMenu->addActions(m_playback->actions());
    m_window->menuBar()->insertMenu(beforeMenu, m_animationMenu);
    m_window->menuBar()->insertMenu(beforeMenu, m_playbackMenu);

    m_transport = m_window->addToolBar(tr("Transport"));
    m_transport->setObjectName(QStringLiteral("transportToolBar"));
    m_transport->addActions(m_playback->actions());
    m_transport->addSeparator();
    m_transport->addAction(m_lipSync);
    m_transport->addAction(preview->editPoseAction());
    m_transport->addAction(m_exportAnimation);
    // The transport's shortcuts (Space, arrows, Home, End) work anywhere in the window.
    m_window->addActions(m_playback->actions());
    updateEnabled();
}

QString Studio::defaultExportPath(const QString &suffix) const
{
    const QString from = !m_document->filePath().isEmpty() ? m_document->filePath() : m_document->project().photoPath;
    if (from.isEmpty())
        return QDir(QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation))
            .filePath(QStringLiteral("animation.") + suffix);
    const QFileInfo info(from);
    return info.absoluteDir().filePath(info.completeBaseName() + QLatin1Char('.') + suffix);
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

} // namespace toonface
