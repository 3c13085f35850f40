#include "speech/dtw.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace toonface {

namespace {

struct Level
{
    std::vector<float> vectors;
    std::vector<float> silence;
    std::vector<float> pause;
    std::vector<float> pauseAt;
    int frames = 0;
};

// The channels `channels` of each frame of `s` (vectors of `dim` channels).
Level fromSequence(const DtwSequence &s, int dim, const std::vector<int> &channels)
{
    Level l;
    l.frames = s.frames;
    l.vectors.resize(size_t(s.frames) * channels.size());
    for (int t = 0; t < s.frames; ++t)
        for (size_t c = 0; c < channels.size(); ++c)
            l.vectors[size_t(t) * channels.size() + c] = s.vectors[size_t(t) * size_t(dim) + size_t(channels[c])];
    if (s.silence)
        l.silence.assign(s.silence, s.silence + s.frames);
    else
        l.silence.assign(size_t(s.frames), 0.0f);
    auto copy = [&](const float *v, std::vector<float> &to) {
        if (v)
            to.assign(v, v + s.frames);
        else
            to.assign(size_t(s.frames), 0.0f);
    };
    copy(s.pause, l.pause);
    copy(s.pauseAt, l.pauseAt);
    return l;
}

// Frame i of `from` halved (the mean of its frames 2i and 2i + 1) into frame i of `to`, which
// may be `from` itself when frames are halved in increasing order: frames 2i and 2i + 1 are
// then not yet overwritten.
void halveFrame(const Level &from, Level &to, int i, int dim)
{
    const int a = 2 * i, b = std::min(2 * i + 1, from.frames - 1);
    for (int d = 0; d < dim; ++d)
        to.vectors[size_t(i) * size_t(dim) + size_t(d)] = 0.5f
            * (from.vectors[size_t(a) * size_t(dim) + size_t(d)] + from.vectors[size_t(b) * size_t(dim) + size_t(d)]);
    to.silence[size_t(i)] = 0.5f * (from.silence[size_t(a)] + from.silence[size_t(b)]);
    to.pause[size_t(i)] = 0.5f * (from.pause[size_t(a)] + from.pause[size_t(b)]);
    // A boundary in either half is a boundary of the coarser frame.
    to.pauseAt[size_t(i)] = std::max(from.pauseAt[size_t(a)], from.pauseAt[size_t(b)]);
}

Level halve(const Level &l, int dim)
{
    Level h;
    h.frames = (l.frames + 1) / 2;
    h.vectors.assign(size_t(h.frames) * size_t(dim), 0.0f);
    h.silence.assign(size_t(h.frames), 0.0f);
    h.pause.assign(size_t(h.frames), 0.0f);
    h.pauseAt.assign(size_t(h.frames), 0.0f);
    for (int i = 0; i < h.frames; ++i)
        halveFrame(l, h, i, dim);
    return h;
}

// halve() in place, to the same numbers.
void halveInPlace(Level &l, int dim)
{
    const int frames = (l.frames + 1) / 2;
    for (int i = 0; i < frames; ++i)
        halveFrame(l, l, i, dim);
    l.frames = frames;
    l.vectors.resize(size_t(frames) * size_t(dim));
    l.vectors.shrink_to_fit();
    for (std::vector<float> *v : {&l.silence, &l.pause, &l.pauseAt}) {
        v->resize(size_t(frames));
        v->shrink_to_fit();
    }
}

// Level `level` (>= 1) of the finest level `l0`: halved that many times, the same numbers as
// halving level by level, with only one coarser level held at a time.
Level levelOf(const Level &l0, int level, int dim)
{
    Level l = halve(l0, dim);
    for (int k = 1; k < level; ++k)
        halveInPlace(l, dim);
    return l;
}

using Path = std::vector<std::pair<int, int>>;

// Squared distance of two frames: four running sums, so that the compiler can keep them in
// one vector register.
inline float squaredDistance(const float *x, const float *y, int dim)
{
    float acc[4] = {0, 0, 0, 0};
    int d = 0;
    for (; d + 4 <= dim; d += 4)
        for (int k = 0; k < 4; ++k) {
            const float v = x[d + k] - y[d + k];
            acc[k] += v * v;
        }
    for (; d < dim; ++d) {
        const float v = x[d] - y[d];
        acc[0] += v * v;
    }
    return (acc[0] + acc[1]) + (acc[2] + acc[3]);
}

// Makes the corridor [lo[r], hi[r]] monotone, starting at column 0 and ending at the last.
void monotoneCorridor(std::vector<int> &lo, std::vector<int> &hi, int columns)
{
    const int rows = int(lo.size());
    lo[0] = 0;
    hi[size_t(rows) - 1] = columns - 1;
    for (int r = 1; r < rows; ++r) {
        lo[size_t(r)] = std::max(lo[size_t(r)], lo[size_t(r) - 1]);
        hi[size_t(r)] = std::max(hi[size_t(r)], hi[size_t(r) - 1]);
    }
    for (int r = rows - 2; r >= 0; --r)
        lo[size_t(r)] = std::min(lo[size_t(r)], lo[size_t(r) + 1]);
    for (int r = 0; r < rows; ++r)
        lo[size_t(r)] = std::min(lo[size_t(r)], hi[size_t(r)]);
}

// The costs of one row of the corridor against columns [lo, hi], in loops without a
// dependency from cell to cell (vectorized): `dist` the local distance, `up` the cost of holding
// b's column while a advances, `left` that of holding a's row while b advances.
struct RowCosts
{
    std::vector<float> dist, up, left;
};

// Per frame of a level: what the holds' costs need of it besides its distance.
struct HoldTerms
{
    std::vector<float> open; // 1 - max(pauseAt, pause) * (1 - pauseCost), times silenceCost
};

HoldTerms holdTerms(const Level &l, const DtwOptions &o)
{
    HoldTerms h;
    h.open.resize(size_t(l.frames));
    for (int t = 0; t < l.frames; ++t)
        h.open[size_t(t)]
            = o.silenceCost * (1 - std::max(l.pauseAt[size_t(t)], l.pause[size_t(t)]) * (1 - o.pauseCost));
    return h;
}

void rowCosts(const Level &a, const Level &b, const HoldTerms &termsA, const HoldTerms &termsB, int i, int rowLo,
    int rowHi, const DtwOptions &o, int dim, RowCosts *out)
{
    const size_t w = size_t(rowHi - rowLo + 1);
    out->dist.resize(w);
    out->up.resize(w);
    out->left.resize(w);
    float *dist = out->dist.data();
    float *up = out->up.data();
    float *left = out->left.data();
    const float *va = a.vectors.data() + size_t(i) * size_t(dim);
    const float *vb = b.vectors.data() + size_t(rowLo) * size_t(dim);
    for (size_t c = 0; c < w; ++c)
        dist[c] = squaredDistance(va, vb + c * size_t(dim), dim);
    const float norm = 1.0f / std::sqrt(float(o.dim));
    const float sa = a.silence[size_t(i)], la = a.pause[size_t(i)];
    // A long pause held where the other may pause costs pauseCost, elsewhere silenceCost (a
    // closure there is silent too, but no place for a pause).
    const float pauseA = termsA.open[size_t(i)];
    const float *sb = b.silence.data() + rowLo;
    const float *lb = b.pause.data() + rowLo;
    const float *pauseB = termsB.open.data() + rowLo;
    const float silenceCost = o.silenceCost;
    for (size_t c = 0; c < w; ++c) {
        // Two silences match whatever their noise spectra.
        const float both = sa * sb[c];
        const float d = (1 - both) * std::sqrt(dist[c]) * norm + both * 0.1f * silenceCost;
        dist[c] = d;
        // Holding b while a advances over a's silence (a pause b does not make), and back.
        up[c] = (1 - sa) * d + sa * ((1 - la) * std::min(d, silenceCost) + la * pauseB[c]);
        left[c] = (1 - sb[c]) * d + sb[c] * ((1 - lb[c]) * std::min(d, silenceCost) + lb[c] * pauseA);
    }
}

// The corridor of `width` columns around the line on which both sequences have spoken the
// same share of their speech (frames with silence < 0.5).
void bandCorridor(const Level &ca, const Level &cb, long width, std::vector<int> *lo, std::vector<int> *hi)
{
    std::vector<double> speechB(size_t(cb.frames) + 1, 0.0);
    for (int j = 0; j < cb.frames; ++j)
        speechB[size_t(j) + 1] = speechB[size_t(j)] + (cb.silence[size_t(j)] < 0.5f ? 1.0 : 0.0);
    double totalA = 0;
    for (int i = 0; i < ca.frames; ++i)
        totalA += ca.silence[size_t(i)] < 0.5f ? 1.0 : 0.0;
    const int half = int(width / 2);
    double spokenA = 0;
    for (int i = 0; i < ca.frames; ++i) {
        spokenA += ca.silence[size_t(i)] < 0.5f ? 1.0 : 0.0;
        const double share = totalA > 0 ? spokenA / totalA : double(i + 1) / ca.frames;
        const int centre
            = int(std::lower_bound(speechB.begin(), speechB.end(), share * speechB.back() - 1e-9) - speechB.begin());
        (*lo)[size_t(i)] = std::clamp(centre - half, 0, cb.frames - 1);
        (*hi)[size_t(i)] = std::clamp(centre + half, 0, cb.frames - 1);
    }
    monotoneCorridor(*lo, *hi, cb.frames);
}

// Narrows the corridor [lo, hi] (of a level `level` times halved) to within `radius`
// full-resolution frames of `guide`'s rows (as much as it holds of each row) and keeps it
// monotone.
void guideCorridor(const Path &guide, int level, int radius, int columns, std::vector<int> *lo, std::vector<int> *hi)
{
    const int rows = int(lo->size());
    std::vector<int> glo(size_t(rows), std::numeric_limits<int>::max()), ghi(size_t(rows), -1);
    for (const auto &[i, j] : guide) {
        const int r = std::clamp(i >> level, 0, rows - 1), c = std::clamp(j >> level, 0, columns - 1);
        glo[size_t(r)] = std::min(glo[size_t(r)], c);
        ghi[size_t(r)] = std::max(ghi[size_t(r)], c);
    }
    const int reach = radius >> level;
    // Rows the guide skips (none when it is a warping path of these sequences) take the row before's.
    for (int r = 0; r < rows; ++r) {
        if (ghi[size_t(r)] < 0) {
            glo[size_t(r)] = r > 0 ? glo[size_t(r) - 1] : 0;
            ghi[size_t(r)] = r > 0 ? ghi[size_t(r) - 1] : 0;
        }
    }
    for (int r = 0; r < rows; ++r) {
        const int r0 = std::max(0, r - reach), r1 = std::min(rows - 1, r + reach);
        (*lo)[size_t(r)] = std::max((*lo)[size_t(r)], glo[size_t(r0)] - reach);
        (*hi)[size_t(r)] = std::min((*hi)[size_t(r)], ghi[size_t(r1)] + reach);
        (*lo)[size_t(r)] = std::clamp((*lo)[size_t(r)], 0, columns - 1);
        (*hi)[size_t(r)] = std::clamp((*hi)[size_t(r)], 0, columns - 1);
    }
    monotoneCorridor(*lo, *hi, columns);
}

// DTW inside a corridor: row i of `a` may meet columns [lo[i], hi[i]] of `b`.
// `dim` is the channels per frame of the levels; distances are normalised by o.dim.
Path corridorDtw(const Level &a, const Level &b, const std::vector<int> &lo, const std::vector<int> &hi,
    const DtwOptions &o, int dim, const std::atomic_bool *cancel)
{
    const int n = a.frames;
    std::vector<size_t> offset(size_t(n) + 1, 0);
    for (int i = 0; i < n; ++i)
        offset[size_t(i) + 1] = offset[size_t(i)] + size_t(hi[size_t(i)] - lo[size_t(i)] + 1);
    // Only the steps are kept for the whole corridor; the costs of two rows at a time.
    std::vector<uint8_t> step(offset.back(), 0);
    const float inf = std::numeric_limits<float>::infinity();
    std::vector<float> prev, cur, above;
    const HoldTerms termsA = holdTerms(a, o), termsB = holdTerms(b, o);
    RowCosts costs;
    for (int i = 0; i < n; ++i) {
        if ((i & 255) == 0 && isCancelled(cancel))
            return {};
        const int rowLo = lo[size_t(i)], rowHi = hi[size_t(i)];
        const int prevLo = i > 0 ? lo[size_t(i) - 1] : 0, prevHi = i > 0 ? hi[size_t(i) - 1] : -1;
        const size_t w = size_t(rowHi - rowLo + 1);
        // The row above over columns rowLo - 1 .. rowHi (infinite outside its corridor).
        above.assign(w + 1, inf);
        for (int j = std::max(rowLo - 1, prevLo); j <= std::min(rowHi, prevHi); ++j)
            above[size_t(j - rowLo + 1)] = prev[size_t(j - prevLo)];
        rowCosts(a, b, termsA, termsB, i, rowLo, rowHi, o, dim, &costs);
        cur.resize(w);
        uint8_t *rowStep = step.data() + offset[size_t(i)];
        // The diagonal and vertical steps depend on the row above alone; then the horizontal
        // steps, cell after cell.
        for (size_t c = 0; c < w; ++c) {
            const float diag = above[c] + 2 * costs.dist[c];
            const float up = above[c + 1] + costs.up[c];
            const bool upBetter = up < diag;
            cur[c] = upBetter ? up : diag;
            rowStep[c] = upBetter ? 1 : 0;
        }
        size_t c0 = 1;
        if (i == 0 && rowLo == 0) {
            cur[0] = costs.dist[0];
            rowStep[0] = 3;
        }
        for (size_t c = c0; c < w; ++c) {
            const float left = cur[c - 1] + costs.left[c];
            if (left < cur[c]) {
                cur[c] = left;
                rowStep[c] = 2;
            }
        }
        std::swap(prev, cur);
    }
    Path path;
    int i = n - 1, j = b.frames - 1;
    if (j < lo[size_t(i)] || j > hi[size_t(i)] || !std::isfinite(prev[size_t(j - lo[size_t(i)])]))
        return {};
    while (true) {
        path.emplace_back(i, j);
        const uint8_t s = step[offset[size_t(i)] + size_t(j - lo[size_t(i)])];
        if (s == 3)
            break;
        if (s == 0) {
            --i;
            --j;
        } else if (s == 1) {
            --i;
        } else {
            --j;
        }
    }
    std::reverse(path.begin(), path.end());
    return path;
}

} // namespace

