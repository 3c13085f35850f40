#include "detect/landmarkfigures.h"

#include <QCoreApplication>
#include <QGuiApplication>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace toonface {

void addLandmarkDebugImages(QMap<QString, QImage> *out, const QImage &image, const std::vector<FaceBox> &faces,
    int chosen, const std::array<QPointF, kIbugPointCount> &ibug, const FaceModel &geometric, const FaceModel &face,
    const HairSearchReport &hair, const HeadRegionReport &regions)
{
    QImage canvas = image.convertToFormat(QImage::Format_RGB32);
    QPainter p(&canvas);
    p.setRenderHint(QPainter::Antialiasing);
    const double unit = std::max(1.0, std::min(canvas.width(), canvas.height()) / 400.0);
    for (int i = 0; i < int(faces.size()); ++i) {
        p.setPen(QPen(i == chosen ? Qt::green : Qt::yellow, unit));
        p.drawRect(faces[i].box);
    }
    p.setPen(Qt::NoPen);
    p.setBrush(Qt::cyan);
    for (const QPointF &q : ibug)
        p.drawEllipse(q, unit, unit);
    p.end();
    out->insert(QStringLiteral("detect-landmarks"), canvas);

    // The points on a crop around the head, enlarged to about 800 px, labelled with their IDs;
    // the geometric estimates of hair and ears (before the photo search) in orange.
    QRectF head = face.bounds().united(geometric.bounds());
    head.adjust(-0.1 * head.width(), -0.1 * head.height(), 0.1 * head.width(), 0.1 * head.height());
    const double zoom = 800.0 / std::max(head.width(), head.height());
    QImage crop(QSize(std::lround(head.width() * zoom), std::lround(head.height() * zoom)), QImage::Format_RGB32);
    crop.fill(Qt::black);
    p.begin(&crop);
    p.setRenderHint(QPainter::Antialiasing);
    p.setRenderHint(QPainter::SmoothPixmapTransform);
    p.scale(zoom, zoom);
    p.translate(-head.topLeft());
    p.drawImage(QPointF(0, 0), image);
    p.setPen(QPen(QColor(255, 255, 255, 140), 1.0 / zoom));
    for (const QLineF &ray : regions.hairUsable ? regions.rays : hair.rays)
        p.drawLine(ray);
    // Text needs fonts, which need a QGuiApplication; a command-line run gets unlabelled points.
    const bool labels = qobject_cast<QGuiApplication *>(QCoreApplication::instance()) != nullptr;
    if (labels) {
        QFont font = p.font();
        font.setPointSizeF(7.0 / zoom);
        p.setFont(font);
    }
    const double r = 3.0 / zoom;
    for (int i = 0; i < kPointCount; ++i) {
        const PointGroup g = pointTable()[i].group;
        p.setPen(Qt::NoPen);
        if ((g == PointGroup::Hair || g == PointGroup::Ears) && geometric.point(i) != face.point(i)) {
            p.setBrush(QColor(255, 140, 0));
            p.drawEllipse(geometric.point(i), r, r);
        }
        p.setBrush(g == PointGroup::Hair ? Qt::magenta : g == PointGroup::Ears ? Qt::cyan : Qt::green);
        p.drawEllipse(face.point(i), r, r);
        if (labels) {
            p.setPen(Qt::yellow);
            p.drawText(face.point(i) + QPointF(r, -r), pointId(i));
        }
    }
    p.end();
    out->insert(QStringLiteral("detect-points-crop"), crop);
    if (!hair.regionMask.isNull())
        out->insert(QStringLiteral("detect-hair-region"), hair.regionMask);
    if (!regions.regionImage.isNull())
        out->insert(QStringLiteral("detect-head-regions"), regions.regionImage);
}

} // namespace toonface
