#pragma once

// A talking face drawn frame by frame for the tracking tests: a portrait whose mouth is opened
// (the jaw below the lips pulled down, the gap painted as the mouth's inside) and whose eyes
// are shut (the eye painted over with the skin below it and a lash line) by a schedule, so the
// frames where each event happens are known.

#include "detect/detector.h"
#include "face/facemodel.h"
#include "face/fapu.h"

#include <QImage>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace toonface::testing {

class TalkingFace
{
public:
    // `portrait` with a face that detectFace() finds (landmarks).
    explicit TalkingFace(const QImage &portrait)
        : m_portrait(portrait.convertToFormat(QImage::Format_RGB32))
    {
        DetectOptions options;
        options.method = DetectionMethod::Landmarks;
        const DetectionResult r = detectFace(m_portrait, options);
        m_ok = r.status == DetectStatus::Ok;
        m_face = r.face;
    }
    bool isValid() const { return m_ok; }
    const FaceModel &face() const { return m_face; }

    // The portrait with the mouth opened by `open` (0 shut .. 1 wide: a gap of 0.35 mouth widths)
    // and the eyes opened by `eyes` (1 as photographed, 0 shut).
    QImage frame(double open, double eyes) const
    {
        QImage out = m_portrait;
        const Fapu f = m_face.fapu();
        if (open > 0) {
            const QPointF l = m_face.point("8.4"), r = m_face.point("8.3");
            const double lineY = (m_face.point("2.2").y() + m_face.point("2.3").y()) / 2;
            const double cx = (l.x() + r.x()) / 2, halfW = 0.8 * f.mw0;
            const double chinY = m_face.point("2.1").y(), fade = 0.4 * f.mw0;
            const double gap = open * 0.35 * f.mw0;
            auto weight = [&](double x, double y) {
                const double u = std::abs(x - cx) / halfW;
                const double wx = u >= 1 ? 0.0 : std::pow(std::cos(u * std::numbers::pi / 2), 2);
                const double wy = y <= chinY ? 1.0 : std::max(0.0, 1.0 - (y - chinY) / fade);
                return wx * wy;
            };
            const int top = int(std::floor(lineY));
            for (int y = std::max(0, top); y < out.height(); ++y) {
                QRgb *row = reinterpret_cast<QRgb *>(out.scanLine(y));
                for (int x = std::max(0, int(cx - halfW)); x <= std::min(out.width() - 1, int(cx + halfW)); ++x) {
                    const double w = weight(x, y);
                    if (w <= 0)
                        continue;
                    const double srcY = y - gap * w;
                    if (srcY < lineY) {
                        // The mouth's inside, darker toward its middle.
                        row[x] = qRgb(70, 25, 30);
                        continue;
                    }
                    const int y0 = std::clamp(int(srcY), 0, out.height() - 1);
                    row[x] = m_portrait.pixel(x, y0);
                }
            }
        }
        if (eyes < 1) {
            QPainter p(&out);
            p.setRenderHint(QPainter::Antialiasing);
            const char *eyeIds[2][4] = {{"3.12", "3.2", "3.8", "3.4"}, {"3.11", "3.1", "3.7", "3.3"}};
            for (const auto &ids : eyeIds) {
                const QPointF outer = m_face.point(ids[0]), upper = m_face.point(ids[1]);
                const QPointF inner = m_face.point(ids[2]), lower = m_face.point(ids[3]);
                const double height = lower.y() - upper.y();
                // The lid comes down over (1 - eyes) of the eye, in the mean colour of the skin
                // above and below the eye, a little shaded.
                const double h = std::max(2.0, height);
                const QColor skin = shaded(meanColour(QPointF(upper.x(), upper.y() - 0.7 * h), h / 2),
                    meanColour(QPointF(lower.x(), lower.y() + 0.8 * h), h / 2));
                const double lidY = upper.y() + (1 - eyes) * (height + 1);
                QPainterPath lid;
                lid.moveTo(outer + QPointF(0, -2));
                lid.quadTo(QPointF(upper.x(), upper.y() - 0.8 * height), inner + QPointF(0, -2));
                lid.quadTo(QPointF(lower.x(), lidY + 0.3 * height), outer + QPointF(0, -2));
                p.setPen(Qt::NoPen);
                p.setBrush(skin);
                p.drawPath(lid);
                p.setPen(QPen(QColor(35, 25, 25), std::max(1.5, 0.3 * height)));
                p.setBrush(Qt::NoBrush);
                QPainterPath lash;
                lash.moveTo(outer);
                lash.quadTo(QPointF(lower.x(), lidY + 0.3 * height), inner);
                p.drawPath(lash);
            }
        }
        return out;
    }

private:
    QColor meanColour(QPointF centre, double radius) const
    {
        double r = 0, g = 0, b = 0;
        int n = 0;
        for (int y = int(centre.y() - radius); y <= int(centre.y() + radius); ++y)
            for (int x = int(centre.x() - radius); x <= int(centre.x() + radius); ++x) {
                if (!m_portrait.rect().contains(x, y))
                    continue;
                const QRgb c = m_portrait.pixel(x, y);
                r += qRed(c);
                g += qGreen(c);
                b += qBlue(c);
                ++n;
            }
        return n ? QColor(int(r / n), int(g / n), int(b / n)) : QColor(200, 160, 140);
    }
    static QColor shaded(const QColor &a, const QColor &b)
    {
        return QColor(
            int(0.42 * (a.red() + b.red())), int(0.42 * (a.green() + b.green())), int(0.42 * (a.blue() + b.blue())));
    }

    QImage m_portrait;
    FaceModel m_face;
    bool m_ok = false;
};

} // namespace toonface::testing
