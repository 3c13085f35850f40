#include "detect/faceregions.h"

#include "face/fapu.h"

#include <QLineF>
#include <QPolygonF>

#include <initializer_list>

namespace toonface {

namespace {

QRectF boxOf(const FaceModel &face, std::initializer_list<const char *> ids)
{
    // QRectF::united() ignores rectangles of no size, so the extremes are taken by hand.
    QPolygonF points;
    for (const char *id : ids)
        points << face.point(id);
    return points.boundingRect();
}

} // namespace

FaceRegions regionsFromPoints(const FaceModel &face)
{
    FaceRegions r;
    for (const char *id : {"11.2", "11.1", "11.3", "5.1", "2.13", "2.11", "2.1", "2.12", "2.14", "5.2"})
        r.faceOutline << face.point(id);
    r.face = r.faceOutline.boundingRect();
    for (int i = 0; i < 19; ++i)
        r.hairOutline << face.point(pt::idx("h.1") + i);
    r.hair = r.hairOutline.boundingRect();
    r.ears[0] = boxOf(face, {"10.2", "10.4", "10.6", "10.10"});
    r.ears[1] = boxOf(face, {"10.1", "10.3", "10.5", "10.9"});
    r.brows[0] = boxOf(face, {"4.6", "4.4a", "4.4", "4.2"});
    r.brows[1] = boxOf(face, {"4.1", "4.3", "4.3a", "4.5"});
    r.eyes[0] = boxOf(face, {"3.12", "3.2", "3.8", "3.4", "3.6"});
    r.eyes[1] = boxOf(face, {"3.11", "3.1", "3.7", "3.3", "3.5"});
    r.nose = boxOf(face, {"9.6", "9.7", "9.14", "9.13", "9.2", "9.1", "9.4", "9.5", "9.15"});
    r.mouth = boxOf(face, {"8.4", "8.9", "8.1", "8.10", "8.3", "8.2", "2.2", "2.3"});
    return r;
}

void seedGeometryFromPoints(const FaceModel &face, TrackingSeed *seed)
{
    const QPointF l = face.point("3.6"), r = face.point("3.5");
    seed->eyeballs[0] = l;
    seed->eyeballs[1] = r;
    seed->d = QLineF(l, r).length();
    seed->eyeMid = (l + r) / 2;
    const Fapu f = face.fapu();
    seed->eyeballRadius[0] = f.leftEyeH / 2;
    seed->eyeballRadius[1] = f.rightEyeH / 2;
    // Algorithm 4.5: Div_EE one pixel above the top of the image-left eyeball.
    seed->divEE = l.y() - seed->eyeballRadius[0] - 1;
    seed->divEN = seed->eyeMid.y() + seed->d / 3;
    seed->divNM = seed->eyeMid.y() + seed->d;
    seed->mouth = boxOf(face, {"8.4", "8.9", "8.1", "8.10", "8.3", "8.2", "2.2", "2.3"});
}

} // namespace toonface
