#include "export/smilreduce.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace toonface::smil {

namespace {

// Keys merged into one interval at most: longer runs rarely fit one timing, and each try costs
// the samples of all the intervals it covers.
constexpr int kMaxMerged = 16;
// The keyed animation is compared at every eighth of each interval it has (and at its keys) to
// fit and choose a timing, and the chosen one at every 32nd (the curves bend between eighths).
constexpr int kChecksPerInterval = 8;
constexpr int kConfirmPerInterval = 32;
constexpr int kMaxSamples = kMaxMerged * kConfirmPerInterval;

// A channel's keys in pixels.
struct Keyed
{
    Keyed(const Channel &c, const ChannelKeys &k)
        : keys(k)
        , size(c.size)
        , unit(c.weight / double(kPow10[c.decimals]))
    { }
    double value(qsizetype key, int j) const { return double(keys.values[key * size + j]) * unit; }
    // The progress of interval m at its time fraction f (0 where it holds). Solving a timing
    // with free x control points takes Newton's steps: callers compute it once per time, not
    // once per number.
    double progress(qsizetype m, double f) const
    {
        const std::optional<Timing> &timing = keys.timings[m];
        return timing ? timing->at(f) : 0.0;
    }
    // Number j of interval m at progress p.
    double at(qsizetype m, double p, int j) const
    {
        const double a = value(m, j);
        return a + (value(m + 1, j) - a) * p;
    }

    const ChannelKeys &keys;
    int size;
    double unit;
};

// The times and rows of the keyed animation inside the keys [first, last], as fractions of
// that span; rows are filled lazily by the caller.
struct Samples
{
    int count = 0;
    std::array<double, kMaxSamples> x;
    std::array<qsizetype, kMaxSamples> interval;
    std::array<double, kMaxSamples> fraction;
};

Samples samplesOf(const Keyed &k, qsizetype first, qsizetype last, int perInterval)
{
    Samples s;
    const double t0 = double(k.keys.times[first]);
    const double span = double(k.keys.times[last]) - t0;
    for (qsizetype m = first; m < last; ++m) {
        const double a = double(k.keys.times[m]), b = double(k.keys.times[m + 1]);
        for (int i = m == first ? 1 : 0; i < perInterval; ++i) {
            const double f = double(i) / perInterval;
            s.x[s.count] = (a + f * (b - a) - t0) / span;
            s.interval[s.count] = m;
            s.fraction[s.count++] = f;
        }
    }
    return s;
}

// The largest distance in pixels between the keyed animation at the samples and the interval
// [first, last] with `timing` (nullopt: holding the first key's value); stops early past limit.
double mergedError(const Keyed &k, qsizetype first, qsizetype last, const std::optional<Timing> &timing,
    const Samples &s, double limit)
{
    double worst = 0;
    for (int i = 0; i < s.count; ++i) {
        const double q = timing ? timing->at(s.x[i]) : 0.0;
        const double p = k.progress(s.interval[i], s.fraction[i]);
        for (int j = 0; j < k.size; ++j) {
            const double a = k.value(first, j);
            const double e = std::abs(a + (k.value(last, j) - a) * q - k.at(s.interval[i], p, j));
            worst = std::max(worst, e);
            if (worst > limit)
                return worst;
        }
    }
    return worst;
}

// The timing through (0,0), the points (x[i], p[i]) and (1,1) by least squares, its control
// points inside [0, 1]: the points' parameters on the curve are refined by Newton's steps on
// their distance (Schneider's curve fitting), then the y are fitted again with the parameters
// at which the curve's x is exactly each point's time.
Timing fitTiming(const Samples &s, const std::array<double, kMaxSamples> &p)
{
    std::array<double, kMaxSamples> u;
    std::copy(s.x.cbegin(), s.x.cbegin() + s.count, u.begin());
    Timing t;
    auto solve = [&](bool withX) {
        double m11 = 0, m12 = 0, m22 = 0, x1 = 0, x2 = 0, y1 = 0, y2 = 0;
        for (int i = 0; i < s.count; ++i) {
            const double v = u[i];
            const double b1 = 3 * v * (1 - v) * (1 - v), b2 = 3 * v * v * (1 - v), b3 = v * v * v;
            m11 += b1 * b1;
            m12 += b1 * b2;
            m22 += b2 * b2;
            x1 += b1 * (s.x[i] - b3);
            x2 += b2 * (s.x[i] - b3);
            y1 += b1 * (p[i] - b3);
            y2 += b2 * (p[i] - b3);
        }
        const double det = m11 * m22 - m12 * m12;
        if (!(det > 1e-12 * std::max(1e-12, m11 * m22)))
            return false;
        if (withX) {
            t.x1 = std::clamp((x1 * m22 - m12 * x2) / det, 0.0, 1.0);
            t.x2 = std::clamp((m11 * x2 - m12 * x1) / det, 0.0, 1.0);
        }
        t.y1 = std::clamp((y1 * m22 - m12 * y2) / det, 0.0, 1.0);
        t.y2 = std::clamp((m11 * y2 - m12 * y1) / det, 0.0, 1.0);
        return true;
    };
    for (int round = 0; round < 4; ++round) {
        if (!solve(true))
            return t;
        for (int i = 0; i < s.count; ++i) {
            // One Newton step on |B(u) - (x, p)|^2.
            const double v = u[i];
            auto d1 = [&](double c1, double c2) {
                return 3 * (1 - v) * (1 - v) * c1 + 6 * v * (1 - v) * (c2 - c1) + 3 * v * v * (1 - c2);
            };
            auto d2 = [&](double c1, double c2) { return 6 * (1 - v) * (c2 - 2 * c1) + 6 * v * (1 + c1 - 2 * c2); };
            const double ex = Timing::bezier(t.x1, t.x2, v) - s.x[i];
            const double ey = Timing::bezier(t.y1, t.y2, v) - p[i];
            const double dx = d1(t.x1, t.x2), dy = d1(t.y1, t.y2);
            const double num = ex * dx + ey * dy;
            const double den = dx * dx + dy * dy + ex * d2(t.x1, t.x2) + ey * d2(t.y1, t.y2);
            if (std::abs(den) > 1e-12)
                u[i] = std::clamp(v - num / den, 0.0, 1.0);
        }
    }
    for (int i = 0; i < s.count; ++i)
        u[i] = t.parameter(s.x[i]);
    solve(false);
    return t;
}

// `timing` with its control points rounded to `decimals` (keySplines take them in [0, 1]).
Timing rounded(const Timing &t, int decimals)
{
    const double scale = double(kPow10[decimals]);
    auto r = [&](double v) { return std::clamp(std::round(v * scale) / scale, 0.0, 1.0); };
    Timing out;
    out.x1 = r(t.x1);
    out.y1 = r(t.y1);
    out.x2 = r(t.x2);
    out.y2 = r(t.y2);
    // The thirds the key refinement writes as .333 and .667 stay exact thirds at three decimals.
    if (decimals >= 3 && t.thirds())
        out.x1 = t.x1, out.x2 = t.x2;
    return out;
}

// The timing for the interval [first, last] that keeps the keyed animation within tolerance,
// written to the fewest decimals; nullopt in `ok` when none does.
bool intervalTiming(const Keyed &k, qsizetype first, qsizetype last, double tolerance, std::optional<Timing> *out)
{
    const Samples s = samplesOf(k, first, last, kChecksPerInterval);
    // The merged interval's timing passes the eighths, then every 32nd.
    auto fits = [&](const std::optional<Timing> &t) {
        return mergedError(k, first, last, t, s, tolerance) <= tolerance
            && mergedError(k, first, last, t, samplesOf(k, first, last, kConfirmPerInterval), tolerance) <= tolerance;
    };
    bool moves = false;
    double dd = 0;
    for (int j = 0; j < k.size; ++j) {
        const double d = k.value(last, j) - k.value(first, j);
        moves = moves || k.keys.values[last * k.size + j] != k.keys.values[first * k.size + j];
        dd += d * d;
    }
    if (!moves) {
        if (!fits(std::nullopt))
            return false;
        *out = std::nullopt;
        return true;
    }
    Timing candidate;
    if (last == first + 1 && k.keys.timings[first]) {
        candidate = *k.keys.timings[first];
    } else {
        // The progress of each sample along the line between the ends.
        std::array<double, kMaxSamples> p;
        for (int i = 0; i < s.count; ++i) {
            double dot = 0;
            const double progress = k.progress(s.interval[i], s.fraction[i]);
            for (int j = 0; j < k.size; ++j) {
                const double a = k.value(first, j);
                dot += (k.at(s.interval[i], progress, j) - a) * (k.value(last, j) - a);
            }
            p[i] = dot / dd;
        }
        candidate = fitTiming(s, p);
    }
    for (int decimals = 1; decimals <= 3; ++decimals) {
        const Timing t = rounded(candidate, decimals);
        if (fits(t)) {
            *out = t;
            return true;
        }
    }
    if (last == first + 1) { // the interval as it was
        *out = candidate;
        return true;
    }
    return false;
}

} // namespace

