#include "capture/cameraframesource.h"

#include <QMetaObject>
#include <QVideoFrame>
#include <QVideoSink>

namespace toonface {

struct CameraFrameSource::Connection
{
    QMetaObject::Connection connection;
};

CameraFrameSource::CameraFrameSource(double nominalRate)
    : m_rate(nominalRate)
{
    m_clock.start();
}

CameraFrameSource::~CameraFrameSource()
{
    detach();
    stop();
}

void CameraFrameSource::attach(QVideoSink *sink)
{
    detach();
    m_connection = std::make_unique<Connection>();
    m_connection->connection = QObject::connect(
        sink, &QVideoSink::videoFrameChanged, sink, [this](const QVideoFrame &frame) { push(frame); },
        Qt::DirectConnection);
}

void CameraFrameSource::detach()
{
    if (m_connection)
        QObject::disconnect(m_connection->connection);
    m_connection.reset();
}

bool CameraFrameSource::push(const QVideoFrame &frame)
{
    if (!frame.isValid())
        return false;
    QImage image = frame.toImage();
    if (image.isNull())
        return false;
    if (image.format() != QImage::Format_RGB32)
        image = std::move(image).convertToFormat(QImage::Format_RGB32);
    push(std::move(image));
    return true;
}

void CameraFrameSource::push(QImage image, double time)
{
    if (image.isNull())
        return;
    if (image.format() != QImage::Format_RGB32)
        image = std::move(image).convertToFormat(QImage::Format_RGB32);
    const double arrival = now();
    {
        std::lock_guard lock(m_lock);
        if (m_stopped)
            return;
        if (m_pending)
            ++m_replaced;
        m_size = image.size();
        m_pending = VideoFrame {std::move(image), time >= 0 ? time : arrival, m_pushed};
        m_pendingArrival = arrival;
        ++m_pushed;
    }
    m_arrived.notify_one();
}

std::optional<VideoFrame> CameraFrameSource::next()
{
    std::unique_lock lock(m_lock);
    m_arrived.wait(lock, [this] { return m_stopped || m_pending.has_value(); });
    if (m_stopped)
        return std::nullopt;
    std::optional<VideoFrame> out = std::move(m_pending);
    m_pending.reset();
    m_lastArrival = m_pendingArrival;
    return out;
}

QSize CameraFrameSource::frameSize() const
{
    std::lock_guard lock(m_lock);
    return m_size;
}

QString CameraFrameSource::error() const
{
    std::lock_guard lock(m_lock);
    return m_error;
}

void CameraFrameSource::stop()
{
    {
        std::lock_guard lock(m_lock);
        m_stopped = true;
        m_pending.reset();
    }
    m_arrived.notify_all();
}

void CameraFrameSource::fail(const QString &message)
{
    {
        std::lock_guard lock(m_lock);
        m_error = message;
    }
    stop();
}

double CameraFrameSource::now() const
{
    return m_clock.nsecsElapsed() / 1e9;
}

double CameraFrameSource::lastArrival() const
{
    std::lock_guard lock(m_lock);
    return m_lastArrival;
}

int CameraFrameSource::pushedFrames() const
{
    std::lock_guard lock(m_lock);
    return m_pushed;
}

int CameraFrameSource::replacedFrames() const
{
    std::lock_guard lock(m_lock);
    return m_replaced;
}

} // namespace toonface
