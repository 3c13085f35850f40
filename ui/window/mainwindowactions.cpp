// The main window's commands, menus, tool bar and status bar: made and wired here, so that
// mainwindow.cpp holds what the window does with them.
#include "window/mainwindow.h"

#include "dialogs/manualdialog.h"
#include "dialogs/shortcutsdialog.h"
#include "document/document.h"
#include "render/style.h"
#include "views/displaynames.h"
#include "views/photoview.h"
#include "views/previewview.h"
#include "views/themedicon.h"
#include "window/detectionstepsui.h"
#include "window/questions.h"
#include "window/settings.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QComboBox>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QStatusBar>
#include <QToolBar>
#include <QToolButton>
#include <QUndoStack>

namespace toonface {

void MainWindow::createActions()
{
    auto make = [this](const QString &objectName, const QString &text, const QKeySequence &shortcut = {}) {
        auto *action = new QAction(text, this);
        action->setObjectName(objectName);
        if (!shortcut.isEmpty())
            action->setShortcut(shortcut);
        return action;
    };

    m_openAction = make(QStringLiteral("actionOpen"), tr("&Open Photo or Project…"), QKeySequence::Open);
    m_openAction->setIcon(themedIcon("document-open", "document-open.svg"));
    connect(m_openAction, &QAction::triggered, this, &MainWindow::openDialog);
    m_saveAction = make(QStringLiteral("actionSave"), tr("&Save"), QKeySequence::Save);
    m_saveAction->setIcon(themedIcon("document-save", "document-save.svg"));
    connect(m_saveAction, &QAction::triggered, this, &MainWindow::save);
    m_saveAsAction = make(QStringLiteral("actionSaveAs"), tr("Save &As…"), QKeySequence::SaveAs);
    connect(m_saveAsAction, &QAction::triggered, this, &MainWindow::saveAs);
    m_exportAction = make(QStringLiteral("actionExport"), tr("&Export Cartoon…"), QKeySequence(Qt::CTRL | Qt::Key_E));
    m_exportAction->setIcon(themedIcon("image-x-generic", "toonface.svg"));
    connect(m_exportAction, &QAction::triggered, this, &MainWindow::exportCartoon);
    m_quitAction = make(QStringLiteral("actionQuit"), tr("&Quit"), QKeySequence::Quit);
    m_quitAction->setMenuRole(QAction::QuitRole);
    connect(m_quitAction, &QAction::triggered, this, &QWidget::close);

    m_undoAction = m_document->undoStack()->createUndoAction(this, tr("&Undo"));
    m_undoAction->setObjectName(QStringLiteral("actionUndo"));
    m_undoAction->setShortcut(QKeySequence::Undo);
    m_undoAction->setIcon(themedIcon("edit-undo", "edit-undo.svg"));
    m_redoAction = m_document->undoStack()->createRedoAction(this, tr("&Redo"));
    m_redoAction->setObjectName(QStringLiteral("actionRedo"));
    m_redoAction->setShortcut(QKeySequence::Redo);
    m_redoAction->setIcon(themedIcon("edit-redo", "edit-redo.svg"));
    m_redetectAction
        = make(QStringLiteral("actionRedetect"), tr("Re-&detect Points"), QKeySequence(Qt::CTRL | Qt::Key_D));
    m_redetectAction->setToolTip(tr("Detect the face again and replace every point"));
    m_redetectAction->setIcon(themedIcon("view-refresh", "redetect.svg"));
    connect(m_redetectAction, &QAction::triggered, this, [this] {
        // Points moved by hand are the user's work: not thrown away without a word.
        int handPlaced = 0;
        if (m_document->hasFace())
            for (int i = 0; i < kPointCount; ++i)
                handPlaced += m_document->face().isHandPlaced(i) ? 1 : 0;
        const RedetectChoice choice
            = handPlaced > 0 ? askRedetectOverHandPlaced(this, handPlaced) : RedetectChoice::ReplaceAll;
        if (choice != RedetectChoice::Cancel)
            startDetection(choice == RedetectChoice::KeepMine);
    });
    m_redetectKeepAction = make(QStringLiteral("actionRedetectKeep"), tr("Re-detect &Keeping My Points"),
        QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_D));
    m_redetectKeepAction->setToolTip(tr("Detect the face again but keep the points placed by hand"));
    connect(m_redetectKeepAction, &QAction::triggered, this, [this] { startDetection(true); });

