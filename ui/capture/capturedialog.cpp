#include "capture/capturedialog.h"

#include "capture/camerafeed.h"
#include "capture/framepane.h"
#include "detect/facescan.h"
#include "document/companionfile.h"
#include "document/document.h"
#include "window/settings.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QStandardPaths>
#include <QTimer>
#include <QVBoxLayout>
#include <QVideoFrame>
#include <QVideoSink>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>

namespace toonface {

namespace {

// Faces are looked for on a copy this wide: fast enough to follow a camera.
constexpr int kScanWidth = 320;

QRectF largestFace(const QImage &image)
{
    if (image.isNull())
        return {};
    const double scale = image.width() > kScanWidth ? double(kScanWidth) / image.width() : 1.0;
    const QImage gray = image.scaledToWidth(int(image.width() * scale), Qt::SmoothTransformation)
                            .convertToFormat(QImage::Format_Grayscale8);
    const std::vector<FaceBox> faces = scanFaces(gray, 0);
    QRectF best;
    for (const FaceBox &f : faces) {
        if (f.box.width() * f.box.height() > best.width() * best.height())
            best = f.box;
    }
    return best.isEmpty() ? QRectF() : QRectF(best.topLeft() / scale, best.size() / scale);
}

} // namespace

QString CaptureDialog::run(QWidget *parent, Document *document)
{
    CaptureDialog dialog(document, parent);
    return dialog.exec() == QDialog::Accepted ? dialog.savedPath() : QString();
}

CaptureDialog::CaptureDialog(Document *document, QWidget *parent)
    : QDialog(parent)
    , m_document(document)
    , m_feed(new CameraFeed(this))
    , m_cameras(new QComboBox(this))
    , m_view(new FramePane(this))
    , m_message(new QLabel(this))
    , m_take(new QPushButton(tr("&Take Photo in 3 s"), this))
    , m_countdown(new QTimer(this))
{
    setWindowTitle(tr("Capture from Camera"));
    m_view->setMinimumSize(480, 360);
    m_view->setMirrored(true);
    m_message->setWordWrap(true);
    m_take->setDefault(true);
    m_take->setToolTip(tr("Look straight at the camera with a relaxed face, mouth closed: the photo becomes the "
                          "neutral face"));

    auto *top = new QHBoxLayout;
    top->addWidget(new QLabel(tr("&Camera:"), this));
    top->addWidget(m_cameras, 1);
    qobject_cast<QLabel *>(top->itemAt(0)->widget())->setBuddy(m_cameras);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    buttons->addButton(m_take, QDialogButtonBox::ActionRole);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(m_view, 1);
    layout->addWidget(m_message);
    layout->addWidget(buttons);

    m_countdown->setInterval(1000);
    connect(m_countdown, &QTimer::timeout, this, &CaptureDialog::tick);
    connect(m_take, &QPushButton::clicked, this, [this] { takePhoto(3); });
    connect(m_cameras, &QComboBox::activated, this, &CaptureDialog::startCamera);
    // Latest frame wins: the sink's thread posts one call at a time, which takes the sink's newest.
    connect(
        m_feed, &CameraFeed::frame, this,
        [this](const QVideoFrame &) {
            if (!m_framePending.exchange(true)) {
                QMetaObject::invokeMethod(
                    this,
                    [this] {
                        m_framePending = false;
                        if (m_feed->sink())
                            onVideoFrame(m_feed->sink()->videoFrame());
                    },
                    Qt::QueuedConnection);
            }
        },
        Qt::DirectConnection);
    connect(m_feed, &CameraFeed::failed, this, [this](const QString &text) {
        m_countdown->stop();
        m_view->setCaption(tr("No camera"));
        m_take->setEnabled(false);
        setMessage(text);
        fillCameras();
    });
    connect(m_feed, &CameraFeed::camerasChanged, this, [this] {
        if (!m_feed->isActive())
            fillCameras();
    });
    connect(&m_scan, &QFutureWatcher<QRectF>::finished, this, [this] {
        m_box = m_scan.future().resultCount() > 0 ? m_scan.result() : QRectF();
        m_view->setBox(m_box);
        setMessage(m_box.isEmpty() ? tr("No face in view yet.") : tr("Face found: keep still and take the photo."));
    });

    fillCameras();
    startCamera();
}

CaptureDialog::~CaptureDialog()
{
    m_feed->stop();
    m_scan.waitForFinished();
}

void CaptureDialog::fillCameras()
{
    m_cameras->clear();
    const QStringList cameras = CameraFeed::cameras();
    m_cameras->addItems(cameras);
    const int remembered = m_cameras->findText(Settings().cameraDescription());
    if (remembered >= 0)
        m_cameras->setCurrentIndex(remembered);
    m_cameras->setEnabled(!cameras.isEmpty());
}

bool CaptureDialog::hasCamera() const
{
    return m_feed->isActive();
}

void CaptureDialog::startCamera()
{
    QString error;
    if (!m_feed->start(m_cameras->currentText(), &error)) {
        m_view->setCaption(tr("No camera"));
        m_take->setEnabled(false);
        setMessage(error);
        return;
    }
    Settings().setCameraDescription(m_feed->description());
    m_view->setCaption(tr("Starting the camera…"));
    m_take->setEnabled(true);
    setMessage(tr("Camera “%1”").arg(m_feed->description()));
}

void CaptureDialog::onVideoFrame(const QVideoFrame &frame)
{
    if (!m_feed->isActive())
        return;
    const QImage image = frame.toImage();
    if (!image.isNull())
        showFrame(image);
}

void CaptureDialog::showFrame(const QImage &image)
{
    m_latest = image;
    m_view->setImage(image);
    if (!m_countdown->isActive())
        m_view->setCaption(QString());
    m_take->setEnabled(true);
    scanForFace();
}

void CaptureDialog::scanForFace()
{
    if (m_scan.isRunning() || m_latest.isNull())
        return;
    m_scan.setFuture(QtConcurrent::run(&largestFace, m_latest));
}

void CaptureDialog::takePhoto(int seconds)
{
    if (m_latest.isNull()) {
        setMessage(hasCamera() ? tr("The camera has not shown a picture yet.") : CameraFeed::noCameraMessage());
        return;
    }
    m_remaining = std::max(0, seconds);
    if (m_remaining == 0) {
        snapshot();
        return;
    }
    m_take->setEnabled(false);
    m_view->setCaption(QString::number(m_remaining));
    m_countdown->start();
}

void CaptureDialog::tick()
{
    if (--m_remaining > 0) {
        m_view->setCaption(QString::number(m_remaining));
        return;
    }
    m_countdown->stop();
    m_view->setCaption(QString());
    snapshot();
}

void CaptureDialog::snapshot()
{
    const QImage photo = m_latest.convertToFormat(QImage::Format_RGB32);
    const QString path = companionFile(*m_document, QStringLiteral("camera"), QStringLiteral("png"),
        QStandardPaths::writableLocation(QStandardPaths::PicturesLocation));
    if (!photo.save(path, "PNG")) {
        setMessage(tr("%1: the photo cannot be written").arg(QDir::toNativeSeparators(path)));
        m_take->setEnabled(true);
        return;
    }
    m_saved = path;
    m_feed->stop();
    Q_EMIT photoTaken(path, photo);
    accept();
}

QString CaptureDialog::messageText() const
{
    return m_message->text();
}

void CaptureDialog::setMessage(const QString &text)
{
    m_message->setText(text);
}

} // namespace toonface
