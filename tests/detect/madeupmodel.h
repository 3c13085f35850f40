#pragma once

// Small made-up 68-point models in dlib's file format, for the tests of the model's readers
// and its cache.

#include "detect/landmarkmap.h"

#include <QFile>
#include <QString>

#include <dlib/image_processing/shape_predictor.h>
#include <dlib/serialize.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace toonface::testing {

// `cascades` cascades of `trees` trees of depth `depth`, splits and leaves drawn from `seed`;
// `leafSign` -1 flips every leaf, which changes the model but not the size of its file.
// `special` puts values a reader could get wrong among the leaves: zero and minus zero,
// subnormal, huge, infinite.
inline dlib::shape_predictor madeUpModel(
    unsigned seed, int cascades = 3, int trees = 40, int depth = 3, float leafSign = 1, bool special = false)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    dlib::matrix<float, 0, 1> initial(2 * kIbugPointCount);
    for (int i = 0; i < kIbugPointCount; ++i) {
        const double a = 2 * std::numbers::pi * i / kIbugPointCount;
        initial(2 * i) = float(0.5 + 0.35 * std::cos(a));
        initial(2 * i + 1) = float(0.5 + 0.35 * std::sin(a));
    }
    constexpr int kFeatures = 50;
    const float kSpecial[] = {0.0f, -0.0f, 1e-40f, -3e-39f, 3e38f, -1.5e38f, INFINITY, -INFINITY, 1.0f, -0.25f};
    std::vector<std::vector<dlib::impl::regression_tree>> forests(cascades);
    std::vector<std::vector<dlib::vector<float, 2>>> pixels(cascades);
    const int splits = (1 << depth) - 1;
    for (int c = 0; c < cascades; ++c) {
        for (int f = 0; f < kFeatures; ++f)
            pixels[c].emplace_back(unit(random), unit(random));
        for (int t = 0; t < trees; ++t) {
            dlib::impl::regression_tree tree;
            for (int s = 0; s < splits; ++s)
                tree.splits.push_back({random() % kFeatures, random() % kFeatures, 60 * unit(random) - 30});
            for (int l = 0; l <= splits; ++l) {
                dlib::matrix<float, 0, 1> leaf(2 * kIbugPointCount);
                for (long v = 0; v < leaf.size(); ++v)
                    leaf(v) = leafSign * 0.004f * (unit(random) - 0.5f);
                if (special)
                    leaf(random() % leaf.size()) = kSpecial[random() % std::size(kSpecial)];
                tree.leaf_values.push_back(leaf);
            }
            forests[c].push_back(tree);
        }
    }
    return dlib::shape_predictor(initial, forests, pixels);
}

inline void writeModel(const QString &path, const dlib::shape_predictor &model)
{
    dlib::serialize(QFile::encodeName(path).toStdString()) << model;
}

inline void writeModel(
    const QString &path, unsigned seed, int cascades = 3, int trees = 40, int depth = 3, float leafSign = 1)
{
    writeModel(path, madeUpModel(seed, cascades, trees, depth, leafSign));
}

} // namespace toonface::testing
