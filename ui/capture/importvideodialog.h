#pragma once

#include "track/neutralchoice.h"
#include "track/trackvideo.h"
#include "window/backgroundjob.h"

#include <QDialog>

class QButtonGroup;
class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QRadioButton;
class QSlider;
class QSpinBox;

namespace toonface {

class Document;
class FrameDecoder;
class FrameView;
class JobStatus;
class TrackTask;

// Import Video…: a clip of a person speaking drives the cartoon (thesis ch. 6). The user picks
// the clip and its neutral frame (a slider and a spin box, the frame shown large, decoded off the
// GUI thread), the tracking method, whether the mouth snaps to the nine shapes (mouth keys) or
// keeps its continuous motion (pose keys), whether the clip's sound becomes a clip on the audio
// track (by default only when the project has no sound yet, which the dialog says), and where
// the clip starts (the playhead or 0). The sound goes where the motion does: when other
// recordings play there, the dialog says which, and they are kept (sounding together with it)
// unless the user ticks to replace them. Tracking runs in the background with progress and
// Cancel. The result lands as ONE undo step: the pose, blink, gaze and head tracks (and the
// mouth keys when snapped), the clip's sound, and the clip itself (shown beside the cartoon).
// With no face in the project yet, the neutral frame can become the photo (a new project whose
// face is the neutral frame's). A clip that cannot be read, or whose neutral frame shows no face,
// is said in the dialog naming the file, and nothing changes; so does cancelling.
class ImportVideoDialog : public QDialog
{
    Q_OBJECT

public:
    // Opens the dialog modally; true when a clip was imported.
    static bool run(QWidget *parent, Document *document, double playheadTime);

    ImportVideoDialog(Document *document, double playheadTime, QWidget *parent = nullptr);
    ~ImportVideoDialog() override;

    // Opens `path` as the clip (as the Browse button does); false with the problem shown.
    bool openClip(const QString &path);
    // The neutral frame chosen, and the frame now shown large (null until decoded).
    int neutralFrame() const;
    void setNeutralFrame(int index);
    QImage shownFrame() const;
    int shownFrameIndex() const { return m_shownIndex; }
    // What the large view says instead of a frame (e.g. a frame past the end of a cut file).
    QString frameText() const;
    bool isRunning() const;
    // What the last import noted but went on with (e.g. a damaged file decoded around its bad
    // packets); empty when none.
    QStringList warnings() const { return m_warnings; }
    // The message under the form (an error, or a note such as "cancelled"), or empty.
    QString message() const;

public Q_SLOTS:
    // Starts tracking (the Import button).
    void start();
    // Stops the tracking; nothing is changed.
    void cancel();
    void reject() override;

Q_SIGNALS:
    void applied();
    void failed(const QString &message);
    void cancelled();
    // The large view shows the frame `index`.
    void frameShown(int index);
    // The search for a frame at rest is over: `frame` is the one found (-1: no face found in
    // the clip's first seconds); it became the neutral frame unless the user had chosen one.
    void neutralSuggested(int frame);

private:
    void browse();
    void onFrameReady(int index, const QImage &image);
    void onTracked(const TrackResult &result);
    void apply(const TrackResult &result);
    void fail(const QString &message);
    void setRunning(bool running);
    void updateButtons();
    void updateNeutralLabel();
    void suggestNeutral(const NeutralChoice &choice);
    // Says which recordings the clip's sound would play over where it starts, and offers to
    // replace them; says why the sound is off when the project has one already.
    void updateSoundChoice();

    Document *m_document;
    double m_playheadTime;
    FrameDecoder *m_decoder;
    TrackTask *m_task;
    QLineEdit *m_clip;
    QLabel *m_clipInfo;
    FrameView *m_frame;
    QSlider *m_slider;
    QSpinBox *m_spin;
    QLabel *m_neutralTime;
    QLabel *m_neutralNote;
    QComboBox *m_method;
    QRadioButton *m_snap;
    QRadioButton *m_continuous;
    QCheckBox *m_useSound;
    QCheckBox *m_replaceOverlap;
    QLabel *m_soundNote;
    QRadioButton *m_atPlayhead;
    QRadioButton *m_atStart;
    QCheckBox *m_usePhoto;
    JobStatus *m_status;
    QDialogButtonBox *m_buttons;
    QPushButton *m_startButton;
    QPushButton *m_cancelButton;
    QList<QWidget *> m_inputs;
    int m_shownIndex = -1;
    BackgroundJob<NeutralChoice> m_neutralSearch {this};
    bool m_neutralChosenByUser = false;
    bool m_suggesting = false; // the neutral frame is being set to the suggestion
    QStringList m_warnings;
    // What the running job was started with.
    QString m_runPath;
    double m_runOffset = 0;
    bool m_runSnap = false;
    bool m_runSound = false;
    bool m_runReplace = false;
    bool m_runPhoto = false;
};

} // namespace toonface
