#include "playback/timereadout.h"

#include "document/document.h"
#include "playback/playhead.h"

#include <QFontDatabase>

#include <algorithm>
#include <cmath>

namespace toonface {

TimeReadout::TimeReadout(Document *document, Playhead *playhead, QWidget *parent)
    : QLabel(parent)
    , m_document(document)
    , m_playhead(playhead)
{
    setObjectName(QStringLiteral("timeReadout"));
    // Figures of one width, so the text does not jitter while it plays.
    setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    setContentsMargins(8, 0, 8, 0);
    setToolTip(tr("The playhead's time and frame"));
    connect(m_playhead, &Playhead::timeChanged, this, &TimeReadout::refresh);
    connect(m_document, &Document::changed, this, &TimeReadout::refresh);
    refresh();
}

QString TimeReadout::format(double seconds, double duration, double fps)
{
    const double t = std::max(0.0, seconds);
    const long hundredths = std::lround(t * 100);
    const int frame = int(std::floor(t * fps + 1e-6)) + 1;
    const int frames = std::max(1, int(std::ceil(duration * fps - 1e-6)));
    return tr("%1:%2.%3  frame %4 / %5")
        .arg(hundredths / 6000)
        .arg(hundredths / 100 % 60, 2, 10, QLatin1Char('0'))
        .arg(hundredths % 100, 2, 10, QLatin1Char('0'))
        .arg(frame)
        .arg(std::max(frames, frame));
}

void TimeReadout::refresh()
{
    const Timeline &timeline = m_document->timeline();
    setText(format(m_playhead->time(), timeline.duration(), timeline.frameRate()));
}

} // namespace toonface
