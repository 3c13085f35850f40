#pragma once

#include <QByteArray>
#include <QObject>
#include <QString>
#include <QStringList>

class QCamera;
class QMediaCaptureSession;
class QMediaDevices;
class QVideoFrame;
class QVideoSink;

namespace toonface {

// A camera through QtMultimedia (QCamera -> QMediaCaptureSession -> QVideoSink), chosen by its
// description: Qt 6.4's device ids are not stable from one run to the next, so the editor
// remembers descriptions. No QCamera is made unless a camera is present (Qt 6.4 shows a test
// pattern for a camera with no device). A camera that goes away (unplugged: the device list
// changes; or a camera error) stops the feed and says so in failed(); nothing crashes.
//
// GUI thread. frame() is emitted on the sink's thread: connect it with a direct connection
// to something thread-safe (CameraFrameSource), or queued.
class CameraFeed : public QObject
{
    Q_OBJECT

public:
    explicit CameraFeed(QObject *parent = nullptr);
    ~CameraFeed() override;

    // The cameras present, by description, the default one first.
    static QStringList cameras();
    // What the editor says when there is none.
    static QString noCameraMessage();

    // Starts the camera described `description` (empty or absent: the default one). False with
    // *error when no camera is present.
    bool start(const QString &description, QString *error);
    void stop();
    bool isActive() const { return m_camera != nullptr; }
    // The running camera's description; empty when stopped.
    QString description() const { return m_description; }
    QVideoSink *sink() const { return m_sink; }

Q_SIGNALS:
    void frame(const QVideoFrame &frame);
    // The camera stopped by itself: unplugged, or an error; `message` says which, for the user.
    void failed(const QString &message);
    // Cameras were plugged in or out.
    void camerasChanged();

private:
    void onInputsChanged();
    void fail(const QString &message);

    QMediaDevices *m_devices;
    QVideoSink *m_sink;
    // Children; a camera stopping on its own signal is deleted later, not inside its emission.
    QMediaCaptureSession *m_session = nullptr;
    QCamera *m_camera = nullptr;
    QByteArray m_id;
    QString m_description;
};

} // namespace toonface
