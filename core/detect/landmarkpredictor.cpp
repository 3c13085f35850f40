#include "detect/landmarkpredictor.h"

#include "detect/grayview.h"
#include "detect/landmarkflat.h"
#include "detect/shapemodelfile.h"
#include "i18n/coretext.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <dlib/image_processing/shape_predictor.h>
#include <dlib/serialize.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <new>
#include <tuple>

namespace toonface {

// One cascade of the model: the pixels its features read (each an anchor point of the shape
// and an offset from it in the mean shape's unit square), and its trees, all of one depth:
// the splits of tree t at t * splitsPerTree (pairs of feature indices and a threshold on the
// difference), its leaves (shape corrections of 2 x 68 floats) at t * leavesPerTree. The
// arrays of splits and leaves lie in the model's block; the pixel features (a few hundred) are
// copied into the vectors dlib's feature extraction takes.
struct LandmarkPredictor::Cascade
{
    std::vector<unsigned long> anchors;
    std::vector<dlib::vector<float, 2>> deltas;
    int trees = 0;
    int splitsPerTree = 0;
    const quint16 *splitFeatures = nullptr; // two per split
    const float *thresholds = nullptr;
    const float *leaves = nullptr;
};

LandmarkPredictor::LandmarkPredictor() = default;
LandmarkPredictor::~LandmarkPredictor() = default;

namespace {

QString missingText()
{
    return DetectText::tr("is missing (install the package libdlib-data, or set "
                          "TOONFACE_LANDMARK_MODEL to shape_predictor_68_face_landmarks.dat).");
}

using flat::alignUp;
using flat::kMagic;
using flat::kMaxCascades;
using flat::kMaxFeatures;
using flat::kMaxSplitsPerTree;
using flat::kMaxTrees;
using flat::kSectionAlignment;
using flat::kShapeValues;
using flat::kVersion;

// The shape lives in the face box's normalised frame (about 0..1): a value far outside it, or one
// that is not a number, comes from a damaged model. Positions that large would overflow the
// integer pixel coordinates dlib turns them into.
constexpr float kMaxShapeValue = 1000;

bool plausible(float v)
{
    return std::isfinite(v) && std::abs(v) <= kMaxShapeValue;
}

// A cascade as read from dlib's file, before it is laid out in a block.
struct ReadCascade
{
    int trees = 0;
    int splitsPerTree = -1;
    std::vector<quint16> features; // two per split
    std::vector<float> thresholds;
    std::vector<float> leaves;
    std::vector<unsigned long> anchors;
    std::vector<dlib::vector<float, 2>> deltas;
};

// Reads a cascade's forest tree by tree (dlib writes a vector as its length, then its items),
// so that only the flat copy is ever whole in memory.
void readForest(std::istream &in, std::vector<ReadCascade> *cascades)
{
    unsigned long count = 0;
    dlib::deserialize(count, in);
    if (count == 0 || count > kMaxCascades)
        throw dlib::serialization_error("implausible number of cascades");
    for (unsigned long c = 0; c < count; ++c) {
        unsigned long trees = 0;
        dlib::deserialize(trees, in);
        if (trees == 0 || trees > kMaxTrees)
            throw dlib::serialization_error("implausible number of trees");
        ReadCascade &cascade = cascades->emplace_back();
        cascade.trees = int(trees);
        for (unsigned long t = 0; t < trees; ++t) {
            dlib::impl::regression_tree tree;
            deserialize(tree, in); // the tree's own reader, found by argument-dependent lookup
            const int splits = int(tree.splits.size());
            if (cascade.splitsPerTree < 0)
                cascade.splitsPerTree = splits;
            if (splits != cascade.splitsPerTree || tree.leaf_values.size() != tree.splits.size() + 1
                || tree.splits.size() > kMaxSplitsPerTree)
                throw dlib::serialization_error("trees of a cascade differ in depth");
            for (const auto &s : tree.splits) {
                if (s.idx1 >= kMaxFeatures || s.idx2 >= kMaxFeatures)
                    throw dlib::serialization_error("a split reads a feature out of range");
                cascade.features.push_back(quint16(s.idx1));
                cascade.features.push_back(quint16(s.idx2));
                cascade.thresholds.push_back(s.thresh);
            }
            for (const auto &leaf : tree.leaf_values) {
                if (leaf.size() != kShapeValues)
                    throw dlib::serialization_error("a leaf is not a 68-point shape");
                cascade.leaves.insert(cascade.leaves.end(), leaf.begin(), leaf.end());
            }
        }
    }
}

// A block of `size` bytes aligned as the sections are, zeroed (the padding between sections
// is part of the cache file).
std::shared_ptr<std::byte> alignedBlock(size_t size)
{
    auto *bytes = static_cast<std::byte *>(::operator new(size, std::align_val_t(kSectionAlignment)));
    std::fill(bytes, bytes + size, std::byte(0));
    return std::shared_ptr<std::byte>(
        bytes, [](std::byte *p) { ::operator delete(p, std::align_val_t(kSectionAlignment)); });
}

// Lays out a model read from dlib's file in one block (the layout of flat::Header).
std::pair<std::shared_ptr<std::byte>, size_t> layOut(
    const dlib::matrix<float, 0, 1> &initial, const std::vector<ReadCascade> &cascades)
{
    flat::Header header {};
    std::copy(std::begin(kMagic), std::end(kMagic), header.magic);
    header.version = kVersion;
    header.points = kIbugPointCount;
    header.cascades = quint32(cascades.size());
    size_t at = alignUp(sizeof(flat::Header));
    header.initialAt = at;
    at = alignUp(at + kShapeValues * sizeof(float));
    header.tableAt = at;
    at = alignUp(at + cascades.size() * sizeof(flat::Cascade));
    // In the order of dlib's file, as shapemodelfile.cpp lays them out: each cascade's trees,
    // then every cascade's anchors, then every cascade's offsets.
    std::vector<flat::Cascade> table;
    for (const ReadCascade &c : cascades) {
        flat::Cascade entry {};
        entry.trees = quint32(c.trees);
        entry.splitsPerTree = quint32(c.splitsPerTree);
        entry.features = quint32(c.anchors.size());
        entry.splitFeaturesAt = at;
        at = alignUp(at + c.features.size() * sizeof(quint16));
        entry.thresholdsAt = at;
        at = alignUp(at + c.thresholds.size() * sizeof(float));
        entry.leavesAt = at;
        at = alignUp(at + c.leaves.size() * sizeof(float));
        table.push_back(entry);
    }
    for (flat::Cascade &entry : table) {
        entry.anchorsAt = at;
        at = alignUp(at + entry.features * sizeof(quint32));
    }
    size_t end = at;
    for (flat::Cascade &entry : table) {
        entry.deltasAt = alignUp(end);
        end = entry.deltasAt + entry.features * 2 * sizeof(float);
    }
    // The block ends where its last array does: a block cut short is one missing data.
    const size_t size = end;
    std::shared_ptr<std::byte> block = alignedBlock(size);
    std::byte *out = block.get();
    auto put = [out](quint64 offset, const void *data, size_t bytes) {
        if (bytes > 0) // an empty array's data() may be null
            std::memcpy(out + offset, data, bytes);
    };
    put(0, &header, sizeof header);
    put(header.initialAt, &initial(0), kShapeValues * sizeof(float));
    put(header.tableAt, table.data(), table.size() * sizeof(flat::Cascade));
    for (size_t i = 0; i < cascades.size(); ++i) {
        const ReadCascade &c = cascades[i];
        const flat::Cascade &e = table[i];
        std::vector<quint32> anchors(c.anchors.begin(), c.anchors.end());
        std::vector<float> deltas;
        for (const auto &d : c.deltas) {
            deltas.push_back(d.x());
            deltas.push_back(d.y());
        }
        put(e.anchorsAt, anchors.data(), anchors.size() * sizeof(quint32));
        put(e.deltasAt, deltas.data(), deltas.size() * sizeof(float));
        put(e.splitFeaturesAt, c.features.data(), c.features.size() * sizeof(quint16));
        put(e.thresholdsAt, c.thresholds.data(), c.thresholds.size() * sizeof(float));
        put(e.leavesAt, c.leaves.data(), c.leaves.size() * sizeof(float));
    }
    return {block, size};
}

// `count` items of T at `offset` of the block, or nullptr when they do not lie wholly in it or
// are not aligned for T.
template<typename T>
const T *section(std::span<const std::byte> block, quint64 offset, quint64 count)
{
    if (offset > block.size() || offset % alignof(T) != 0 || count > (block.size() - offset) / sizeof(T))
        return nullptr;
    return reinterpret_cast<const T *>(block.data() + offset);
}

} // namespace

std::shared_ptr<const LandmarkPredictor> LandmarkPredictor::read(const QString &path, QString *error)
{
    auto fail = [&](const QString &why) {
        if (error)
            *error = DetectText::tr("The landmark model %1 %2").arg(QDir::toNativeSeparators(path), why);
        return std::shared_ptr<const LandmarkPredictor>();
    };
    const QFileInfo info(path);
    if (!info.isFile() || !info.isReadable())
        return fail(missingText());
    const ShapeModelFile file = readShapeModelFile(path);
    if (file.status == ShapeModelFile::Status::OldFormat)
        return readThroughDlib(path, error);
    if (file.status != ShapeModelFile::Status::Read)
        return fail(file.error);
    QString why;
    auto model = fromFlat(file.owner, file.block, &why);
    if (!model)
        return fail(DetectText::tr("could not be read: %1").arg(why));
    return model;
}

std::shared_ptr<const LandmarkPredictor> LandmarkPredictor::readThroughDlib(const QString &path, QString *error)
{
    auto fail = [&](const QString &why) {
        if (error)
            *error = DetectText::tr("The landmark model %1 %2").arg(QDir::toNativeSeparators(path), why);
        return std::shared_ptr<const LandmarkPredictor>();
    };
    const QFileInfo info(path);
    if (!info.isFile() || !info.isReadable())
        return fail(missingText());

    std::shared_ptr<std::byte> block;
    size_t size = 0;
    try {
        std::ifstream in(QFile::encodeName(path).toStdString(), std::ios::binary);
        if (!in)
            return fail(DetectText::tr("could not be opened."));
        int version = 0;
        dlib::deserialize(version, in);
        if (version != 1)
            throw dlib::serialization_error("unknown format version " + std::to_string(version));
        dlib::matrix<float, 0, 1> initial;
        dlib::deserialize(initial, in);
        if (initial.size() != kShapeValues)
            return fail(DetectText::tr("gives %1 points, not the 68 of the iBUG scheme.").arg(initial.size() / 2));
        std::vector<ReadCascade> cascades;
        readForest(in, &cascades);
        std::vector<std::vector<unsigned long>> anchors;
        std::vector<std::vector<dlib::vector<float, 2>>> deltas;
        dlib::deserialize(anchors, in);
        dlib::deserialize(deltas, in);
        if (anchors.size() != cascades.size() || deltas.size() != cascades.size())
            throw dlib::serialization_error("pixel features do not match the cascades");
        for (size_t c = 0; c < cascades.size(); ++c) {
            if (anchors[c].size() != deltas[c].size() || anchors[c].size() > kMaxFeatures)
                throw dlib::serialization_error("pixel features do not match their anchors");
            cascades[c].anchors = std::move(anchors[c]);
            cascades[c].deltas = std::move(deltas[c]);
        }
        std::tie(block, size) = layOut(initial, cascades);
    } catch (const std::exception &e) {
        return fail(DetectText::tr("could not be read: %1").arg(QString::fromLocal8Bit(e.what()).trimmed()));
    }
    QString why;
    auto model = fromFlat(block, std::span<const std::byte>(block.get(), size), &why);
    if (!model)
        return fail(DetectText::tr("could not be read: %1").arg(why));
    return model;
}

std::shared_ptr<const LandmarkPredictor> LandmarkPredictor::fromFlat(
    std::shared_ptr<const void> owner, std::span<const std::byte> block, QString *error)
{
    auto fail = [&](const char *why) {
        if (error)
            *error = QString::fromLatin1(why);
        return std::shared_ptr<const LandmarkPredictor>();
    };
    flat::Header header {};
    if (block.size() < sizeof header)
        return fail("the block is shorter than its header");
    std::memcpy(&header, block.data(), sizeof header);
    if (!std::equal(std::begin(kMagic), std::end(kMagic), header.magic))
        return fail("the block is not a landmark model");
    if (header.version != kVersion)
        return fail("the block has another layout version");
    if (header.points != kIbugPointCount)
        return fail("the model is not one of the 68 iBUG points");
    if (header.cascades == 0 || header.cascades > kMaxCascades)
        return fail("implausible number of cascades");
    const float *initial = section<float>(block, header.initialAt, kShapeValues);
    const auto *tableBytes
        = section<std::byte>(block, header.tableAt, quint64(header.cascades) * sizeof(flat::Cascade));
    if (!initial || !tableBytes)
        return fail("the mean shape or the table of cascades lies outside the block");
    if (!std::all_of(initial, initial + kShapeValues, plausible))
        return fail("the mean shape holds a value that is not a plausible position");

    std::shared_ptr<LandmarkPredictor> model(new LandmarkPredictor);
    model->m_initial.assign(initial, initial + kShapeValues);
    for (int i = 0; i < kIbugPointCount; ++i)
        model->m_meanShape[i] = QPointF(initial[2 * i], initial[2 * i + 1]);
    for (quint32 c = 0; c < header.cascades; ++c) {
        flat::Cascade e {};
        std::memcpy(&e, tableBytes + c * sizeof(flat::Cascade), sizeof e);
        if (e.trees == 0 || e.trees > kMaxTrees || e.splitsPerTree > kMaxSplitsPerTree || e.features > kMaxFeatures)
            return fail("a cascade has implausible counts");
        const quint64 splits = quint64(e.trees) * e.splitsPerTree;
        const quint64 leaves = quint64(e.trees) * (e.splitsPerTree + 1) * kShapeValues;
        const quint32 *anchors = section<quint32>(block, e.anchorsAt, e.features);
        const float *deltas = section<float>(block, e.deltasAt, 2 * quint64(e.features));
        Cascade cascade;
        cascade.trees = int(e.trees);
        cascade.splitsPerTree = int(e.splitsPerTree);
        cascade.splitFeatures = section<quint16>(block, e.splitFeaturesAt, 2 * splits);
        cascade.thresholds = section<float>(block, e.thresholdsAt, splits);
        cascade.leaves = section<float>(block, e.leavesAt, leaves);
        if (!anchors || !deltas || !cascade.splitFeatures || !cascade.thresholds || !cascade.leaves)
            return fail("a cascade's arrays lie outside the block");
        for (quint32 f = 0; f < e.features; ++f) {
            if (anchors[f] >= quint32(kIbugPointCount))
                return fail("a pixel feature is anchored to no point");
            if (!plausible(deltas[2 * f]) || !plausible(deltas[2 * f + 1]))
                return fail("a pixel feature's offset is not a plausible position");
            cascade.anchors.push_back(anchors[f]);
            cascade.deltas.emplace_back(deltas[2 * f], deltas[2 * f + 1]);
        }
        for (quint64 i = 0; i < 2 * splits; ++i) {
            if (cascade.splitFeatures[i] >= e.features)
                return fail("a split reads a feature out of range");
        }
        model->m_cascades.push_back(std::move(cascade));
    }
    model->m_owner = std::move(owner);
    model->m_block = block;
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
            const quint16 *f = c.splitFeatures + 2 * size_t(t) * c.splitsPerTree;
            const float *thresh = c.thresholds + size_t(t) * c.splitsPerTree;
            int node = 0;
            while (node < c.splitsPerTree)
                node = features[f[2 * node]] - features[f[2 * node + 1]] > thresh[node] ? 2 * node + 1 : 2 * node + 2;
            chosen[t] = c.leaves + (size_t(t) * leavesPerTree + size_t(node - c.splitsPerTree)) * kShapeValues;
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
        // Leaves are not checked when a model is read (there are millions): a damaged model's
        // leaves can push the shape anywhere, and then it gives its mean shape.
        if (!std::all_of(sum, sum + kShapeValues, plausible)) {
            shape = initial;
            break;
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
