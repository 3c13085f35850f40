#pragma once

#include <QColor>
#include <QImage>
#include <QSize>
#include <QString>

#include <optional>

namespace toonface {

// What is behind the cartoon in a video or picture export: the format's own choice, a colour,
// nothing (transparent: the face's pixels opaque, the rest alpha 0, edges antialiased), or a
// photo.
struct ExportBackground
{
    enum class Kind {
        Automatic, // transparent where the format keeps alpha, white otherwise
        Colour,
        Transparent,
        Photo, // drawn to cover the whole frame, centred, its aspect kept
    };
    Kind kind = Kind::Automatic;
    QColor colour; // Kind::Colour, opaque
    QString photoPath; // Kind::Photo

    static ExportBackground ofColour(const QColor &colour) { return {Kind::Colour, colour, {}}; }
    static ExportBackground transparent() { return {Kind::Transparent, {}, {}}; }
    static ExportBackground ofPhoto(const QString &path) { return {Kind::Photo, {}, path}; }
    bool operator==(const ExportBackground &) const = default;
};

// "transparent", "auto", a colour (an SVG colour name such as "white", "#rgb" or "#rrggbb"),
// or the path of an existing image (a photo; a file of that name wins over a colour name).
// nullopt with *error naming the text and what it takes otherwise (a colour with alpha too:
// "transparent" is the one way to ask for it).
std::optional<ExportBackground> parseExportBackground(const QString &text, QString *error);

// The photo of a Kind::Photo background scaled and cropped to cover `size`; a null image and
// *error "<path>: <problem>" when it cannot be read.
QImage backgroundPicture(const QString &path, QSize size, QString *error);

} // namespace toonface
