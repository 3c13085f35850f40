#include "capture/importvideodialog.h"

#include "capture/framedecoder.h"
#include "capture/frameview.h"
#include "capture/tracktask.h"
#include "dialogs/jobstatus.h"
#include "document/document.h"
#include "timeline/audioclipedits.h"
#include "track/retarget.h"

#include <QButtonGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QSlider>
#include <QSpinBox>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

namespace toonface {

namespace {

// A file name beside `clip` for its neutral frame that does not overwrite anything.
QString neutralPhotoPath(const QString &clip)
{
    const QFileInfo info(clip);
    const QDir dir = info.absoluteDir();
    QString path = dir.filePath(info.completeBaseName() + QStringLiteral("-neutral.png"));
    for (int n = 2; QFileInfo::exists(path); ++n)
        path = dir.filePath(info.completeBaseName() + QStringLiteral("-neutral-%1.png").arg(n));
    return path;
}

QString seconds(double s)
{
    return QCoreApplication::translate("toonface", "%1 s").arg(s, 0, 'f', 2);
}

} // namespace

bool ImportVideoDialog::run(QWidget *parent, Document *document, double playheadTime)
{
    ImportVideoDialog dialog(document, playheadTime, parent);
    return dialog.exec() == QDialog::Accepted;
}

ImportVideoDialog::ImportVideoDialog(Document *document, double playheadTime, QWidget *parent)
    : QDialog(parent)
    , m_document(document)
    , m_playheadTime(playheadTime)
    , m_decoder(new FrameDecoder(this))
    , m_task(new TrackTask(this))
    , m_clip(new QLineEdit(this))
    , m_clipInfo(new QLabel(this))
    , m_frame(new FrameView(this))
    , m_slider(new QSlider(Qt::Horizontal, this))
    , m_spin(new QSpinBox(this))
    , m_neutralTime(new QLabel(this))
    , m_neutralNote(new QLabel(this))
    , m_method(new QComboBox(this))
    , m_snap(new QRadioButton(tr("Snap to the nine mouth &shapes (mouth keys)"), this))
    , m_continuous(new QRadioButton(tr("Keep the &continuous motion (pose keys)"), this))
    , m_useSound(new QCheckBox(tr("Use the clip's s&ound (a new clip on the audio track)"), this))
    , m_replaceOverlap(new QCheckBox(this))
    , m_soundNote(new QLabel(this))
    , m_atPlayhead(new QRadioButton(tr("At the &playhead (%1)").arg(seconds(playheadTime)), this))
    , m_atStart(new QRadioButton(tr("At the s&tart (0 s)"), this))
    , m_usePhoto(new QCheckBox(tr("Use the neutral frame as the p&hoto (a new project with its face)"), this))
    , m_status(new JobStatus(this))
    , m_buttons(new QDialogButtonBox(this))
{
    setWindowTitle(tr("Import Video"));
    auto *intro = new QLabel(tr("Tracks a clip of a person speaking: the face of the neutral frame is the rest "
                                "pose, and the motion of every other frame lands on the timeline as key frames "
                                "(pose, blinks, gaze, head), editable like any others."),
        this);
    intro->setWordWrap(true);
    // The dialog's width and the text's height at it: the layout sets the dialog's minimum size
    // from its widgets' (SetMinimumSize below), which undid a minimum width set on the dialog,
    // and it reckoned with fewer lines of the wrapped text than it has there, so the neutral
    // frame's slider was drawn over the picture (seen at 1280x720).
    constexpr int introWidth = 600;
    intro->setMinimumWidth(introWidth);
    intro->setMinimumHeight(intro->heightForWidth(introWidth));

    m_clip->setObjectName(QStringLiteral("clip"));
    m_clip->setPlaceholderText(tr("A video of a face speaking"));
    auto *browseButton = new QPushButton(tr("Browse…"), this);
    browseButton->setObjectName(QStringLiteral("browse"));
    auto *clipRow = new QHBoxLayout;
    clipRow->addWidget(m_clip, 1);
    clipRow->addWidget(browseButton);
    m_clipInfo->setObjectName(QStringLiteral("clipInfo"));
    m_clipInfo->setWordWrap(true);
    // Its room kept before a clip is chosen (two lines: a long path's problem wraps): the
    // layout does not grow the dialog for a wrapped label's lines, it pushes the rows below
    // over the picture.
    m_clipInfo->setMinimumHeight(2 * m_clipInfo->fontMetrics().lineSpacing());

    m_frame->setObjectName(QStringLiteral("neutralView"));
    m_frame->setMinimumSize(320, 180); // the dialog fits an 800 x 600 screen
    m_frame->setText(tr("Choose a clip"));
    m_slider->setObjectName(QStringLiteral("neutralSlider"));
    m_spin->setObjectName(QStringLiteral("neutralFrame"));
    m_neutralTime->setObjectName(QStringLiteral("neutralTime"));
    m_neutralTime->setMinimumWidth(fontMetrics().horizontalAdvance(QStringLiteral("000.00 s")));
    auto *neutralRow = new QHBoxLayout;
    neutralRow->addWidget(m_slider, 1);
    neutralRow->addWidget(m_spin);
    neutralRow->addWidget(m_neutralTime);
    m_slider->setToolTip(tr("The frame whose face is at rest: mouth closed, eyes open, looking ahead"));
    m_neutralNote->setObjectName(QStringLiteral("neutralNote"));
    // One line, its room kept: the rows below do not jump when the note comes.
    m_neutralNote->setMinimumHeight(m_neutralNote->fontMetrics().lineSpacing());
    // As wide as the dialog, never wider (the whole text is its tooltip too).
    m_neutralNote->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);

