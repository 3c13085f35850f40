#pragma once

#include "anim/timelineevaluator.h"
#include "export/smilchannels.h"
#include "export/svgnumbers.h"

#include <QByteArray>
#include <QVector>

#include <algorithm>
#include <cmath>
#include <optional>

namespace toonface {
struct AnimationExportOptions;
}

// The key times of the SMIL export: for each animated channel, the times, values and timing
// curves that follow the renderer's geometry within the tolerance.
namespace toonface::smil {

// Animation time on a grid of duration / 10^digits, at most 0.1 ms: keyTimes are then exact
// decimal fractions of `digits` digits. Key times move to the grid; an ease cut or extended
// by so little keeps a timing that writes as the whole ease's to keySplines' three decimals.
struct Grid
{
    explicit Grid(double duration)
        : duration(duration)
        , digits(std::clamp(int(std::ceil(std::log10(std::max(duration, 1e-3) * 1e4))), 3, 9))
        , steps(kPow10[digits])
    { }
    double time(qint64 n) const { return duration * double(n) / double(steps); }
    qint64 snap(double t) const
    {
        return std::clamp(qint64(std::llround(t / duration * double(steps))), qint64(0), steps);
    }

    double duration;
    int digits;
    qint64 steps;
};

// The timing curve of one interval: the cubic Bezier (0,0) (x1,y1) (x2,y2) (1,1) of keySplines.
// With x1 = 1/3 and x2 = 2/3 (as the key refinement makes them) its x is the time fraction
// itself, so the progress is the cubic 3x(1-x)^2 y1 + 3x^2(1-x) y2 + x^3; other x (a timing
// fitted over several intervals when keys are dropped) are solved for.
struct Timing
{
    double y1 = 1.0 / 3.0;
    double y2 = 2.0 / 3.0;
    double x1 = 1.0 / 3.0;
    double x2 = 2.0 / 3.0;
    bool thirds() const { return x1 == 1.0 / 3.0 && x2 == 2.0 / 3.0; }
    // The curve's x and y at its parameter s.
    static double bezier(double p1, double p2, double s)
    {
        return 3 * s * (1 - s) * ((1 - s) * p1 + s * p2) + s * s * s;
    }
    // The parameter at which the curve's x is x (x rises monotonically for x1, x2 in [0, 1]).
    double parameter(double x) const;
    double at(double x) const { return thirds() ? bezier(y1, y2, x) : bezier(y1, y2, parameter(x)); }
};

// One animated channel, ready to write: its key times, values and timings.
struct ChannelKeys
{
    int channel = -1;
    QVector<qint64> times;
    QVector<qint64> values; // quantized, channel size per key
    QVector<std::optional<Timing>> timings; // per interval; nullopt: the value holds
};

// Refines the key times of the channels `which` (moved by the same tracks) until every number
// follows its channel's timing within the tolerance, and returns their keys.
bool buildGroup(const QVector<int> &which, const QVector<Channel> &channels, const Sampler &sampler,
    const TimelineEvaluator &evaluator, const Grid &grid, const AnimationExportOptions &options,
    QVector<ChannelKeys> *result, QString *error);

} // namespace toonface::smil
