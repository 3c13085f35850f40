#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QString>

namespace toonface {

class MainWindow;

// For measuring the editor's start (bench/bench_launch.cpp): with TOONFACE_TIMINGS set, prints
// on stderr, as "toonface: timing: EVENT MS" in milliseconds since main() began, when the
// window is first painted ("window-shown") and then idle ("window-usable"), when a photo was
// asked for ("open"), opened ("photo-opened") and when its detected points have been painted
// ("points-shown", MainWindow::pointsPlaced()). TOONFACE_TIMINGS_OPEN_DELAY_MS=N holds the photo of the command line
// back N ms after the window is usable, as a person opening a photo after launch would.
class LaunchTimings : public QObject
{
public:
    // Watches `window`; `clock` started when main() did.
    LaunchTimings(MainWindow *window, QElapsedTimer clock);

    static bool wanted();
    // Opens `path` in `window` now, or after the delay asked for (see above).
    void open(const QString &path);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void print(const char *event) const;

    MainWindow *m_window;
    QElapsedTimer m_clock;
    bool m_shown = false;
    bool m_usable = false;
    bool m_awaitingPoints = false;
    QString m_pending; // a photo to open once the window is usable
    int m_delayMs = 0;
};

} // namespace toonface
