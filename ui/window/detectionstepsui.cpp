#include "window/detectionstepsui.h"

#include "views/photoview.h"
#include "views/stepimagedialog.h"
#include "window/detectionsteps.h"
#include "window/settings.h"

#include <QActionGroup>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMainWindow>
#include <QMenu>
#include <QSignalBlocker>
#include <QSlider>
#include <QStatusBar>

#include <algorithm>
#include <utility>

namespace toonface {

namespace {

constexpr int kOpacitySteps = 100; // the opacity slider's range, 0..kOpacitySteps

} // namespace

DetectionStepsUi::DetectionStepsUi(DetectionSteps *steps, PhotoView *photoView, QMainWindow *window)
    : QObject(window)
    , m_steps(steps)
    , m_photoView(photoView)
    , m_window(window)
{
    connect(m_steps, &DetectionSteps::changed, this, &DetectionStepsUi::rebuild);
}

void DetectionStepsUi::install(QMenu *view)
{
    // Tool tips on, so that the disabled steps entry can say why it is disabled.
    view->setToolTipsVisible(true);
    m_menu = view->addMenu(tr("Detection &Steps"));
    m_menu->setObjectName(QStringLiteral("menuDetectionSteps"));
    m_menu->setToolTipsVisible(true);
    m_group = new QActionGroup(this);
    m_group->setExclusive(true);

    // In the status bar, below the views, where the main toolbar's width does not push it out
    // of sight; not a tool bar row of its own, which took a short screen's last timeline row.
    m_stepBar = new QWidget;
    m_stepBar->setObjectName(QStringLiteral("detectionStepsBar"));
    m_stepBar->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Preferred); // its controls side by side
    auto *row = new QHBoxLayout(m_stepBar);
    row->setContentsMargins(0, 0, 0, 0);
    row->setSpacing(0);
    m_window->statusBar()->insertPermanentWidget(0, m_stepBar);
    auto *stepLabel = new QLabel(tr("Step:") + QLatin1Char(' '));
    row->addWidget(stepLabel);
    m_combo = new QComboBox;
    m_combo->setObjectName(QStringLiteral("detectionStepCombo"));
    m_combo->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    stepLabel->setBuddy(m_combo);
    connect(m_combo, &QComboBox::activated, this,
        [this](int index) { setOverlayStep(m_combo->itemData(index).toString()); });
    row->addWidget(m_combo);
    row->addWidget(new QLabel(QLatin1Char(' ') + tr("Opacity:") + QLatin1Char(' ')));
    m_opacitySlider = new QSlider(Qt::Horizontal);
    m_opacitySlider->setObjectName(QStringLiteral("overlayOpacitySlider"));
    m_opacitySlider->setRange(0, kOpacitySteps);
    m_opacitySlider->setPageStep(kOpacitySteps / 10);
    m_opacitySlider->setFixedWidth(110);
    m_opacitySlider->setToolTip(tr("How strongly the detection step covers the photo"));
    m_opacitySlider->setValue(qRound(Settings().overlayOpacity() * kOpacitySteps));
    m_photoView->setOverlayOpacity(double(m_opacitySlider->value()) / kOpacitySteps);
    connect(m_opacitySlider, &QSlider::valueChanged, this, [this](int value) {
        m_photoView->setOverlayOpacity(double(value) / kOpacitySteps);
        Settings().setOverlayOpacity(double(value) / kOpacitySteps);
    });
    row->addWidget(m_opacitySlider);
    rebuild();
}

void DetectionStepsUi::show(const QString &name)
{
    if (!name.isEmpty() && DetectionSteps::isCloseUp(name) && !m_steps->image(name).isNull())
        openCloseUp(name);
    else
        setOverlayStep(name);
}

