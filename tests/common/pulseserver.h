#pragma once

#include <QProcess>
#include <QStandardPaths>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>
#include <QTest>

// A private PulseAudio sound server for the tests of the sound devices, as a machine with a
// microphone and speakers has them, on a machine with no sound card: a speaker (a null sink)
// and a microphone that hears what the speaker plays (a source remapped from the sink's
// monitor). Start it before QtMultimedia is first used: the process's XDG_RUNTIME_DIR points at
// it, so Qt finds its devices. Stopped with the object.
namespace toonface::testing {

class PulseServer
{
public:
    static constexpr const char *kSpeaker = "toonface_speaker";
    static constexpr const char *kMicrophone = "toonface_microphone";
    static constexpr const char *kMicrophoneDescription = "Toonface-Test-Microphone";

    ~PulseServer() { stop(); }

    // Empty when the server runs, else why not (no pulseaudio installed, it failed to start).
    QString start()
    {
        const QString daemon = QStandardPaths::findExecutable(QStringLiteral("pulseaudio"));
        if (daemon.isEmpty() || QStandardPaths::findExecutable(QStringLiteral("pactl")).isEmpty()
            || QStandardPaths::findExecutable(QStringLiteral("paplay")).isEmpty())
            return QStringLiteral("pulseaudio and pulseaudio-utils are not installed");
        if (!m_dir.isValid())
            return QStringLiteral("no temporary directory");
        qputenv("XDG_RUNTIME_DIR", m_dir.path().toLocal8Bit());
        qputenv("XDG_CONFIG_HOME", m_dir.filePath(QStringLiteral("config")).toLocal8Bit());
        qputenv("PULSE_RUNTIME_PATH", m_dir.filePath(QStringLiteral("pulse")).toLocal8Bit());
        qunsetenv("PULSE_SERVER");
        m_daemon.setProcessChannelMode(QProcess::ForwardedErrorChannel);
        m_daemon.start(daemon,
            {QStringLiteral("-n"), QStringLiteral("--daemonize=no"), QStringLiteral("--exit-idle-time=-1"),
                QStringLiteral("--use-pid-file=no"), QStringLiteral("--log-level=error"),
                QStringLiteral("--load=module-native-protocol-unix"),
                QStringLiteral("--load=module-null-sink sink_name=%1").arg(QLatin1String(kSpeaker)),
                QStringLiteral("--load=module-remap-source master=%1.monitor source_name=%2 "
                               "source_properties=device.description=%3")
                    .arg(QLatin1String(kSpeaker), QLatin1String(kMicrophone), QLatin1String(kMicrophoneDescription))});
        if (!m_daemon.waitForStarted(5000))
            return QStringLiteral("pulseaudio does not start: %1").arg(m_daemon.errorString());
        if (!QTest::qWaitFor([] { return pactl({QStringLiteral("info")}); }, 10000))
            return QStringLiteral("pulseaudio started but does not answer");
        if (!pactl({QStringLiteral("set-default-source"), QLatin1String(kMicrophone)})
            || !pactl({QStringLiteral("set-default-sink"), QLatin1String(kSpeaker)}))
            return QStringLiteral("pulseaudio's devices cannot be chosen");
        return {};
    }

    void stop()
    {
        if (m_daemon.state() == QProcess::NotRunning)
            return;
        m_daemon.terminate();
        if (!m_daemon.waitForFinished(5000))
            m_daemon.kill();
        m_daemon.waitForFinished(2000);
    }

    // Runs `pactl args`; whether it succeeded.
    static bool pactl(const QStringList &args)
    {
        QProcess p;
        p.start(QStringLiteral("pactl"), args);
        return p.waitForFinished(5000) && p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0;
    }

    // Plays a sound file on the speaker (so the microphone hears it); the player runs until the
    // sound ends.
    static void play(QProcess &player, const QString &path)
    {
        player.start(QStringLiteral("paplay"), {QStringLiteral("--device=%1").arg(QLatin1String(kSpeaker)), path});
    }

private:
    QTemporaryDir m_dir;
    QProcess m_daemon;
};

} // namespace toonface::testing
