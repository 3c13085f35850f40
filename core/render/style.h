#pragma once

#include <QColor>
#include <QMap>
#include <QString>
#include <QStringList>

class QImage;

namespace toonface {

class FaceModel;

// How one drawn component looks. Component names are the style keys of SvgFace's parts:
// "hair", "ears", "face", "jaw", "cheeks", "nose", "eyebrows", "eyes", "eyeballs", "pupils",
// "highlights", "lips", "mouth-inner", "teeth", "tongue". A key missing from a Style's map
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
enum class NoseVariant { Full, Simple, Tip };

// A drawing style: a named preset ("normal", "cute", ...) plus the user's overrides.
// A plain value type.
struct Style
{
    QString name = QStringLiteral("normal");
    int cornerCutDepth = 2; // corner-cutting depth for hair and eyebrows (thesis: 2)
    bool cute = false; // thesis Fig. 7.8c: rounder jaw, larger eyeballs, smaller nose
    EyebrowVariant eyebrows = EyebrowVariant::Polyline;
    NoseVariant nose = NoseVariant::Full;
    QMap<QString, ComponentStyle> components;

    // The built-in presets; unknown names give an empty optional-like result via ok=false.
    static QStringList presetNames();
    static Style preset(const QString &name, bool *ok = nullptr);

    // Sets skin, hair, lip and iris colours from the photo under the face's points.
    void sampleColours(const QImage &photo, const FaceModel &face);

    bool operator==(const Style &) const = default;
};

QString eyebrowVariantName(EyebrowVariant v);
bool eyebrowVariantFromName(const QString &name, EyebrowVariant *v);
QString noseVariantName(NoseVariant v);
bool noseVariantFromName(const QString &name, NoseVariant *v);

} // namespace toonface
