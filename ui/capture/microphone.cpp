#include "capture/microphone.h"

#include "speech/audio.h"

#include <QAudioDevice>
#include <QAudioSource>
#include <QMediaDevices>
#include <QTimer>

#include <algorithm>
#include <cstring>

namespace toonface {

Microphone::Microphone(QObject *parent)
    : QObject(parent)
    , m_devices(new QMediaDevices(this))
    , m_watch(new QTimer(this))
{
    connect(m_devices, &QMediaDevices::audioInputsChanged, this, &Microphone::checkStillThere);
    m_watch->setInterval(500);
    connect(m_watch, &QTimer::timeout, this, &Microphone::checkStillThere);
}

Microphone::~Microphone()
{
    stop();
}

bool Microphone::isPresent()
{
    return !QMediaDevices::audioInputs().isEmpty();
}

QString Microphone::noMicrophoneMessage()
{
    return tr("No microphone was found: the sound cannot drive the mouth, and recordings keep the motion only.");
}

bool Microphone::start(QString *error)
{
    stop();
    const QAudioDevice device = QMediaDevices::defaultAudioInput();
    if (device.isNull() || !isPresent()) {
        if (error)
            *error = noMicrophoneMessage();
        return false;
    }
    QAudioFormat format;
    format.setSampleRate(kSpeechSampleRate);
    format.setChannelCount(1);
    format.setSampleFormat(QAudioFormat::Float);
    if (!device.isFormatSupported(format))
        format = device.preferredFormat();
    m_format = format;
    m_input = device;
    m_source = new QAudioSource(device, format, this);
    m_device = m_source->start();
    if (!m_device || m_source->error() != QAudio::NoError) {
        if (error)
            *error = tr("The microphone “%1” cannot be opened.").arg(device.description());
        stop();
        return false;
    }
    connect(m_device, &QIODevice::readyRead, this, &Microphone::read);
    m_sinceData.start();
    m_watch->start();
    connect(m_source, &QAudioSource::stateChanged, this, [this, name = device.description()](QAudio::State state) {
        // Not from inside the source's own signal: stop() deletes the source.
        if (state == QAudio::StoppedState && m_source && m_source->error() != QAudio::NoError)
            QMetaObject::invokeMethod(
                this,
                [this, name, source = m_source] {
                    if (m_source == source)
                        fail(name);
                },
                Qt::QueuedConnection);
    });
    return true;
}

void Microphone::stop()
{
    m_watch->stop();
    if (!m_source)
        return;
    m_source->disconnect(this);
    if (m_device)
        m_device->disconnect(this);
    m_source->stop();
    // At once: Qt 6.4's PulseAudio source crashes when deleted later, after its device went away.
    delete m_source;
    m_source = nullptr;
    m_device = nullptr;
}

void Microphone::fail(const QString &description)
{
    stop();
    Q_EMIT failed(tr("The microphone “%1” stopped.").arg(description));
}

void Microphone::checkStillThere()
{
    if (!m_source)
        return;
    const QList<QAudioDevice> inputs = QMediaDevices::audioInputs();
    if (std::none_of(inputs.begin(), inputs.end(), [&](const QAudioDevice &d) { return d.id() == m_input.id(); })
        || m_sinceData.elapsed() > 3000)
        fail(m_input.description());
}

void Microphone::read()
{
    if (!m_device)
        return;
    const QByteArray data = m_device->readAll();
    if (data.isEmpty())
        return;
    m_sinceData.start();
    const QVector<float> mono = toMono(data, m_format);
    if (!mono.isEmpty())
        Q_EMIT samples(mono, m_format.sampleRate());
}

QVector<float> Microphone::toMono(const QByteArray &data, const QAudioFormat &format)
{
    const int channels = std::max(1, format.channelCount());
    const int bytes = format.bytesPerSample();
    if (bytes <= 0)
        return {};
    const qsizetype frames = data.size() / (qsizetype(bytes) * channels);
    QVector<float> out(frames);
    const char *p = data.constData();
    for (qsizetype i = 0; i < frames; ++i) {
        double sum = 0;
        for (int c = 0; c < channels; ++c, p += bytes)
            sum += format.normalizedSampleValue(p);
        out[i] = float(sum / channels);
    }
    return out;
}

} // namespace toonface
