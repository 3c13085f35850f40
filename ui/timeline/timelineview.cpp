#include "timeline/timelineview.h"

#include "playback/playhead.h"
#include "speech/pinyin.h"
#include "timeline/emotionpalette.h"
#include "timeline/timelinegeometry.h"

#include <QApplication>
#include <QClipboard>
#include <QJsonDocument>
#include <QKeyEvent>
#include <QLineEdit>
#include <QMimeData>
#include <QPainter>
#include <QRandomGenerator>
#include <QScrollBar>

#include <cmath>

namespace toonface {

namespace {

constexpr double kMaxPixelsPerSecond = 4000;
constexpr double kZoomStep = 1.25;
constexpr int kSnapPixels = 6;
constexpr double kEmotionLength = 2.0; // seconds of a preset dropped with no range selected
// A selection shorter than this is not a range an expression is meant to fill (a face needs
// about half a second to show one): a preset dropped on it starts where it was dropped.
constexpr double kShortestEmotionRange = 0.5;
constexpr double kHeadMoveLength = 1.5;
// Viewport widths (time area) narrower than this are a layout in progress, not one to fit to.
constexpr int kNarrowestFit = 200;
// The recording's loudness is drawn at this share of the row's half height.
constexpr double kWaveformFill = 0.9;
// Quieter than this (-40 dBFS) is drawn as if it were this loud: hiss or a silent file is not
// blown up to fill the row.
constexpr double kQuietestShown = 0.01;

std::optional<MouthShape> shapeForKey(int key)
{
    switch (key) {
    case Qt::Key_M: return MouthShape::M;
    case Qt::Key_F: return MouthShape::F;
    case Qt::Key_H: return MouthShape::H;
    case Qt::Key_A: return MouthShape::A;
    case Qt::Key_I: return MouthShape::I;
    case Qt::Key_U: return MouthShape::U;
    case Qt::Key_E: return MouthShape::E;
    case Qt::Key_O: return MouthShape::O;
    case Qt::Key_N: return MouthShape::N;
    default: return std::nullopt;
    }
}

} // namespace

TimelineView::TimelineView(Document *document, Playhead *playhead, QWidget *parent)
    : QAbstractScrollArea(parent)
    , m_document(document)
    , m_playhead(playhead)
{
    setFocusPolicy(Qt::StrongFocus);
    viewport()->setAttribute(Qt::WA_OpaquePaintEvent);
    viewport()->setMouseTracking(true);
    viewport()->setAcceptDrops(true);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOn);
    setVerticalScrollBarPolicy(Qt::ScrollBarAsNeeded);
    setFrameShape(QFrame::NoFrame);
    connect(m_document, &Document::changed, this, &TimelineView::onDocumentChanged);
    connect(m_playhead, &Playhead::timeChanged, this, [this](double t) {
        followPlayhead(t);
        viewport()->update();
    });
    m_waveforms.push_back(std::make_unique<WaveformSource>());
    connect(m_waveforms.back().get(), &WaveformSource::ready, viewport(), qOverload<>(&QWidget::update));
    fitHeightToRows();
    onDocumentChanged(ChangeFlags(Change::Photo) | Change::Animation | Change::MouthShapes);
}

TimelineView::~TimelineView() = default;

QSize TimelineView::sizeHint() const
{
    return QSize(900, TimelineLayout::kRulerHeight + m_layout.comfortableHeight() + 18);
}

int TimelineView::compactHeight() const
{
    return TimelineLayout::kRulerHeight + m_layout.compactHeight() + horizontalScrollBar()->sizeHint().height()
        + 2 * frameWidth();
}

void TimelineView::fitHeightToRows()
{
    // No taller than its rows: the room below the last would be empty.
    setMaximumHeight(sizeHint().height() + 2 * frameWidth());
    updateGeometry();
}

QSize TimelineView::minimumSizeHint() const
{
    return QSize(300, TimelineLayout::kRulerHeight + 120);
}

double TimelineView::minSpan() const
{
    return 1.0 / m_document->timeline().frameRate();
}

