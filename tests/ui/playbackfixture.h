#pragma once

#include "anim/timeline.h"
#include "document/document.h"
#include "playback/audiotrack.h"

#include <QVector>

#include <cmath>
#include <functional>
#include <optional>

// Fixtures of the playback and preview tests: a talking timeline and a sound player whose clock
// the test controls.
namespace toonface::fixture {

// `seconds` of speech at 25 fps: a mouth shape every 0.2 s, cycling through the nine shapes.
inline Timeline talkingTimeline(double seconds)
{
    Timeline timeline;
    timeline.setFrameRate(25);
    QVector<MouthCue> cues;
    const MouthShape shapes[] = {MouthShape::A, MouthShape::O, MouthShape::E, MouthShape::I, MouthShape::U,
        MouthShape::F, MouthShape::M, MouthShape::N, MouthShape::H};
    for (int i = 0; (i + 1) * 0.2 <= seconds + 1e-9; ++i)
        cues.append(MouthCue {i * 0.2, (i + 1) * 0.2, shapes[i % 9]});
    timeline.addMouthCues(cues);
    return timeline;
}

inline void setTimeline(Document &document, const Timeline &timeline)
{
    Animation animation = document.animation();
    animation.timeline = timeline;
    document.changeAnimation(animation, QStringLiteral("timeline"));
}

// An AudioTrack on a simulated clock: it sounds from where play() put it at `rate` seconds of
// file per second of `wall` time, after `startupMs` of start-up silence, reporting positions in
// steps of `quantumMs` (as audio back ends do), and ends after `fileSeconds`.
class FakeAudioTrack : public AudioTrack
{
public:
    explicit FakeAudioTrack(std::function<qint64()> wall)
        : m_wall(std::move(wall))
    { }

    double rate = 1.0;
    int quantumMs = 0;
    double startupMs = 0;
    double fileSeconds = 1e9;
    // The sound stands still for stallMs when it reaches stallAt seconds of the file (a device
    // that stops taking data for a while); 0: never.
    double stallAt = 0;
    double stallMs = 0;
    QVector<double> plays; // where each play() started
    int pauses = 0;
    QString opened;

    bool open(const QString &path, QString *) override
    {
        opened = path;
        return true;
    }
    void play(double seconds) override
    {
        plays.append(seconds);
        m_playing = true;
        m_from = seconds;
        m_since = m_wall();
    }
    void pause() override
    {
        ++pauses;
        m_playing = false;
    }
    bool isPlaying() const override { return m_playing && heard() < fileSeconds; }
    std::optional<double> position() const override
    {
        if (!isPlaying() || sinceStart() < startupMs / 1000.0)
            return std::nullopt;
        const double p = heard();
        return quantumMs > 0 ? std::floor(p * 1000.0 / quantumMs) * quantumMs / 1000.0 : p;
    }
    // Seconds of the file the listener hears now (exact), whether or not it is still playing.
    double heard() const
    {
        const double flowing = std::max(0.0, sinceStart() - startupMs / 1000.0);
        const double reachStall = (stallAt - m_from) / rate; // flowing seconds to the stall
        if (stallMs <= 0 || m_from >= stallAt || flowing <= reachStall)
            return m_from + flowing * rate;
        return stallAt + std::max(0.0, flowing - reachStall - stallMs / 1000.0) * rate;
    }

private:
    double sinceStart() const { return double(m_wall() - m_since) * 1e-9; }

    std::function<qint64()> m_wall;
    bool m_playing = false;
    double m_from = 0;
    qint64 m_since = 0;
};

} // namespace toonface::fixture
