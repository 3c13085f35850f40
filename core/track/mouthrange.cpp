#include "track/mouthrange.h"

#include <algorithm>
#include <cmath>

namespace toonface {

namespace {

std::array<QPointF, 4> mouthOf(const TrackedFrame &f)
{
    std::array<QPointF, 4> m;
    for (int k = 0; k < 4; ++k)
        m[k] = f.motion.displacementEs0[pt::idx(kMouthControlIds[k])];
    return m;
}

// How far the outer lips part: 8.2's y (down the face) less 8.9's.
double parting(const std::array<QPointF, 4> &m)
{
    return m[Down].y() - m[Up].y();
}

double median(QVector<double> v)
{
    if (v.isEmpty())
        return 0;
    const auto mid = v.begin() + v.size() / 2;
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

// The value below which `share` of `v` lies (nearest rank).
double percentile(QVector<double> v, double share)
{
    if (v.isEmpty())
        return 0;
    std::sort(v.begin(), v.end());
    const auto rank = qsizetype(std::ceil(share * double(v.size()))) - 1;
    return v[std::clamp<qsizetype>(rank, 0, v.size() - 1)];
}

} // namespace

MouthRange measureMouthRange(const QVector<TrackedFrame> &frames, double widestOpeningEs0)
{
    MouthRange range;
    QVector<std::array<QPointF, 4>> mouths;
    for (const TrackedFrame &f : frames) {
        if (!f.lost)
            mouths.append(mouthOf(f));
    }
    range.framesMeasured = int(mouths.size());
    if (mouths.isEmpty())
        return range;

    // Shut: the median, control by control, of the frames that part the least.
    std::stable_sort(
        mouths.begin(), mouths.end(), [](const auto &a, const auto &b) { return parting(a) < parting(b); });
    const qsizetype closedCount = std::max<qsizetype>(1, qsizetype(std::ceil(kClosedShare * double(mouths.size()))));
    for (int k = 0; k < 4; ++k) {
        QVector<double> xs, ys;
        for (qsizetype i = 0; i < closedCount; ++i) {
            xs.append(mouths[i][k].x());
            ys.append(mouths[i][k].y());
        }
        range.closedEs0[k] = QPointF(median(xs), median(ys));
    }

    QVector<double> openings;
    for (const auto &m : std::as_const(mouths))
        openings.append(parting(m) - parting(range.closedEs0));
    range.wideOpeningEs0 = std::max(0.0, percentile(openings, kWideOpeningPercentile));
    if (widestOpeningEs0 > 0)
        range.gain = widestOpeningEs0 / std::max(range.wideOpeningEs0, widestOpeningEs0 / kMaxMouthGain);
    return range;
}

double widestMouthOpeningEs0(const Tracker &tracker)
{
    double widest = 0;
    for (MouthShape s : kAllMouthShapes) {
        if (s != MouthShape::N) // snapping leaves `n` out (Tracker::nearestMouthShape)
            widest = std::max(widest, parting(tracker.mouthShapeEs0(s)));
    }
    return widest;
}

void snapClipMouth(
    QVector<TrackedFrame> *frames, const Tracker &tracker, const MouthRange &range, const QVector<bool> &silent)
{
    MouthShape held = MouthShape::M;
    for (qsizetype i = 0; i < frames->size(); ++i) {
        TrackedFrame &f = (*frames)[i];
        if (i < silent.size() && silent[i]) {
            held = MouthShape::M;
        } else if (!f.lost) {
            std::array<QPointF, 4> m = mouthOf(f);
            for (int k = 0; k < 4; ++k)
                m[k] = (m[k] - range.closedEs0[k]) * range.gain;
            held = tracker.nearestMouthShape(m);
        }
        f.mouthShape = held;
        const std::array<QPointF, 4> &shape = tracker.mouthShapeEs0(held);
        for (int k = 0; k < 4; ++k)
            f.motion.displacementEs0[pt::idx(kMouthControlIds[k])] = shape[k];
    }
}

} // namespace toonface