TimelineScene TimelineView::scene() const
{
    TimelineScene s;
    s.animation = m_document->animation();
    s.mouthSpans = &m_mouthSpans;
    s.layout = &m_layout;
    s.selection = &m_selection;
    const qsizetype clips = m_document->timeline().audioClips().size();
    for (qsizetype i = 0; i < clips && size_t(i) < m_waveforms.size(); ++i) {
        const WaveformSource &w = *m_waveforms[size_t(i)];
        s.clipPeaks.append(&w.peaks());
        s.clipStatus.append(w.isLoading() ? tr("Reading the sound…") : w.error());
    }
    for (qsizetype i = 0; i < s.clipPeaks.size(); ++i)
        s.clipGains.append(waveformGain(int(i)));
    s.icons = &m_icons;
    s.playhead = m_playhead->time();
    s.focusRow = m_focusRow;
    s.rubberBand = m_rubberBand;
    s.snapLine = m_snapLine;
    s.width = viewport()->width();
    s.height = viewport()->height();
    return s;
}

void TimelineView::onDocumentChanged(ChangeFlags what)
{
    if (what & (Change::Animation | Change::Photo)) {
        m_mouthSpans = itemSpans(m_document->animation(), ItemKind::Mouth);
        const Animation a = m_document->animation();
        // Overlapping clips stack in lanes (the row grows) so that none hides another's name.
        const bool audioGrew = m_layout.setItemLanes(RowKind::Waveform, stackInLanes(itemSpans(a, ItemKind::Audio)));
        const bool emotionGrew = m_layout.setItemLanes(RowKind::Emotion, stackInLanes(itemSpans(a, ItemKind::Emotion)));
        if (audioGrew || emotionGrew)
            fitHeightToRows();
        const Selection before = m_selection;
        m_selection.clip([&](ItemKind kind) { return itemCount(a, kind); });
        const QVector<AudioClip> &clips = m_document->timeline().audioClips();
        while (m_waveforms.size() < size_t(std::max<qsizetype>(1, clips.size()))) {
            m_waveforms.push_back(std::make_unique<WaveformSource>());
            connect(m_waveforms.back().get(), &WaveformSource::ready, viewport(), qOverload<>(&QWidget::update));
        }
        m_waveforms.resize(size_t(std::max<qsizetype>(1, clips.size())));
        QString media;
        for (size_t i = 0; i < m_waveforms.size(); ++i) {
            const QString path = qsizetype(i) < clips.size() ? clips[qsizetype(i)].path : QString();
            m_waveforms[i]->setPath(path);
            media += path + QLatin1Char('|');
        }
        // A new recording or clip (lip sync, Say Text, Import Video) is shown whole, not the
        // first second of it.
        const std::optional<VideoClip> &video = m_document->timeline().video();
        media += video ? video->path : QString();
        if (media != m_media) {
            const bool first = m_media.isNull();
            m_media = media;
            if (!first && media != QLatin1String("|") && media.size() > 1
                && viewport()->width() > TimelineLayout::kLabelWidth)
                zoomToFit();
        }
        if (m_selection != before)
            Q_EMIT selectionChanged();
    }
    if ((what & (Change::Face | Change::Points | Change::Style | Change::MouthShapes | Change::Photo))
        && m_icons.update(m_document->face(), m_document->style(), m_document->mouthShapes(), m_document->hasFace()))
        Q_EMIT mouthIconsChanged();
    if (what & Change::Photo) {
        m_fitted = false;
        if (viewport()->width() > TimelineLayout::kLabelWidth)
            zoomToFit();
    }
    updateScrollBars();
    viewport()->update();
}

void TimelineView::setSelection(const Selection &selection)
{
    if (selection == m_selection)
        return;
    m_selection = selection;
    viewport()->update();
    Q_EMIT selectionChanged();
}

void TimelineView::setFocusRow(std::optional<RowKind> row)
{
    m_focusRow = row;
    viewport()->update();
}

double TimelineView::waveformGain(int clip) const
{
    const WaveformSource *w
        = clip >= 0 && size_t(clip) < m_waveforms.size() ? m_waveforms[size_t(clip)].get() : nullptr;
    if (!w || w->peaks().isEmpty())
        return m_waveformZoom;
    return m_waveformZoom * kWaveformFill / std::max(kQuietestShown, w->loudness());
}

