#include "playback/mediaaudiotrack.h"

#include <QAudioOutput>
#include <QDir>
#include <QFileInfo>
#include <QMediaPlayer>
#include <QUrl>

#include <cmath>

namespace toonface {

MediaAudioTrack::MediaAudioTrack(QObject *parent)
    : AudioTrack(parent)
    , m_player(new QMediaPlayer(this))
    , m_output(new QAudioOutput(this))
{
    m_player->setAudioOutput(m_output);
    connect(m_player, &QMediaPlayer::errorOccurred, this, [this](QMediaPlayer::Error, const QString &text) {
        Q_EMIT failed(tr("Cannot play the audio file %1: %2").arg(QDir::toNativeSeparators(m_path), text));
    });
}

MediaAudioTrack::~MediaAudioTrack() = default;

bool MediaAudioTrack::open(const QString &path, QString *error)
{
    const QFileInfo info(path);
    if (!info.isFile() || !info.isReadable()) {
        if (error)
            *error = tr("The audio file %1 %2.")
                         .arg(QDir::toNativeSeparators(path), info.exists() ? tr("cannot be read") : tr("is missing"));
        m_player->setSource(QUrl());
        m_path.clear();
        return false;
    }
    if (path != m_path) {
        m_path = path;
        m_player->setSource(QUrl::fromLocalFile(info.absoluteFilePath()));
    }
    return true;
}

void MediaAudioTrack::play(double seconds)
{
    const qint64 ms = qint64(std::llround(std::max(0.0, seconds) * 1000.0));
    m_player->setPosition(ms);
    m_startMs = ms;
    m_player->play();
}

void MediaAudioTrack::pause()
{
    m_player->pause();
    m_startMs = -1;
}

bool MediaAudioTrack::isPlaying() const
{
    return m_player->playbackState() == QMediaPlayer::PlayingState;
}

std::optional<double> MediaAudioTrack::position() const
{
    if (!isPlaying())
        return std::nullopt;
    const qint64 ms = m_player->position();
    if (m_startMs >= 0) {
        if (ms == m_startMs)
            return std::nullopt; // not flowing yet
        m_startMs = -1;
    }
    return ms / 1000.0;
}

} // namespace toonface