    m_method->setObjectName(QStringLiteral("method"));
    m_method->addItem(tr("Automatic"), int(DetectionMethod::Auto));
    m_method->addItem(tr("Landmarks"), int(DetectionMethod::Landmarks));
    m_method->addItem(tr("Classic (thesis ch. 6)"), int(DetectionMethod::Classic));
    m_snap->setObjectName(QStringLiteral("snapMouth"));
    m_continuous->setObjectName(QStringLiteral("continuousMouth"));
    auto *mouthBox = new QVBoxLayout;
    mouthBox->addWidget(m_continuous);
    mouthBox->addWidget(m_snap);
    m_useSound->setObjectName(QStringLiteral("useSound"));
    m_atPlayhead->setObjectName(QStringLiteral("atPlayhead"));
    m_atStart->setObjectName(QStringLiteral("atStart"));
    auto *placeBox = new QHBoxLayout;
    placeBox->addWidget(m_atStart);
    placeBox->addWidget(m_atPlayhead);
    placeBox->addStretch(1);
    m_usePhoto->setObjectName(QStringLiteral("usePhoto"));
    m_usePhoto->setVisible(!document->hasFace());
    m_usePhoto->setChecked(!document->hasFace() && document->photo().isNull());
    m_usePhoto->setToolTip(tr("The project has no face yet: the neutral frame becomes its photo, saved as a PNG "
                              "beside the clip"));

    // Each pair of choices is its own group (they share a parent).
    auto *mouthGroup = new QButtonGroup(this);
    mouthGroup->addButton(m_continuous);
    mouthGroup->addButton(m_snap);
    auto *placeGroup = new QButtonGroup(this);
    placeGroup->addButton(m_atStart);
    placeGroup->addButton(m_atPlayhead);
    m_continuous->setChecked(true);
    (playheadTime > 0 ? m_atPlayhead : m_atStart)->setChecked(true);