void TimelineView::setWaveformZoom(double zoom)
{
    m_waveformZoom = std::clamp(zoom, 1 / 16.0, 16.0);
    viewport()->update();
}

void TimelineView::setSnapEnabled(bool on)
{
    if (on == m_snap)
        return;
    m_snap = on;
    Q_EMIT snapChanged(on);
}

QRectF TimelineView::itemRect(const ItemRef &item) const
{
    const TimelineScene s = scene();
    const QVector<Span> spans = item.kind == ItemKind::Mouth ? m_mouthSpans : itemSpans(s.animation, item.kind);
    if (item.index < 0 || item.index >= spans.size())
        return {};
    if (hasSpans(item.kind))
        return geometry::itemSpanRect(s, rowOf(item.kind), item.index, spans[item.index]);
    return geometry::keyRect(s, rowOf(item.kind), spans[item.index].start);
}

QPointF TimelineView::emotionHandle(int clip, HitPart part) const
{
    const TimelineScene s = scene();
    const QVector<EmotionClip> &clips = s.animation.timeline.emotionClips();
    if (clip < 0 || clip >= clips.size())
        return {};
    const geometry::ClipHandles h = geometry::clipHandles(s, clip, clips[clip]);
    if (part == HitPart::FadeIn)
        return h.fadeIn;
    if (part == HitPart::FadeOut)
        return h.fadeOut;
    return QPointF((h.fadeIn.x() + h.fadeOut.x()) / 2, h.intensityY);
}

TimelineHit TimelineView::hitAt(QPoint viewportPos) const
{
    return hitTest(scene(), viewportPos);
}

Span TimelineView::targetRange(double length) const
{
    if (const std::optional<Span> range = selectionRange(m_document->animation(), m_selection);
        range && range->end - range->start > minSpan())
        return *range;
    return {m_playhead->time(), m_playhead->time() + length};
}

// --- zoom and scrolling ---

void TimelineView::setPixelsPerSecond(double pps, double anchorX)
{
    const double width = std::max(1, viewport()->width() - TimelineLayout::kLabelWidth);
    const double duration = std::max(1.0, m_document->timeline().duration());
    pps = std::clamp(pps, std::min(kMaxPixelsPerSecond, width / duration / 2), kMaxPixelsPerSecond);
    const double anchorTime = m_layout.timeAt(anchorX);
    m_layout.setPixelsPerSecond(pps);
    m_layout.setScrollTime(std::max(0.0, anchorTime - (anchorX - TimelineLayout::kLabelWidth) / pps));
    updateScrollBars();
    viewport()->update();
}

void TimelineView::zoomIn()
{
    setPixelsPerSecond(m_layout.pixelsPerSecond() * kZoomStep, m_layout.xOf(m_playhead->time()));
}

void TimelineView::zoomOut()
{
    setPixelsPerSecond(m_layout.pixelsPerSecond() / kZoomStep, m_layout.xOf(m_playhead->time()));
}

void TimelineView::zoomToFit()
{
    const double width = std::max(1, viewport()->width() - TimelineLayout::kLabelWidth - 16);
    const double duration = std::max(1.0, m_document->timeline().duration());
    m_layout.setScrollTime(0);
    m_layout.setPixelsPerSecond(std::min(kMaxPixelsPerSecond, width / duration));
    // A viewport not yet laid out fits a second into a pixel or two; the first real size fits again.
    m_fitted = width >= kNarrowestFit;
    updateScrollBars();
    viewport()->update();
}

void TimelineView::updateScrollBars()
{
    const double pps = m_layout.pixelsPerSecond();
    const double width = std::max(0, viewport()->width() - TimelineLayout::kLabelWidth);
    const double total = (std::max(1.0, m_document->timeline().duration()) + 1.0) * pps;
    m_syncingScroll = true;
    horizontalScrollBar()->setRange(0, int(std::max(0.0, std::max(total - width, m_layout.scrollTime() * pps))));
    horizontalScrollBar()->setPageStep(int(width));
    horizontalScrollBar()->setSingleStep(std::max(1, int(width / 20)));
    horizontalScrollBar()->setValue(int(std::lround(m_layout.scrollTime() * pps)));
    const int rows = viewport()->height() - TimelineLayout::kRulerHeight;
    // The rows shrink to the viewport (down to their compact heights) before they scroll.
    m_layout.fitRows(rows);
    verticalScrollBar()->setRange(0, std::max(0, m_layout.contentHeight() - rows));
    verticalScrollBar()->setPageStep(std::max(1, rows));
    verticalScrollBar()->setSingleStep(12);
    m_layout.setVerticalScroll(verticalScrollBar()->value());
    m_syncingScroll = false;
}

