#include "launchtimings.h"

#include "views/photoview.h"
#include "window/mainwindow.h"

#include <QAbstractScrollArea>
#include <QEvent>
#include <QTimer>

#include <cstdio>

namespace toonface {

LaunchTimings::LaunchTimings(MainWindow *window, QElapsedTimer clock)
    : QObject(window)
    , m_window(window)
    , m_clock(clock)
    , m_delayMs(qEnvironmentVariableIntValue("TOONFACE_TIMINGS_OPEN_DELAY_MS"))
{
    window->installEventFilter(this);
    window->photoView()->viewport()->installEventFilter(this);
    connect(window, &MainWindow::fileOpened, this, [this] { print("photo-opened"); });
    connect(window, &MainWindow::pointsPlaced, this, [this] {
        m_awaitingPoints = true;
        m_window->photoView()->viewport()->update();
    });
}

bool LaunchTimings::wanted()
{
    return qEnvironmentVariableIsSet("TOONFACE_TIMINGS");
}

void LaunchTimings::open(const QString &path)
{
    if (m_delayMs <= 0 || m_usable) {
        print("open");
        m_window->openFile(path);
        return;
    }
    m_pending = path;
}

bool LaunchTimings::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() != QEvent::Paint)
        return false;
    if (watched == m_window && !m_shown) {
        m_shown = true;
        print("window-shown");
        // Usable: the first paint done and the event loop free to take the user's input.
        QTimer::singleShot(0, this, [this] {
            m_usable = true;
            print("window-usable");
            if (!m_pending.isEmpty())
                QTimer::singleShot(m_delayMs, this, [this] { open(std::exchange(m_pending, QString())); });
        });
    } else if (watched == m_window->photoView()->viewport() && m_awaitingPoints) {
        m_awaitingPoints = false;
        // After this paint event has been handled: the points are on screen.
        QTimer::singleShot(0, this, [this] { print("points-shown"); });
    }
    return false;
}

void LaunchTimings::print(const char *event) const
{
    std::fprintf(stderr, "toonface: timing: %s %.1f\n", event, m_clock.nsecsElapsed() / 1e6);
    std::fflush(stderr);
}

} // namespace toonface
