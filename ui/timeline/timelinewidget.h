#pragma once

#include "face/emotion.h"
#include "timeline/timelinepainter.h"

#include <QDockWidget>
#include <QList>
#include <QWidget>

#include <array>

class QAction;

class QToolBar;

namespace toonface {

class Document;
class Playhead;
class TimelineView;
class ShapePalette;
class EmotionPalette;

// The timeline's commands, for the main window's menus and toolbars. Their shortcuts act while
// the timeline has focus (Qt::WidgetWithChildrenShortcut).
struct TimelineActions
{
    QAction *zoomIn = nullptr;
    QAction *zoomOut = nullptr;
    QAction *zoomToFit = nullptr;
    QAction *waveformTaller = nullptr; // the waveform's vertical zoom
    QAction *waveformShorter = nullptr;
    QAction *snap = nullptr; // checkable: snap to frames and syllable boundaries
    QAction *deleteItems = nullptr;
    QAction *copy = nullptr;
    QAction *paste = nullptr;
    QAction *selectAll = nullptr;
    QAction *regenerateBlinks = nullptr;
    QAction *addShake = nullptr;
    QAction *addNod = nullptr;
    std::array<QAction *, 5> applyEmotion {}; // by Emotion, over the selected range

    QList<QAction *> all() const;
};

// The timeline dock's contents: a tool bar (zoom, snap, edit, blinks and head motion, the
// emotion presets and the mouth-shape palette) above the TimelineView. Takes the document and
// the shared playhead; holds nothing of the main window.
class TimelineWidget : public QWidget
{
    Q_OBJECT

public:
    TimelineWidget(Document *document, Playhead *playhead, QWidget *parent = nullptr);

    TimelineView *view() const { return m_view; }
    // The height that shows the tool bar and every row at its compact height: what a short
    // screen gives the timeline at first.
    int compactHeight() const;
    // Asks for an emotion clip's intensity in percent (dialog "emotionIntensityDialog") and
    // sets it as one undo step.
    void editEmotionIntensity(int clip);
    const TimelineActions &timelineActions() const { return m_actions; }

private:
    void createActions();
    void updateActions();
    // One mouth key selected (and not playing): the playhead goes into it, so the cartoon shows
    // that shape.
    void showSelectedMouthKey();
    void showContextMenu(const TimelineHit &hit, const QPoint &globalPos);

    Document *m_document;
    Playhead *m_playhead;
    QToolBar *m_toolBar = nullptr;
    TimelineView *m_view;
    ShapePalette *m_shapes;
    EmotionPalette *m_emotions;
    TimelineActions m_actions;
};

// The timeline as a dock for the main window ("Timeline", object name "timelineDock").
class TimelineDock : public QDockWidget
{
    Q_OBJECT

public:
    TimelineDock(Document *document, Playhead *playhead, QWidget *parent = nullptr);
    TimelineWidget *timeline() const { return m_timeline; }

private:
    TimelineWidget *m_timeline;
};

} // namespace toonface