    m_methodGroup = new QActionGroup(this);
    m_methodGroup->setExclusive(true);
    const struct
    {
        DetectionMethod method;
        const char *objectName;
        QString text;
        QString toolTip;
    } methods[] = {
        {DetectionMethod::Auto, "actionMethodAuto", tr("&Automatic"),
            tr("The landmark model where it is installed, the thesis pipeline where it is not")},
        {DetectionMethod::Classic, "actionMethodClassic", tr("&Thesis Pipeline (Classic)"),
            tr("The thesis' steps only: thresholds, eye pair, edges and feature regions; best on a plain "
               "background with frontal light")},
        {DetectionMethod::Landmarks, "actionMethodLandmarks", tr("&Landmarks"),
            tr("The landmark model's 68 points mapped to the face model, hair and ears found around them")},
    };
    const QString current = Settings().detectionMethod();
    for (const auto &m : methods) {
        QAction *action = make(QLatin1StringView(m.objectName), m.text);
        action->setCheckable(true);
        action->setToolTip(m.toolTip);
        action->setStatusTip(m.toolTip);
        action->setData(detectionMethodName(m.method));
        action->setChecked(detectionMethodName(m.method) == current);
        m_methodGroup->addAction(action);
    }
    connect(m_methodGroup, &QActionGroup::triggered, this,
        [](QAction *action) { Settings().setDetectionMethod(action->data().toString()); });

    m_zoomInAction = make(QStringLiteral("actionZoomIn"), tr("Zoom &In"), QKeySequence::ZoomIn);
    connect(m_zoomInAction, &QAction::triggered, m_photoView, &PhotoView::zoomIn);
    m_zoomOutAction = make(QStringLiteral("actionZoomOut"), tr("Zoom &Out"), QKeySequence::ZoomOut);
    connect(m_zoomOutAction, &QAction::triggered, m_photoView, &PhotoView::zoomOut);
    m_actualSizeAction
        = make(QStringLiteral("actionActualSize"), tr("&Actual Size"), QKeySequence(Qt::CTRL | Qt::Key_1));
    connect(m_actualSizeAction, &QAction::triggered, m_photoView, &PhotoView::zoomToActualSize);
    m_fitAction = make(QStringLiteral("actionFit"), tr("&Fit to Window"), QKeySequence(Qt::CTRL | Qt::Key_0));
    m_fitAction->setIcon(themedIcon("zoom-fit-best", "zoom-fit.svg"));
    connect(m_fitAction, &QAction::triggered, m_photoView, &PhotoView::fitToWindow);
    m_zoomFaceAction = make(QStringLiteral("actionZoomFace"), tr("Zoom to F&ace"), QKeySequence(Qt::CTRL | Qt::Key_2));
    m_zoomFaceAction->setIcon(themedIcon("zoom-in", "zoom-face.svg"));
    connect(m_zoomFaceAction, &QAction::triggered, m_photoView, &PhotoView::zoomToFace);
    m_showIdsAction = make(QStringLiteral("actionShowIds"), tr("Show Point &IDs"), QKeySequence(Qt::CTRL | Qt::Key_I));
    m_showIdsAction->setCheckable(true);
    connect(m_showIdsAction, &QAction::toggled, this, [this](bool show) {
        m_photoView->setShowPointIds(show);
        Settings().setShowPointIds(show);
    });
    connect(m_previewView->transparentAction(), &QAction::toggled, this,
        [](bool transparent) { Settings().setTransparentPreview(transparent); });

    m_aboutAction = make(QStringLiteral("actionAbout"), tr("&About Toonface"));
    m_aboutAction->setMenuRole(QAction::AboutRole);
    connect(m_aboutAction, &QAction::triggered, this, [this] {
        QMessageBox::about(this, tr("About Toonface"),
            tr("<h3>Toonface %1</h3><p>Personal talking cartoon faces from photos, drawn in SVG.</p>")
                .arg(QStringLiteral(TOONFACE_VERSION)));
    });
}