void reduceKeys(const Channel &channel, double tolerance, ChannelKeys *keys)
{
    const qsizetype n = keys->times.size();
    if (!(tolerance > 0) || n < 2)
        return;
    const Keyed k(channel, *keys);
    ChannelKeys out;
    out.channel = keys->channel;
    out.times.append(keys->times.first());
    out.values.append(keys->values.mid(0, channel.size));
    for (qsizetype first = 0; first + 1 < n;) {
        qsizetype last = first + 1;
        std::optional<Timing> timing;
        intervalTiming(k, first, last, tolerance, &timing);
        for (qsizetype next = last + 1; next < n && next - first <= kMaxMerged; ++next) {
            std::optional<Timing> longer;
            if (!intervalTiming(k, first, next, tolerance, &longer))
                break;
            last = next;
            timing = longer;
        }
        out.times.append(keys->times[last]);
        out.values.append(keys->values.mid(last * channel.size, channel.size));
        out.timings.append(timing);
        first = last;
    }
    *keys = std::move(out);
}

void keyedValue(const Channel &channel, const ChannelKeys &keys, double n, double *out)
{
    const Keyed k(channel, keys);
    const auto it = std::upper_bound(keys.times.cbegin(), keys.times.cend(), n);
    const qsizetype m = std::clamp<qsizetype>(it - keys.times.cbegin() - 1, 0, keys.times.size() - 1);
    const double scale = double(kPow10[channel.decimals]);
    for (int j = 0; j < channel.size; ++j) {
        if (m + 1 >= keys.times.size()) {
            out[j] = double(keys.values[m * channel.size + j]) / scale;
            continue;
        }
        const double f = (n - double(keys.times[m])) / double(keys.times[m + 1] - keys.times[m]);
        out[j] = k.at(m, k.progress(m, std::clamp(f, 0.0, 1.0)), j) / k.unit / scale;
    }
}

} // namespace toonface::smil