void TimelineView::scrollContentsBy(int, int)
{
    if (m_syncingScroll)
        return;
    m_layout.setScrollTime(horizontalScrollBar()->value() / m_layout.pixelsPerSecond());
    m_layout.setVerticalScroll(verticalScrollBar()->value());
    viewport()->update();
}

void TimelineView::followPlayhead(double t)
{
    // Playing, or moved by a key (Home, End, the arrows): the playhead stays in sight. A drag in
    // the timeline moves it where the pointer is, in sight already.
    if (m_drag.mode != DragMode::None)
        return;
    const double x = m_layout.xOf(t);
    if (x < TimelineLayout::kLabelWidth || x > viewport()->width() - 10) {
        m_layout.setScrollTime(
            std::max(0.0, t - 0.1 * (viewport()->width() - TimelineLayout::kLabelWidth) / m_layout.pixelsPerSecond()));
        updateScrollBars();
    }
}

void TimelineView::resizeEvent(QResizeEvent *event)
{
    QAbstractScrollArea::resizeEvent(event);
    if (!m_fitted && viewport()->width() > TimelineLayout::kLabelWidth)
        zoomToFit();
    updateScrollBars();
}

void TimelineView::wheelEvent(QWheelEvent *event)
{
    const QPoint delta = event->angleDelta();
    if (event->modifiers() & Qt::AltModifier) {
        // Qt turns the wheel sideways while Alt is held.
        const int d = delta.y() != 0 ? delta.y() : delta.x();
        setWaveformZoom(m_waveformZoom * std::pow(kWaveformZoomStep, d / 120.0));
    } else if (event->modifiers() & Qt::ControlModifier) {
        const double steps = delta.y() / 120.0;
        setPixelsPerSecond(m_layout.pixelsPerSecond() * std::pow(kZoomStep, steps), event->position().x());
    } else if (event->modifiers() & Qt::ShiftModifier) {
        verticalScrollBar()->setValue(verticalScrollBar()->value() - delta.y() / 2);
    } else {
        const int d = delta.x() != 0 ? delta.x() : delta.y();
        horizontalScrollBar()->setValue(horizontalScrollBar()->value() - d * horizontalScrollBar()->singleStep() / 120);
    }
    event->accept();
}

void TimelineView::paintEvent(QPaintEvent *)
{
    QPainter painter(viewport());
    paintTimeline(painter, scene());
}

// --- gestures (the mouse: timelinegestures.cpp) ---

double TimelineView::snapped(double t, bool *toBoundary) const
{
    if (toBoundary)
        *toBoundary = false;
    if (!m_snap)
        return std::max(0.0, t);
    const QVector<double> boundaries = syllableBoundaries(m_document->animation());
    const double s
        = snapTime(t, m_document->timeline().frameRate(), boundaries, kSnapPixels / m_layout.pixelsPerSecond());
    if (toBoundary)
        *toBoundary = std::binary_search(boundaries.begin(), boundaries.end(), s);
    return std::max(0.0, s);
}

void TimelineView::apply(const Animation &after, const QString &text)
{
    m_document->changeAnimation(after, text);
}

// --- keys ---

bool TimelineView::event(QEvent *event)
{
    // The view's own keys come before window shortcuts while it has focus.
    if (event->type() == QEvent::ShortcutOverride) {
        auto *key = static_cast<QKeyEvent *>(event);
        const bool shapeKey
            = key->modifiers() == Qt::NoModifier && shapeForKey(key->key()).has_value() && m_focusRow == RowKind::Mouth;
        if (shapeKey || key->matches(QKeySequence::Copy) || key->matches(QKeySequence::Paste)
            || key->matches(QKeySequence::Delete) || key->key() == Qt::Key_Backspace
            || key->matches(QKeySequence::SelectAll)) {
            event->accept();
            return true;
        }
    }
    return QAbstractScrollArea::event(event);
}

