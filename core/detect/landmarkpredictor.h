#pragma once

// The 68-point landmark model: the cascade of regression-tree forests that dlib's trainer
// writes (shape_predictor_68_face_landmarks.dat), read once and held in flat arrays.
//
// dlib's own shape_predictor keeps every leaf of its 120 000 as a separate heap vector; a
// prediction adds 7 500 of them, scattered over 65 MB, and after the face detector has filled
// the caches each one is a wait on memory (about 5 ms a fit on this project's machines). Here
// the leaves of a cascade lie in one array, and a cascade first walks all its trees (their
// splits read only the cascade's pixel features, not the shape being built) and then sums
// the chosen leaves with the next ones already on their way in: about 1.7 ms a fit from cold
// caches. The pixel features are dlib's own (impl::extract_feature_pixel_values), so the
// result is dlib's, less its rounding of the points to whole pixels.
//
// All the arrays lie in one block of bytes (flat()), which is what the model's cache file
// holds (modelcache.h): a model is made from such a block in place, without copying it, so
// that a block mapped from the cache is the model.

#include "detect/landmarkmap.h"

#include <QPointF>
#include <QRect>
#include <QString>

#include <array>
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

namespace toonface {

struct GrayView;

class LandmarkPredictor
{
public:
    using Shape = std::array<QPointF, kIbugPointCount>;

    // Reads a model file of dlib's (shapemodelfile.h: decoded straight into the flat arrays;
    // a file in dlib's old text form through dlib's own reader); nullptr with `error` naming the
    // file and the problem when it is missing, unreadable, damaged or not a 68-point model.
    static std::shared_ptr<const LandmarkPredictor> read(const QString &path, QString *error);

    // The same through dlib's stream deserialisation (ten times slower): the reference the
    // tests hold read() to, byte for byte of flat(), and the reader of dlib's old text form.
    static std::shared_ptr<const LandmarkPredictor> readThroughDlib(const QString &path, QString *error);

    // The model held in `block` (as flat() gives it), used in place: `owner` keeps the bytes
    // alive as long as the model. Every count and offset is checked against the block's size
    // first, so that a damaged block gives nullptr and *error (the problem, without a file
    // name), never a read outside it. requires: block.data() aligned to 8 bytes.
    static std::shared_ptr<const LandmarkPredictor> fromFlat(
        std::shared_ptr<const void> owner, std::span<const std::byte> block, QString *error);

    // The model's arrays as one block of bytes, for fromFlat().
    std::span<const std::byte> flat() const { return m_block; }

    // The 68 points in `image` for a face in `box` (pixels, inclusive of its right and bottom
    // edge as dlib's rectangles are), to sub-pixel precision.
    Shape predict(const GrayView &image, const QRect &box) const;

    // The points as they lie, on average, in the unit square of the face detector's box: the
    // cascade's starting shape.
    const Shape &meanShape() const { return m_meanShape; }

    ~LandmarkPredictor();

private:
    LandmarkPredictor();
    struct Cascade;
    std::shared_ptr<const void> m_owner; // keeps m_block's bytes alive
    std::span<const std::byte> m_block;
    Shape m_meanShape {};
    std::vector<float> m_initial; // x0, y0, x1, y1, ... in the unit square
    std::vector<Cascade> m_cascades;
};

} // namespace toonface
