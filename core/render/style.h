#pragma once

#include "face/appearance.h"

#include <QByteArray>
#include <QColor>
#include <QMap>
#include <QPointF>
#include <QString>
#include <QStringList>
#include <QVector>

class QImage;

namespace toonface {

// How one drawn component looks. Component names are the style keys of SvgFace's parts:
// "hair", "ears", "face", "jaw", "cheeks", "nose", "eyebrows", "eyes", "eyeballs", "pupils",
// "highlights", "lips", "mouth-inner", "teeth", "tongue", "glasses", "moustache", "beard",
// "hat", "creases" and "blush" (the cues of expressions) and "body" (the clothes on the
// shoulders; when hidden, neither neck nor shoulders are drawn). A key missing from a Style's map
// is drawn as in the "normal" preset.
struct ComponentStyle
{
    QColor fill; // invalid colour = no fill
    QColor stroke; // invalid colour = no stroke
    double strokeWidth = 0; // in units of ES0/100 (the thesis' pixel at its photo scale)
    bool visible = true;

    bool operator==(const ComponentStyle &) const = default;
};

enum class EyebrowVariant { Polyline, Bezier, Thick };

// How much the drawing exaggerates what makes the face differ from the average face
// (0 = exactly the points; 1 = twice the difference). New styles start mild.
inline constexpr double kDefaultCaricature = 0.35;
inline constexpr double kMaxCaricature = 1.0;
enum class NoseVariant { Full, Simple, Tip };

// A drawing of the user's own from an SVG file (clothing, an accessory: thesis Fig. 7.9), placed on
// the face: its centre `offset` from the face's centre and `width` wide, both in ES0. Either it
// follows the head (a hat, earrings, a mask: drawn in the head's group, it moves, turns and nods
// with it) or it stays where the neutral face is (as clothes and the room do). Drawn behind the
// head (over the neck and shoulders) or in front of it, in order, the same in the editor and in
// every export.
struct StyleLayer
{
    QString name; // shown in the editor: the file's name
    QByteArray svg; // the file's content, copied (a project holds it): made inert when drawn
    QPointF offset; // ES0
    double width = 2.0; // ES0
    bool front = true;
    bool visible = true;
    bool followsHead = false; // projects from before keep their layers still

    bool operator==(const StyleLayer &) const = default;
};

// A drawing style: a named preset ("normal", "cute", ...) plus the user's overrides.
// A plain value type.
struct Style
{
    QString name = QStringLiteral("normal");
    int cornerCutDepth = 2; // corner-cutting depth for hair and eyebrows (thesis: 2)
    bool cute = false; // thesis Fig. 7.8c: rounder jaw, larger eyeballs, smaller nose
    EyebrowVariant eyebrows = EyebrowVariant::Polyline;
    NoseVariant nose = NoseVariant::Full;
    double caricature = kDefaultCaricature;
    Appearance appearance;
    QMap<QString, ComponentStyle> components;
    QVector<StyleLayer> layers; // the user's, in drawing order

    // The built-in presets; unknown names give an empty optional-like result via ok=false.
    static QStringList presetNames();
    static Style preset(const QString &name, bool *ok = nullptr);

    // The colours and line weights every preset starts from (widths in ES0/100); a photo's
    // colours are set over them by sampleColours() (detect/photocolours.h).
    static QMap<QString, ComponentStyle> baseComponents();

    bool operator==(const Style &) const = default;
};

QString eyebrowVariantName(EyebrowVariant v);
bool eyebrowVariantFromName(const QString &name, EyebrowVariant *v);
QString noseVariantName(NoseVariant v);
bool noseVariantFromName(const QString &name, NoseVariant *v);

} // namespace toonface
