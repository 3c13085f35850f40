#include "detect/landmarkpredictor.h"

#include "detect/grayview.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <dlib/image_processing/shape_predictor.h>
#include <dlib/serialize.h>

#include <cmath>
#include <fstream>

namespace toonface {

// One cascade of the model: the pixels its features read (each an anchor point of the shape
// and an offset from it in the mean shape's unit square), and its trees, all of one depth:
// the splits of tree t at t * splitsPerTree (pairs of feature indices and a threshold on the
// difference), its leaves (shape corrections of 2 x 68 floats) at t * leavesPerTree.
struct LandmarkPredictor::Cascade
{
    std::vector<unsigned long> anchors;
    std::vector<dlib::vector<float, 2>> deltas;
    int trees = 0;
    int splitsPerTree = 0;
    std::vector<quint16> splitFeatures; // two per split
    std::vector<float> thresholds;
    std::vector<float> leaves;
};

LandmarkPredictor::LandmarkPredictor() = default;
LandmarkPredictor::~LandmarkPredictor() = default;

namespace {

constexpr int kShapeValues = 2 * kIbugPointCount;

// Reads a cascade's forest tree by tree (dlib writes a vector as its length, then its items),
// so that only the flat copy is ever whole in memory.
void readForest(std::istream &in, std::vector<int> *treeCounts, std::vector<std::vector<float>> *leaves,
    std::vector<std::vector<quint16>> *features, std::vector<std::vector<float>> *thresholds,
    std::vector<int> *splitsPerTree)
{
    unsigned long cascades = 0;
    dlib::deserialize(cascades, in);
    if (cascades == 0 || cascades > 1000)
        throw dlib::serialization_error("implausible number of cascades");
    for (unsigned long c = 0; c < cascades; ++c) {
        unsigned long trees = 0;
        dlib::deserialize(trees, in);
        if (trees == 0 || trees > 100000)
            throw dlib::serialization_error("implausible number of trees");
        treeCounts->push_back(int(trees));
        leaves->emplace_back();
        features->emplace_back();
        thresholds->emplace_back();
        splitsPerTree->push_back(-1);
        for (unsigned long t = 0; t < trees; ++t) {
            dlib::impl::regression_tree tree;
            deserialize(tree, in); // the tree's own reader, found by argument-dependent lookup
            const int splits = int(tree.splits.size());
            if (splitsPerTree->back() < 0)
                splitsPerTree->back() = splits;
            if (splits != splitsPerTree->back() || tree.leaf_values.size() != tree.splits.size() + 1)
                throw dlib::serialization_error("trees of a cascade differ in depth");
            for (const auto &s : tree.splits) {
                if (s.idx1 > 0xffff || s.idx2 > 0xffff)
                    throw dlib::serialization_error("a split reads a feature out of range");
                features->back().push_back(quint16(s.idx1));
                features->back().push_back(quint16(s.idx2));
                thresholds->back().push_back(s.thresh);
            }
            for (const auto &leaf : tree.leaf_values) {
                if (leaf.size() != kShapeValues)
                    throw dlib::serialization_error("a leaf is not a 68-point shape");
                leaves->back().insert(leaves->back().end(), leaf.begin(), leaf.end());
            }
        }
    }
}

} // namespace

std::shared_ptr<const LandmarkPredictor> LandmarkPredictor::read(const QString &path, QString *error)
{
    auto fail = [&](const QString &why) {
        if (error)
            *error = QStringLiteral("The landmark model %1 %2").arg(QDir::toNativeSeparators(path), why);
        return std::shared_ptr<const LandmarkPredictor>();
    };
    const QFileInfo info(path);
    if (!info.isFile() || !info.isReadable())
        return fail(QStringLiteral("is missing (install the package libdlib-data, or set "
                                   "TOONFACE_LANDMARK_MODEL to shape_predictor_68_face_landmarks.dat)."));

    std::shared_ptr<LandmarkPredictor> model(new LandmarkPredictor);
    try {
        std::ifstream in(QFile::encodeName(path).toStdString(), std::ios::binary);
        if (!in)
            return fail(QStringLiteral("could not be opened."));
        int version = 0;
        dlib::deserialize(version, in);
        if (version != 1)
            throw dlib::serialization_error("unknown format version " + std::to_string(version));
        dlib::matrix<float, 0, 1> initial;
        dlib::deserialize(initial, in);
        if (initial.size() != kShapeValues)
            return fail(QStringLiteral("gives %1 points, not the 68 of the iBUG scheme.").arg(initial.size() / 2));
        std::vector<int> treeCounts, splitsPerTree;
        std::vector<std::vector<float>> leaves, thresholds;
        std::vector<std::vector<quint16>> features;
        readForest(in, &treeCounts, &leaves, &features, &thresholds, &splitsPerTree);
        std::vector<std::vector<unsigned long>> anchors;
        std::vector<std::vector<dlib::vector<float, 2>>> deltas;
        dlib::deserialize(anchors, in);
        dlib::deserialize(deltas, in);
        if (anchors.size() != treeCounts.size() || deltas.size() != treeCounts.size())
            throw dlib::serialization_error("pixel features do not match the cascades");

        model->m_initial.assign(initial.begin(), initial.end());
        for (int i = 0; i < kIbugPointCount; ++i)
            model->m_meanShape[i] = QPointF(initial(2 * i), initial(2 * i + 1));
        for (size_t c = 0; c < treeCounts.size(); ++c) {
            Cascade cascade;
            if (anchors[c].size() != deltas[c].size())
                throw dlib::serialization_error("pixel features do not match their anchors");
            for (unsigned long a : anchors[c]) {
                if (a >= unsigned(kIbugPointCount))
                    throw dlib::serialization_error("a pixel feature is anchored to no point");
            }
            for (quint16 f : features[c]) {
                if (f >= anchors[c].size())
                    throw dlib::serialization_error("a split reads a feature out of range");
            }
            cascade.anchors = std::move(anchors[c]);
            cascade.deltas = std::move(deltas[c]);
            cascade.trees = treeCounts[c];
            cascade.splitsPerTree = splitsPerTree[c];
            cascade.splitFeatures = std::move(features[c]);
            cascade.thresholds = std::move(thresholds[c]);
            cascade.leaves = std::move(leaves[c]);
            model->m_cascades.push_back(std::move(cascade));
        }
    } catch (const std::exception &e) {
        return fail(QStringLiteral("could not be read: %1").arg(QString::fromLocal8Bit(e.what()).trimmed()));
    }
    return model;
}

LandmarkPredictor::Shape LandmarkPredictor::predict(const GrayView &image, const QRect &box) const
{
    const dlib::rectangle rect(box.left(), box.top(), box.right(), box.bottom());
    dlib::matrix<float, 0, 1> initial(kShapeValues);
    std::copy(m_initial.begin(), m_initial.end(), initial.begin());
    dlib::matrix<float, 0, 1> shape = initial;
    std::vector<float> features;
    std::vector<const float *> chosen;
    for (const Cascade &c : m_cascades) {
        dlib::impl::extract_feature_pixel_values(image, rect, shape, initial, c.anchors, c.deltas, features);
        // Every tree's leaf first: a split compares two of the cascade's pixel features.
        chosen.resize(c.trees);
        const int leavesPerTree = c.splitsPerTree + 1;
        for (int t = 0; t < c.trees; ++t) {
            const quint16 *f = c.splitFeatures.data() + 2 * size_t(t) * c.splitsPerTree;
            const float *thresh = c.thresholds.data() + size_t(t) * c.splitsPerTree;
            int node = 0;
            while (node < c.splitsPerTree)
                node = features[f[2 * node]] - features[f[2 * node + 1]] > thresh[node] ? 2 * node + 1 : 2 * node + 2;
            chosen[t] = c.leaves.data() + (size_t(t) * leavesPerTree + size_t(node - c.splitsPerTree)) * kShapeValues;
        }
        // Then their sum, asking for a leaf a few trees ahead of the one being added.
        constexpr int kAhead = 4;
        float *__restrict sum = &shape(0);
        for (int t = 0; t < c.trees; ++t) {
            if (t + kAhead < c.trees) {
                const char *next = reinterpret_cast<const char *>(chosen[t + kAhead]);
                for (size_t byte = 0; byte < kShapeValues * sizeof(float); byte += 64)
                    __builtin_prefetch(next + byte);
            }
            const float *__restrict leaf = chosen[t];
            for (int i = 0; i < kShapeValues; ++i)
                sum[i] += leaf[i];
        }
    }
    const dlib::point_transform_affine toImage = dlib::impl::unnormalizing_tform(rect);
    Shape out {};
    for (int i = 0; i < kIbugPointCount; ++i) {
        const dlib::dpoint p = toImage(dlib::dpoint(shape(2 * i), shape(2 * i + 1)));
        out[i] = QPointF(p.x(), p.y());
    }
    return out;
}

} // namespace toonface
