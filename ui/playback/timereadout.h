#pragma once

#include <QLabel>

namespace toonface {

class Document;
class Playhead;

// Where the playhead is, as the transport shows it: "0:01.24  frame 32 / 150" (minutes,
// seconds and hundredths; the frame counted from 1 at the animation's rate, of its frames).
class TimeReadout : public QLabel
{
    Q_OBJECT

public:
    TimeReadout(Document *document, Playhead *playhead, QWidget *parent = nullptr);

    // The text for the playhead at `seconds` in an animation of `duration` seconds at `fps`.
    static QString format(double seconds, double duration, double fps);

private:
    void refresh();

    Document *m_document;
    Playhead *m_playhead;
};

} // namespace toonface
