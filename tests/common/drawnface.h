#pragma once

// A face drawn from the average face's points, with what a photo of a person may show: glasses,
// a moustache, a beard, a hat, a bald head, any skin and hair colour. The tests of appearance
// detection and colour sampling read these, knowing exactly what is there.

#include "face/averageface.h"
#include "face/facemodel.h"

#include <QImage>
#include <QPainter>
#include <QPainterPath>
#include <QRandomGenerator>

namespace toonface::testing {

struct DrawnFaceOptions
{
    QColor skin = QColor(226, 184, 156);
    QColor hair = QColor(70, 48, 34);
    QColor hatColour = QColor(40, 60, 140);
    QColor beardColour; // invalid: the hair's, a little darker
    bool glasses = false;
    bool roundGlasses = false;
    bool upperRimsOnly = false; // browline frames: top rims and bridge, the lenses' lower half bare
    // The lenses' half width and half height (0: 0.25, round 0.3) and their centres' drop below the
    // eyes' middles, in ES0.
    double lensHalfWidth = 0.36, lensHalfHeight = 0, lensDrop = 0.03;
    bool moustache = false;
    bool beard = false;
    bool goatee = false; // hair on the chin only, under the lower lip
    bool stubble = false; // the moustache and beard are short stubble: dark speckles on the skin
    // The moustache and beard are grey strands finer than a pixel: points lighter and darker than
    // the skin, as light as it on average.
    bool greyStrands = false;
    int grain = 3; // the noise over the whole photo, in 8-bit levels either way
    bool hat = false;
    bool bald = false;
    QColor background; // invalid: a wall of several colours with edges
    double browWidth = 0.07; // in ES0
    QColor browColour; // invalid: the hair's, a little darker (a bald head's a dark brown)
    // The frame: its rims' width in ES0 (0: 0.03 ES0, at least two pixels) and colour (invalid:
    // near black); rimless lenses show only a faint light edge, with a thin metal bridge.
    double frameWidth = 0;
    QColor frameColour;
    bool rimless = false;
    // What a face shows that is neither glasses nor hair, each a soft shadow of the skin's own
    // colour: dark upper lids, a brow's shadow over deep-set eyes, bags under the eyes (with the
    // lid's crease below them), the shadow under the lower lip and under the nose, and a dark jaw
    // line along the chin.
    bool darkLids = false, browShadow = false, eyeBags = false;
    bool lipShadow = false, jawShadow = false;
    // Cheeks flushed (a smile's or make-up's blush): redder than the rest of the face under the eyes.
    bool flushedCheeks = false;
};

// A soft dark patch of `colour`: an ellipse at `c` with radii `rx`, `ry`, its darkness fading from
// the middle out (a shadow has no edge).
inline void drawShadow(QPainter &p, QPointF c, double rx, double ry, const QColor &colour)
{
    if (rx <= 0 || ry <= 0)
        return;
    p.save();
    p.translate(c);
    p.scale(1.0, ry / rx);
    QRadialGradient g(QPointF(0, 0), rx);
    QColor edge = colour;
    edge.setAlpha(0);
    g.setColorAt(0, colour);
    g.setColorAt(0.55, colour);
    g.setColorAt(1, edge);
    p.setPen(Qt::NoPen);
    p.setBrush(g);
    p.drawEllipse(QPointF(0, 0), rx, rx);
    p.restore();
}

// The confounders of DrawnFaceOptions, drawn on the skin before the features.
inline void drawConfounders(QPainter &p, const DrawnFaceOptions &o, const FaceModel &face, double es0)
{
    auto P = [&](const char *id) { return face.point(id); };
    for (bool left : {true, false}) {
        const QPointF outer = P(left ? "3.12" : "3.7"), inner = P(left ? "3.8" : "3.11");
        const QPointF top = P(left ? "3.2" : "3.1"), bottom = P(left ? "3.4" : "3.3");
        const QPointF brow = P(left ? "4.4" : "4.3");
        const double half = QLineF(outer, inner).length() / 2.0;
        const double cx = (outer.x() + inner.x()) / 2.0;
        if (o.flushedCheeks) // a soft red patch over the cheekbone, the chin and the forehead left as they are
            drawShadow(p, QPointF(cx, bottom.y() + 0.45 * es0), 1.3 * half, 0.22 * es0,
                QColor(std::min(255, o.skin.red() + 18), std::max(0, o.skin.green() - 14),
                    std::max(0, o.skin.blue() - 6)));
        if (o.browShadow) // the whole socket under the brow in shade
            drawShadow(p, QPointF(cx, (brow.y() + top.y()) / 2.0 + 0.03 * es0), 1.25 * half,
                0.55 * (top.y() - brow.y()) + 0.08 * es0, o.skin.darker(150));
        if (o.darkLids) // the lid from the lashes up to the crease, dark, and darkest at the lashes
            drawShadow(p, QPointF(cx, top.y() - 0.02 * es0), 1.1 * half, 0.13 * es0, o.skin.darker(190));
        if (o.eyeBags) {
            // A puffy crescent under the lower lid, and the lid's crease below it: a thin dark
            // curve, the line a frame's lower rim would draw there.
            drawShadow(p, QPointF(cx, bottom.y() + 0.09 * es0), 1.0 * half, 0.09 * es0, o.skin.darker(145));
            QPainterPath crease;
            crease.moveTo(QPointF(cx - 0.9 * half, bottom.y() + 0.1 * es0));
            crease.quadTo(QPointF(cx, bottom.y() + 0.26 * es0), QPointF(cx + 0.9 * half, bottom.y() + 0.1 * es0));
            p.save();
            p.setBrush(Qt::NoBrush);
            p.setPen(QPen(o.skin.darker(150), std::max(1.5, 0.025 * es0), Qt::SolidLine, Qt::RoundCap));
            p.drawPath(crease);
            p.restore();
        }
    }
    if (o.lipShadow) {
        // Under the lower lip, in the chin's fold, and under the nose over the lip.
        const double mouth = QLineF(P("8.4"), P("8.3")).length();
        drawShadow(p, P("8.2") + QPointF(0, 0.1 * es0), 0.32 * mouth, 0.09 * es0, o.skin.darker(165));
        drawShadow(p, (P("9.15") + P("8.1")) / 2.0, 0.2 * mouth, 0.06 * es0, o.skin.darker(140));
    }
    if (o.jawShadow) {
        // Along the jaw from one angle to the other, inside the face's outline.
        QPainterPath jaw;
        jaw.moveTo(P("2.14"));
        jaw.cubicTo(P("2.12"), P("2.12") + (P("2.1") - P("2.12")) * 0.5, P("2.1"));
        jaw.cubicTo(P("2.11") + (P("2.1") - P("2.11")) * 0.5, P("2.11"), P("2.13"));
        p.save();
        p.setBrush(Qt::NoBrush);
        QColor shade = o.skin.darker(170);
        shade.setAlpha(170);
        p.setPen(QPen(shade, 0.22 * es0, Qt::SolidLine, Qt::RoundCap));
        p.drawPath(jaw);
        p.restore();
    }
}

inline FaceModel drawnFaceModel()
{
    return averageFace(QRectF(150, 190, 200, 240), QSize(500, 560));
}

inline QImage drawnFace(const DrawnFaceOptions &o, const FaceModel &face = drawnFaceModel())
{
    QImage img(face.imageSize(), QImage::Format_RGB32);
    // A background of several colours with edges, as rooms and walls have.
    QPainter p(&img);
    const QColor wall[] = {QColor(120, 150, 190), QColor(200, 200, 190), QColor(90, 120, 80), QColor(180, 120, 90)};
    for (int i = 0; i < 10; ++i)
        p.fillRect(QRect(i * img.width() / 10, 0, img.width() / 10 + 1, img.height()),
            o.background.isValid() ? o.background : wall[i % 4]);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(Qt::NoPen);
    auto P = [&](const char *id) { return face.point(id); };
    QPolygonF hairShape;
    for (int i = 0; i < 19; ++i)
        hairShape << face.point(pt::idx("h.1") + i);
    hairShape << P("2.13") << P("2.14");
    p.setBrush(o.bald ? o.skin : o.hair);
    p.drawPolygon(hairShape);
    QPolygonF faceShape;
    for (const char *id : {"11.2", "11.1", "11.3", "5.1", "2.13", "2.11", "2.1", "2.12", "2.14", "5.2"})
        faceShape << P(id);
    QPainterPath facePath;
    facePath.addPolygon(faceShape);
    p.setBrush(o.skin);
    p.drawPath(facePath);
    if (o.hat) {
        // The hat covers the head down to a straight brim across the forehead at the temples'
        // height; the hair shows at the sides below it.
        QPainterPath clip;
        clip.addRect(QRectF(0, 0, img.width(), std::max(P("11.2").y(), P("11.3").y())));
        QPainterPath head;
        head.addPolygon(hairShape);
        p.save();
        p.setClipPath(clip);
        p.setBrush(o.hatColour);
        p.drawPath(head.united(facePath));
        p.restore();
    }
    const double es0 = QLineF(P("3.6"), P("3.5")).length();
    {
        // The shadows stay on the skin (the face's outline), as real ones do.
        p.save();
        p.setClipPath(facePath);
        drawConfounders(p, o, face, es0);
        p.restore();
    }
    // Brows, eyes, nose shadow, lips.
    p.setBrush(Qt::NoBrush);
    const QColor brow = o.browColour.isValid() ? o.browColour : o.bald ? QColor(90, 70, 60) : o.hair.darker(120);
    p.setPen(QPen(brow, o.browWidth * es0, Qt::SolidLine, Qt::RoundCap));
    p.drawPolyline(QPolygonF {P("4.6"), P("4.4a"), P("4.4"), P("4.2")});
    p.drawPolyline(QPolygonF {P("4.1"), P("4.3"), P("4.3a"), P("4.5")});
    p.setPen(Qt::NoPen);
    for (bool left : {true, false}) {
        const QPointF a = P(left ? "3.12" : "3.11"), b = P(left ? "3.8" : "3.7");
        const double h = P(left ? "3.4" : "3.3").y() - P(left ? "3.2" : "3.1").y();
        p.setBrush(QColor(245, 245, 240));
        p.drawEllipse((a + b) / 2.0, QLineF(a, b).length() / 2.0, h / 2.0);
        p.setBrush(QColor(70, 50, 35));
        p.drawEllipse(P(left ? "3.6" : "3.5"), h * 0.4, h * 0.4);
    }
    p.setBrush(o.skin.darker(125));
    p.drawEllipse(P("9.4"), 0.04 * es0, 0.025 * es0);
    p.drawEllipse(P("9.5"), 0.04 * es0, 0.025 * es0);
    p.setBrush(QColor(190, 90, 90));
    p.drawPolygon(QPolygonF {P("8.4"), P("8.9"), P("8.1"), P("8.10"), P("8.3"), P("8.2")});
    const QColor beardColour = o.beardColour.isValid() ? o.beardColour : o.hair.darker(110);
    // Stubble: the facial hair's shapes filled with a speckle of dark dots (a third of the skin
    // covered) instead of a solid colour.
    QImage speckle(img.size(), QImage::Format_ARGB32_Premultiplied);
    speckle.fill(Qt::transparent);
    {
        QRandomGenerator dots(11);
        for (int y = 0; y < speckle.height(); ++y)
            for (int x = 0; x < speckle.width(); ++x)
                if (dots.bounded(100) < 36)
                    speckle.setPixel(x, y, beardColour.rgb());
    }
    QImage strands(img.size(), QImage::Format_ARGB32_Premultiplied);
    strands.fill(Qt::transparent);
    if (o.greyStrands) {
        QRandomGenerator points(13);
        auto shifted = [&](int by) {
            return qRgb(std::clamp(o.skin.red() + by, 0, 255), std::clamp(o.skin.green() + by, 0, 255),
                std::clamp(o.skin.blue() + by, 0, 255));
        };
        for (int y = 0; y < strands.height(); ++y)
            for (int x = 0; x < strands.width(); ++x) {
                const int k = int(points.bounded(100));
                if (k < 15)
                    strands.setPixel(x, y, shifted(40));
                else if (k < 30)
                    strands.setPixel(x, y, shifted(-40));
            }
    }
    const QBrush hairBrush = o.greyStrands ? QBrush(strands) : o.stubble ? QBrush(speckle) : QBrush(beardColour);
    if (o.moustache) {
        p.setBrush(hairBrush);
        const double top = std::max(P("9.4").y(), P("9.15").y()) + 0.03 * es0;
        p.drawPolygon(QPolygonF {P("8.4") + QPointF(-0.03 * es0, 0), QPointF(P("9.2").x(), top),
            QPointF(P("9.1").x(), top), P("8.3") + QPointF(0.03 * es0, 0), P("8.10") - QPointF(0, 0.01 * es0),
            P("8.9") - QPointF(0, 0.01 * es0)});
    }
    if (o.beard) {
        p.setBrush(hairBrush);
        p.drawPolygon(QPolygonF {QLineF(P("5.2"), P("2.14")).pointAt(0.4), P("2.14"), P("2.12"), P("2.1"), P("2.11"),
            P("2.13"), QLineF(P("5.1"), P("2.13")).pointAt(0.4), P("8.3") + QPointF(0.04 * es0, 0.06 * es0),
            P("8.2") + QPointF(0, 0.06 * es0), P("8.4") + QPointF(-0.04 * es0, 0.06 * es0)});
    }
    if (o.goatee) {
        p.setBrush(hairBrush);
        const QPointF l = QLineF(P("8.4"), P("2.12")).pointAt(0.45), r = QLineF(P("8.3"), P("2.11")).pointAt(0.45);
        p.drawPolygon(QPolygonF {l, QLineF(l, P("2.1")).pointAt(0.6) + QPointF(-0.03 * es0, 0), P("2.1"),
            QLineF(r, P("2.1")).pointAt(0.6) + QPointF(0.03 * es0, 0), r, P("8.2") + QPointF(0, 0.08 * es0)});
    }
    if (o.glasses) {
        p.setBrush(Qt::NoBrush);
        const QColor frame = o.frameColour.isValid() ? o.frameColour : QColor(25, 25, 30);
        const double width = o.frameWidth > 0 ? o.frameWidth * es0 : std::max(2.0, 0.03 * es0);
        // A rimless lens's edge catches the light: a faint line a little lighter than the skin.
        const QPen rim = o.rimless ? QPen(o.skin.lighter(112), 1.0) : QPen(frame, width);
        p.setPen(rim);
        QPointF inner[2];
        for (bool left : {true, false}) {
            const QPointF c
                = (P(left ? "3.12" : "3.11") + P(left ? "3.8" : "3.7")) / 2.0 + QPointF(0, o.lensDrop * es0);
            const double hh = o.lensHalfHeight > 0 ? o.lensHalfHeight : o.roundGlasses ? 0.3 : 0.25;
            const double above = o.lensHalfHeight > 0 ? hh : 0.25;
            const QRectF r(c.x() - o.lensHalfWidth * es0, c.y() - above * es0, 2 * o.lensHalfWidth * es0, 2 * hh * es0);
            p.save();
            if (o.upperRimsOnly) {
                p.setClipRect(r.adjusted(-0.05 * es0, -0.05 * es0, 0.05 * es0, -0.6 * r.height()));
                p.setPen(QPen(QColor(25, 25, 30), std::max(3.0, 0.06 * es0)));
            }
            if (o.roundGlasses)
                p.drawEllipse(r);
            else
                p.drawRoundedRect(r, 0.08 * es0, 0.08 * es0);
            p.restore();
            inner[left ? 0 : 1] = QPointF(left ? r.right() : r.left(), r.top() + 0.3 * r.height());
        }
        p.setPen(o.rimless ? QPen(frame, std::max(1.5, 0.02 * es0)) : rim);
        p.drawLine(inner[0], inner[1]);
    }
    p.end();
    // Skin and hair are never flat: a little noise everywhere.
    QRandomGenerator rng(7);
    for (int y = 0; y < img.height(); ++y) {
        auto *line = reinterpret_cast<QRgb *>(img.scanLine(y));
        for (int x = 0; x < img.width(); ++x) {
            const int n = int(rng.bounded(2 * o.grain + 1)) - o.grain;
            const QRgb c = line[x];
            line[x] = qRgb(
                std::clamp(qRed(c) + n, 0, 255), std::clamp(qGreen(c) + n, 0, 255), std::clamp(qBlue(c) + n, 0, 255));
        }
    }
    return img;
}

} // namespace toonface::testing
