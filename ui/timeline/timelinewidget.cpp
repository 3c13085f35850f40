#include "timeline/timelinewidget.h"

#include "playback/playhead.h"

#include "document/document.h"
#include "timeline/emotionpalette.h"
#include "timeline/shapepalette.h"
#include "timeline/timelineicons.h"
#include "timeline/timelineview.h"
#include "views/displaynames.h"

#include <QAction>
#include <QInputDialog>
#include <QLabel>
#include <QMenu>
#include <QToolBar>
#include <QVBoxLayout>

#include <algorithm>

namespace toonface {

namespace {

// The dock's dark scheme, as animation editors have it, so the tracks' colours read well.
QPalette timelinePalette(QPalette palette)
{
    palette.setColor(QPalette::Window, QColor(0x2b, 0x2d, 0x32));
    palette.setColor(QPalette::WindowText, QColor(0xdc, 0xde, 0xe2));
    palette.setColor(QPalette::Base, QColor(0x1f, 0x21, 0x25));
    palette.setColor(QPalette::Text, QColor(0xdc, 0xde, 0xe2));
    palette.setColor(QPalette::Button, QColor(0x38, 0x3b, 0x41));
    palette.setColor(QPalette::ButtonText, QColor(0xdc, 0xde, 0xe2));
    palette.setColor(QPalette::Highlight, QColor(0x4a, 0x8c, 0xe8));
    palette.setColor(QPalette::ToolTipBase, QColor(0x38, 0x3b, 0x41));
    palette.setColor(QPalette::ToolTipText, QColor(0xdc, 0xde, 0xe2));
    return palette;
}

QWidget *separatorLabel(const QString &text, QWidget *parent)
{
    auto *label = new QLabel(text, parent);
    label->setContentsMargins(8, 0, 3, 0);
    QPalette p = label->palette();
    p.setColor(QPalette::WindowText, QColor(0x9a, 0x9e, 0xa6));
    label->setPalette(p);
    return label;
}

} // namespace

QList<QAction *> TimelineActions::all() const
{
    QList<QAction *> list {zoomIn, zoomOut, zoomToFit, waveformTaller, waveformShorter, snap, deleteItems, copy, paste,
        selectAll, regenerateBlinks, addShake, addNod};
    for (QAction *a : applyEmotion)
        list.append(a);
    return list;
}

TimelineWidget::TimelineWidget(Document *document, Playhead *playhead, QWidget *parent)
    : QWidget(parent)
    , m_document(document)
    , m_playhead(playhead)
    , m_view(new TimelineView(document, playhead, this))
    , m_shapes(new ShapePalette(this))
    , m_emotions(new EmotionPalette(this))
{
    setObjectName(QStringLiteral("timelineWidget"));
    setPalette(timelinePalette(palette()));
    setAutoFillBackground(true);
    createActions();

    auto *bar = new QToolBar(this);
    m_toolBar = bar;
    bar->setObjectName(QStringLiteral("timelineToolBar"));
    bar->setIconSize(QSize(20, 20));
    bar->addAction(m_actions.zoomOut);
    bar->addAction(m_actions.zoomIn);
    bar->addAction(m_actions.zoomToFit);
    bar->addAction(m_actions.snap);
    bar->addSeparator();
    bar->addAction(m_actions.copy);
    bar->addAction(m_actions.paste);
    bar->addAction(m_actions.deleteItems);
    bar->addSeparator();
    bar->addAction(m_actions.regenerateBlinks);
    bar->addAction(m_actions.addShake);
    bar->addAction(m_actions.addNod);
    bar->addSeparator();
    bar->addWidget(separatorLabel(tr("Emotion"), bar));
    bar->addWidget(m_emotions);
    bar->addSeparator();
    bar->addWidget(separatorLabel(tr("Mouth"), bar));
    bar->addWidget(m_shapes);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(bar);
    layout->addWidget(m_view, 1);
    addActions(m_actions.all());

    m_shapes->setIcons(m_view->mouthIcons());
    connect(m_view, &TimelineView::mouthIconsChanged, this, [this]() { m_shapes->setIcons(m_view->mouthIcons()); });
    connect(m_shapes, &ShapePalette::shapeChosen, m_view, [this](MouthShape shape) {
        m_view->setFocusRow(RowKind::Mouth);
        m_view->setMouthShape(shape);
    });
    connect(m_emotions, &EmotionPalette::applied, m_view, &TimelineView::applyEmotion);
    connect(m_view, &TimelineView::contextMenuRequested, this, &TimelineWidget::showContextMenu);
    connect(m_view, &TimelineView::emotionIntensityRequested, this, &TimelineWidget::editEmotionIntensity);
    connect(m_view, &TimelineView::selectionChanged, this, &TimelineWidget::updateActions);
    connect(m_view, &TimelineView::selectionChanged, this, &TimelineWidget::showSelectedMouthKey);
    connect(m_view, &TimelineView::snapChanged, m_actions.snap, &QAction::setChecked);
    updateActions();
}

void TimelineWidget::showSelectedMouthKey()
{
    const Selection &selection = m_view->selection();
    if (selection.size() != 1 || !selection.hasKind(ItemKind::Mouth) || m_playhead->isPlaying())
        return;
    const QVector<MouthKey> &keys = m_document->timeline().mouthKeys();
    const int i = selection.items().first().index;
    if (i < 0 || i >= keys.size())
        return;
    // The middle of the key's sound, where its shape is held (not the start, where it is still
    // coming from the shape before).
    double end = keys[i].duration ? keys[i].time + *keys[i].duration : keys[i].time + 0.2;
    if (i + 1 < keys.size())
        end = std::min(end, keys[i + 1].time);
    m_playhead->setTime(keys[i].time + std::max(0.0, end - keys[i].time) / 2);
}

int TimelineWidget::compactHeight() const
{
    return m_toolBar->sizeHint().height() + m_view->compactHeight();
}

void TimelineWidget::editEmotionIntensity(int clip)
{
    const QVector<EmotionClip> clips = m_document->timeline().emotionClips();
    if (clip < 0 || clip >= clips.size())
        return;
    QInputDialog dialog(this);
    dialog.setObjectName(QStringLiteral("emotionIntensityDialog"));
    dialog.setWindowTitle(tr("Emotion Intensity"));
    dialog.setLabelText(tr("Intensity of %1 (%):").arg(emotionTitle(clips[clip].emotion)));
    dialog.setInputMode(QInputDialog::IntInput);
    dialog.setIntRange(0, 100);
    dialog.setIntStep(5);
    dialog.setIntValue(qRound(clips[clip].intensity * 100));
    if (dialog.exec() == QDialog::Accepted && dialog.intValue() != qRound(clips[clip].intensity * 100))
        m_view->setEmotionIntensity(clip, dialog.intValue() / 100.0);
}

void TimelineWidget::createActions()
{
    auto make = [this](const QString &text, const QString &icon, const QKeySequence &key = {}) {
        auto *a = new QAction(timelineIcon({}, icon), text, this);
        a->setObjectName(QStringLiteral("timeline-") + icon.section(QLatin1Char('-'), 1));
        if (!key.isEmpty())
            a->setShortcut(key);
        a->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        return a;
    };
    // Keys of their own (as video editors have them): the window's Ctrl++, Ctrl+- and Ctrl+0
    // zoom the photo, and a key bound twice does nothing at all.
    m_actions.zoomIn = make(tr("Zoom In"), QStringLiteral("timeline-zoom-in"), QKeySequence(Qt::Key_Equal));
    m_actions.zoomOut = make(tr("Zoom Out"), QStringLiteral("timeline-zoom-out"), QKeySequence(Qt::Key_Minus));
    m_actions.zoomToFit = make(tr("Zoom to Fit"), QStringLiteral("timeline-zoom-fit"), QKeySequence(Qt::Key_Backslash));
    m_actions.waveformTaller = new QAction(tr("Taller Waveform"), this);
    m_actions.waveformTaller->setObjectName(QStringLiteral("timeline-waveform-taller"));
    m_actions.waveformShorter = new QAction(tr("Shorter Waveform"), this);
    m_actions.waveformShorter->setObjectName(QStringLiteral("timeline-waveform-shorter"));
    for (QAction *a : {m_actions.waveformTaller, m_actions.waveformShorter})
        a->setToolTip(a->text() + tr(" (Alt+wheel)"));
    m_actions.snap = make(tr("Snap to Frames and Syllables"), QStringLiteral("timeline-snap"));
    m_actions.snap->setCheckable(true);
    m_actions.snap->setChecked(m_view->snapEnabled());
    m_actions.deleteItems = make(tr("Delete"), QStringLiteral("timeline-delete"));
    m_actions.copy = make(tr("Copy Keys"), QStringLiteral("timeline-copy"));
    m_actions.paste = make(tr("Paste Keys at Playhead"), QStringLiteral("timeline-paste"));
    m_actions.selectAll = new QAction(tr("Select All in Row"), this);
    m_actions.regenerateBlinks = make(tr("Regenerate Blinks"), QStringLiteral("timeline-blinks"));
    m_actions.addShake = make(tr("Add Head Shake"), QStringLiteral("timeline-shake"));
    m_actions.addNod = make(tr("Add Head Nod"), QStringLiteral("timeline-nod"));
    for (Emotion e : kAllEmotions) {
        auto *a = new QAction(emotionIcon(e), tr("Apply %1").arg(emotionTitle(e)), this);
        a->setObjectName(QStringLiteral("timeline-emotion-%1").arg(emotionName(e)));
        connect(a, &QAction::triggered, m_view, [this, e]() { m_view->applyEmotion(e); });
        m_actions.applyEmotion[int(e)] = a;
    }
    connect(m_actions.zoomIn, &QAction::triggered, m_view, &TimelineView::zoomIn);
    connect(m_actions.zoomOut, &QAction::triggered, m_view, &TimelineView::zoomOut);
    connect(m_actions.zoomToFit, &QAction::triggered, m_view, &TimelineView::zoomToFit);
    connect(m_actions.waveformTaller, &QAction::triggered, m_view, &TimelineView::waveformTaller);
    connect(m_actions.waveformShorter, &QAction::triggered, m_view, &TimelineView::waveformShorter);
    connect(m_actions.snap, &QAction::toggled, m_view, &TimelineView::setSnapEnabled);
    connect(m_actions.deleteItems, &QAction::triggered, m_view, &TimelineView::deleteSelection);
    connect(m_actions.copy, &QAction::triggered, m_view, &TimelineView::copySelection);
    connect(m_actions.paste, &QAction::triggered, m_view, &TimelineView::paste);
    connect(m_actions.selectAll, &QAction::triggered, m_view, &TimelineView::selectAll);
    connect(m_actions.regenerateBlinks, &QAction::triggered, m_view, &TimelineView::regenerateBlinks);
    connect(m_actions.addShake, &QAction::triggered, m_view, &TimelineView::addShake);
    connect(m_actions.addNod, &QAction::triggered, m_view, &TimelineView::addNod);
}

void TimelineWidget::updateActions()
{
    const bool any = !m_view->selection().isEmpty();
    m_actions.deleteItems->setEnabled(any);
    m_actions.copy->setEnabled(any);
}

void TimelineWidget::showContextMenu(const TimelineHit &hit, const QPoint &globalPos)
{
    QMenu menu(this);
    const std::optional<ItemKind> kind = hit.item ? std::optional(hit.item->kind) : std::nullopt;
    if (hit.row == RowKind::Mouth) {
        QMenu *shapes = menu.addMenu(kind ? tr("Replace Shape") : tr("Insert Shape"));
        for (MouthShape shape : kAllMouthShapes) {
            QAction *a = shapes->addAction(QIcon(QPixmap::fromImage(m_view->mouthIcons().icon(shape))),
                mouthShapeName(shape), m_view, [this, shape]() { m_view->setMouthShape(shape); });
            a->setShortcut(QKeySequence(mouthShapeName(shape).toUpper()));
        }
        if (kind) {
            QMenu *weights = menu.addMenu(tr("Weight"));
            for (int percent : {100, 75, 50, 25})
                weights->addAction(QStringLiteral("%1 %").arg(percent), m_view,
                    [this, percent]() { m_view->setMouthWeight(percent / 100.0); });
        }
    } else if (hit.row == RowKind::Emotion) {
        if (kind) {
            const int index = hit.item->index;
            menu.addAction(tr("Intensity…"), this, [this, index]() { editEmotionIntensity(index); });
        }
        QMenu *emotions = menu.addMenu(tr("Add Emotion"));
        for (QAction *a : m_actions.applyEmotion)
            emotions->addAction(a);
    } else if (hit.row == RowKind::Script && kind) {
        const int index = hit.item->index;
        menu.addAction(tr("Edit Pinyin…"), m_view, [this, index]() { m_view->editSyllable(index); });
    } else if (hit.row == RowKind::Waveform) {
        menu.addAction(m_actions.waveformTaller);
        menu.addAction(m_actions.waveformShorter);
    } else if (hit.row == RowKind::Blink) {
        menu.addAction(m_actions.regenerateBlinks);
    } else if (hit.row == RowKind::Head) {
        menu.addAction(m_actions.addShake);
        menu.addAction(m_actions.addNod);
    }
    if (!menu.isEmpty())
        menu.addSeparator();
    menu.addAction(m_actions.copy);
    menu.addAction(m_actions.paste);
    menu.addAction(m_actions.deleteItems);
    menu.addSeparator();
    menu.addAction(m_actions.zoomToFit);
    menu.exec(globalPos);
}

TimelineDock::TimelineDock(Document *document, Playhead *playhead, QWidget *parent)
    : QDockWidget(tr("Timeline"), parent)
    , m_timeline(new TimelineWidget(document, playhead, this))
{
    setObjectName(QStringLiteral("timelineDock"));
    setWidget(m_timeline);
}

} // namespace toonface
