#pragma once

// What SvgFace draws a face from (internal to core/render): the drawing's proportions, the
// geometry of a face that does not depend on the pose, the style's rules (caricature, cute) and
// the builders of its parts, static (hair, ears, face, nose, brows) and posed (jaw, mouth, eyes).
// svgface.cpp assembles them into documents.

#include "render/style.h"
#include "render/svgparts.h"

#include <QByteArray>
#include <QMap>
#include <QPointF>

#include <algorithm>
#include <array>
#include <vector>

namespace toonface {

class FaceModel;

namespace svgfacebuild {

using namespace svgparts;

// The proportions of the drawing, in ES0 (eye distance) units unless said otherwise.
inline constexpr double kEyeballRadius = 0.105;
inline constexpr double kCuteEyeballScale = 1.45;
inline constexpr double kPupilRadius = 0.45; // of the eyeball radius
inline constexpr double kHighlightRadius = 0.24; // of the eyeball radius
inline constexpr double kCuteChinRaise = 0.22; // of JawH
inline constexpr double kCuteEyeScale = 1.3;
inline constexpr double kCheekRadius = 0.12;
inline constexpr double kCuteNoseScale = 0.6;
inline constexpr double kJawOverlap = 3.0; // thesis pixels (ES0/100) the jaw reaches up behind the face
inline constexpr double kThickBrow = 0.085;
inline constexpr double kLowerLipSpread = 1.5; // method B: the lower lip rounder than thirds
// The upper teeth and the tongue take fixed shares of the mouth opening (of the distance
// between the lips' inner edges). Fixed shares keep them linear in the pose like the rest of the
// mouth, so they ease exactly with it and an SMIL export interpolates them between key frames
// (a fixed height would need many more key frames).
inline constexpr double kTeethShare = 0.3;
inline constexpr double kTongueShare = 0.28;
inline constexpr double kHairInset = 0.15; // how far the hair's hidden closing runs inside the face

// Everything about a face that does not depend on the pose.
struct SvgFaceGeometry
{
    Points neutral; // the neutral points with the style's rules applied
    Points rest; // ... and those of the face at rest (restingFacePose), with them
    std::array<QPointF, kPointCount> ruleOffset {}; // what the style's rules add to every pose
    double unit = 1; // ES0 / 100: the thesis' pixel at its photo scale
    double es0 = 100;
    QPointF centre; // head rotation centre
    QPointF jawStartTangent; // the face contour's direction at 2.14 and 2.13, shared by face and jaw
    QPointF jawEndTangent;
    double eyeballRadius = 10;
    std::vector<Part> staticParts; // everything of the static layer but the eyebrows
    std::vector<Part> bodyParts; // neck and shoulders, or none
    QByteArray behind, front; // the style's visible layers, placed, that stay still
    QByteArray headBehind, headFront; // ... and those that follow the head (in its group)
    QMap<QString, ComponentStyle> components;
    // The style keys of components not drawn (componentStyle(...).visible false), so that
    // drawing a pose, done thousands of times by the SMIL export, looks no styles up.
    std::vector<QByteArray> hidden;
};

inline bool drawn(const SvgFaceGeometry &g, const char *key)
{
    return std::none_of(g.hidden.cbegin(), g.hidden.cend(), [&](const QByteArray &h) { return h == key; });
}

std::array<QPointF, kPointCount> styleRuleOffsets(const FaceModel &original, const Style &style);
void applyStyleRules(Points &p, const SvgFaceGeometry &g, const Style &style);
Part makeHair(const Pt &P, const SvgFaceGeometry &g, int depth);
void makeEar(const Pt &P, const SvgFaceGeometry &g, bool left, std::vector<Part> *out);
Part makeFace(const Pt &P, const SvgFaceGeometry &g, bool bald);
void makeNose(const Pt &P, NoseVariant variant, double es0, std::vector<Part> *out);
void makeEyebrows(const Pt &P, const Style &style, double es0, std::vector<Part> *out);
Part makeJaw(const Pt &P, const SvgFaceGeometry &g);
void makeMouth(const Pt &P, std::vector<Part> *out);
void makeEye(const Pt &P, const SvgFaceGeometry &g, bool left, bool cover, std::vector<Part> *out);

} // namespace svgfacebuild

} // namespace toonface
