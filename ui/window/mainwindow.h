#pragma once

#include "detect/detector.h"
#include "document/autosaver.h"
#include "document/document.h"
#include "document/loadedfile.h"

#include <QFutureWatcher>
#include <QMainWindow>

#include <optional>

class QAction;
class QActionGroup;
class QComboBox;
class QLabel;
class QMenu;
class QProgressBar;
class QSplitter;
class QToolBar;
class QToolButton;

namespace toonface {

class WindowLayout;

class DetectionSteps;
class DetectionStepsUi;
class DetectionTask;
class PhotoView;
class PreviewView;
class Studio;

// The editor window: the photo with its points beside the live cartoon, the menus, and the
// wiring of the long jobs (opening, detection, export) that run off the GUI thread and come
// back as commands on the Document.
class MainWindow : public QMainWindow
{
    Q_OBJECT

public:
    struct Options
    {
        bool preloadLandmarkModel = true; // warm detection up in the background at start (warmUpDetection())
        QString recoveryDirectory; // empty: Autosaver::defaultDirectory()
    };

    explicit MainWindow(QWidget *parent = nullptr);
    explicit MainWindow(const Options &options, QWidget *parent = nullptr);
    ~MainWindow() override;

    Document *document() const { return m_document; }
    PhotoView *photoView() const { return m_photoView; }
    PreviewView *previewView() const { return m_previewView; }
    Autosaver *autosaver() const { return m_autosaver; }
    // The animation studio: playhead, playback, timeline dock, animation menus.
    Studio *studio() const { return m_studio; }
    // The intermediate images of the last detection of the open photo.
    DetectionSteps *detectionSteps() const { return m_steps; }

    // The method detections use from now on, for this session; the Edit ▸ Detection Method
    // menu also keeps the user's choice in the settings for the next sessions.
    void setDetectionMethod(DetectionMethod method);
    DetectionMethod detectionMethod() const;

    // Shows the detection step `name` (a key of detectionSteps()): over the photo, or in a
    // window of its own for a close-up. An empty or unknown name shows the photo alone.
    void showDetectionStep(const QString &name);
    // The step drawn over the photo now; empty when none.
    QString overlayStep() const;

    // After show(): offers to restore a leftover recovery file; when none is restored, opens
    // `path` (a photo or a project) if it is not empty.
    void startup(const QString &path);
    // Opens a photo (then detects its face) or a project, in the background; asks first when
    // the open document has unsaved changes.
    void openFile(const QString &path);
    bool saveTo(const QString &path);
    // Writes the cartoon in the background: .svg as drawn, .png rasterised at the photo's size.
    // exported() follows.
    void exportTo(const QString &path);
    // True while a file is being opened or a face detected.
    bool isBusy() const;

Q_SIGNALS:
    void fileOpened(const QString &path);
    void openFailed(const QString &error);
    // A detection's points are in the document (its steps may still be on their way).
    void pointsPlaced();
    // A detection ended: its points placed and its steps ready, or its failure told.
    void detectionDone();
    void exported(const QString &path, const QString &error); // error empty on success

protected:
    void closeEvent(QCloseEvent *event) override;
    void dragEnterEvent(QDragEnterEvent *event) override;
    void dropEvent(QDropEvent *event) override;

private:
    enum class Job { None, Opening, Detecting };

    void createActions();
    void createMenus();
    void createToolBar();
    void createStatusBar();
    void restoreSettings();
    void saveSettings();

    void onDocumentChanged(ChangeFlags what);
    void updateTitle();
    void updateActions();

    void openDialog();
    bool save();
    bool saveAs();
    void exportCartoon();
    bool maybeSave();
    void fillRecentMenu();

    // With `recovery`, `path` is that leftover and loading restores it.
    void startLoading(const QString &path, const std::optional<RecoveryFile> &recovery = std::nullopt);
    void onLoaded();
    // faceAt: detect the face whose box holds this point (another face of the photo).
    void startDetection(bool keepHandPlaced, std::optional<QPointF> faceAt = std::nullopt);
    void onPointsReady(const DetectionResult &result);
    void applyDetectedFace(const DetectionResult &result);
    void onDetectionFinished(const DetectionResult &result);
    void onDetectionCancelled();
    void cancelJob();
    void setBusy(Job job, const QString &text);

    void updateDetectionStepsEnabled();

    void onStyleActivated(int index);
    void syncStyleCombo();
    void showPointStatus(int index);
    QString dialogDirectory() const;

    bool m_pointsApplied = false; // the running detection's points are in the document
    Options m_options;
    Document *m_document;
    Autosaver *m_autosaver;
    DetectionTask *m_detection;
    PhotoView *m_photoView;
    PreviewView *m_previewView;
    Studio *m_studio;
    QSplitter *m_splitter;
    DetectionSteps *m_steps;
    DetectionStepsUi *m_stepsUi = nullptr;
    WindowLayout *m_layout = nullptr;
    QMenu *m_viewMenu = nullptr;
    QMenu *m_helpMenu = nullptr;

    QFutureWatcher<LoadedFile> *m_loadWatcher = nullptr;
    std::optional<RecoveryFile> m_recovering; // the leftover being restored, if any
    Job m_job = Job::None;
    bool m_detectKeepsHandPlaced = false;
    bool m_detectChoosesFace = false; // the running detection is of another face of the photo

    QAction *m_openAction = nullptr;
    QAction *m_saveAction = nullptr;
    QAction *m_saveAsAction = nullptr;
    QAction *m_exportAction = nullptr;
    QAction *m_quitAction = nullptr;
    QAction *m_undoAction = nullptr;
    QAction *m_redoAction = nullptr;
    QAction *m_redetectAction = nullptr;
    QAction *m_redetectKeepAction = nullptr;
    QAction *m_zoomInAction = nullptr;
    QAction *m_zoomOutAction = nullptr;
    QAction *m_actualSizeAction = nullptr;
    QAction *m_fitAction = nullptr;
    QAction *m_zoomFaceAction = nullptr;
    QAction *m_showIdsAction = nullptr;
    QAction *m_aboutAction = nullptr;
    QMenu *m_recentMenu = nullptr;
    QComboBox *m_styleCombo = nullptr;
    QMenu *m_methodMenu = nullptr;
    QActionGroup *m_methodGroup = nullptr;

    QLabel *m_busyLabel = nullptr;
    QProgressBar *m_busyBar = nullptr;
    QToolButton *m_cancelButton = nullptr;
    QLabel *m_zoomLabel = nullptr;
};

} // namespace toonface
