#pragma once

#include "io/project.h"

#include <optional>

#include "detect/detector.h"
#include "face/emotion.h"
#include "face/facemodel.h"
#include "face/mouthshape.h"
#include "render/style.h"

#include <QCommandLineParser>
#include <QImage>
#include <QRectF>
#include <QString>
#include <QStringList>

namespace toonface::cli {

// A face to draw, from any of the inputs the CLI accepts: a photo (detected now), a face
// JSON (toonface.face/1) or a project (.toonface).
struct FaceInput
{
    FaceModel face;
    Style style; // the project's style, or the default preset
    bool hasProjectStyle = false;
    QImage photo; // may be null (face JSON whose photo is gone)
    QString photoPath;
    QStringList layerPaths;
    MouthShapeSet mouthShapes; // the project's presets, or the defaults
    DetectionResult detection; // set when the input was a photo
    std::optional<Project> project; // set when the input was a project
};

// Reads `path` into *out. Returns ExitOk, or prints the error line and returns the exit code
// of the contract (3 unreadable/invalid, 4 no face).
int loadFaceInput(const QString &path, const DetectOptions &options, FaceInput *out);

// Options several commands share. Each reads its option's value from `parser`; on a bad value
// it prints the error line and returns ExitUsage, else ExitOk.
int parseMethodOption(const QCommandLineParser &parser, const QCommandLineOption &method, DetectOptions *out);
int parseEmotionOption(const QCommandLineParser &parser, const QCommandLineOption &emotion, Emotion *out);
// *out stays empty when the option is not given.
int parseStyleOption(const QCommandLineParser &parser, const QCommandLineOption &style, std::optional<Style> *out);

// --frame head|photo: what part of the photo a drawing shows. The head (the default) is framed
// square by headFrame(); "photo" keeps the photo's frame, so the drawing lies over the photo.
QCommandLineOption frameOption();
int parseFrameOption(const QCommandLineParser &parser, const QCommandLineOption &frame, bool *wholePhoto);
// The frame to give SvgFace::setFrame(): empty for the whole photo.
QRectF drawingFrame(const FaceModel &face, bool wholePhoto);

// The style to draw `input` with: the one asked for, else the project's, else the default; a
// style not from a project takes its colours from the photo.
Style drawingStyle(const FaceInput &input, const std::optional<Style> &chosen);

} // namespace toonface::cli
