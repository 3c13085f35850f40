#pragma once

// Small statistics for the likeness benchmarks: precision and recall, a threshold chosen on
// training folds and judged on the held-out fold (stratified k-fold), ROC area, rank correlation.

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <random>
#include <vector>

namespace toonface::bench {

struct Counts
{
    int tp = 0, fp = 0, fn = 0, tn = 0;
    void add(bool predicted, bool truth) { (predicted ? (truth ? tp : fp) : (truth ? fn : tn))++; }
    int n() const { return tp + fp + fn + tn; }
    double precision() const { return tp + fp > 0 ? double(tp) / (tp + fp) : 1.0; }
    double recall() const { return tp + fn > 0 ? double(tp) / (tp + fn) : 1.0; }
    double accuracy() const { return n() > 0 ? double(tp + tn) / n() : 0.0; }
    // F-beta: beta < 1 weighs precision above recall (a drawn feature nobody has is worse than a
    // missed one).
    double fBeta(double beta) const
    {
        const double p = precision(), r = recall(), b2 = beta * beta;
        return tp == 0 ? 0.0 : (1 + b2) * p * r / (b2 * p + r);
    }
};

// Fold (0..k-1) of each row, stratified by `label`: each label's rows shuffled with a fixed seed
// and dealt round the folds, so every fold holds its share of positives.
inline std::vector<int> stratifiedFolds(const std::vector<int> &label, int k, unsigned seed = 20261128)
{
    std::vector<int> fold(label.size(), 0);
    std::mt19937 rng(seed);
    std::vector<int> classes(label);
    std::sort(classes.begin(), classes.end());
    classes.erase(std::unique(classes.begin(), classes.end()), classes.end());
    int next = 0;
    for (int c : classes) {
        std::vector<size_t> rows;
        for (size_t i = 0; i < label.size(); ++i)
            if (label[i] == c)
                rows.push_back(i);
        std::shuffle(rows.begin(), rows.end(), rng);
        for (size_t i : rows)
            fold[i] = next++ % k;
    }
    return fold;
}

// A decision's rule with parameters chosen from candidates: `decide(row, params)`.
struct Rule
{
    std::vector<std::vector<double>> candidates; // per parameter, the values tried
    std::function<bool(size_t row, const std::vector<double> &params)> decide;
};

// The parameters (from the candidates' grid) that maximise `objective` over `rows`; ties go
// to the first found.
inline std::vector<double> fitRule(const Rule &rule, const std::vector<size_t> &rows, const std::vector<bool> &truth,
    const std::function<double(const Counts &)> &objective)
{
    std::vector<double> best, params(rule.candidates.size());
    double bestScore = -1e300;
    std::function<void(size_t)> walk = [&](size_t depth) {
        if (depth == rule.candidates.size()) {
            Counts c;
            for (size_t r : rows)
                c.add(rule.decide(r, params), truth[r]);
            const double s = objective(c);
            if (s > bestScore) {
                bestScore = s;
                best = params;
            }
            return;
        }
        for (double v : rule.candidates[depth]) {
            params[depth] = v;
            walk(depth + 1);
        }
    };
    walk(0);
    return best;
}

// Candidate thresholds: the midpoints between consecutive distinct values (at most `most`,
// evenly through them), one below all and one above all.
inline std::vector<double> thresholdsFrom(std::vector<double> v, size_t most = 40)
{
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    std::vector<double> mids;
    if (v.empty())
        return {0.0};
    for (size_t i = 0; i + 1 < v.size(); ++i)
        mids.push_back((v[i] + v[i + 1]) / 2.0);
    std::vector<double> out {v.front() - 1e-9};
    if (mids.size() <= most)
        out.insert(out.end(), mids.begin(), mids.end());
    else
        for (size_t i = 0; i < most; ++i)
            out.push_back(mids[i * (mids.size() - 1) / (most - 1)]);
    out.push_back(v.back() + 1e-9);
    return out;
}

// Area under the ROC curve of `score` for `truth` over `rows` (0.5: no better than chance).
inline double rocArea(const std::vector<double> &score, const std::vector<bool> &truth, const std::vector<size_t> &rows)
{
    double pairs = 0, wins = 0;
    for (size_t i : rows) {
        if (!truth[i])
            continue;
        for (size_t j : rows) {
            if (truth[j])
                continue;
            pairs += 1;
            wins += score[i] > score[j] ? 1.0 : score[i] == score[j] ? 0.5 : 0.0;
        }
    }
    return pairs > 0 ? wins / pairs : 0.5;
}

inline std::vector<double> ranks(const std::vector<double> &v)
{
    std::vector<size_t> order(v.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return v[a] < v[b]; });
    std::vector<double> r(v.size());
    for (size_t i = 0; i < order.size();) {
        size_t j = i;
        while (j + 1 < order.size() && v[order[j + 1]] == v[order[i]])
            ++j;
        for (size_t k = i; k <= j; ++k)
            r[order[k]] = (double(i) + double(j)) / 2.0;
        i = j + 1;
    }
    return r;
}

inline double spearman(const std::vector<double> &a, const std::vector<double> &b)
{
    if (a.size() < 2 || a.size() != b.size())
        return 0;
    const std::vector<double> ra = ranks(a), rb = ranks(b);
    const double ma = std::accumulate(ra.begin(), ra.end(), 0.0) / double(ra.size());
    const double mb = std::accumulate(rb.begin(), rb.end(), 0.0) / double(rb.size());
    double sab = 0, saa = 0, sbb = 0;
    for (size_t i = 0; i < ra.size(); ++i) {
        sab += (ra[i] - ma) * (rb[i] - mb);
        saa += (ra[i] - ma) * (ra[i] - ma);
        sbb += (rb[i] - mb) * (rb[i] - mb);
    }
    return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : 0.0;
}

inline double quantile(std::vector<double> v, double q)
{
    if (v.empty())
        return 0;
    std::sort(v.begin(), v.end());
    return v[size_t(std::lround(q * double(v.size() - 1)))];
}

} // namespace toonface::bench
