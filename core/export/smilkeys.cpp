#include "export/smilkeys.h"

#include "export/smilutil.h"
#include "i18n/coretext.h"

#include <QHash>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <span>

namespace toonface::smil {

double Timing::parameter(double x) const
{
    // Newton's steps from x itself, kept inside a bracket that bisection narrows where a step
    // leaves it (x'(s) vanishes at the ends when x1 = 0 or x2 = 1).
    double lo = 0, hi = 1, s = std::clamp(x, 0.0, 1.0);
    for (int i = 0; i < 40; ++i) {
        const double f = bezier(x1, x2, s) - x;
        if (std::abs(f) < 1e-12)
            break;
        (f < 0 ? lo : hi) = s;
        const double slope = 3 * (1 - s) * (1 - s) * x1 + 6 * s * (1 - s) * (x2 - x1) + 3 * s * s * (1 - x2);
        const double next = slope > 1e-9 ? s - f / slope : -1;
        s = next > lo && next < hi ? next : (lo + hi) / 2;
    }
    return s;
}

namespace {

// The part [u0, u1] of the ease 3u^2 - 2u^3, as a timing curve (exact: a piece of a cubic is
// a cubic).
Timing easeTiming(double u0, double u1)
{
    auto y = [](double u) { return u * u * (3 - 2 * u); };
    auto slope = [](double u) { return 6 * u * (1 - u); };
    const double du = u1 - u0;
    const double dy = y(u1) - y(u0);
    if (!(dy > 1e-12))
        return {};
    return {std::clamp(slope(u0) * du / (3 * dy), 0.0, 1.0), std::clamp(1 - slope(u1) * du / (3 * dy), 0.0, 1.0)};
}

// A stretch of time on which a channel follows its end values along one timing.
struct Piece
{
    qint64 a, b;
    Timing timing;
};

// The samples of one group of channels, one row of numbers per grid time.
class SampleTable
{
public:
    explicit SampleTable(int width)
        : m_width(width)
    { }
    // The row of time n, valid until the next add().
    const double *row(qint64 n) const { return m_data.constData() + qsizetype(m_rows.value(n)) * m_width; }

