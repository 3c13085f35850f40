#include "window/mainwindow.h"

#include "detect/photocolours.h"
#include "dialogs/bookdialog.h"
#include "document/autosaver.h"
#include "export/cartoonfile.h"
#include "render/svgface.h"
#include "views/displaynames.h"
#include "views/photoview.h"
#include "views/previewview.h"
#include "views/themedicon.h"
#include "window/applydetection.h"
#include "window/detectionsteps.h"
#include "window/detectionstepsui.h"
#include "window/detectiontask.h"
#include "window/questions.h"
#include "window/settings.h"
#include "window/studio.h"
#include "window/windowlayout.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QImageReader>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressBar>
#include <QPushButton>
#include <QSlider>
#include <QSplitter>
#include <QStatusBar>
#include <QToolBar>
#include <QToolButton>
#include <QUndoStack>
#include <QtConcurrent/QtConcurrentRun>

#include <utility>

namespace toonface {

namespace {

constexpr int kStatusTimeoutMs = 6000;

QString photoFilter()
{
    QStringList patterns;
    const QList<QByteArray> formats = QImageReader::supportedImageFormats();
    for (const QByteArray &format : formats)
        patterns << QStringLiteral("*.") + QString::fromLatin1(format);
    return patterns.join(QLatin1Char(' '));
}

bool isOpenablePath(const QString &path)
{
    if (isProjectPath(path))
        return true;
    const QByteArray suffix = QFileInfo(path).suffix().toLower().toLatin1();
    return QImageReader::supportedImageFormats().contains(suffix);
}

} // namespace

MainWindow::MainWindow(QWidget *parent)
    : MainWindow(Options(), parent)
{ }

MainWindow::MainWindow(const Options &options, QWidget *parent)
    : QMainWindow(parent)
    , m_options(options)
    , m_document(new Document(this))
    , m_detection(new DetectionTask(this))
    , m_steps(new DetectionSteps(this))
{
    setObjectName(QStringLiteral("MainWindow"));
    setAcceptDrops(true);
    setWindowIcon(QIcon(QStringLiteral(":/toonface/icons/toonface.svg")));

    const QString recoveryDir
        = m_options.recoveryDirectory.isEmpty() ? Autosaver::defaultDirectory() : m_options.recoveryDirectory;
    m_autosaver = new Autosaver(m_document, recoveryDir, this);
    m_autosaver->setInterval(Settings().autosaveInterval());
    connect(m_autosaver, &Autosaver::failed, this,
        [this](const QString &error) { statusBar()->showMessage(error, kStatusTimeoutMs); });

    m_photoView = new PhotoView(m_document);
    m_photoView->setObjectName(QStringLiteral("photoView"));
    m_stepsUi = new DetectionStepsUi(m_steps, m_photoView, this);
    m_studio = new Studio(m_document, this);
    m_previewView = new PreviewView(m_document, m_studio->playhead());
    m_previewView->setObjectName(QStringLiteral("previewView"));
    m_splitter = new QSplitter(Qt::Horizontal);
    m_splitter->setObjectName(QStringLiteral("splitter"));
    m_splitter->addWidget(m_photoView);
    m_splitter->addWidget(m_previewView);
    m_splitter->setStretchFactor(0, 3);
    m_splitter->setStretchFactor(1, 2);
    m_splitter->setChildrenCollapsible(false);
    setCentralWidget(m_splitter);
    m_layout = new WindowLayout(this, m_splitter);
    m_layout->addAppearanceDock(m_document);

    createActions();
    createMenus();
    createToolBar();
    createStatusBar();
    m_studio->install(m_previewView, menuBar()->actions().constLast());
    if (QMenu *file = menuBar()->actions().constFirst()->menu())
        file->insertAction(m_exportAction, m_studio->exportAnimationAction());
    if (QMenu *file = menuBar()->actions().constFirst()->menu())
        file->insertAction(m_exportAction, BookDialog::createAction(this, m_document));
    connect(m_studio, &Studio::message, this,
        [this](const QString &text) { statusBar()->showMessage(text, kStatusTimeoutMs); });
    // A camera snapshot becomes the photo, as if opened.
    connect(m_studio, &Studio::photoCaptured, this, &MainWindow::openFile);
    m_layout->addViewActions(m_viewMenu);
    m_layout->captureDefault();
    restoreSettings();

    connect(m_document, &Document::changed, this, &MainWindow::onDocumentChanged);
    connect(m_photoView, &PhotoView::pointHovered, this, &MainWindow::showPointStatus);
    connect(m_photoView, &PhotoView::otherFaceChosen, this, [this](QPointF at) { startDetection(false, at); });
    connect(m_photoView, &PhotoView::zoomChanged, this,
        [this](double zoom) { m_zoomLabel->setText(tr("%1%").arg(qRound(zoom * 100))); });
    connect(m_detection, &DetectionTask::progress, this, [this](double fraction, const QString &stage) {
        m_busyBar->setRange(0, 100);
        m_busyBar->setValue(qRound(fraction * 100));
        if (!stage.isEmpty())
            m_busyLabel->setText(tr("Detecting the face: %1").arg(stage));
    });
    connect(m_detection, &DetectionTask::pointsReady, this, &MainWindow::onPointsReady);
    connect(m_detection, &DetectionTask::finished, this, &MainWindow::onDetectionFinished);
    connect(m_detection, &DetectionTask::cancelled, this, &MainWindow::onDetectionCancelled);
    connect(m_steps, &DetectionSteps::changed, this, &MainWindow::updateDetectionStepsEnabled);

    connect(m_detection, &DetectionTask::preloadFailed, this, [this](const QString &error) {
        statusBar()->showMessage(
            tr("Landmark model unavailable (%1): detection may fail, but points can be placed by hand.").arg(error),
            kStatusTimeoutMs);
    });
    if (m_options.preloadLandmarkModel)
        m_detection->preload();

    onDocumentChanged(Change::Photo | Change::Face | Change::Style | Change::FileState);
    updateDetectionStepsEnabled();
}

MainWindow::~MainWindow() = default;

void MainWindow::restoreSettings()
{
    Settings settings;
    if (!restoreGeometry(settings.windowGeometry()) || !restoreState(settings.windowState()))
        m_layout->firstRun();
    m_splitter->restoreState(settings.splitterState());
    m_showIdsAction->setChecked(settings.showPointIds());
    m_previewView->transparentAction()->setChecked(settings.transparentPreview());
}

void MainWindow::saveSettings()
{
    Settings settings;
    settings.setWindowGeometry(saveGeometry());
    settings.setWindowState(saveState());
    settings.setSplitterState(m_splitter->saveState());
}

void MainWindow::startup(const QString &path)
{
    const QList<RecoveryFile> leftovers = Autosaver::leftovers(
        m_options.recoveryDirectory.isEmpty() ? Autosaver::defaultDirectory() : m_options.recoveryDirectory);
    if (!leftovers.isEmpty()) {
        const RecoveryFile &newest = leftovers.first();
        if (askToRestore(this, newest)) {
            startLoading(newest.path, newest);
            return;
        }
        Autosaver::remove(newest);
    }
    if (!path.isEmpty())
        openFile(path);
}

void MainWindow::openFile(const QString &path)
{
    if (!maybeSave())
        return;
    startLoading(path, {});
}

void MainWindow::openDialog()
{
    const QString filter
        = tr("Photos and projects (*.toonface %1);;Toonface projects (*.toonface);;Photos (%1);;All files (*)")
              .arg(photoFilter());
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Photo or Project"), dialogDirectory(), filter);
    if (!path.isEmpty())
        openFile(path);
}

void MainWindow::startLoading(const QString &path, const std::optional<RecoveryFile> &recovery)
{
    m_detection->abandon();
    if (m_loadWatcher) {
        m_loadWatcher->disconnect(this);
        m_loadWatcher->deleteLater();
    }
    m_recovering = recovery;
    m_loadWatcher = new QFutureWatcher<LoadedFile>(this);
    connect(m_loadWatcher, &QFutureWatcherBase::finished, this, &MainWindow::onLoaded);
    if (recovery)
        m_loadWatcher->setFuture(QtConcurrent::run([file = *recovery] { return Autosaver::load(file); }));
    else
        m_loadWatcher->setFuture(QtConcurrent::run([path] { return loadFile(path); }));
    setBusy(Job::Opening, tr("Opening %1…").arg(QFileInfo(path).fileName()));
}

void MainWindow::onLoaded()
{
    QFutureWatcher<LoadedFile> *watcher = m_loadWatcher;
    m_loadWatcher = nullptr;
    watcher->deleteLater();
    setBusy(Job::None, {});
    const LoadedFile file = watcher->result();
    const std::optional<RecoveryFile> recovery = std::exchange(m_recovering, std::nullopt);
    // A project from someone else (not one this user has opened before) that names files
    // outside its folder says which, before the user plays or exports them.
    const bool fromElsewhere = !recovery && !Settings().recentFiles().contains(file.path);

    if (!file.ok()) {
        if (!recovery)
            Settings().removeRecentFile(file.path);
        QMessageBox::warning(this, tr("Cannot Open"), file.error);
        Q_EMIT openFailed(file.error);
        return;
    }
    if (recovery) {
        Autosaver::restoreInto(m_document, file);
        Autosaver::remove(*recovery);
        statusBar()->showMessage(tr("Restored unsaved work on %1.").arg(m_document->displayName()), kStatusTimeoutMs);
    } else {
        m_document->open(file);
        Settings settings;
        settings.addRecentFile(file.path);
        settings.setLastDirectory(QFileInfo(file.path).absolutePath());
    }
    if (!file.photoWarning.isEmpty())
        QMessageBox::warning(this, tr("Photo Missing"),
            tr("The project opened, but its photo could not be read:\n%1").arg(file.photoWarning));
    if (fromElsewhere && !file.outsideFiles.isEmpty())
        showOutsideFiles(this, file.path, file.outsideFiles);
    Q_EMIT fileOpened(file.path);
    if (!m_document->hasFace() && !m_document->photo().isNull())
        startDetection(false);
}

void MainWindow::startDetection(bool keepHandPlaced, std::optional<QPointF> faceAt)
{
    if (m_document->photo().isNull() || m_job == Job::Opening)
        return;
    m_detectKeepsHandPlaced = keepHandPlaced && !faceAt;
    m_detectChoosesFace = faceAt.has_value();
    m_steps->clear(); // the new run's steps replace them
    m_pointsApplied = false;
    DetectOptions options;
    options.method = detectionMethod();
    options.faceAt = faceAt;
    m_detection->start(m_document->photo(), options);
    setBusy(Job::Detecting, tr("Detecting the face…"));
}

// The points as soon as they are placed; the steps follow with onDetectionFinished(), which
// also tells a failure.
void MainWindow::onPointsReady(const DetectionResult &result)
{
    if (result.status != DetectStatus::Ok)
        return;
    applyDetectedFace(result);
    m_pointsApplied = true;
}

void MainWindow::applyDetectedFace(const DetectionResult &result)
{
    m_photoView->setOtherFaces(result.otherFaces);
    const bool showOtherFaces = !result.otherFaces.isEmpty() && !m_document->hasFace();
    const DetectionUse use = !m_document->hasFace() || m_detectChoosesFace ? DetectionUse::NewFace
        : m_detectKeepsHandPlaced                                          ? DetectionUse::KeepHandPlaced
                                                                           : DetectionUse::Replace;
    applyDetection(m_document, result, use, m_detectChoosesFace);
    // A photo of several people, first seen: the whole photo, so that the other faces' boxes
    // can be clicked.
    if (showOtherFaces)
        m_photoView->fitToWindow();
    // Auto's fallback to the thesis' pipeline, and the choice of faces, stay up until the next
    // message.
    statusBar()->showMessage(detectionSummary(result, m_detectChoosesFace),
        result.note.isEmpty() && result.faceCount <= 1 && turnedFaceWarning(result.face).isEmpty() ? kStatusTimeoutMs
                                                                                                   : 0);
    Q_EMIT pointsPlaced();
}

void MainWindow::onDetectionFinished(const DetectionResult &result)
{
    if (m_job == Job::Detecting)
        setBusy(Job::None, {});
    // Also when no face was found: the steps show how far the method got.
    m_steps->setImages(result.debugImages);
    if (result.status != DetectStatus::Ok) {
        if (result.status == DetectStatus::BadImage || m_document->hasFace())
            QMessageBox::warning(this, tr("Detection Failed"),
                m_document->hasFace() ? tr("%1\nThe points are unchanged.").arg(result.error) : result.error);
        else // no face, or no detector able to look for one: the user can still place the points
            offerAverageFace(this, m_document, result.error);
        Q_EMIT detectionDone();
        return;
    }
    // The points came first (onPointsReady); a detection whose first report was lost places
    // them now.
    if (!std::exchange(m_pointsApplied, false))
        applyDetectedFace(result);
    Q_EMIT detectionDone();
}

void MainWindow::onDetectionCancelled()
{
    if (m_job == Job::Detecting)
        setBusy(Job::None, {});
    statusBar()->showMessage(tr("Detection cancelled."), kStatusTimeoutMs);
    Q_EMIT detectionDone();
}

void MainWindow::cancelJob()
{
    if (m_job == Job::Detecting) {
        m_detection->cancel();
        m_busyLabel->setText(tr("Cancelling…"));
    } else if (m_job == Job::Opening && m_loadWatcher) {
        m_loadWatcher->disconnect(this);
        m_loadWatcher->deleteLater();
        m_loadWatcher = nullptr;
        m_recovering.reset();
        setBusy(Job::None, {});
    }
}

void MainWindow::setBusy(Job job, const QString &text)
{
    m_job = job;
    const bool busy = job != Job::None;
    m_busyLabel->setText(text);
    m_busyLabel->setVisible(busy);
    m_busyBar->setRange(0, 0); // indeterminate until the job reports progress
    m_busyBar->setVisible(busy);
    m_cancelButton->setVisible(busy);
    m_cancelButton->setToolTip(job == Job::Detecting ? tr("Stop detecting the face") : tr("Stop opening the file"));
    updateActions();
}

bool MainWindow::isBusy() const
{
    return m_job != Job::None;
}

bool MainWindow::save()
{
    if (m_document->filePath().isEmpty())
        return saveAs();
    if (m_document->changedOnDisk()) {
        // Another editor (or program) wrote the file since it was opened here: never silently
        // overwrite its work.
        switch (askOverwriteChanged(this, m_document->filePath())) {
        case DiskConflict::Overwrite: break;
        case DiskConflict::SaveAs: return saveAs();
        case DiskConflict::Cancel: return false;
        }
    }
    return saveTo(m_document->filePath());
}

bool MainWindow::saveAs()
{
    QString suggested = m_document->filePath();
    if (suggested.isEmpty()) {
        const QFileInfo photo(m_document->project().photoPath);
        suggested = QDir(photo.absolutePath()).filePath(photo.completeBaseName() + QStringLiteral(".toonface"));
    }
    QString path
        = QFileDialog::getSaveFileName(this, tr("Save Project"), suggested, tr("Toonface projects (*.toonface)"));
    if (path.isEmpty())
        return false;
    if (!isProjectPath(path))
        path += QStringLiteral(".toonface");
    return saveTo(path);
}

bool MainWindow::saveTo(const QString &path)
{
    QString error;
    if (!m_document->save(path, &error)) {
        QMessageBox::warning(this, tr("Cannot Save"), error);
        return false;
    }
    Settings settings;
    settings.addRecentFile(path);
    settings.setLastDirectory(QFileInfo(path).absolutePath());
    statusBar()->showMessage(tr("Saved %1.").arg(QDir::toNativeSeparators(path)), kStatusTimeoutMs);
    return true;
}

void MainWindow::exportCartoon()
{
    if (!m_document->hasFace())
        return;
    const QFileInfo base(m_document->filePath().isEmpty() ? m_document->project().photoPath : m_document->filePath());
    const QString suggested
        = QDir(base.absolutePath()).filePath(base.completeBaseName() + QStringLiteral("-cartoon.svg"));
    QString selectedFilter;
    QString path = QFileDialog::getSaveFileName(
        this, tr("Export Cartoon"), suggested, tr("SVG image (*.svg);;PNG image (*.png)"), &selectedFilter);
    if (path.isEmpty())
        return;
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix != QLatin1StringView("svg") && suffix != QLatin1StringView("png"))
        path += selectedFilter.contains(QLatin1StringView("*.png")) ? QStringLiteral(".png") : QStringLiteral(".svg");
    exportTo(path);
}

