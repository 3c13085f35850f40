#include "timeline/timelinepainter.h"

#include "speech/waveformpeaks.h"
#include "timeline/timelinegeometry.h"
#include "timeline/timelinetracks.h"

#include <QFileInfo>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace toonface {

using namespace tracks::colors;

namespace {

const QColor kLabelColumn(0x30, 0x33, 0x39);
const QColor kRuler(0x34, 0x37, 0x3d);
const QColor kTick(0x8a, 0x8f, 0x98);
const QColor kPlayhead(0xff, 0x5a, 0x4e);
const QColor kWave(0x4f, 0xc3, 0xb4);
const QColor kFocus(0x4a, 0x8c, 0xe8);

// "1:05" at whole seconds; between them (zoomed in to frames) the frame within the second, "10f".
QString timeLabel(double t, double fps, bool *wholeSecond)
{
    const int whole = int(std::floor(t + 1e-6));
    const int frame = int(std::lround((t - whole) * fps));
    *wholeSecond = frame == 0;
    if (frame != 0)
        return QStringLiteral("%1f").arg(frame);
    return QStringLiteral("%1:%2").arg(whole / 60).arg(whole % 60, 2, 10, QLatin1Char('0'));
}

// The major tick step: the shortest of frames or round seconds at least `minPixels` apart.
double majorStep(double pps, double fps, double minPixels, bool *frames)
{
    // Frame steps that divide a second, so that every whole second gets its label.
    const double frameSteps[] = {1, 2, 3, 5, 6, 10, 12, 15};
    const long perSecond = std::lround(fps);
    for (double f : frameSteps)
        if (f < fps && perSecond % long(f) == 0 && std::abs(fps - perSecond) < 1e-9 && f / fps * pps >= minPixels) {
            *frames = true;
            return f / fps;
        }
    *frames = false;
    const double secondSteps[] = {0.5, 1, 2, 5, 10, 15, 30, 60, 120, 300, 600};
    for (double s : secondSteps) {
        if (s < 1.0 && fps * s != std::floor(fps * s))
            continue;
        if (s * pps >= minPixels) {
            *frames = s < 1.0;
            return s;
        }
    }
    return 600;
}

// The gain every recording with a waveform is drawn at, when they share one (to a tenth of a
// dB); none when they differ or none has a waveform yet.
std::optional<double> sharedGain(const TimelineScene &s)
{
    std::optional<double> shared;
    for (qsizetype i = 0; i < s.clipPeaks.size(); ++i) {
        if (!s.clipPeaks[i] || s.clipPeaks[i]->isEmpty())
            continue;
        const double gain = s.clipGains.value(i, 1.0);
        if (shared && std::abs(20 * std::log10(gain / *shared)) > 0.1)
            return std::nullopt;
        shared = gain;
    }
    return shared;
}

// A gain that rounds to 0 dB is not said ("-0 dB" over a clip drawn as it is).
bool gainIsSaid(double gain)
{
    return std::abs(20 * std::log10(gain)) >= 0.5;
}

QString gainText(double gain)
{
    return QObject::tr("%1 dB").arg(QString::asprintf("%+.0f", 20 * std::log10(gain)));
}

void paintLabels(QPainter &p, const TimelineScene &s)
{
    const TimelineLayout &l = *s.layout;
    p.fillRect(QRect(0, 0, TimelineLayout::kLabelWidth, s.height), kLabelColumn);
    QFont font = p.font();
    font.setBold(true);
    p.setFont(font);
    for (const TimelineRow &r : l.rows()) {
        if (r.kind == RowKind::Ruler)
            continue;
        const QRect rect = l.rowRect(r.kind, s.width);
        const QRect label(0, rect.top(), TimelineLayout::kLabelWidth, rect.height());
        if (label.bottom() < TimelineLayout::kRulerHeight)
            continue;
        if (s.focusRow == r.kind) {
            p.fillRect(label, kFocus.darker(250));
            p.fillRect(QRect(0, label.top(), 3, label.height()), kFocus);
        }
        p.setPen(s.focusRow == r.kind ? kText : kDimText);
        p.drawText(label.adjusted(10, 0, -4, 0), Qt::AlignVCenter | Qt::AlignLeft, rowTitle(r.kind));
        const std::optional<double> gain = sharedGain(s);
        if (r.kind == RowKind::Waveform && gain && gainIsSaid(*gain)) {
            // How much the drawing is magnified, so a quiet recording is not taken for a loud one.
            p.setPen(kDimText);
            p.drawText(label.adjusted(10, 0, -4, -3), Qt::AlignBottom | Qt::AlignLeft, gainText(*gain));
        }
        p.setPen(kGrid);
        p.drawLine(label.bottomLeft(), label.bottomRight());
    }
    font.setBold(false);
    p.setFont(font);
    p.setPen(kGrid);
    p.drawLine(TimelineLayout::kLabelWidth - 1, 0, TimelineLayout::kLabelWidth - 1, s.height);
}

void paintRuler(QPainter &p, const TimelineScene &s, double t0, double t1)
{
    const TimelineLayout &l = *s.layout;
    const QRect ruler = l.rowRect(RowKind::Ruler, s.width);
    p.fillRect(QRect(0, 0, s.width, ruler.height()), kRuler);
    const double fps = s.animation.timeline.frameRate();
    bool frames = false;
    const double step = majorStep(l.pixelsPerSecond(), fps, 90, &frames);
    // Minor ticks: frames where they are far enough apart, else fifths of the major step.
    double minor = 1.0 / fps;
    if (minor * l.pixelsPerSecond() < 5)
        minor = step / 5;
    p.setPen(kTick);
    const double first = std::floor(t0 / minor) * minor;
    const int bottom = ruler.bottom();
    for (double t = std::max(0.0, first); t <= t1; t += minor) {
        const double x = l.xOf(t);
        const bool major = std::abs(std::remainder(t, step)) < minor * 0.01;
        if (!major)
            p.drawLine(QPointF(x, bottom - 5), QPointF(x, bottom));
    }
    QFont font = p.font();
    font.setPointSizeF(font.pointSizeF() * 0.85);
    p.setFont(font);
    for (double t = std::max(0.0, std::floor(t0 / step) * step); t <= t1 + step; t += step) {
        const double x = l.xOf(t);
        p.setPen(kTick);
        p.drawLine(QPointF(x, bottom - 12), QPointF(x, bottom));
        bool wholeSecond = true;
        const QString label = timeLabel(t, fps, &wholeSecond);
        p.setPen(wholeSecond ? kText : kDimText);
        p.drawText(QPointF(x + 3, bottom - 14), label);
    }
    p.setPen(kGrid);
    p.drawLine(0, bottom, s.width, bottom);
    // The corner: the frame rate.
    p.fillRect(QRect(0, 0, TimelineLayout::kLabelWidth, ruler.height()), kLabelColumn);
    p.setPen(kDimText);
    p.drawText(QRect(10, 0, TimelineLayout::kLabelWidth - 12, ruler.height()), Qt::AlignVCenter | Qt::AlignLeft,
        QStringLiteral("%1 fps").arg(fps, 0, 'g', 4));
    font.setPointSizeF(font.pointSizeF() / 0.85);
    p.setFont(font);
}

// Vertical lines at the ruler's major ticks through every row, so times line up by eye.
void paintGrid(QPainter &p, const TimelineScene &s, double t0, double t1)
{
    const TimelineLayout &l = *s.layout;
    bool frames = false;
    const double step = majorStep(l.pixelsPerSecond(), s.animation.timeline.frameRate(), 90, &frames);
    p.setPen(kGrid);
    for (double t = std::max(0.0, std::floor(t0 / step) * step); t <= t1; t += step) {
        const double x = l.xOf(t);
        p.drawLine(QPointF(x, TimelineLayout::kRulerHeight), QPointF(x, s.height));
    }
}

// One audio clip: a box over where it is heard, its title strip (file and script), and the
// waveform of its file at its offset inside the box.
void paintAudioClip(QPainter &p, const TimelineScene &s, int index, const QRect &row)
{
    const AudioClip &clip = s.animation.timeline.audioClips()[index];
    const TimelineLayout &l = *s.layout;
    const double gain = s.clipGains.value(index, 1.0);
    const QRectF box = geometry::itemSpanRect(s, RowKind::Waveform, index, {clip.start(), clip.end()});
    const bool selected = s.selection && s.selection->contains({ItemKind::Audio, index});
    p.setPen(QPen(selected ? kSelection : kWave.darker(170), selected ? 2 : 1));
    p.setBrush(QColor(kWave.red(), kWave.green(), kWave.blue(), 28));
    p.drawRoundedRect(box.adjusted(0.5, 0.5, -0.5, -0.5), 3, 3);
    const QRectF title(box.left(), box.top(), box.width(), geometry::kAudioTitle);
    p.fillRect(title.adjusted(1, 1, -1, 0), QColor(kWave.red(), kWave.green(), kWave.blue(), selected ? 110 : 70));
    if (box.width() > 24) {
        QFont small = p.font();
        const QFont base = small;
        small.setPointSizeF(base.pointSizeF() * 0.8);
        p.setFont(small);
        const QString name = QFileInfo(clip.path).fileName();
        const QString script = clip.script.simplified();
        const QString text = script.isEmpty() ? name : QStringLiteral("%1 — %2").arg(name, script);
        QRectF textRect = title.adjusted(4, 0, -3, 0);
        const bool hasPeaks = index < s.clipPeaks.size() && s.clipPeaks[index] && !s.clipPeaks[index]->isEmpty();
        if (hasPeaks && !sharedGain(s) && gainIsSaid(gain)) {
            // Recordings drawn at different gains: each says its own, at the title's end.
            const QString said = gainText(gain);
            const int width = p.fontMetrics().horizontalAdvance(said);
            if (textRect.width() > 3 * width) {
                p.setPen(kDimText);
                p.drawText(textRect, Qt::AlignVCenter | Qt::AlignRight, said);
                textRect.setRight(textRect.right() - width - 6);
            }
        }
        p.setPen(kText);
        p.drawText(textRect, Qt::AlignVCenter | Qt::AlignLeft,
            p.fontMetrics().elidedText(text, Qt::ElideRight, int(textRect.width())));
        p.setFont(base);
    }
    const WaveformPeaks *peaks = index < s.clipPeaks.size() ? s.clipPeaks[index] : nullptr;
    const QRectF wave = box.adjusted(1, geometry::kAudioTitle + 1, -1, -1);
    if (!peaks || peaks->isEmpty()) {
        p.setPen(kDimText);
        p.drawText(wave.adjusted(6, 0, 0, 0), Qt::AlignVCenter | Qt::AlignLeft, s.clipStatus.value(index));
        return;
    }
    const double mid = wave.center().y();
    const double half = wave.height() / 2.0 - 1;
    const int x0 = std::max(row.left(), int(std::floor(wave.left())));
    const int x1
        = std::min(row.right(), int(std::ceil(std::min(wave.right(), l.xOf(clip.offset + peaks->duration())))));
    if (x1 < x0)
        return;
    p.setPen(QPen(kWave.darker(160), 1));
    p.drawLine(QPointF(x0, mid), QPointF(x1, mid));
    p.setPen(QPen(kWave, 1));
    QVector<QLineF> lines;
    lines.reserve(std::max(0, x1 - x0 + 1));
    for (int x = x0; x <= x1; ++x) {
        const double a = l.timeAt(x) - clip.offset, b = l.timeAt(x + 1) - clip.offset;
        const auto [rawLo, rawHi] = peaks->range(a, b);
        const double lo = std::clamp(rawLo * gain, -1.0, 1.0);
        const double hi = std::clamp(rawHi * gain, -1.0, 1.0);
        lines.append(QLineF(x + 0.5, mid - hi * half, x + 0.5, mid - lo * half + 0.01));
    }
    p.drawLines(lines);
}

void paintWaveform(QPainter &p, const TimelineScene &s, double t0, double t1)
{
    const QRect row = s.layout->rowRect(RowKind::Waveform, s.width);
    const QVector<AudioClip> &clips = s.animation.timeline.audioClips();
    if (clips.isEmpty()) {
        p.setPen(kDimText);
        p.drawText(row.adjusted(8, 0, 0, 0), Qt::AlignVCenter | Qt::AlignLeft, QObject::tr("No sound"));
        return;
    }
    p.save();
    p.setClipRect(row, Qt::IntersectClip);
    for (qsizetype i = 0; i < clips.size(); ++i)
        if (clips[i].end() >= t0 && clips[i].start() <= t1)
            paintAudioClip(p, s, int(i), row);
    p.restore();
}

void paintPlayhead(QPainter &p, const TimelineScene &s)
{
    const double x = s.layout->xOf(s.playhead);
    if (x < TimelineLayout::kLabelWidth - 1 || x > s.width)
        return;
    p.setPen(QPen(kPlayhead, 1.5));
    p.drawLine(QPointF(x, TimelineLayout::kRulerHeight - 8), QPointF(x, s.height));
    QPainterPath head;
    const double y = TimelineLayout::kRulerHeight;
    head.moveTo(x - 6, y - 14);
    head.lineTo(x + 6, y - 14);
    head.lineTo(x + 6, y - 7);
    head.lineTo(x, y - 1);
    head.lineTo(x - 6, y - 7);
    head.closeSubpath();
    p.setPen(Qt::NoPen);
    p.setBrush(kPlayhead);
    p.drawPath(head);
}

} // namespace

