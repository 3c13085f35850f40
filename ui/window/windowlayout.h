#pragma once

#include <QByteArray>
#include <QObject>

class QAction;
class QDockWidget;
class QMainWindow;
class QMenu;
class QSplitter;

namespace toonface {

class Document;

// The main window's arrangement: the Appearance dock, the sizes a first run (or View ▸ Reset
// Layout) gives the photo, the cartoon, the docks and the timeline on the screen at hand, and
// the View menu's dock toggles.
class WindowLayout : public QObject
{
    Q_OBJECT

public:
    WindowLayout(QMainWindow *window, QSplitter *photoAndCartoon);

    // The Appearance dock on the right, scrolled vertically only.
    QDockWidget *addAppearanceDock(Document *document);
    // Remembers the docks' arrangement as built (call once every dock is added, before a saved
    // state is restored).
    void captureDefault();
    // The window sized to the screen, and the docks to their contents once it shows.
    void firstRun();
    // The docks sized to their contents within the window as it is.
    void applyDefaultSizes();
    // Back to the arrangement as built and the first run's sizes.
    void reset();
    // The docks' show/hide toggles and Reset Layout, appended to `view`.
    void addViewActions(QMenu *view);

    QAction *resetAction() const { return m_reset; }

private:
    QMainWindow *m_window;
    QSplitter *m_splitter;
    QByteArray m_defaultState;
    QAction *m_reset;
};

} // namespace toonface
