#include "window/windowlayout.h"

#include "appearance/appearancepanel.h"
#include "timeline/timelinewidget.h"

#include <QAction>
#include <QDockWidget>
#include <QMainWindow>
#include <QMenu>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSplitter>
#include <QTimer>

#include <algorithm>

namespace toonface {

namespace {

// The share of the screen's free area a first run takes: room left for a panel or dock of
// the desktop's own.
constexpr double kScreenShare = 0.92;
// The side docks never take more of the window's width than this, so that the photo and the
// cartoon stay the work.
constexpr double kSideDockShare = 0.26;
// The timeline takes this share of the window's height at first, more when its rows need
// more at their compact heights (a short screen), never more than its rows at their comfortable.
constexpr double kBottomDockShare = 0.36;
// Screens shorter than this start the window maximized: a share of 720 pixels left free costs
// the timeline its last rows.
constexpr int kShortScreen = 900;

} // namespace

WindowLayout::WindowLayout(QMainWindow *window, QSplitter *photoAndCartoon)
    : QObject(window)
    , m_window(window)
    , m_splitter(photoAndCartoon)
    , m_reset(new QAction(tr("&Reset Layout"), this))
{
    m_reset->setObjectName(QStringLiteral("actionResetLayout"));
    m_reset->setStatusTip(tr("Put the panels back where they were at first and size them to the window"));
    connect(m_reset, &QAction::triggered, this, &WindowLayout::reset);
}

QDockWidget *WindowLayout::addAppearanceDock(Document *document)
{
    auto *dock = new QDockWidget(tr("Appearance"), m_window);
    dock->setObjectName(QStringLiteral("appearanceDock"));
    // Scrolled, so that its many controls never set the window's height; vertically only: its
    // width follows the dock, which is never narrower than the controls.
    auto *scroll = new QScrollArea;
    scroll->setObjectName(QStringLiteral("appearanceScroll"));
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    auto *panel = new AppearancePanel(document);
    scroll->setWidget(panel);
    scroll->setMinimumWidth(panel->minimumSizeHint().width() + scroll->verticalScrollBar()->sizeHint().width());
    dock->setWidget(scroll);
    m_window->addDockWidget(Qt::RightDockWidgetArea, dock);
    return dock;
}

void WindowLayout::captureDefault()
{
    m_defaultState = m_window->saveState();
}

void WindowLayout::firstRun()
{
    const QSize available = m_window->screen()->availableSize();
    m_window->resize(int(available.width() * kScreenShare), int(available.height() * kScreenShare));
    if (available.height() < kShortScreen)
        m_window->setWindowState(m_window->windowState() | Qt::WindowMaximized);
    // The docks' sizes need the window laid out at its size.
    QTimer::singleShot(0, this, &WindowLayout::applyDefaultSizes);
}

void WindowLayout::applyDefaultSizes()
{
    const int width = m_window->width();
    QList<QDockWidget *> side;
    QList<int> widths;
    for (QDockWidget *dock : m_window->findChildren<QDockWidget *>()) {
        if (dock->parentWidget() != m_window || dock->isFloating() || !dock->isVisible())
            continue;
        const Qt::DockWidgetArea area = m_window->dockWidgetArea(dock);
        if (area == Qt::BottomDockWidgetArea || area == Qt::TopDockWidgetArea) {
            // As tall as its contents ask (the timeline: its rows), but leaving the photo and
            // the cartoon most of a laptop's screen; the timeline's rows all show, compact if
            // need be. The dock's title bar comes on top of its contents.
            const int title = std::max(0, dock->height() - dock->widget()->height());
            int height = std::min(dock->widget()->sizeHint().height(), int(m_window->height() * kBottomDockShare));
            if (const auto *timeline = qobject_cast<const TimelineWidget *>(dock->widget()))
                height = std::max(height, timeline->compactHeight());
            height = std::max(height, dock->widget()->minimumHeight());
            m_window->resizeDocks({dock}, {height + title}, Qt::Vertical);
        } else {
            side.append(dock);
            widths.append(std::clamp(dock->widget()->minimumSizeHint().width(), 1, int(width * kSideDockShare)));
        }
    }
    if (!side.isEmpty())
        m_window->resizeDocks(side, widths, Qt::Horizontal);
    const int half = std::max(1, m_splitter->width() / 2);
    m_splitter->setSizes({half, half});
}

void WindowLayout::reset()
{
    if (!m_defaultState.isEmpty())
        m_window->restoreState(m_defaultState);
    for (QDockWidget *dock : m_window->findChildren<QDockWidget *>())
        if (dock->parentWidget() == m_window && dock->isFloating())
            dock->setFloating(false);
    applyDefaultSizes();
}

void WindowLayout::addViewActions(QMenu *view)
{
    view->addSeparator();
    for (QDockWidget *dock : m_window->findChildren<QDockWidget *>())
        if (dock->parentWidget() == m_window && !view->actions().contains(dock->toggleViewAction()))
            view->addAction(dock->toggleViewAction());
    view->addAction(m_reset);
}

} // namespace toonface
