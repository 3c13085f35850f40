#pragma once

#include "playback/audiotrack.h"

class QAudioOutput;
class QMediaPlayer;

namespace toonface {

// An AudioTrack through QtMultimedia: a QMediaPlayer (GStreamer) into a QAudioOutput on the
// default output device. Its position is the media pipeline's, which follows the device's clock.
// Create it only when QMediaDevices::audioOutputs() is not empty.
class MediaAudioTrack : public AudioTrack
{
    Q_OBJECT

public:
    explicit MediaAudioTrack(QObject *parent = nullptr);
    ~MediaAudioTrack() override;

    bool open(const QString &path, QString *error) override;
    void play(double seconds) override;
    void pause() override;
    bool isPlaying() const override;
    std::optional<double> position() const override;

private:
    QMediaPlayer *m_player;
    QAudioOutput *m_output;
    QString m_path;
    mutable qint64 m_startMs = -1; // where play() started, until the position moves on from it
};

} // namespace toonface
