#include "capture/microphone.h"

#include "speech/audio.h"

#include <QAudioDevice>
#include <QAudioSource>
#include <QMediaDevices>

#include <cstring>

namespace toonface {

Microphone::Microphone(QObject *parent)
    : QObject(parent)
{ }

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
    m_source = new QAudioSource(device, format, this);
    m_device = m_source->start();
    if (!m_device || m_source->error() != QAudio::NoError) {
        if (error)
            *error = tr("The microphone “%1” cannot be opened.").arg(device.description());
        stop();
        return false;
    }
    connect(m_device, &QIODevice::readyRead, this, &Microphone::read);
    connect(m_source, &QAudioSource::stateChanged, this, [this, name = device.description()](QAudio::State state) {
        if (state == QAudio::StoppedState && m_source && m_source->error() != QAudio::NoError) {
            stop();
            Q_EMIT failed(tr("The microphone “%1” stopped.").arg(name));
        }
    });
    return true;
}

void Microphone::stop()
{
    if (!m_source)
        return;
    m_source->disconnect(this);
    if (m_device)
        m_device->disconnect(this);
    m_source->stop();
    m_source->deleteLater();
    m_source = nullptr;
    m_device = nullptr;
}

void Microphone::read()
{
    if (!m_device)
        return;
    const QByteArray data = m_device->readAll();
    if (data.isEmpty())
        return;
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
