#pragma once

#include <QObject>

namespace toonface {

// The editor's current time: where the preview shows the animation and where the timeline
// draws its playhead. One per window, shared by the timeline (which scrubs it), the playback
// clock (which advances it) and the preview (which follows it). Holds no document state.
//
// Lives on the GUI thread; not thread-safe.
class Playhead : public QObject
{
    Q_OBJECT

public:
    explicit Playhead(QObject *parent = nullptr);

    // Seconds from the start of the animation, >= 0.
    double time() const { return m_time; }
    // The frame shown at time(): floor(time * fps + 1e-9).
    int frame(double fps) const;

    // Whether the playback clock is running (set by the clock; views may show it).
    bool isPlaying() const { return m_playing; }

    // While the user drags the playhead on the ruler (a scrub), the preview may favour speed.
    bool isScrubbing() const { return m_scrubbing; }

public Q_SLOTS:
    // Clamps to >= 0; emits timeChanged only when the time changes.
    void setTime(double seconds);
    void setPlaying(bool playing);
    void setScrubbing(bool scrubbing);

Q_SIGNALS:
    void timeChanged(double seconds);
    void playingChanged(bool playing);
    void scrubbingChanged(bool scrubbing);

private:
    double m_time = 0;
    bool m_playing = false;
    bool m_scrubbing = false;
};

} // namespace toonface
