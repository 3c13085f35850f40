#include "capture/livewindow.h"

#include "capture/camerafeed.h"
#include "capture/cameraframesource.h"
#include "capture/framepane.h"
#include "capture/livesession.h"
#include "capture/livetake.h"
#include "capture/microphone.h"
#include "document/companionfile.h"
#include "document/document.h"
#include "i18n/coretext.h"
#include "media/mediareader.h"
#include "playback/playhead.h"
#include "track/clocksource.h"
#include "track/videofilesource.h"
#include "window/settings.h"

#include <QCheckBox>
#include <QCloseEvent>
#include <QComboBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QStandardPaths>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>

namespace toonface {

namespace {

constexpr int kClipItem = -1; // the source box's "Video file…" entry
constexpr int kMicrophoneItem = -2; // its "Microphone only" entry
constexpr double kHeardOnlyFps = 30; // the cartoon's rate when the performer is only heard

double percentile(QVector<double> values, double p)
{
    if (values.isEmpty())
        return 0;
    std::sort(values.begin(), values.end());
    return values[std::min(values.size() - 1, qsizetype(p * double(values.size() - 1) + 0.5))];
}

// The face's box in the frame: the tracked points' bounds.
QRectF faceBox(const LiveFrame &frame)
{
    if (!frame.hasTrack || frame.tracked.lost)
        return {};
    QRectF box;
    for (const QPointF &p : frame.tracked.points) {
        if (!p.isNull())
            box = box.isNull() ? QRectF(p, QSizeF(1, 1)) : box.united(QRectF(p, QSizeF(1, 1)));
    }
    return box.adjusted(-box.width() * 0.08, -box.height() * 0.08, box.width() * 0.08, box.height() * 0.08);
}

} // namespace

QRect LiveWindow::placement(const QRect &mainFrame, QSize wanted, const QRect &available)
{
    const QSize size = wanted.boundedTo(available.size());
    const auto clampY = [&](int y) { return std::clamp(y, available.top(), available.bottom() + 1 - size.height()); };
    if (available.right() - mainFrame.right() >= size.width())
        return QRect(QPoint(mainFrame.right() + 1, clampY(mainFrame.top())), size);
    if (mainFrame.left() - available.left() >= size.width())
        return QRect(QPoint(mainFrame.left() - size.width(), clampY(mainFrame.top())), size);
    return QRect(QPoint(available.right() + 1 - size.width(), clampY(mainFrame.top())), size);
}

LiveWindow::LiveWindow(Document *document, Playhead *playhead, QWidget *parent)
    : QWidget(parent, Qt::Window)
    , m_document(document)
    , m_playhead(playhead)
    , m_session(new LiveSession(document, this))
    , m_feed(new CameraFeed(this))
    , m_microphone(new Microphone(this))
    , m_cartoon(new FramePane(this))
    , m_source(new FramePane(this))
    , m_sources(new QComboBox(this))
    , m_mouth(new QComboBox(this))
    , m_loop(new QCheckBox(tr("&Loop clip"), this))
    , m_restPose(new QPushButton(tr("Set &Rest Pose"), this))
    , m_record(new QPushButton(tr("● &Record"), this))
    , m_figures(new QLabel(this))
    , m_status(new QLabel(this))
    , m_figuresTimer(new QTimer(this))
{
    setWindowTitle(tr("Live Mode — Toonface"));
    setObjectName(QStringLiteral("liveWindow"));

    // Said of the picture, whatever shows it (a camera, a video file, a clock): not "camera".
    m_mouth->setObjectName(QStringLiteral("liveMouth"));
    m_mouth->addItem(tr("Mouth from the lips in the picture"), int(LiveMouth::Camera));
    m_mouth->addItem(tr("Mouth from microphone"), int(LiveMouth::Microphone));
    m_mouth->addItem(tr("Lips in the picture, microphone when they are lost"), int(LiveMouth::Both));
    m_mouth->setToolTip(tr("What drives the cartoon's mouth: the lips the source shows, the loudness and colour of the "
                           "voice, or both"));
    m_loop->setChecked(true);
    m_restPose->setToolTip(tr("Take the current frame as the performer's neutral face"));
    m_record->setCheckable(true);
    m_record->setToolTip(tr("Record the performance onto the timeline at the playhead"));
    m_record->setStyleSheet(QStringLiteral("QPushButton:checked { background: #c62828; color: white; }"));
    m_source->setFixedSize(260, 200);
    m_source->setMirrored(false);
    m_cartoon->setMinimumSize(360, 360);
    m_figures->setWordWrap(true);
    m_figures->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    m_status->setWordWrap(true);

    auto *controls = new QHBoxLayout;
    controls->addWidget(new QLabel(tr("Source:"), this));
    controls->addWidget(m_sources, 1);
    controls->addWidget(m_loop);
    controls->addSpacing(12);
    controls->addWidget(m_mouth);
    controls->addStretch();
    controls->addWidget(m_restPose);
    controls->addWidget(m_record);

    auto *side = new QVBoxLayout;
    side->addWidget(new QLabel(tr("<b>Performer</b>"), this));
    side->addWidget(m_source);
    side->addWidget(m_figures, 1);

    auto *middle = new QHBoxLayout;
    middle->addWidget(m_cartoon, 1);
    middle->addLayout(side);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(controls);
    layout->addLayout(middle, 1);
    layout->addWidget(m_status);
    resize(960, 640);

    fillSources();
    connect(m_sources, &QComboBox::activated, this, &LiveWindow::onSourceChosen);
    connect(m_mouth, &QComboBox::currentIndexChanged, this, &LiveWindow::applyMouthMode);
    connect(m_restPose, &QPushButton::clicked, this, [this] {
        m_session->setRestPose();
        setStatus(tr("The next frame becomes the rest pose…"));
    });
    connect(m_record, &QPushButton::toggled, this, &LiveWindow::toggleRecording);
    connect(m_session, &LiveSession::frameReady, this, &LiveWindow::onFrame);
    connect(m_session, &LiveSession::status, this, &LiveWindow::setStatus);
    connect(m_session, &LiveSession::finished, this, &LiveWindow::onFinished);
    connect(m_feed, &CameraFeed::failed, this, [this](const QString &text) {
        m_session->stop();
        if (m_record->isChecked())
            m_record->setChecked(false);
        setStatus(text);
    });
    connect(m_feed, &CameraFeed::camerasChanged, this, &LiveWindow::fillSources);
    connect(m_microphone, &Microphone::samples, this,
        [this](const QVector<float> &mono, int rate) { m_session->pushAudio(mono.constData(), mono.size(), rate); });
    connect(m_microphone, &Microphone::failed, this, &LiveWindow::setStatus);
    connect(m_figuresTimer, &QTimer::timeout, this, &LiveWindow::updateFigures);
    m_figuresTimer->start(500);
    m_session->setImageSize(m_cartoon->size() * devicePixelRatioF());

    m_cartoon->setCaption(m_document->hasFace() ? QString()
                                                : tr("Open a photo with a face first: the cartoon of that face "
                                                     "follows the performer."));
    if (CameraFeed::cameras().isEmpty())
        m_source->setCaption(tr("No camera"));
    m_restPose->setEnabled(false);
    m_record->setEnabled(false);
    setStatus(CameraFeed::cameras().isEmpty() ? joinSentences(CameraFeed::noCameraMessage(),
                  tr("Choose “Video file…” to perform from a clip, or “Microphone only” to speak for the cartoon."))
                                              : tr("Choose a camera, a video file, or the microphone only."));
}

LiveWindow::~LiveWindow()
{
    m_feed->stop();
    m_microphone->stop();
    m_session->stop();
}

void LiveWindow::fillSources()
{
    const QString current = m_sources->currentText();
    m_sources->clear();
    const QStringList cameras = CameraFeed::cameras();
    for (const QString &camera : cameras)
        m_sources->addItem(tr("Camera: %1").arg(camera), camera);
    m_sources->addItem(tr("Video file…"), kClipItem);
    m_sources->addItem(tr("Microphone only (no camera)"), kMicrophoneItem);
    const int again = m_sources->findText(current);
    if (again >= 0)
        m_sources->setCurrentIndex(again);
    else if (!cameras.isEmpty())
        m_sources->setCurrentIndex(std::max(0, m_sources->findData(Settings().cameraDescription())));
}

void LiveWindow::onSourceChosen(int index)
{
    const QVariant data = m_sources->itemData(index);
    if (data.typeId() == QMetaType::Int && data.toInt() == kMicrophoneItem) {
        startMicrophoneOnly();
        return;
    }
    if (data.typeId() == QMetaType::Int && data.toInt() == kClipItem) {
        const QString path = QFileDialog::getOpenFileName(this, tr("Perform from a Video"), Settings().lastDirectory(),
            tr("Videos (*.mp4 *.mov *.mkv *.avi *.mpg *.mpeg *.webm);;All files (*)"));
        if (!path.isEmpty())
            startClip(path);
        return;
    }
    startCamera(m_sources->itemData(index).toString());
}

bool LiveWindow::startCamera(const QString &description)
{
    stopSource();
    QString error;
    if (!m_feed->start(description, &error)) {
        m_source->setCaption(tr("No camera"));
        setStatus(error);
        return false;
    }
    Settings().setCameraDescription(m_feed->description());
    auto source = std::make_unique<CameraFrameSource>();
    source->attach(m_feed->sink());
    m_clip.clear();
    m_session->start(std::move(source));
    m_source->setCaption(QString());
    m_restPose->setEnabled(true);
    m_mouth->show();
    m_record->setEnabled(m_document->hasFace());
    setStatus(tr("Camera “%1”: look straight at it with a relaxed face").arg(m_feed->description()));
    applyMouthMode();
    return true;
}

bool LiveWindow::startClip(const QString &path)
{
    stopSource();
    auto source = std::make_unique<VideoFileSource>();
    VideoFileSource::Options options;
    options.paced = true;
    QString error;
    if (!source->open(path, options, &error)) {
        setStatus(error);
        return false;
    }
    Audio sound;
    if (source->hasAudio()) {
        QString soundError;
        if (std::optional<QVector<float>> samples = readAudio(path, kSpeechSampleRate, &soundError))
            sound = Audio {std::move(*samples), kSpeechSampleRate};
    }
    const bool same = path == m_clip;
    m_clip = path;
    m_clipHasSound = !sound.isEmpty();
    m_session->start(std::move(source), std::move(sound), same);
    m_source->setCaption(QString());
    m_restPose->setEnabled(true);
    m_mouth->show();
    m_record->setEnabled(m_document->hasFace());
    const int item = m_sources->findData(kClipItem);
    m_sources->setItemText(item, tr("Video file: %1").arg(QFileInfo(path).fileName()));
    m_sources->setCurrentIndex(item);
    if (!same)
        setStatus(tr("Playing %1 as the performer").arg(QFileInfo(path).fileName()));
    applyMouthMode();
    return true;
}

bool LiveWindow::startMicrophoneOnly()
{
    stopSource();
    QString error;
    if (!m_microphone->isActive() && !m_microphone->start(&error)) {
        setStatus(error);
        return false;
    }
    m_clip.clear();
    // No picture: the cartoon rests and the voice moves its mouth, at a camera's rate.
    m_session->start(std::make_unique<ClockSource>(kHeardOnlyFps));
    m_source->setBox({});
    m_source->setImage({});
    m_source->setCaption(tr("Microphone “%1”").arg(m_microphone->description()));
    m_restPose->setEnabled(false);
    m_mouth->hide(); // the microphone is all there is
    m_record->setEnabled(m_document->hasFace());
    m_sources->setCurrentIndex(m_sources->findData(kMicrophoneItem));
    setStatus(tr("Listening to “%1”: speak, and the cartoon speaks with you").arg(m_microphone->description()));
    return true;
}

void LiveWindow::stopSource()
{
    if (m_record->isChecked())
        m_record->setChecked(false); // commits the take
    m_feed->stop();
    m_session->stop();
}

void LiveWindow::setMouthMode(LiveMouth mode)
{
    m_mouth->setCurrentIndex(m_mouth->findData(int(mode)));
    applyMouthMode();
}

void LiveWindow::setLooping(bool loop)
{
    m_loop->setChecked(loop);
}

void LiveWindow::applyMouthMode()
{
    LiveMouth mode = LiveMouth(m_mouth->currentData().toInt());
    if (mode != LiveMouth::Camera) {
        if (!m_clip.isEmpty()) {
            if (!m_clipHasSound) {
                setStatus(tr("The clip has no sound: the mouth follows the camera."));
                mode = LiveMouth::Camera;
            }
        } else if (!m_microphone->isActive()) {
            QString error;
            if (!m_microphone->start(&error)) {
                setStatus(joinSentences(error, tr("The mouth follows the camera.")));
                mode = LiveMouth::Camera;
            }
        }
    }
    m_session->setMouthMode(mode);
}

void LiveWindow::onFrame()
{
    const LiveFrame &frame = m_session->current();
    if (!frame.cartoon.isNull()) {
        m_cartoon->setCaption(QString());
        m_cartoon->setImage(frame.cartoon);
    }
    m_source->setImage(frame.source);
    m_source->setBox(faceBox(frame));
}

void LiveWindow::onFinished(const QString &error)
{
    if (!error.isEmpty()) {
        if (m_record->isChecked())
            m_record->setChecked(false);
        setStatus(error);
        return;
    }
    if (m_clip.isEmpty())
        return;
    if (m_record->isChecked()) {
        // A take ends with its clip.
        m_record->setChecked(false);
        return;
    }
    if (m_loop->isChecked())
        startClip(m_clip);
}

void LiveWindow::toggleRecording(bool on)
{
    if (on) {
        if (!m_session->isRunning() || !m_document->hasFace()) {
            QSignalBlocker block(m_record);
            m_record->setChecked(false);
            setStatus(tr("Start a camera, a clip or the microphone, with a face open, before recording."));
            return;
        }
        if (m_clip.isEmpty() && !m_microphone->isActive()) {
            QString error;
            if (!m_microphone->start(&error))
                setStatus(error);
        }
        m_recordAt = m_playhead ? m_playhead->time() : 0.0;
        m_session->startRecording();
        m_record->setText(tr("■ &Stop"));
        if (m_clip.isEmpty() && !m_microphone->isActive())
            setStatus(tr("Recording: motion only (no microphone)"));
        else
            setStatus(tr("Recording…"));
        return;
    }
    m_record->setText(tr("● &Record"));
    finishRecording();
}

void LiveWindow::finishRecording()
{
    if (!m_session->isRecording())
        return;
    const LiveTake take = m_session->stopRecording();
    const QString audioPath = take.audio.isEmpty()
        ? QString()
        : companionFile(*m_document, QStringLiteral("take"), QStringLiteral("wav"),
            QStandardPaths::writableLocation(QStandardPaths::MusicLocation));
    QString text;
    commitTake(m_document, take, m_recordAt, audioPath, &text);
    setStatus(text);
    Q_EMIT message(text);
}

void LiveWindow::updateFigures()
{
    m_figures->setText(figuresText());
}

QString LiveWindow::figuresText() const
{
    const LiveFigures f = m_session->figures();
    if (f.delivered == 0)
        return tr("No frames yet.");
    return tr("Frames shown: %1 of %2\nLatency to the picture: %3 ms (95 %: %4 ms)\nFace lost in %5 frames%6")
        .arg(f.shown)
        .arg(f.delivered)
        .arg(percentile(f.readyMs, 0.5), 0, 'f', 0)
        .arg(percentile(f.readyMs, 0.95), 0, 'f', 0)
        .arg(f.lost)
        .arg(m_session->isRecording() ? tr("\n● Recording") : QString());
}

QString LiveWindow::statusText() const
{
    return m_status->text();
}

void LiveWindow::setStatus(const QString &text)
{
    m_status->setText(text);
}

void LiveWindow::closeEvent(QCloseEvent *event)
{
    stopSource();
    m_microphone->stop();
    QWidget::closeEvent(event);
    Q_EMIT closed();
}

void LiveWindow::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    m_session->setImageSize(m_cartoon->size() * devicePixelRatioF());
    // Until a source drives it, the cartoon waits at rest (drawn once the window has its size).
    if (!m_session->isRunning())
        m_cartoon->setImage(m_session->restCartoon());
}

} // namespace toonface
