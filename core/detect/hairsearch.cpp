#include "detect/hairsearch.h"

namespace toonface {

void refineFromPhoto(FaceModel *face, const QImage &image, HairSearchReport *report, bool withDebugImages)
{
    Q_UNUSED(face);
    Q_UNUSED(image);
    Q_UNUSED(report);
    Q_UNUSED(withDebugImages);
}

} // namespace toonface