std::vector<std::pair<int, int>> dtwPath(
    const DtwSequence &a, const DtwSequence &b, const DtwOptions &options, const std::atomic_bool *cancel)
{
    if (a.frames <= 0 || b.frames <= 0 || options.dim <= 0)
        return {};
    // Channels that are zero in every frame of both sequences (weighted out) add nothing to
    // any distance: they are left out of the work.
    std::vector<int> channels;
    for (int d = 0; d < options.dim; ++d) {
        bool used = false;
        for (int t = 0; t < a.frames && !used; ++t)
            used = a.vectors[size_t(t) * size_t(options.dim) + size_t(d)] != 0.0f;
        for (int t = 0; t < b.frames && !used; ++t)
            used = b.vectors[size_t(t) * size_t(options.dim) + size_t(d)] != 0.0f;
        if (used)
            channels.push_back(d);
    }
    const int dim = std::max(int(channels.size()), 1);
    if (channels.empty())
        channels.push_back(0);
    std::vector<Level> as {fromSequence(a, options.dim, channels)}, bs {fromSequence(b, options.dim, channels)};
    // Columns a row of the coarsest level may meet: all, or the band's.
    auto width = [&] {
        const long band = 2L * (long(options.band) >> (as.size() - 1)) + 1;
        return options.band > 0 ? std::min(long(bs.back().frames), band) : long(bs.back().frames);
    };
    // Of the levels between the finest and the coarsest none is held: each is made again from
    // the finest when its turn to be refined comes (the coarser levels together are as large as
    // the finest; an hour's recording and reference: 45 MB).
    while (long(as.back().frames) * width() > options.maxFullCells && as.back().frames > 8 && bs.back().frames > 8) {
        if (as.size() == 1) {
            as.push_back(halve(as.back(), dim));
            bs.push_back(halve(bs.back(), dim));
            continue;
        }
        for (std::vector<Level> *levels : {&as, &bs}) {
            Level coarser = std::move(levels->back());
            halveInPlace(coarser, dim);
            levels->back() = Level {};
            levels->push_back(std::move(coarser));
        }
    }
    int level = int(as.size()) - 1;
    const Level &ca = as[size_t(level)], &cb = bs[size_t(level)];
    std::vector<int> lo(size_t(ca.frames), 0), hi(size_t(ca.frames), cb.frames - 1);
    if (width() < cb.frames)
        bandCorridor(ca, cb, width(), &lo, &hi);
    const int guideRadius = std::max(options.guideRadius, 0);
    if (options.guide && !options.guide->empty()) {
        guideCorridor(*options.guide, level, guideRadius, cb.frames, &lo, &hi);
    } else if (options.pilot && ca.frames > 16 && cb.frames > 16) {
        long cells = 0;
        for (int i = 0; i < ca.frames; ++i)
            cells += hi[size_t(i)] - lo[size_t(i)] + 1;
        const long reach = 2L * (guideRadius >> level) + 1;
        if (cells > 4 * reach * ca.frames) {
            // The pilot: the band's search one level coarser, whose path then guides this level.
            const Level pa = halve(ca, dim), pb = halve(cb, dim);
            std::vector<int> plo(size_t(pa.frames), 0), phi(size_t(pa.frames), pb.frames - 1);
            const long band = 2L * (long(options.band) >> (level + 1)) + 1;
            if (options.band > 0 && band < pb.frames)
                bandCorridor(pa, pb, band, &plo, &phi);
            const Path pilot = corridorDtw(pa, pb, plo, phi, options, dim, cancel);
            Path guide;
            guide.reserve(pilot.size() * 4);
            for (const auto &[i, j] : pilot)
                for (int di = 0; di < 2; ++di)
                    for (int dj = 0; dj < 2; ++dj)
                        guide.emplace_back((2 * i + di) << level, (2 * j + dj) << level);
            if (!guide.empty())
                guideCorridor(guide, level, guideRadius, cb.frames, &lo, &hi);
        }
    }
    Path path = corridorDtw(ca, cb, lo, hi, options, dim, cancel);
    const int coarsest = level;
    while (level > 0 && !path.empty()) {
        const int radius = level == coarsest ? std::max(options.radius, options.coarseRadius) : options.radius;
        --level;
        // The coarser levels are done with once their path is known: freed before the finer
        // level's corridor is searched.
        as.resize(size_t(level) + 1);
        bs.resize(size_t(level) + 1);
        if (level > 0 && as[size_t(level)].frames == 0) {
            as[size_t(level)] = levelOf(as[0], level, dim);
            bs[size_t(level)] = levelOf(bs[0], level, dim);
        }
        const Level &fa = as[size_t(level)];
        const Level &fb = bs[size_t(level)];
        std::vector<int> flo(size_t(fa.frames), std::numeric_limits<int>::max()), fhi(size_t(fa.frames), -1);
        for (const auto &[ci, cj] : path) {
            for (int di = 0; di < 2; ++di) {
                const int r = 2 * ci + di;
                if (r >= fa.frames)
                    continue;
                flo[size_t(r)] = std::min(flo[size_t(r)], 2 * cj);
                fhi[size_t(r)] = std::max(fhi[size_t(r)], std::min(2 * cj + 1, fb.frames - 1));
            }
        }
        for (int r = 0; r < fa.frames; ++r) {
            flo[size_t(r)] = std::max(0, flo[size_t(r)] - radius);
            fhi[size_t(r)] = std::min(fb.frames - 1, fhi[size_t(r)] + radius);
        }
        // Also widen along rows: rows within the radius share their corridors.
        std::vector<int> wlo = flo, whi = fhi;
        for (int r = 0; r < fa.frames; ++r) {
            const int r0 = std::max(0, r - radius), r1 = std::min(fa.frames - 1, r + radius);
            wlo[size_t(r)] = flo[size_t(r0)];
            whi[size_t(r)] = fhi[size_t(r1)];
        }
        monotoneCorridor(wlo, whi, fb.frames);
        path = corridorDtw(fa, fb, wlo, whi, options, dim, cancel);
    }
    return path;
}

} // namespace toonface
