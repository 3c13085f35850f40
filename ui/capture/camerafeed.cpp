#include "capture/camerafeed.h"

#include <QCamera>
#include <QCameraDevice>
#include <QMediaCaptureSession>
#include <QMediaDevices>
#include <QVideoSink>

#include <algorithm>

namespace toonface {

CameraFeed::CameraFeed(QObject *parent)
    : QObject(parent)
    , m_devices(new QMediaDevices(this))
    , m_sink(new QVideoSink(this))
{
    connect(m_devices, &QMediaDevices::videoInputsChanged, this, &CameraFeed::onInputsChanged);
    connect(m_sink, &QVideoSink::videoFrameChanged, this, &CameraFeed::frame, Qt::DirectConnection);
}

CameraFeed::~CameraFeed()
{
    stop();
}

QStringList CameraFeed::cameras()
{
    const QList<QCameraDevice> inputs = QMediaDevices::videoInputs();
    const QCameraDevice preferred = QMediaDevices::defaultVideoInput();
    QStringList out;
    for (const QCameraDevice &d : inputs) {
        if (d.id() == preferred.id())
            out.prepend(d.description());
        else
            out.append(d.description());
    }
    return out;
}

QString CameraFeed::noCameraMessage()
{
    return tr("No camera was found on this computer. Connect a camera and try again, or open a "
              "photo (File ▸ Open) or a video instead.");
}

bool CameraFeed::start(const QString &description, QString *error)
{
    stop();
    const QList<QCameraDevice> inputs = QMediaDevices::videoInputs();
    if (inputs.isEmpty()) {
        if (error)
            *error = noCameraMessage();
        return false;
    }
    QCameraDevice device = QMediaDevices::defaultVideoInput();
    for (const QCameraDevice &d : inputs) {
        if (d.description() == description) {
            device = d;
            break;
        }
    }
    if (device.isNull())
        device = inputs.first();
    m_camera = new QCamera(device, this);
    m_session = new QMediaCaptureSession(this);
    m_session->setCamera(m_camera);
    m_session->setVideoSink(m_sink);
    m_id = device.id();
    m_description = device.description();
    connect(m_camera, &QCamera::errorOccurred, this, [this](QCamera::Error, const QString &text) {
        fail(tr("The camera “%1” stopped: %2").arg(m_description, text));
    });
    m_camera->start();
    return true;
}

void CameraFeed::stop()
{
    if (m_camera) {
        m_camera->disconnect(this);
        m_camera->stop();
    }
    if (m_session) {
        m_session->setVideoSink(nullptr);
        m_session->setCamera(nullptr);
        m_session->deleteLater();
    }
    if (m_camera)
        m_camera->deleteLater();
    m_session = nullptr;
    m_camera = nullptr;
    m_id.clear();
    m_description.clear();
}

void CameraFeed::onInputsChanged()
{
    Q_EMIT camerasChanged();
    if (!m_camera)
        return;
    const QList<QCameraDevice> inputs = QMediaDevices::videoInputs();
    const bool present
        = std::any_of(inputs.cbegin(), inputs.cend(), [this](const QCameraDevice &d) { return d.id() == m_id; });
    if (!present)
        fail(tr("The camera “%1” was disconnected.").arg(m_description));
}

void CameraFeed::fail(const QString &message)
{
    stop();
    Q_EMIT failed(message);
}

} // namespace toonface
