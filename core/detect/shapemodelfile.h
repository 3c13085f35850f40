#pragma once

// dlib's 68-point model file (shape_predictor_68_face_landmarks.dat) decoded straight into a
// landmark model's flat block (landmarkflat.h), without dlib's stream deserialisation: the
// file is mapped whole and read once, front to back, each number written where the block
// wants it. dlib's reader makes 120 000 heap vectors of leaves through an istream, a byte at
// a time (about 1 s for the 100 MB file); this takes a tenth of that.
//
// The format, as dlib's serialize.h and shape_predictor.h write it: an integer is a control
// byte (its low four bits the count of bytes that follow, bit 7 the sign of a signed one)
// and that many bytes, least significant first; a float is two such integers, a mantissa and
// a power of two; a vector is its length, then its items; a matrix is its rows and columns
// (negated), then its items. The model is a version (1), the mean shape (a 136 x 1 matrix),
// the cascades (a vector of vectors of trees: each tree a vector of splits, two feature
// indices and a threshold each, and a vector of leaves, 136 x 1 matrices), then each
// cascade's pixel features (a vector of vectors of anchor points, then a vector of vectors
// of offsets, pairs of floats).

#include <QString>

#include <cstddef>
#include <memory>
#include <span>

namespace toonface {

struct ShapeModelFile
{
    enum class Status {
        Read, // `block` holds the model
        Failed, // the file is missing, unreadable, damaged or not a 68-point model: `error` says how
        OldFormat, // the file writes its numbers in dlib's old text form: read it with dlib's reader
    };
    Status status = Status::Failed;
    std::shared_ptr<const void> owner; // keeps `block` alive
    std::span<const std::byte> block; // aligned to 64 bytes
    QString error; // the problem, to follow the file's name ("could not be read: ...")
};

ShapeModelFile readShapeModelFile(const QString &path);

} // namespace toonface
