#include "crossvalidation.h"
#include "likenessage.h"

#include <array>
#include <cmath>
#include <functional>

// The age group models (detect/agegroup.h): class-balanced logistic regressions with an L2
// penalty of 1 on standardised features (the penalty keeps five weights fitted on 21 children
// from swinging with one face), fitted by Newton's method. Cross-validated as shipped: both
// models fitted on four folds (the elderly one on the folds' faces not labelled child), the fifth
// decided child, else elderly, else adult; pooled over ten random stratified splits.

namespace toonface::bench {

namespace {

constexpr int kFolds = 5;
constexpr int kSplits = 10;
constexpr double kPenalty = 1.0;

// Solves a x = b (a small dense system) by Gaussian elimination with partial pivoting.
std::vector<double> solve(std::vector<std::vector<double>> a, std::vector<double> b)
{
    const size_t n = b.size();
    for (size_t c = 0; c < n; ++c) {
        size_t pivot = c;
        for (size_t r = c + 1; r < n; ++r)
            if (std::abs(a[r][c]) > std::abs(a[pivot][c]))
                pivot = r;
        std::swap(a[c], a[pivot]);
        std::swap(b[c], b[pivot]);
        if (std::abs(a[c][c]) < 1e-12)
            continue;
        for (size_t r = c + 1; r < n; ++r) {
            const double f = a[r][c] / a[c][c];
            for (size_t k = c; k < n; ++k)
                a[r][k] -= f * a[c][k];
            b[r] -= f * b[c];
        }
    }
    std::vector<double> x(n, 0.0);
    for (size_t c = n; c-- > 0;) {
        double s = b[c];
        for (size_t k = c + 1; k < n; ++k)
            s -= a[c][k] * x[k];
        x[c] = std::abs(a[c][c]) < 1e-12 ? 0.0 : s / a[c][c];
    }
    return x;
}

// A logistic model on the raw features: bias then one weight per feature.
std::vector<double> fitLogistic(const std::vector<std::vector<double>> &x, const std::vector<bool> &y)
{
    const size_t n = x.size(), d = x.empty() ? 0 : x.front().size();
    std::vector<double> mean(d, 0.0), sd(d, 0.0);
    for (const auto &r : x)
        for (size_t j = 0; j < d; ++j)
            mean[j] += r[j] / double(n);
    for (const auto &r : x)
        for (size_t j = 0; j < d; ++j)
            sd[j] += (r[j] - mean[j]) * (r[j] - mean[j]) / double(n);
    for (double &s : sd)
        s = std::max(1e-9, std::sqrt(s));
    const double positives = double(std::count(y.begin(), y.end(), true));
    const double wPos = double(n) / (2.0 * std::max(1.0, positives));
    const double wNeg = double(n) / (2.0 * std::max(1.0, double(n) - positives));
    std::vector<double> w(d + 1, 0.0); // standardised: bias, weights
    for (int iteration = 0; iteration < 50; ++iteration) {
        std::vector<double> gradient(d + 1, 0.0);
        std::vector<std::vector<double>> hessian(d + 1, std::vector<double>(d + 1, 0.0));
        for (size_t j = 1; j <= d; ++j) {
            gradient[j] = w[j] / kPenalty;
            hessian[j][j] = 1.0 / kPenalty;
        }
        for (size_t i = 0; i < n; ++i) {
            std::vector<double> z(d + 1, 1.0);
            for (size_t j = 0; j < d; ++j)
                z[j + 1] = (x[i][j] - mean[j]) / sd[j];
            double s = 0;
            for (size_t j = 0; j <= d; ++j)
                s += w[j] * z[j];
            const double p = 1.0 / (1.0 + std::exp(-s));
            const double c = y[i] ? wPos : wNeg;
            for (size_t j = 0; j <= d; ++j) {
                gradient[j] += c * (p - double(y[i])) * z[j];
                for (size_t k = 0; k <= d; ++k)
                    hessian[j][k] += c * p * (1 - p) * z[j] * z[k];
            }
        }
        const std::vector<double> step = solve(hessian, gradient);
        double size = 0;
        for (size_t j = 0; j <= d; ++j) {
            w[j] -= step[j];
            size += std::abs(step[j]);
        }
        if (size < 1e-10)
            break;
    }
    // Back onto the raw features.
    std::vector<double> raw(d + 1, 0.0);
    raw[0] = w[0];
    for (size_t j = 0; j < d; ++j) {
        raw[j + 1] = w[j + 1] / sd[j];
        raw[0] -= w[j + 1] * mean[j] / sd[j];
    }
    return raw;
}

template<size_t N>
std::vector<double> features(const AgeEvidence &e, const std::array<const char *, N> &names)
{
    std::vector<double> v;
    for (const char *name : names)
        v.push_back(ageFeature(e, name));
    return v;
}

// Both models fitted on `train` (indices into rows).
AgeModels fitModels(
    const std::vector<AgeRow> &rows, const std::vector<size_t> &train, double childThreshold, double elderlyThreshold)
{
    std::vector<std::vector<double>> xc, xe;
    std::vector<bool> yc, ye;
    for (size_t i : train) {
        const bool child = rows[i].label == QLatin1String("child");
        xc.push_back(features(rows[i].evidence, kChildFeatures));
        yc.push_back(child);
        if (!child) {
            xe.push_back(features(rows[i].evidence, kElderlyFeatures));
            ye.push_back(rows[i].label == QLatin1String("elderly"));
        }
    }
    AgeModels m;
    const std::vector<double> c = fitLogistic(xc, yc), e = fitLogistic(xe, ye);
    std::copy(c.begin(), c.end(), m.child.begin());
    std::copy(e.begin(), e.end(), m.elderly.begin());
    m.childThreshold = childThreshold;
    m.elderlyThreshold = elderlyThreshold;
    return m;
}

int labelIndex(const QString &label)
{
    return int(QStringList {
        QStringLiteral("child"), QStringLiteral("young"), QStringLiteral("adult"), QStringLiteral("elderly")}
                   .indexOf(label));
}

QString counts(const Counts &c)
{
    return QStringLiteral("P %1 R %2 (tp %3 fp %4 fn %5)")
        .arg(c.precision(), 0, 'f', 2)
        .arg(c.recall(), 0, 'f', 2)
        .arg(c.tp)
        .arg(c.fp)
        .arg(c.fn);
}

// Held-out decisions pooled over the splits: per class counts and the confusion (rows: child,
// young, adult, elderly labels; columns: adult, child, elderly decided).
struct HeldOut
{
    Counts child, elderly;
    std::array<std::array<int, 3>, 4> confusion {};
};

HeldOut crossValidate(
    const std::vector<AgeRow> &rows, const std::vector<size_t> &scored, double childThreshold, double elderlyThreshold)
{
    std::vector<int> label;
    for (size_t i : scored)
        label.push_back(labelIndex(rows[i].label));
    HeldOut h;
    for (int s = 0; s < kSplits; ++s) {
        const std::vector<int> fold = stratifiedFolds(label, kFolds, 20261129u + unsigned(s));
        for (int f = 0; f < kFolds; ++f) {
            std::vector<size_t> train, test;
            for (size_t i = 0; i < scored.size(); ++i)
                (fold[i] == f ? test : train).push_back(scored[i]);
            const AgeModels m = fitModels(rows, train, childThreshold, elderlyThreshold);
            for (size_t r : test) {
                const AgeGroup g = decideAge(rows[r].evidence, m).group;
                h.child.add(g == AgeGroup::Child, rows[r].label == QLatin1String("child"));
                h.elderly.add(g == AgeGroup::Elderly, rows[r].label == QLatin1String("elderly"));
                ++h.confusion[size_t(labelIndex(rows[r].label))][size_t(g)];
            }
        }
    }
    return h;
}

} // namespace

QStringList ageReport(const std::vector<AgeRow> &rows)
{
    std::vector<size_t> scored;
    for (size_t i = 0; i < rows.size(); ++i)
        if (rows[i].evidence.measured && labelIndex(rows[i].label) >= 0)
            scored.push_back(i);
    QStringList out;
    if (scored.empty())
        return out;
    // The shipped decision against the labels.
    {
        Counts child, elderly;
        for (size_t i : scored) {
            child.add(rows[i].shipped == AgeGroup::Child, rows[i].label == QLatin1String("child"));
            elderly.add(rows[i].shipped == AgeGroup::Elderly, rows[i].label == QLatin1String("elderly"));
        }
        out << QStringLiteral("age group — as shipped (models fitted on all faces: not held out): child %1; elderly %2")
                   .arg(counts(child), counts(elderly));
    }
    // The thresholds: held-out figures for each pair tried (the shipped pair favours precision).
    out << QStringLiteral("age group — held-out folds (%1-fold, pooled over %2 random splits) by thresholds "
                          "(child, elderly):")
               .arg(kFolds)
               .arg(kSplits);
    for (double ct : {0.5, 0.7, 0.8, 0.9}) {
        for (double et : {0.5, 0.65, 0.75, 0.85}) {
            const HeldOut h = crossValidate(rows, scored, ct, et);
            out << QStringLiteral("  %1 %2: child %3; elderly %4")
                       .arg(ct, 0, 'f', 2)
                       .arg(et, 0, 'f', 2)
                       .arg(counts(h.child), counts(h.elderly));
        }
    }
    const AgeModels shipped = shippedAgeModels();
    const HeldOut h = crossValidate(rows, scored, shipped.childThreshold, shipped.elderlyThreshold);
    out << QStringLiteral("age group — shipped thresholds %1, %2, held out: child %3; elderly %4; rows labelled "
                          "child/young/adult/elderly, columns decided adult/child/elderly:")
               .arg(shipped.childThreshold, 0, 'f', 2)
               .arg(shipped.elderlyThreshold, 0, 'f', 2)
               .arg(counts(h.child), counts(h.elderly));
    const char *names[] = {"child", "young", "adult", "elderly"};
    for (size_t r = 0; r < 4; ++r)
        out << QStringLiteral("  %1 %2 %3 %4")
                   .arg(QLatin1StringView(names[r]), 8)
                   .arg(h.confusion[r][0], 4)
                   .arg(h.confusion[r][1], 4)
                   .arg(h.confusion[r][2], 4);
    // The models fitted on all faces: the coefficients agegroup.cpp ships.
    const AgeModels all = fitModels(rows, scored, shipped.childThreshold, shipped.elderlyThreshold);
    auto list = [](const auto &v) {
        QStringList s;
        for (double x : v)
            s << QString::number(x, 'g', 6);
        return s.join(QStringLiteral(", "));
    };
    out << QStringLiteral("age group — fitted on all %1 faces: child {%2}; elderly {%3}")
               .arg(scored.size())
               .arg(list(all.child), list(all.elderly));
    return out;
}

QStringList browReport(const std::vector<AgeRow> &rows)
{
    auto line = [&](const QString &group, const std::function<bool(const AgeRow &)> &in, bool percentiles) {
        std::vector<double> t, c;
        for (const AgeRow &r : rows)
            if (in(r)) {
                t.push_back(r.browThickness);
                c.push_back(r.browContrast);
            }
        if (t.empty())
            return QString();
        if (!percentiles)
            return QStringLiteral("  %1 (n %2): thickness %3, contrast %4")
                .arg(group)
                .arg(t.size())
                .arg(quantile(t, 0.5), 0, 'f', 3)
                .arg(quantile(c, 0.5), 0, 'f', 1);
        return QStringLiteral("  %1 (n %2): thickness (ES0) %3 / %4 / %5, contrast (L*) %6 / %7 / %8")
            .arg(group)
            .arg(t.size())
            .arg(quantile(t, 0.1), 0, 'f', 3)
            .arg(quantile(t, 0.5), 0, 'f', 3)
            .arg(quantile(t, 0.9), 0, 'f', 3)
            .arg(quantile(c, 0.1), 0, 'f', 1)
            .arg(quantile(c, 0.5), 0, 'f', 1)
            .arg(quantile(c, 0.9), 0, 'f', 1);
    };
    QStringList out {QStringLiteral("brows — measured (browlook.h), 10th / 50th / 90th percentile, then medians "
                                    "by group:")};
    out << line(
        QStringLiteral("all"), [](const AgeRow &) { return true; }, true);
    for (const char *g : {"child", "young", "adult", "elderly"})
        out << line(
            QStringLiteral("age %1").arg(QLatin1StringView(g)),
            [g](const AgeRow &r) { return r.label == QLatin1StringView(g); }, false);
    for (const char *g : {"m", "f"})
        out << line(
            QStringLiteral("sex %1").arg(QLatin1StringView(g)),
            [g](const AgeRow &r) { return r.sex == QLatin1StringView(g); }, false);
    out.removeAll(QString());
    return out;
}

} // namespace toonface::bench
