#pragma once

#include <QByteArray>
#include <QRectF>
#include <QString>

namespace toonface {

struct StyleLayer;

// A user's SVG file made safe to embed in the cartoon and in its exports, which a browser opens:
// the children of its root <svg>, inert. Only what static drawing needs is kept, by allow-lists
// (render/svgallowlist.h): SVG elements of drawing (no script, animation, foreign content or
// other namespaces, which are left out with everything inside; a link <a> becomes a group), their
// drawing attributes (no event handlers, no attribute of another namespace), links only to the
// file's own elements or to raster pictures inside it, and CSS with no escape, at-rule or
// reference outside the file. Entities the file uses without declaring them are written out
// when they are HTML's usual ones (&nbsp;) and refused otherwise; the tree is at most 64 deep
// and 100,000 elements large. Every id is prefixed with `idPrefix` (and every reference to
// it), so the layer's ids never clash with the face's ("mouth-inner", "head") or another
// layer's.
struct LayerDrawing
{
    QByteArray fragment; // the root's children, in the SVG namespace
    QRectF viewBox; // the root's viewBox, or (0, 0, width, height); (0, 0, 100, 100) when neither
};

// Returns false and sets *error (the problem, without the file's name) when the content is not
// an SVG document: not XML, or a root other than <svg>.
bool readLayerSvg(const QByteArray &content, const QString &idPrefix, LayerDrawing *out, QString *error);

// The cleaned layer as a standalone SVG document: what a project stores, never the original.
// false with *error (the problem, without the file's name) as readLayerSvg. Cleaning a cleaned
// layer gives it back unchanged.
bool cleanLayerSvg(const QByteArray &content, QByteArray *cleaned, QString *error);

// A layer file is at most this large.
constexpr qint64 kMaxLayerFileBytes = 16 << 20;

// Reads a user's layer file for Style::layers: named after the file, its content cleaned (cleanLayerSvg), placed
// in the middle of the face `width` ES0 wide. On failure, *error names the file and the problem.
bool loadLayerFile(const QString &path, StyleLayer *out, QString *error);

} // namespace toonface
