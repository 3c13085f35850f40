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
    return l;
}

Level halve(const Level &l, int dim)
{
    Level h;
    h.frames = (l.frames + 1) / 2;
    h.vectors.assign(size_t(h.frames) * size_t(dim), 0.0f);
    h.silence.assign(size_t(h.frames), 0.0f);
    for (int i = 0; i < h.frames; ++i) {
        const int a = 2 * i, b = std::min(2 * i + 1, l.frames - 1);
        for (int d = 0; d < dim; ++d)
            h.vectors[size_t(i) * size_t(dim) + size_t(d)] = 0.5f
                * (l.vectors[size_t(a) * size_t(dim) + size_t(d)] + l.vectors[size_t(b) * size_t(dim) + size_t(d)]);
        h.silence[size_t(i)] = 0.5f * (l.silence[size_t(a)] + l.silence[size_t(b)]);
    }
    return h;
}

using Path = std::vector<std::pair<int, int>>;

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
    std::vector<float> prev, cur;
    const float norm = 1.0f / std::sqrt(float(o.dim));
    for (int i = 0; i < n; ++i) {
        if ((i & 255) == 0 && isCancelled(cancel))
            return {};
        const int rowLo = lo[size_t(i)], rowHi = hi[size_t(i)];
        const int prevLo = i > 0 ? lo[size_t(i) - 1] : 0, prevHi = i > 0 ? hi[size_t(i) - 1] : -1;
        auto above = [&](int j) { return j < prevLo || j > prevHi ? inf : prev[size_t(j - prevLo)]; };
        cur.assign(size_t(rowHi - rowLo + 1), inf);
        const float *va = a.vectors.data() + size_t(i) * size_t(dim);
        const float sa = a.silence[size_t(i)];
        for (int j = rowLo; j <= rowHi; ++j) {
            const float *vb = b.vectors.data() + size_t(j) * size_t(dim);
            float acc = 0;
            for (int d = 0; d < dim; ++d) {
                const float x = va[d] - vb[d];
                acc += x * x;
            }
            const float sb = b.silence[size_t(j)];
            // Two silences match whatever their noise spectra.
            const float both = sa * sb;
            const float dist = (1 - both) * std::sqrt(acc) * norm + both * 0.1f * o.silenceCost;
            // Holding b while a advances over a's silence (a pause b does not make), and back.
            const float holdB = (1 - sa) * dist + sa * std::min(dist, o.silenceCost);
            const float holdA = (1 - sb) * dist + sb * std::min(dist, o.silenceCost);
            float best;
            uint8_t s;
            if (i == 0 && j == 0) {
                best = dist;
                s = 3;
            } else {
                const float diag = above(j - 1) + 2 * dist;
                const float up = above(j) + holdB;
                const float left = j > rowLo ? cur[size_t(j - 1 - rowLo)] + holdA : inf;
                best = diag;
                s = 0;
                if (up < best) {
                    best = up;
                    s = 1;
                }
                if (left < best) {
                    best = left;
                    s = 2;
                }
            }
            cur[size_t(j - rowLo)] = best;
            step[offset[size_t(i)] + size_t(j - rowLo)] = s;
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
    while (long(as.back().frames) * long(bs.back().frames) > options.maxFullCells && as.back().frames > 8
        && bs.back().frames > 8) {
        as.push_back(halve(as.back(), dim));
        bs.push_back(halve(bs.back(), dim));
    }
    int level = int(as.size()) - 1;
    std::vector<int> lo(size_t(as[size_t(level)].frames), 0),
        hi(size_t(as[size_t(level)].frames), bs[size_t(level)].frames - 1);
    Path path = corridorDtw(as[size_t(level)], bs[size_t(level)], lo, hi, options, dim, cancel);
    while (level > 0 && !path.empty()) {
        --level;
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
            flo[size_t(r)] = std::max(0, flo[size_t(r)] - options.radius);
            fhi[size_t(r)] = std::min(fb.frames - 1, fhi[size_t(r)] + options.radius);
        }
        // Also widen along rows: rows within the radius share their corridors.
        std::vector<int> wlo = flo, whi = fhi;
        for (int r = 0; r < fa.frames; ++r) {
            const int r0 = std::max(0, r - options.radius), r1 = std::min(fa.frames - 1, r + options.radius);
            wlo[size_t(r)] = flo[size_t(r0)];
            whi[size_t(r)] = fhi[size_t(r1)];
        }
        // Monotone corridor that starts at column 0 and ends at the last column.
        wlo[0] = 0;
        whi[size_t(fa.frames) - 1] = fb.frames - 1;
        for (int r = 1; r < fa.frames; ++r) {
            wlo[size_t(r)] = std::max(wlo[size_t(r)], wlo[size_t(r) - 1]);
            whi[size_t(r)] = std::max(whi[size_t(r)], whi[size_t(r) - 1]);
        }
        for (int r = fa.frames - 2; r >= 0; --r)
            wlo[size_t(r)] = std::min(wlo[size_t(r)], wlo[size_t(r) + 1]);
        for (int r = 0; r < fa.frames; ++r)
            wlo[size_t(r)] = std::min(wlo[size_t(r)], whi[size_t(r)]);
        path = corridorDtw(fa, fb, wlo, whi, options, dim, cancel);
    }
    return path;
}

} // namespace toonface