QColor mouthShapeColor(MouthShape shape)
{
    static const QColor colors[kMouthShapeCount] = {
        QColor(0x8e, 0x6c, 0xd8), // m
        QColor(0x5d, 0x9c, 0xec), // f
        QColor(0x4f, 0xb3, 0xa9), // h
        QColor(0xe8, 0x6a, 0x5c), // a
        QColor(0xee, 0xa2, 0x3a), // i
        QColor(0x62, 0xb8, 0x5e), // u
        QColor(0xd9, 0x7e, 0xb8), // e
        QColor(0xe0, 0x8a, 0x4a), // o
        QColor(0x7f, 0x8c, 0x9a), // n
    };
    return colors[int(shape)];
}

QColor emotionColor(Emotion emotion)
{
    switch (emotion) {
    case Emotion::Neutral: return QColor(0x8d, 0x95, 0xa3);
    case Emotion::Smile: return QColor(0xf2, 0xb8, 0x3b);
    case Emotion::Sad: return QColor(0x4f, 0x86, 0xd9);
    case Emotion::Angry: return QColor(0xdf, 0x4b, 0x43);
    case Emotion::Surprise: return QColor(0xa8, 0x6c, 0xe0);
    }
    return Qt::gray;
}

void paintTimeline(QPainter &p, const TimelineScene &s)
{
    const TimelineLayout &l = *s.layout;
    p.fillRect(QRect(0, 0, s.width, s.height), kBackground);
    const double t0 = std::max(0.0, l.timeAt(TimelineLayout::kLabelWidth));
    const double t1 = l.timeAt(s.width);

    // Rows, clipped below the ruler (they scroll under it).
    p.save();
    p.setClipRect(QRect(TimelineLayout::kLabelWidth, TimelineLayout::kRulerHeight, s.width, s.height));
    int n = 0;
    for (const TimelineRow &r : l.rows())
        if (r.kind != RowKind::Ruler)
            p.fillRect(l.rowRect(r.kind, s.width), n++ % 2 ? kRowOdd : kRowEven);
    // Past the end of the animation, darker.
    const double end = std::max(s.animation.timeline.duration(), 0.0);
    const double xEnd = l.xOf(end);
    if (xEnd < s.width)
        p.fillRect(QRectF(xEnd, TimelineLayout::kRulerHeight, s.width - xEnd, s.height), QColor(0, 0, 0, 60));
    paintGrid(p, s, t0, t1);
    paintWaveform(p, s, t0, t1);
    p.setRenderHint(QPainter::Antialiasing, true);
    tracks::paintScriptRow(p, s, t0, t1);
    tracks::paintMouthRow(p, s, t0, t1);
    tracks::paintEmotionRow(p, s, t0, t1);
    tracks::paintBlinkRow(p, s, t0, t1);
    tracks::paintHeadRow(p, s, t0, t1);
    tracks::paintGazeRow(p, s, t0, t1);
    tracks::paintPoseRow(p, s, t0, t1);
    if (s.snapLine) {
        p.setPen(QPen(kSelection, 1, Qt::DashLine));
        p.drawLine(QPointF(l.xOf(*s.snapLine), TimelineLayout::kRulerHeight), QPointF(l.xOf(*s.snapLine), s.height));
    }
    if (!s.rubberBand.isNull()) {
        p.setPen(QPen(kFocus, 1));
        p.setBrush(QColor(kFocus.red(), kFocus.green(), kFocus.blue(), 50));
        p.drawRect(s.rubberBand);
    }
    p.restore();

    p.setRenderHint(QPainter::Antialiasing, false);
    paintLabels(p, s);
    paintRuler(p, s, t0, t1);
    p.setRenderHint(QPainter::Antialiasing, true);
    p.setClipRect(QRect(TimelineLayout::kLabelWidth - 6, 0, s.width, s.height));
    paintPlayhead(p, s);
    p.setClipping(false);
}

} // namespace toonface