void MainWindow::exportTo(const QString &path)
{
    if (!m_document->hasFace())
        return;
    // The SVG is built here (fast, and the document is only read on the GUI thread); writing
    // and rasterising happen in the background.
    const QByteArray svg = SvgFace(m_document->face(), m_document->style()).svg();
    const QSize size = m_document->canvasSize();
    auto *watcher = new QFutureWatcher<QString>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, path] {
        watcher->deleteLater();
        const QString error = watcher->result();
        if (error.isEmpty())
            statusBar()->showMessage(tr("Exported %1.").arg(QDir::toNativeSeparators(path)), kStatusTimeoutMs);
        else
            QMessageBox::warning(this, tr("Cannot Export"), error);
        Q_EMIT exported(path, error);
    });
    watcher->setFuture(QtConcurrent::run([svg, size, path] {
        QString error;
        writeCartoonFile(svg, size, path, &error);
        return error;
    }));
}

bool MainWindow::maybeSave()
{
    if (!m_document->isModified())
        return true;
    // Name the project, not the photo: the photo is never written.
    const QString question = m_document->filePath().isEmpty()
        ? tr("The cartoon made from %1 is not saved as a project yet. Save it?").arg(m_document->displayName())
        : tr("The project %1 has unsaved changes. Save them?").arg(m_document->displayName());
    const QMessageBox::StandardButton answer = QMessageBox::warning(this, tr("Unsaved Changes"), question,
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save)
        return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::fillRecentMenu()
{
    m_recentMenu->clear();
    const QStringList files = Settings().recentFiles();
    for (const QString &path : files) {
        QAction *action = m_recentMenu->addAction(QFileInfo(path).fileName());
        action->setToolTip(QDir::toNativeSeparators(path));
        action->setStatusTip(QDir::toNativeSeparators(path));
        connect(action, &QAction::triggered, this, [this, path] { openFile(path); });
    }
    if (!files.isEmpty())
        m_recentMenu->addSeparator();
    QAction *clear = m_recentMenu->addAction(tr("&Clear Menu"));
    clear->setEnabled(!files.isEmpty());
    connect(clear, &QAction::triggered, this, [] { Settings().clearRecentFiles(); });
}

void MainWindow::onDocumentChanged(ChangeFlags what)
{
    if (what & Change::Photo) {
        // The steps belong to the photo they came from.
        m_stepsUi->forgetChoice();
        m_steps->clear();
    }
    if (what & Change::Style)
        syncStyleCombo();
    if (what & (Change::FileState | Change::Photo))
        updateTitle();
    if (what & (Change::Points | Change::Face | Change::Photo | Change::FileState))
        updateActions();
}

void MainWindow::updateTitle()
{
    setWindowTitle(tr("%1[*] — Toonface").arg(m_document->projectName()));
    setWindowFilePath(m_document->filePath());
    setWindowModified(m_document->isModified());
}

void MainWindow::updateActions()
{
    const bool hasFace = m_document->hasFace();
    const bool hasPhoto = !m_document->photo().isNull();
    m_saveAction->setEnabled(hasFace);
    m_saveAsAction->setEnabled(hasFace);
    m_exportAction->setEnabled(hasFace);
    m_redetectAction->setEnabled(hasPhoto && !isBusy());
    m_redetectKeepAction->setEnabled(hasPhoto && hasFace && !isBusy() && m_document->face().handPlacedCount() > 0);
    m_styleCombo->setEnabled(hasFace);
    m_zoomFaceAction->setEnabled(hasFace);
    updateDetectionStepsEnabled();
}

void MainWindow::setDetectionMethod(DetectionMethod method)
{
    const QString name = detectionMethodName(method);
    const QList<QAction *> actions = m_methodGroup->actions();
    for (QAction *action : actions)
        action->setChecked(action->data().toString() == name);
}

DetectionMethod MainWindow::detectionMethod() const
{
    DetectionMethod method = DetectionMethod::Auto;
    if (const QAction *checked = m_methodGroup->checkedAction())
        detectionMethodFromName(checked->data().toString(), &method);
    return method;
}

void MainWindow::showDetectionStep(const QString &name)
{
    m_stepsUi->show(name);
}

QString MainWindow::overlayStep() const
{
    return m_stepsUi->overlayStep();
}

void MainWindow::updateDetectionStepsEnabled()
{
    QString why;
    if (m_job == Job::Detecting)
        why = tr("The detection's steps appear when it ends");
    else if (m_document->photo().isNull())
        why = tr("Open a photo: its face detection's steps can be shown here");
    else
        why = tr("No detection steps for this photo: they are not saved in projects. Use Edit ▸ Re-detect Points "
                 "to see them");
    m_stepsUi->updateEnabled(why);
}

void MainWindow::onStyleActivated(int index)
{
    const QString name = m_styleCombo->itemData(index).toString();
    if (name == m_document->style().name)
        return;
    bool ok = false;
    Style style = Style::preset(name, &ok);
    if (!ok)
        return;
    if (m_document->hasFace() && !m_document->photo().isNull())
        sampleColours(m_document->photo(), m_document->face(), &style);
    m_document->changeStyle(style, tr("Style “%1”").arg(m_styleCombo->itemText(index)));
}

void MainWindow::syncStyleCombo()
{
    const int index = m_styleCombo->findData(m_document->style().name);
    const QSignalBlocker blocker(m_styleCombo);
    m_styleCombo->setCurrentIndex(index);
}

void MainWindow::showPointStatus(int index)
{
    if (index < 0 || !m_document->hasFace()) {
        statusBar()->clearMessage();
        return;
    }
    const PointInfo &info = pointTable()[index];
    const QPointF p = m_document->face().point(index);
    QString text = tr("%1 at %2, %3").arg(pointTitle(index)).arg(p.x(), 0, 'f', 1).arg(p.y(), 0, 'f', 1);
    if (info.control)
        text += tr(" · control point");
    if (m_document->face().isHandPlaced(index))
        text += tr(" · placed by hand");
    statusBar()->showMessage(text);
}

QString MainWindow::dialogDirectory() const
{
    if (!m_document->filePath().isEmpty())
        return QFileInfo(m_document->filePath()).absolutePath();
    return Settings().lastDirectory();
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    m_studio->closeLiveMode(); // first: a take it was recording joins what is saved
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    m_detection->abandon();
    m_autosaver->discard();
    saveSettings();
    event->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent *event)
{
    const QList<QUrl> urls = event->mimeData()->urls();
    if (urls.size() == 1 && urls.first().isLocalFile() && isOpenablePath(urls.first().toLocalFile()))
        event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent *event)
{
    const QList<QUrl> urls = event->mimeData()->urls();
    if (urls.isEmpty() || !urls.first().isLocalFile())
        return;
    event->acceptProposedAction();
    // Opening may ask about unsaved changes: not from inside the drop.
    const QString path = urls.first().toLocalFile();
    QMetaObject::invokeMethod(
        this, [this, path] { openFile(path); }, Qt::QueuedConnection);
}

} // namespace toonface