void TimelineView::keyPressEvent(QKeyEvent *event)
{
    if (event->matches(QKeySequence::Copy)) {
        copySelection();
    } else if (event->matches(QKeySequence::Paste)) {
        paste();
    } else if (event->matches(QKeySequence::SelectAll)) {
        selectAll();
    } else if (event->matches(QKeySequence::Delete) || event->key() == Qt::Key_Backspace) {
        deleteSelection();
    } else if (const auto shape = shapeForKey(event->key());
               shape && event->modifiers() == Qt::NoModifier && m_focusRow == RowKind::Mouth) {
        setMouthShape(*shape);
    } else {
        QAbstractScrollArea::keyPressEvent(event);
    }
}

// --- edits on the selection ---

void TimelineView::deleteSelection()
{
    if (m_selection.isEmpty())
        return;
    const Animation after = deleteItems(m_document->animation(), m_selection);
    setSelection({});
    apply(after, tr("Delete from Timeline"));
}

void TimelineView::copySelection()
{
    const QJsonObject items = copyItems(m_document->animation(), m_selection);
    if (items.isEmpty())
        return;
    auto *mime = new QMimeData;
    mime->setData(QString::fromLatin1(kTimelineItemsMime), QJsonDocument(items).toJson(QJsonDocument::Compact));
    QApplication::clipboard()->setMimeData(mime);
}

void TimelineView::paste()
{
    const QMimeData *mime = QApplication::clipboard()->mimeData();
    if (!mime || !mime->hasFormat(QString::fromLatin1(kTimelineItemsMime)))
        return;
    QString error;
    Selection pasted;
    const QJsonObject items = QJsonDocument::fromJson(mime->data(QString::fromLatin1(kTimelineItemsMime))).object();
    const std::optional<Animation> after
        = pasteItems(m_document->animation(), items, snapped(m_playhead->time()), &error, &pasted);
    if (!after) {
        Q_EMIT message(error);
        return;
    }
    apply(*after, tr("Paste on Timeline"));
    setSelection(pasted);
}

void TimelineView::selectAll()
{
    const Animation a = m_document->animation();
    Selection s;
    const std::optional<ItemKind> kind = m_focusRow ? itemKindOf(*m_focusRow) : std::nullopt;
    for (int k = 0; k < kItemKindCount; ++k)
        if (!kind || *kind == ItemKind(k))
            for (int i = 0; i < itemCount(a, ItemKind(k)); ++i)
                s.insert({ItemKind(k), i});
    setSelection(s);
}

void TimelineView::setMouthShape(MouthShape shape)
{
    const QVector<int> keys = m_selection.indices(ItemKind::Mouth);
    if (!keys.isEmpty()) {
        apply(toonface::setMouthShape(m_document->animation(), keys, shape), tr("Replace Mouth Shape"));
        return;
    }
    int index = -1;
    const Animation after
        = insertMouthKey(m_document->animation(), snapped(m_playhead->time()), shape, minSpan(), &index);
    apply(after, tr("Insert Mouth Shape"));
    setSelection({{ItemKind::Mouth, index}});
}

void TimelineView::setMouthWeight(double weight)
{
    const QVector<int> keys = m_selection.indices(ItemKind::Mouth);
    if (!keys.isEmpty())
        apply(toonface::setMouthWeight(m_document->animation(), keys, weight), tr("Change Mouth Weight"));
}

void TimelineView::setEmotionIntensity(int clip, double intensity)
{
    apply(toonface::setEmotionIntensity(m_document->animation(), clip, intensity), tr("Change Emotion Intensity"));
}

void TimelineView::applyEmotion(Emotion emotion)
{
    const Span range = targetRange(kEmotionLength);
    int index = -1;
    const Animation after = insertEmotion(m_document->animation(), emotion, range.start, range.end, 1.0, &index);
    apply(after, tr("Add Emotion"));
    setSelection({{ItemKind::Emotion, index}});
}

void TimelineView::regenerateBlinks()
{
    apply(toonface::regenerateBlinks(m_document->animation(), QRandomGenerator::global()->generate()),
        tr("Regenerate Blinks"));
}