    // Samples the times not yet sampled, in parallel.
    bool add(QVector<qint64> times, const Sampler &sampler, const QVector<int> &which, const Grid &grid)
    {
        std::sort(times.begin(), times.end());
        times.erase(std::unique(times.begin(), times.end()), times.end());
        times.removeIf([&](qint64 n) { return m_rows.contains(n); });
        const qsizetype first = m_data.size() / m_width;
        m_data.resize((first + times.size()) * m_width);
        std::atomic_bool ok = true;
        double *data = m_data.data();
        forEachParallel(times.size(), [&](qsizetype i) {
            if (!sampler.sample(grid.time(times[i]), which, data + (first + i) * m_width))
                ok = false;
        });
        for (qsizetype i = 0; i < times.size(); ++i)
            m_rows.insert(times[i], int(first + i));
        return ok;
    }

private:
    int m_width;
    QHash<qint64, int> m_rows;
    QVector<double> m_data;
};

// Samples inside a span and the time fractions at which they are.
struct Checks
{
    int count = 0;
    std::array<const double *, 15> rows;
    std::array<double, 15> x;
};

// The numbers [from, to) of a group's rows, with their weights (pixels per unit).
struct Slice
{
    int from, to;
    const QVector<double> &weights;
};

// The largest weighted distance between the check samples and what the timing gives them
// from the span's end values.
double timingError(const Timing &timing, const double *a, const double *b, const Checks &checks, const Slice &s)
{
    double worst = 0;
    for (int k = 0; k < checks.count; ++k) {
        const double p = timing.at(checks.x[k]);
        const double *c = checks.rows[k];
        for (int j = s.from; j < s.to; ++j)
            worst = std::max(worst, s.weights[j] * std::abs(a[j] + (b[j] - a[j]) * p - c[j]));
    }
    return worst;
}

// The timing that fits the check samples best (weighted least squares on y1, y2), clamped to
// the [0, 1] that keySplines allows.
Timing fittedTiming(const double *a, const double *b, const Checks &checks, const Slice &s)
{
    double m11 = 0, m12 = 0, m22 = 0, r1 = 0, r2 = 0;
    for (int k = 0; k < checks.count; ++k) {
        const double x = checks.x[k];
        const double b1 = 3 * x * (1 - x) * (1 - x);
        const double b2 = 3 * x * x * (1 - x);
        double dd = 0, dr = 0;
        for (int j = s.from; j < s.to; ++j) {
            const double w2 = s.weights[j] * s.weights[j];
            const double d = b[j] - a[j];
            dd += w2 * d * d;
            dr += w2 * d * (checks.rows[k][j] - a[j] - d * x * x * x);
        }
        m11 += dd * b1 * b1;
        m12 += dd * b1 * b2;
        m22 += dd * b2 * b2;
        r1 += dr * b1;
        r2 += dr * b2;
    }
    const double det = m11 * m22 - m12 * m12;
    if (!(det > 1e-12 * std::max(1e-12, m11 * m22)))
        return {};
    return {std::clamp((r1 * m22 - m12 * r2) / det, 0.0, 1.0), std::clamp((m11 * r2 - m12 * r1) / det, 0.0, 1.0)};
}

// The time fraction at which `timing` reaches progress p (it rises monotonically).
double timingInverse(const Timing &timing, double p)
{
    double lo = 0, hi = 1;
    for (int i = 0; i < 40; ++i) {
        const double mid = (lo + hi) / 2;
        (timing.at(mid) < p ? lo : hi) = mid;
    }
    return (lo + hi) / 2;
}

// Where to split a span that no timing fits, as a time fraction; `checks` at its quarter,
// half and three quarters. Where the renderer clamps (lips that touch, an eyeball reaching
// past the lids) its geometry bends: against the progress of the span's timing, the worst
// number's samples lie on two lines. Splitting where they meet leaves two halves that each
// follow the timing exactly. When the samples show the bend in the first or last quarter but
// not where, split at that quarter; when they show no bend, in the middle.
double splitPoint(const Timing &timing, const double *a, const double *b, const Checks &checks, int j, double weight)
{
    const double x[5] = {0, checks.x[0], checks.x[1], checks.x[2], 1};
    double e[5];
    const double v[5] = {a[j] * weight, checks.rows[0][j] * weight, checks.rows[1][j] * weight,
        checks.rows[2][j] * weight, b[j] * weight};
    for (int k = 0; k < 5; ++k)
        e[k] = timing.at(x[k]);
    for (int k = 0; k < 4; ++k) {
        if (!(e[k + 1] > e[k] + 1e-9))
            return 0.5;
    }
    auto line = [&](int p, int q, double at) { return v[p] + (v[q] - v[p]) * (at - e[p]) / (e[q] - e[p]); };
    // Samples are read from the renderer's text, to 0.01 px.
    constexpr double kNoise = 0.04;
    const bool middleOnLeft = std::abs(line(0, 1, e[2]) - v[2]) <= kNoise;
    const bool middleOnRight = std::abs(line(3, 4, e[2]) - v[2]) <= kNoise;
    const double left = (v[1] - v[0]) / (e[1] - e[0]);
    const double right = (v[4] - v[3]) / (e[4] - e[3]);
    if (std::abs(left - right) > 1e-9) {
        const double bend = (v[3] - v[0] - right * e[3] + left * e[0]) / (left - right);
        if (bend > e[1] && bend < e[3] && (bend > e[2] ? middleOnLeft : middleOnRight))
            return timingInverse(timing, bend);
    }
    if (middleOnRight && !middleOnLeft)
        return x[1];
    if (middleOnLeft && !middleOnRight)
        return x[3];
    return 0.5;
}

} // namespace

bool buildGroup(const QVector<int> &which, const QVector<Channel> &channels, const Sampler &sampler,
    const TimelineEvaluator &evaluator, const Grid &grid, const AnimationExportOptions &options,
    QVector<ChannelKeys> *result, QString *error)
{
    QVector<double> weights;
    QVector<int> starts; // of each channel's numbers in a row, and the row's end
    for (int c : which) {
        starts.append(int(weights.size()));
        for (int k = 0; k < channels[c].size; ++k)
            weights.append(channels[c].weight);
    }
    starts.append(int(weights.size()));
    const int width = int(weights.size());
    const int channelCount = int(which.size());
    SampleTable table(width);

    const TimelineEvaluator::ExportKeys keys = evaluator.exportKeys(channels[which.first()].tracks);
    QVector<qint64> nodes;
    QVector<double> keyTimes; // the key time each node stands for
    QVector<TimelineEvaluator::Segment> segments;
    for (qsizetype i = 0; i < keys.times.size(); ++i) {
        const qint64 n = grid.snap(keys.times[i]);
        if (!nodes.isEmpty() && n <= nodes.last())
            continue; // closer than the grid to the previous key: one key
        if (!nodes.isEmpty())
            segments.append(i - 1 < keys.segments.size() ? keys.segments[i - 1] : TimelineEvaluator::Segment::Mixed);
        nodes.append(n);
        keyTimes.append(keys.times[i]);
    }
    if (nodes.isEmpty() || nodes.first() != 0) {
        nodes.prepend(0);
        keyTimes.prepend(0);
        segments.prepend(TimelineEvaluator::Segment::Mixed);
    }
    if (nodes.last() != grid.steps) {
        nodes.append(grid.steps);
        keyTimes.append(grid.duration);
        segments.append(TimelineEvaluator::Segment::Mixed);
    }
    const QString structureError = ExportText::tr("the drawing changes its structure with the pose");
    if (!table.add(nodes, sampler, which, grid)) {
        *error = structureError;
        return false;
    }

    // Each channel is refined on its own (all share the samples), so a channel that bends
    // (the teeth as the mouth closes) does not add key times to the others.
    struct Span
    {
        qint64 a, b;
        int channel;
        bool ease; // the pose eases over [u0, u1] of one ease
        double u0, u1;
        int checks = 0; // at its quarters (0), eighths (1) or sixteenths (2)
    };
    QVector<QVector<Piece>> pieces(channelCount);
    QVector<Span> pending;
    for (qsizetype s = 0; s < segments.size(); ++s) {
        const qint64 a = nodes[s], b = nodes[s + 1];
        const bool ease = segments[s] == TimelineEvaluator::Segment::Ease;
        // The span of the ease that the grid times cover (a little more or less than all).
        const double length = keyTimes[s + 1] - keyTimes[s];
        const double u0 = ease ? (grid.time(a) - keyTimes[s]) / length : 0.0;
        const double u1 = ease ? (grid.time(b) - keyTimes[s]) / length : 1.0;
        for (int c = 0; c < channelCount; ++c) {
            if (segments[s] == TimelineEvaluator::Segment::Hold
                && std::equal(table.row(a) + starts[c], table.row(a) + starts[c + 1], table.row(b) + starts[c]))
                pieces[c].append({a, b, {}});
            else
                pending.append({a, b, c, ease, u0, u1, ease ? 0 : 1});
        }
    }

    // Spans shorter than this are not split further (a jump becomes a 1 ms ramp).
    const qint64 minSpan = std::max<qint64>(4, qint64(std::ceil(1e-3 / grid.time(1))));
    while (!pending.isEmpty()) {
        if (cancelled(options)) {
            *error = ExportText::tr("cancelled");
            return false;
        }
        // A span over one ease is checked at its quarters: the geometry being linear in the
        // pose between bends, its ease fits everywhere when it fits there, and a bend anywhere
        // shows at them. Where eases overlap the motion is only smooth: such spans are checked
        // at every eighth, and a timing fitted to them (whose two free parameters could meet
        // the checks while missing a bend between them) at every sixteenth.
        auto sixteenths = [](const Span &s) {
            static constexpr int quarters[] = {4, 8, 12};
            static constexpr int eighths[] = {2, 4, 6, 8, 10, 12, 14};
            static constexpr int all[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
            return s.checks == 0 ? std::span<const int>(quarters)
                : s.checks == 1  ? std::span<const int>(eighths)
                                 : std::span<const int>(all);
        };
        QVector<qint64> needed;
        for (const Span &s : pending) {
            if (s.b - s.a >= 16) {
                for (int k : sixteenths(s))
                    needed.append(s.a + (s.b - s.a) * k / 16);
            }
        }
        if (!table.add(needed, sampler, which, grid)) {
            *error = structureError;
            return false;
        }
        QVector<Span> next;
        QVector<qint64> splits;
        for (const Span &s : pending) {
            Timing base = s.ease ? easeTiming(s.u0, s.u1) : Timing {};
            if (s.b - s.a < 16) {
                pieces[s.channel].append({s.a, s.b, base});
                continue;
            }
            const double *a = table.row(s.a);
            const double *b = table.row(s.b);
            Checks checks, quarters;
            for (int k : sixteenths(s)) {
                const qint64 n = s.a + (s.b - s.a) * k / 16;
                const double x = double(n - s.a) / double(s.b - s.a);
                checks.rows[checks.count] = table.row(n);
                checks.x[checks.count++] = x;
                if (k % 4 == 0) {
                    quarters.rows[quarters.count] = table.row(n);
                    quarters.x[quarters.count++] = x;
                }
            }
            // The pose's own ease (or a linear timing where eases overlap) when it fits.
            const Slice slice {starts[s.channel], starts[s.channel + 1], weights};
            double baseError = timingError(base, a, b, checks, slice);
            // The grid trims or stretches an ease by a fraction of a step; the whole ease's
            // spline (written shorter) is taken when it fits as well.
            if (s.ease && (s.u0 != 0.0 || s.u1 != 1.0)) {
                const Timing whole = easeTiming(0.0, 1.0);
                const double wholeError = timingError(whole, a, b, checks, slice);
                if (wholeError <= std::max(baseError, 0.5 * options.tolerance)) {
                    base = whole;
                    baseError = wholeError;
                }
            }
            if (baseError <= options.tolerance) {
                pieces[s.channel].append({s.a, s.b, base});
                continue;
            }
            // Where eases overlap, a fitted timing (checked at every sixteenth first).
            if (!s.ease) {
                const Timing fitted = fittedTiming(a, b, checks, slice);
                if (timingError(fitted, a, b, checks, slice) <= options.tolerance) {
                    if (s.checks == 2) {
                        pieces[s.channel].append({s.a, s.b, fitted});
                    } else {
                        Span closer = s;
                        closer.checks = 2;
                        next.append(closer);
                    }
                    continue;
                }
            }
            if (s.b - s.a <= minSpan) {
                pieces[s.channel].append({s.a, s.b, base});
                continue;
            }
            // Split, where the number that strays most from the span's own timing bends.
            int worst = slice.from;
            double most = -1;
            for (int j = slice.from; j < slice.to; ++j) {
                for (int k = 0; k < quarters.count; ++k) {
                    const double d
                        = weights[j] * std::abs(a[j] + (b[j] - a[j]) * base.at(quarters.x[k]) - quarters.rows[k][j]);
                    if (d > most) {
                        most = d;
                        worst = j;
                    }
                }
            }
            const double x = splitPoint(base, a, b, quarters, worst, weights[worst]);
            const qint64 m = std::clamp(s.a + qint64(std::llround(x * double(s.b - s.a))), s.a + 1, s.b - 1);
            const double um = s.u0 + (s.u1 - s.u0) * double(m - s.a) / double(s.b - s.a);
            next.append({s.a, m, s.channel, s.ease, s.u0, um, s.ease ? 0 : 1});
            next.append({m, s.b, s.channel, s.ease, um, s.u1, s.ease ? 0 : 1});
            splits.append(m);
        }
        if (!table.add(splits, sampler, which, grid)) {
            *error = structureError;
            return false;
        }
        pending = std::move(next);
    }

    // Per channel: quantized values at the piece ends; consecutive pieces on which a channel
    // holds its value merge into one.
    for (int c = 0; c < channelCount; ++c) {
        std::sort(pieces[c].begin(), pieces[c].end(), [](const Piece &p, const Piece &q) { return p.a < q.a; });
        const Channel &channel = channels[which[c]];
        ChannelKeys k;
        k.channel = which[c];
        auto quantized = [&](qint64 n, QVector<qint64> *out) {
            const double *row = table.row(n) + starts[c];
            for (int j = 0; j < channel.size; ++j)
                out->append(channel.grain
                    * quantize(
                        (row[j] - (channel.base.isEmpty() ? 0.0 : channel.base[j])) / channel.grain, channel.decimals));
        };
        QVector<qint64> end;
        k.times.append(0);
        quantized(0, &k.values);
        bool lastHolds = false;
        for (const Piece &p : pieces[c]) {
            end.clear();
            quantized(p.b, &end);
            const bool holds = std::equal(end.cbegin(), end.cend(), k.values.cend() - channel.size);
            if (holds && lastHolds) {
                k.times.last() = p.b;
                continue;
            }
            k.times.append(p.b);
            k.values.append(end);
            k.timings.append(holds ? std::nullopt : std::optional<Timing>(p.timing));
            lastHolds = holds;
        }
        result->append(std::move(k));
    }
    return true;
}

} // namespace toonface::smil