    auto *clipForm = new QFormLayout;
    clipForm->addRow(tr("&Clip:"), clipRow);
    clipForm->addRow(QString(), m_clipInfo);
    static_cast<QLabel *>(clipForm->labelForField(clipRow))->setBuddy(m_clip);
    auto *neutralLabel = new QLabel(tr("&Neutral frame:"), this);
    neutralLabel->setBuddy(m_slider);
    neutralRow->insertWidget(0, neutralLabel);
    auto *form = new QFormLayout;
    form->addRow(tr("&Method:"), m_method);
    form->addRow(tr("Mouth:"), mouthBox);
    auto *soundBox = new QVBoxLayout;
    soundBox->addWidget(m_useSound);
    soundBox->addWidget(m_replaceOverlap);
    soundBox->addWidget(m_soundNote);
    m_replaceOverlap->setObjectName(QStringLiteral("replaceOverlap"));
    m_replaceOverlap->setVisible(false);
    m_soundNote->setObjectName(QStringLiteral("soundNote"));
    m_soundNote->setVisible(false);
    // Wrapped (the recordings' names can be long), its two lines' room kept while shown: the
    // layout does not grow the dialog for a wrapped label's lines.
    m_soundNote->setWordWrap(true);
    m_soundNote->setMinimumHeight(2 * m_soundNote->fontMetrics().lineSpacing());
    form->addRow(tr("Sound:"), soundBox);
    form->addRow(tr("Starts:"), placeBox);
    if (!document->hasFace())
        form->addRow(tr("Photo:"), m_usePhoto);

    m_startButton = m_buttons->addButton(tr("&Import"), QDialogButtonBox::AcceptRole);
    m_startButton->setObjectName(QStringLiteral("start"));
    m_startButton->setDefault(true);
    m_cancelButton = m_buttons->addButton(QDialogButtonBox::Cancel);
    m_cancelButton->setObjectName(QStringLiteral("cancel"));

    auto *layout = new QVBoxLayout(this);
    layout->setSizeConstraint(QLayout::SetMinimumSize); // the frame never covers the rows below
    layout->addWidget(intro);
    layout->addLayout(clipForm);
    layout->addWidget(m_frame, 1);
    layout->addLayout(neutralRow);
    layout->addWidget(m_neutralNote);
    layout->addLayout(form);
    layout->addWidget(m_status);
    layout->addWidget(m_buttons);
    m_inputs = {m_clip, browseButton, m_slider, m_spin, m_method, m_snap, m_continuous, m_useSound, m_replaceOverlap,
        m_atPlayhead, m_atStart, m_usePhoto};
    connect(m_useSound, &QCheckBox::toggled, this, &ImportVideoDialog::updateSoundChoice);
    connect(m_atPlayhead, &QRadioButton::toggled, this, &ImportVideoDialog::updateSoundChoice);

    connect(m_buttons, &QDialogButtonBox::accepted, this, &ImportVideoDialog::start);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &ImportVideoDialog::reject);
    connect(browseButton, &QPushButton::clicked, this, &ImportVideoDialog::browse);
    connect(m_clip, &QLineEdit::editingFinished, this, [this] {
        const QString path = m_clip->text().trimmed();
        if (!path.isEmpty() && QFileInfo(path).absoluteFilePath() != m_decoder->path())
            openClip(path);
    });
    connect(m_slider, &QSlider::valueChanged, m_spin, &QSpinBox::setValue);
    connect(m_spin, &QSpinBox::valueChanged, m_slider, &QSlider::setValue);
    connect(m_spin, &QSpinBox::valueChanged, this, [this](int index) {
        if (!m_suggesting)
            m_neutralChosenByUser = true;
        updateNeutralLabel();
        m_decoder->request(index);
    });
    connect(m_decoder, &FrameDecoder::frameReady, this, &ImportVideoDialog::onFrameReady);
    connect(m_decoder, &FrameDecoder::failed, this, [this](int, const QString &error) {
        m_shownIndex = -1;
        m_frame->setText(error);
    });
    connect(m_task, &TrackTask::progress, this, [this](int done, int total) {
        const int count = total > 0 ? total : m_decoder->frameCount();
        m_status->showProgress(count > 0 ? double(done) / count : 0,
            count > 0 ? tr("Tracking frame %1 of %2").arg(done).arg(count) : tr("Tracking frame %1").arg(done));
    });
    connect(m_task, &TrackTask::finished, this, &ImportVideoDialog::onTracked);
    openClip(QString());
}