void DetectionStepsUi::rebuild()
{
    if (!m_menu)
        return;
    const QStringList names = m_steps->names();
    if (m_steps->isEmpty()) {
        for (const QPointer<StepImageDialog> &dialog : std::as_const(m_closeUps)) {
            if (dialog)
                dialog->close();
        }
        m_closeUps.clear();
    }

    const QList<QAction *> old = m_group->actions();
    for (QAction *action : old)
        m_group->removeAction(action);
    m_menu->clear(); // deletes the actions it owns

    const QSignalBlocker blocker(m_combo);
    m_combo->clear();

    QAction *none = m_menu->addAction(tr("&None"));
    none->setObjectName(QStringLiteral("actionStepNone"));
    none->setCheckable(true);
    none->setData(QString());
    m_group->addAction(none);
    m_combo->addItem(tr("None"), QString());
    connect(none, &QAction::triggered, this, [this] { setOverlayStep({}); });

    bool firstOverlay = true;
    for (const QString &name : names) {
        if (DetectionSteps::isCloseUp(name))
            continue;
        if (std::exchange(firstOverlay, false))
            m_menu->addSeparator();
        const QString text = DetectionSteps::displayName(name);
        QAction *action = m_menu->addAction(text);
        action->setObjectName(QStringLiteral("actionStep-") + name);
        action->setCheckable(true);
        action->setData(name);
        action->setToolTip(tr("Draw “%1” over the photo (%2.png with --debug-dir)").arg(text, name));
        m_group->addAction(action);
        connect(action, &QAction::triggered, this, [this, name] { setOverlayStep(name); });
        m_combo->addItem(text, name);
        m_combo->setItemData(m_combo->count() - 1, name, Qt::ToolTipRole);
    }
    bool firstCloseUp = true;
    for (const QString &name : names) {
        if (!DetectionSteps::isCloseUp(name))
            continue;
        if (std::exchange(firstCloseUp, false))
            m_menu->addSeparator();
        const QString text = DetectionSteps::displayName(name);
        QAction *action = m_menu->addAction(tr("%1…").arg(text));
        action->setObjectName(QStringLiteral("actionStep-") + name);
        action->setData(name);
        action->setToolTip(tr("Show “%1” in a window of its own (%2.png with --debug-dir)").arg(text, name));
        connect(action, &QAction::triggered, this, [this, name] { openCloseUp(name); });
    }

    // A re-detection of the same photo brings the same steps: keep showing the chosen one.
    showChosenStep();
}

void DetectionStepsUi::setOverlayStep(const QString &name)
{
    m_chosenStep = DetectionSteps::isCloseUp(name) || m_steps->image(name).isNull() ? QString() : name;
    showChosenStep();
}

void DetectionStepsUi::showChosenStep()
{
    const QImage image = m_chosenStep.isEmpty() ? QImage() : m_steps->image(m_chosenStep);
    m_overlayStep = image.isNull() ? QString() : m_chosenStep;
    m_photoView->setOverlay(image);

    const QList<QAction *> actions = m_group->actions();
    for (QAction *action : actions) {
        if (action->data().toString() == m_overlayStep)
            action->setChecked(true);
    }
    const QSignalBlocker blocker(m_combo);
    m_combo->setCurrentIndex(std::max(0, m_combo->findData(m_overlayStep)));
    m_opacitySlider->setEnabled(!m_overlayStep.isEmpty());
}

void DetectionStepsUi::openCloseUp(const QString &name)
{
    const QImage image = m_steps->image(name);
    if (image.isNull())
        return;
    QPointer<StepImageDialog> &dialog = m_closeUps[name];
    if (!dialog) {
        dialog = new StepImageDialog(image, DetectionSteps::displayName(name), m_window);
        dialog->setObjectName(QStringLiteral("closeUp-") + name);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
    }
    dialog->show();
    dialog->raise();
    dialog->activateWindow();
}

void DetectionStepsUi::updateEnabled(const QString &whyNot)
{
    if (!m_menu)
        return;
    const bool available = !m_steps->isEmpty();
    const QString why = available ? tr("Show an intermediate image of the face detection over the photo") : whyNot;
    QAction *menuAction = m_menu->menuAction();
    menuAction->setEnabled(available);
    menuAction->setToolTip(why);
    menuAction->setStatusTip(why);
    m_combo->setEnabled(available);
    m_combo->setToolTip(why);
}

} // namespace toonface