void TimelineView::addShake()
{
    const Span range = targetRange(kHeadMoveLength);
    apply(toonface::addShake(m_document->animation(), range.start, range.end), tr("Add Head Shake"));
}

void TimelineView::addNod()
{
    const Span range = targetRange(kHeadMoveLength);
    apply(toonface::addNod(m_document->animation(), range.start, range.end), tr("Add Head Nod"));
}

// --- the pinyin editor ---

void TimelineView::editSyllable(int index)
{
    const QVector<LipsyncSyllable> &syllables = m_document->syllables();
    if (index < 0 || index >= syllables.size())
        return;
    if (syllables[index].pinyin.isEmpty()) {
        Q_EMIT message(
            tr("'%1' is an English word: only Mandarin syllables have pinyin to edit").arg(syllables[index].text));
        return;
    }
    if (!m_pinyinEditor) {
        m_pinyinEditor = new QLineEdit(viewport());
        m_pinyinEditor->setObjectName(QStringLiteral("pinyinEditor"));
        m_pinyinEditor->setAlignment(Qt::AlignCenter);
        connect(m_pinyinEditor, &QLineEdit::returnPressed, this, &TimelineView::commitPinyin);
    }
    m_editedSyllable = index;
    const LipsyncSyllable &syl = syllables[index];
    m_pinyinEditor->setText(toneNumberSpelling({syl.pinyin, syl.tone}));
    const QRectF r = itemRect({ItemKind::Syllable, index});
    const int width = std::max(70, int(r.width()));
    m_pinyinEditor->setGeometry(int(r.center().x()) - width / 2, int(r.top()), width, int(r.height()));
    m_pinyinEditor->show();
    m_pinyinEditor->selectAll();
    m_pinyinEditor->setFocus();
}

void TimelineView::commitPinyin()
{
    if (!m_pinyinEditor || m_editedSyllable < 0)
        return;
    const int index = m_editedSyllable;
    m_editedSyllable = -1;
    m_pinyinEditor->hide();
    setFocus();
    QString error;
    const std::optional<Animation> after
        = setSyllablePinyin(m_document->animation(), index, m_pinyinEditor->text(), &error);
    if (!after) {
        Q_EMIT message(error);
        return;
    }
    apply(*after, tr("Change Syllable"));
}

// --- context menu and drops ---

void TimelineView::contextMenuEvent(QContextMenuEvent *event)
{
    TimelineHit hit = hitAt(event->pos());
    if (hit.row)
        setFocusRow(hit.row);
    if (hit.item && !m_selection.contains(*hit.item))
        setSelection({*hit.item});
    Q_EMIT contextMenuRequested(hit, event->globalPos());
}

void TimelineView::dragEnterEvent(QDragEnterEvent *event)
{
    if (emotionFromMimeData(event->mimeData()))
        event->acceptProposedAction();
}

void TimelineView::dragMoveEvent(QDragMoveEvent *event)
{
    const std::optional<RowKind> row = m_layout.rowAt(event->position().toPoint().y());
    if (emotionFromMimeData(event->mimeData()) && row && *row != RowKind::Ruler
        && event->position().x() >= TimelineLayout::kLabelWidth)
        event->acceptProposedAction();
    else
        event->ignore();
}

void TimelineView::dropEvent(QDropEvent *event)
{
    const std::optional<Emotion> emotion = emotionFromMimeData(event->mimeData());
    if (!emotion)
        return;
    // Dropped inside the selected range (a phrase, not one short shape) it fills the range,
    // else it starts where it was dropped.
    const double t = snapped(m_layout.timeAt(event->position().x()));
    Span range {t, t + kEmotionLength};
    if (const std::optional<Span> selected = selectionRange(m_document->animation(), m_selection); selected
        && t >= selected->start && t <= selected->end
        && selected->end - selected->start >= std::max(minSpan(), kShortestEmotionRange))
        range = *selected;
    int index = -1;
    const Animation after = insertEmotion(m_document->animation(), *emotion, range.start, range.end, 1.0, &index);
    apply(after, tr("Add Emotion"));
    setSelection({{ItemKind::Emotion, index}});
    setFocusRow(RowKind::Emotion);
    event->acceptProposedAction();
}

} // namespace toonface