ImportVideoDialog::~ImportVideoDialog() = default;

bool ImportVideoDialog::openClip(const QString &path)
{
    m_status->clear();
    m_decoder->close();
    m_neutralSearch.drop();
    m_neutralChosenByUser = false;
    m_neutralNote->clear();
    const QSignalBlocker blockSlider(m_slider);
    const QSignalBlocker blockSpin(m_spin);
    m_slider->setRange(0, 0);
    m_spin->setRange(0, 0);
    m_clipInfo->clear();
    m_shownIndex = -1;
    bool ok = false;
    if (path.isEmpty()) {
        m_frame->setText(tr("Choose a clip"));
    } else {
        const QString absolute = QFileInfo(path).absoluteFilePath();
        if (m_clip->text().trimmed() != path)
            m_clip->setText(QDir::toNativeSeparators(absolute));
        QString error;
        ok = m_decoder->open(absolute, &error);
        if (!ok) {
            m_frame->setText(tr("No picture"));
            m_status->showError(error);
        } else {
            const int last = std::max(0, m_decoder->frameCount() - 1);
            m_slider->setRange(0, last);
            m_spin->setRange(0, last);
            const QSize size = m_decoder->frameSize();
            const QString frames = m_decoder->frameCount() > 0 ? tr("%n frame(s)", nullptr, m_decoder->frameCount())
                                                               : tr("frames not counted");
            m_clipInfo->setText(tr("%1 × %2, %3 at %4 fps, %5, %6")
                                    .arg(size.width())
                                    .arg(size.height())
                                    .arg(frames)
                                    .arg(m_decoder->frameRate(), 0, 'g', 4)
                                    .arg(seconds(m_decoder->duration()))
                                    .arg(m_decoder->hasAudio() ? tr("with sound") : tr("no sound")));
            m_frame->setText(tr("Decoding…"));
            m_decoder->request(0);
            // A frame at rest, looked for off the GUI thread while the user looks at frame 0.
            m_neutralNote->setText(tr("Looking for a frame at rest in the first seconds…"));
            const auto cancelFlag = m_neutralSearch.newCancelFlag();
            m_neutralSearch.watch(
                QtConcurrent::run([absolute, cancelFlag] { return chooseNeutralFrame(absolute, cancelFlag.get()); }),
                {}, [this](const QFuture<NeutralChoice> &done, bool cancelled) {
                    if (!cancelled && done.resultCount() > 0)
                        suggestNeutral(done.result());
                });
        }
    }
    m_useSound->setEnabled(ok && m_decoder->hasAudio());
    // A project that has a sound keeps it alone: both would play at once, which is seldom
    // wanted; the note below the box says so and the user may tick it.
    m_useSound->setChecked(ok && m_decoder->hasAudio() && m_document->timeline().audioClips().isEmpty());
    updateSoundChoice();
    updateNeutralLabel();
    updateButtons();
    return ok;
}

void ImportVideoDialog::suggestNeutral(const NeutralChoice &choice)
{
    if (!choice.found) {
        m_neutralNote->setText(tr("No face was found in the first seconds: choose a frame that shows one."));
        Q_EMIT neutralSuggested(-1);
        return;
    }
    const QString why = choice.silent ? tr("mouth closed, eyes open, in a silence") : tr("mouth closed, eyes open");
    if (m_neutralChosenByUser || m_task->isRunning()) {
        m_neutralNote->setText(tr("Frame %1 looks at rest (%2); your choice is kept.").arg(choice.frame).arg(why));
    } else {
        m_suggesting = true;
        m_spin->setValue(choice.frame);
        m_suggesting = false;
        m_neutralNote->setText(
            tr("Frame %1 was chosen: %2. Pick another if it is not at rest.").arg(choice.frame).arg(why));
    }
    m_neutralNote->setToolTip(m_neutralNote->text());
    Q_EMIT neutralSuggested(choice.frame);
}

