#pragma once

#include <QHash>
#include <QObject>
#include <QPointer>
#include <QString>

class QActionGroup;
class QComboBox;
class QMainWindow;
class QMenu;
class QSlider;
class QWidget;

namespace toonface {

class DetectionSteps;
class PhotoView;
class StepImageDialog;

// How the user sees the detection's intermediate images: the View ▸ Detection Steps menu, the
// "Step" controls in the status bar (which step covers the photo, and how strongly), and the
// close-ups in windows of their own. It follows DetectionSteps: a new detection's steps refill
// the menu, and the step chosen before stays shown when the new run has it too.
class DetectionStepsUi : public QObject
{
    Q_OBJECT

public:
    DetectionStepsUi(DetectionSteps *steps, PhotoView *photoView, QMainWindow *window);

    // Adds the Detection Steps submenu to `view` and the step controls to the status bar.
    void install(QMenu *view);

    // Shows step `name`: over the photo, or in a window of its own for a close-up; empty hides it.
    void show(const QString &name);
    // The step drawn over the photo now (empty for none).
    QString overlayStep() const { return m_overlayStep; }
    // Forgets the user's choice (the photo changed: its steps are gone).
    void forgetChoice() { m_chosenStep.clear(); }
    // Enables the menu and tool bar when there are steps; `whyNot` says why not when there are none.
    void updateEnabled(const QString &whyNot);

private:
    void rebuild();
    void setOverlayStep(const QString &name); // the user's choice
    void showChosenStep();
    void openCloseUp(const QString &name);

    DetectionSteps *m_steps;
    PhotoView *m_photoView;
    QMainWindow *m_window;
    QMenu *m_menu = nullptr;
    QActionGroup *m_group = nullptr;
    QWidget *m_stepBar = nullptr; // the step and opacity controls, in the status bar
    QComboBox *m_combo = nullptr;
    QSlider *m_opacitySlider = nullptr;
    QString m_overlayStep; // the step drawn over the photo now
    // The step the user chose; shown again when a re-detection brings it back.
    QString m_chosenStep;
    QHash<QString, QPointer<StepImageDialog>> m_closeUps;
};

} // namespace toonface