void MainWindow::createMenus()
{
    QMenu *file = menuBar()->addMenu(tr("&File"));
    file->addAction(m_openAction);
    m_recentMenu = file->addMenu(tr("Open &Recent"));
    m_recentMenu->setObjectName(QStringLiteral("menuRecent"));
    connect(m_recentMenu, &QMenu::aboutToShow, this, &MainWindow::fillRecentMenu);
    fillRecentMenu();
    file->addSeparator();
    file->addAction(m_saveAction);
    file->addAction(m_saveAsAction);
    file->addAction(m_exportAction);
    file->addSeparator();
    file->addAction(m_quitAction);

    QMenu *edit = menuBar()->addMenu(tr("&Edit"));
    edit->addAction(m_undoAction);
    edit->addAction(m_redoAction);
    edit->addSeparator();
    edit->addAction(m_redetectAction);
    edit->addAction(m_redetectKeepAction);
    m_methodMenu = edit->addMenu(tr("Detection &Method"));
    m_methodMenu->setObjectName(QStringLiteral("menuDetectionMethod"));
    m_methodMenu->setToolTipsVisible(true);
    m_methodMenu->addActions(m_methodGroup->actions());

    QMenu *view = m_viewMenu = menuBar()->addMenu(tr("&View"));
    view->addAction(m_zoomInAction);
    view->addAction(m_zoomOutAction);
    view->addAction(m_actualSizeAction);
    view->addAction(m_fitAction);
    view->addAction(m_zoomFaceAction);
    view->addSeparator();
    view->addAction(m_showIdsAction);
    view->addAction(m_previewView->transparentAction());
    view->addSeparator();
    m_stepsUi->install(view);

    m_helpMenu = menuBar()->addMenu(tr("&Help"));
    auto *manual = new QAction(tr("User &Manual"), this);
    manual->setObjectName(QStringLiteral("actionManual"));
    connect(manual, &QAction::triggered, this, [this] {
        ManualDialog dialog(this);
        dialog.exec();
    });
    m_helpMenu->addAction(manual);
    auto *shortcuts = new QAction(tr("&Keyboard Shortcuts"), this);
    connect(shortcuts, &QAction::triggered, this, [this] {
        ShortcutsDialog dialog(menuBar(), this);
        dialog.exec();
    });
    m_helpMenu->addAction(shortcuts);
    shortcuts->setObjectName(QStringLiteral("actionShortcuts"));
    shortcuts->setShortcut(QKeySequence::HelpContents);
    m_helpMenu->addAction(m_aboutAction);
}

void MainWindow::createToolBar()
{
    QToolBar *bar = addToolBar(tr("Main"));
    bar->setObjectName(QStringLiteral("mainToolBar"));
    // Icons only (each says what it does in its tool tip), so that the studio's transport fits beside
    // it on a 1280-pixel screen.
    bar->setToolButtonStyle(Qt::ToolButtonIconOnly);
    bar->addAction(m_openAction);
    bar->addAction(m_saveAction);
    bar->addSeparator();
    bar->addAction(m_undoAction);
    bar->addAction(m_redoAction);
    bar->addSeparator();
    bar->addAction(m_redetectAction);
    bar->addSeparator();
    bar->addWidget(new QLabel(tr("Style:") + QLatin1Char(' ')));
    m_styleCombo = new QComboBox;
    m_styleCombo->setObjectName(QStringLiteral("styleCombo"));
    m_styleCombo->setToolTip(tr("Drawing style of the cartoon"));
    const QStringList presets = Style::presetNames();
    for (const QString &name : presets) {
        m_styleCombo->addItem(styleTitle(name), name);
    }
    connect(m_styleCombo, &QComboBox::activated, this, &MainWindow::onStyleActivated);
    bar->addWidget(m_styleCombo);
    bar->addSeparator();
    bar->addAction(m_fitAction);
    bar->addAction(m_zoomFaceAction);
}

void MainWindow::createStatusBar()
{
    m_busyLabel = new QLabel;
    m_busyBar = new QProgressBar;
    m_busyBar->setMaximumWidth(160);
    m_busyBar->setTextVisible(false);
    m_cancelButton = new QToolButton;
    m_cancelButton->setObjectName(QStringLiteral("cancelButton"));
    m_cancelButton->setText(tr("Cancel"));
    connect(m_cancelButton, &QToolButton::clicked, this, &MainWindow::cancelJob);
    m_zoomLabel = new QLabel;
    m_zoomLabel->setMinimumWidth(48);
    m_zoomLabel->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    statusBar()->addPermanentWidget(m_busyLabel);
    statusBar()->addPermanentWidget(m_busyBar);
    statusBar()->addPermanentWidget(m_cancelButton);
    statusBar()->addPermanentWidget(m_zoomLabel);
    setBusy(Job::None, {});
}

} // namespace toonface
