#pragma once

#include "document/document.h"
#include "timeline/mouthicons.h"
#include "timeline/timelineedits.h"
#include "timeline/timelinelayout.h"
#include "timeline/timelinepainter.h"
#include "timeline/waveformsource.h"

#include <QAbstractScrollArea>

#include <algorithm>
#include <memory>
#include <vector>

class QLineEdit;

namespace toonface {

class Playhead;

// The timeline's rows, custom painted over the visible time range only: ruler, waveform,
// script row, mouth, emotion, blink, head, gaze and pose tracks, the playhead. It turns
// gestures into the edits of timelineedits.h, each pushed as one Document::changeAnimation
// step (a drag pushes its moves with one merge id and commits on release). It keeps no copy of
// the document: only its selection, zoom and caches derived from the document.
//
// Mouse: click/drag on the ruler or waveform scrubs the playhead (and, without Shift or Ctrl,
// clears the selection); click, Shift/Ctrl+click and a
// rubber band select; dragging a body moves, an edge resizes (neighbours give way), an emotion
// clip's handles set its fades and intensity, a mouth block's top its weight; double-click on a
// syllable edits its pinyin, on an emotion clip its intensity. Wheel scrolls, Shift+wheel scrolls the rows, Ctrl+wheel
// zooms about the cursor, Alt+wheel zooms the waveform vertically. Keys: m f h a i u e o n replace (or insert) a mouth
// shape while the mouth row has focus, Delete removes, Ctrl+C/Ctrl+V copy and paste at the playhead.
class TimelineView : public QAbstractScrollArea
{
    Q_OBJECT

public:
    TimelineView(Document *document, Playhead *playhead, QWidget *parent = nullptr);
    ~TimelineView() override;

    const Selection &selection() const { return m_selection; }
    void setSelection(const Selection &selection);
    const TimelineLayout &timelineLayout() const { return m_layout; }
    std::optional<RowKind> focusRow() const { return m_focusRow; }
    void setFocusRow(std::optional<RowKind> row);
    bool snapEnabled() const { return m_snap; }
    // The waveform of audio clip `clip` (of the first when there is none: it shows nothing).
    WaveformSource *waveform(int clip = 0)
    {
        return m_waveforms[std::clamp<size_t>(size_t(std::max(clip, 0)), 0, m_waveforms.size() - 1)].get();
    }
    const MouthIcons &mouthIcons() const { return m_icons; }
    // The waveform's vertical zoom over the recordings' own loudness (1: the loud parts of each
    // recording fill the row). The gain is what clip `clip`'s sample values are multiplied by on
    // screen: each recording has its own, so a quiet take beside a loud clip (a video's sound)
    // is not drawn as a flat line.
    double waveformZoom() const { return m_waveformZoom; }
    double waveformGain(int clip = 0) const;

    // Where an item is drawn, in viewport coordinates (what a click on it takes hold of).
    QRectF itemRect(const ItemRef &item) const;
    // The viewport position of an emotion clip's fade-in, fade-out or intensity handle.
    QPointF emotionHandle(int clip, HitPart part) const;
    TimelineHit hitAt(QPoint viewportPos) const;
    // The viewport x of a time.
    double xOf(double t) const { return m_layout.xOf(t); }

    // The span edits act on: the selection's, else `length` seconds from the playhead.
    Span targetRange(double length) const;
    double minSpan() const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;
    // The height that shows every row at its compact height (the ruler and scroll bar included).
    int compactHeight() const;

public Q_SLOTS:
    void zoomIn();
    void zoomOut();
    void zoomToFit();
    // Zooms to `pps` keeping the time under viewport x `anchorX` in place.
    void setPixelsPerSecond(double pps, double anchorX);
    void setSnapEnabled(bool on);
    void setWaveformZoom(double zoom);
    void waveformTaller() { setWaveformZoom(m_waveformZoom * kWaveformZoomStep); }
    void waveformShorter() { setWaveformZoom(m_waveformZoom / kWaveformZoomStep); }

    void deleteSelection();
    void copySelection();
    void paste();
    void selectAll();
    // Replaces the shapes of the selected mouth keys, or inserts a key at the playhead.
    void setMouthShape(MouthShape shape);
    void setMouthWeight(double weight);
    void setEmotionIntensity(int clip, double intensity);
    void applyEmotion(Emotion emotion);
    void regenerateBlinks();
    void addShake();
    void addNod();
    // Opens the pinyin editor over a syllable.
    void editSyllable(int index);

Q_SIGNALS:
    void selectionChanged();
    void snapChanged(bool on);
    // The mouth-shape pictures were rebuilt (the face, style or presets changed).
    void mouthIconsChanged();
    // A message for the status bar (an edit that could not be made says why).
    void message(const QString &text);
    void contextMenuRequested(const TimelineHit &hit, const QPoint &globalPos);
    // An emotion clip was double-clicked: its intensity is to be asked for.
    void emotionIntensityRequested(int clip);

protected:
    bool event(QEvent *event) override;
    void paintEvent(QPaintEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;
    void scrollContentsBy(int dx, int dy) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void mouseDoubleClickEvent(QMouseEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void contextMenuEvent(QContextMenuEvent *event) override;
    void dragEnterEvent(QDragEnterEvent *event) override;
    void dragMoveEvent(QDragMoveEvent *event) override;
    void dropEvent(QDropEvent *event) override;

private:
    enum class DragMode { None, Scrub, RubberBand, Move, Edge, FadeIn, FadeOut, Intensity, Weight };
    struct Drag
    {
        DragMode mode = DragMode::None;
        QPoint pressPos;
        bool started = false;
        bool pushed = false; // a step of this drag is on the undo stack
        Animation start;
        ItemRef item;
        SpanEdge edge = SpanEdge::Start;
        double grabOffset = 0; // the grabbed point's time minus the pointer's at the press
        Selection baseSelection;
        int mergeId = 0;
    };

    TimelineScene scene() const;
    void onDocumentChanged(ChangeFlags what);
    void updateScrollBars();
    // The view's maximum height follows its rows (which grow when clips overlap).
    void fitHeightToRows();
    void syncScrollBars();
    void followPlayhead(double t);
    double snapped(double t, bool *toBoundary = nullptr) const;
    void apply(const Animation &after, const QString &text);
    void dragTo(QPoint pos, bool commit);
    QString dragText() const;
    void commitPinyin();

    Document *m_document;
    Playhead *m_playhead;
    TimelineLayout m_layout;
    Selection m_selection;
    // The item a Shift+click extends the selection from: the last one clicked without Shift.
    std::optional<ItemRef> m_anchor;
    std::optional<RowKind> m_focusRow;
    QVector<Span> m_mouthSpans;
    MouthIcons m_icons;
    std::vector<std::unique_ptr<WaveformSource>> m_waveforms; // one per audio clip, at least one
    static constexpr double kWaveformZoomStep = 1.5;
    double m_waveformZoom = 1;
    bool m_snap = true;
    bool m_fitted = false;
    QString m_media; // the sound's and the clip's paths last shown, null before the first

    bool m_syncingScroll = false;
    Drag m_drag;
    QRect m_rubberBand;
    std::optional<double> m_snapLine;
    QLineEdit *m_pinyinEditor = nullptr;
    int m_editedSyllable = -1;
};

} // namespace toonface