void ImportVideoDialog::updateSoundChoice()
{
    const double start = m_atPlayhead->isChecked() ? m_playheadTime : 0.0;
    const double length = m_decoder->isOpen() ? std::max(m_decoder->duration(), 0.0) : 0.0;
    const Timeline &timeline = m_document->timeline();
    QStringList names;
    for (int i : audioClipsOverlapping(timeline, start, start + std::max(length, 1e-9)))
        names << QFileInfo(timeline.audioClips()[i].path).fileName();
    const bool overlap = m_useSound->isChecked() && m_useSound->isEnabled() && !names.isEmpty();
    m_replaceOverlap->setVisible(overlap);
    if (!overlap)
        m_replaceOverlap->setChecked(false);
    m_replaceOverlap->setText(
        tr("It plays over %1: &replace it (else both sound together)").arg(names.join(QStringLiteral(", "))));

    QStringList recordings;
    for (const AudioClip &clip : timeline.audioClips())
        recordings << QFileInfo(clip.path).fileName();
    recordings.removeDuplicates();
    const bool left = m_useSound->isEnabled() && !m_useSound->isChecked() && !recordings.isEmpty();
    m_soundNote->setText(left ? tr("Off: the project has a sound already (%1). Tick to add the clip's as well.")
                                    .arg(recordings.join(QStringLiteral(", ")))
                              : QString());
    m_soundNote->setToolTip(m_soundNote->text());
    m_soundNote->setVisible(left);
}

int ImportVideoDialog::neutralFrame() const
{
    return m_spin->value();
}

void ImportVideoDialog::setNeutralFrame(int index)
{
    m_spin->setValue(index);
}

QImage ImportVideoDialog::shownFrame() const
{
    return m_frame->image();
}

QString ImportVideoDialog::frameText() const
{
    return m_frame->text();
}

bool ImportVideoDialog::isRunning() const
{
    return m_task->isRunning();
}

QString ImportVideoDialog::message() const
{
    return m_status->message();
}

void ImportVideoDialog::browse()
{
    const QString current = m_clip->text().trimmed();
    const QString startDir = !current.isEmpty() ? QFileInfo(current).absolutePath()
        : !m_document->filePath().isEmpty()     ? QFileInfo(m_document->filePath()).absolutePath()
                                                : QString();
    const QString path = QFileDialog::getOpenFileName(this, tr("Import Video"), startDir,
        tr("Video (*.mp4 *.mov *.mkv *.webm *.avi *.mpg *.mpeg *.m4v *.gif);;All files (*)"));
    if (!path.isEmpty())
        openClip(path);
}

void ImportVideoDialog::onFrameReady(int index, const QImage &image)
{
    m_shownIndex = index;
    m_frame->setImage(image);
    m_frame->setCaption(tr("frame %1").arg(index));
    Q_EMIT frameShown(index);
}

void ImportVideoDialog::updateNeutralLabel()
{
    const double fps = m_decoder->frameRate();
    m_neutralTime->setText(fps > 0 ? seconds(m_spin->value() / fps) : QString());
}

void ImportVideoDialog::updateButtons()
{
    m_startButton->setEnabled(!m_task->isRunning() && m_decoder->isOpen());
}

void ImportVideoDialog::setRunning(bool running)
{
    for (QWidget *w : std::as_const(m_inputs))
        w->setEnabled(!running);
    if (!running)
        m_useSound->setEnabled(m_decoder->hasAudio());
    m_cancelButton->setEnabled(true);
    updateButtons();
}

void ImportVideoDialog::start()
{
    if (m_task->isRunning() || !m_decoder->isOpen())
        return;
    TrackVideoOptions options;
    options.neutralFrame = m_spin->value();
    options.tracker.method = DetectionMethod(m_method->currentData().toInt());
    options.tracker.snapMouth = m_snap->isChecked();
    options.tracker.shapes = m_document->mouthShapes();
    m_runPath = m_decoder->path();
    m_runOffset = m_atPlayhead->isChecked() ? m_playheadTime : 0.0;
    m_runSnap = m_snap->isChecked();
    m_runSound = m_useSound->isChecked() && m_decoder->hasAudio();
    m_runReplace = m_runSound && m_replaceOverlap->isVisible() && m_replaceOverlap->isChecked();
    m_runPhoto = !m_document->hasFace() && m_usePhoto->isChecked();
    m_status->showProgress(0, tr("Finding the face on frame %1").arg(options.neutralFrame));
    m_task->start(m_runPath, options);
    setRunning(true);
}

