#pragma once

#include <QAudioDevice>
#include <QAudioFormat>
#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QVector>

class QAudioSource;
class QIODevice;
class QMediaDevices;
class QTimer;

namespace toonface {

// The default microphone through QAudioSource, delivering mono float samples. No microphone
// (QMediaDevices::audioInputs() empty, as on a machine without sound input) is a clear message,
// never an exception or a silent failure; a microphone that stops (unplugged, an error) says
// so in failed(). (Qt 6.4's PulseAudio backend neither reports a source that goes away nor
// signals the changed list of inputs: the list is checked twice a second, and a microphone that
// has delivered nothing for 3 s has stopped.)
//
// GUI thread: samples() is emitted there.
class Microphone : public QObject
{
    Q_OBJECT

public:
    explicit Microphone(QObject *parent = nullptr);
    ~Microphone() override;

    static bool isPresent();
    static QString noMicrophoneMessage();

    // Starts the default input: mono at 16 kHz when it can, else its preferred format
    // (converted to mono float). False with *error when there is none or it cannot start.
    bool start(QString *error);
    void stop();
    bool isActive() const { return m_source != nullptr; }
    // The microphone in use (its description), empty when none is.
    QString description() const { return isActive() ? m_input.description() : QString(); }
    int sampleRate() const { return m_format.sampleRate(); }

    // Interleaved samples of `format` -> mono floats in [-1, 1] (channels averaged).
    static QVector<float> toMono(const QByteArray &data, const QAudioFormat &format);

Q_SIGNALS:
    void samples(const QVector<float> &mono, int sampleRate);
    void failed(const QString &message);

private:
    void read();
    void fail(const QString &description);
    void checkStillThere();

    QMediaDevices *m_devices = nullptr; // tells when the microphone in use goes away
    QTimer *m_watch = nullptr; // checks that it is still there and delivering
    QElapsedTimer m_sinceData;
    QAudioDevice m_input; // the microphone in use
    QAudioSource *m_source = nullptr;
    QIODevice *m_device = nullptr;
    QAudioFormat m_format;
};

} // namespace toonface