void ImportVideoDialog::cancel()
{
    if (!m_task->isRunning())
        return;
    m_task->cancel();
    m_cancelButton->setEnabled(false);
    m_status->showProgress(0, tr("Cancelling…"));
}

void ImportVideoDialog::reject()
{
    if (m_task->isRunning()) {
        cancel();
        return;
    }
    QDialog::reject();
}

void ImportVideoDialog::fail(const QString &message)
{
    m_status->showError(message + QLatin1Char('\n') + tr("Nothing was changed."));
    Q_EMIT failed(m_status->message());
}

void ImportVideoDialog::onTracked(const TrackResult &result)
{
    setRunning(false);
    if (result.status == TrackStatus::Cancelled) {
        m_status->showNote(tr("Cancelled: nothing was changed."));
        Q_EMIT cancelled();
        return;
    }
    if (result.status != TrackStatus::Ok) {
        fail(result.error);
        return;
    }
    if (result.frames.isEmpty()) {
        fail(tr("%1: no frame could be tracked").arg(m_runPath));
        return;
    }
    apply(result);
}

void ImportVideoDialog::apply(const TrackResult &result)
{
    if (m_runPhoto) {
        // A new project on the neutral frame: its face is the neutral frame's detection.
        const QString photoPath = neutralPhotoPath(m_runPath);
        if (!result.neutralImage.save(photoPath)) {
            fail(tr("%1: cannot write the neutral frame there").arg(photoPath));
            return;
        }
        Project project = m_document->project();
        project.photoPath = photoPath;
        project.face = result.neutral.face;
        m_document->reset(project, result.neutralImage, QString(), true);
    }
    const double fps = result.fps > 0 ? result.fps : m_decoder->frameRate();
    const double duration = m_decoder->duration() > 0 ? m_decoder->duration()
        : fps > 0                                     ? result.frames.size() / fps
                                                      : result.frames.last().time;
    Animation after = m_document->animation();
    // The sound goes where the motion does: the recordings it plays over stay (mixed with it)
    // unless the user chose to replace them (with their syllables and mouth keys).
    if (m_runSound && m_runReplace)
        after = removeAudioClips(after, audioClipsOverlapping(after.timeline, m_runOffset, m_runOffset + duration));
    RetargetOptions retarget;
    retarget.mouthKeysFromShapes = m_runSnap;
    addTrackToTimeline(result.frames, fps, &after.timeline, retarget, m_runOffset);
    const double end = m_runOffset + duration;
    const auto inClip = [&](double from, double to) { return to > m_runOffset && from < end; };
    if (!m_runSnap) {
        // The pose track moves the mouth where the clip plays: mouth keys there would fight it.
        QVector<MouthKey> mouth;
        for (const MouthKey &k : after.timeline.mouthKeys()) {
            if (!inClip(k.time, k.time + std::max(k.duration.value_or(0.0), 1e-9)))
                mouth.append(k);
        }
        after.timeline.setMouthKeys(mouth);
    }
    if (m_runSound) {
        AudioClip clip;
        clip.path = m_runPath;
        clip.offset = m_runOffset;
        clip.duration = duration;
        after.timeline.addAudioClip(clip);
    }
    after.timeline.setVideo(VideoClip {m_runPath, m_runOffset, duration, fps});
    m_document->changeAnimation(after, tr("Import Video %1").arg(QFileInfo(m_runPath).fileName()));
    m_status->clear();
    m_warnings = result.warnings;
    Q_EMIT applied();
    accept();
}

} // namespace toonface
