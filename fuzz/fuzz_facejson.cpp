// A face file (toonface-cli detect's JSON) as the CLI reads it: the points, and the regions and
// tracking seed that a detection leaves. A face it accepts must write and read back equal, and
// draw.

#include "fuzzinput.h"

#include "detect/faceregions.h"
#include "io/facejson.h"
#include "render/svgface.h"

#include <QJsonDocument>
#include <QJsonObject>

using namespace toonface;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(fuzz::bytes(data, size), &parseError);
    if (!doc.isObject())
        return 0;
    QString error, imagePath;
    const auto face = faceFromJson(doc.object(), &error, &imagePath);
    FaceRegions regions;
    TrackingSeed tracking;
    QString regionsError;
    const bool regionsRead = faceRegionsFromJson(doc.object(), &regions, &tracking, &regionsError);
    TOONFACE_FUZZ_CHECK(regionsRead || !regionsError.isEmpty());
    if (!face) {
        TOONFACE_FUZZ_CHECK(!error.isEmpty());
        return 0;
    }
    QString againImage;
    const auto again = faceFromJson(faceToJson(*face, imagePath), &error, &againImage);
    TOONFACE_FUZZ_CHECK(again && *again == *face && againImage == imagePath);
    if (face->isValid())
        TOONFACE_FUZZ_CHECK(!SvgFace(*face, Style()).svg().isEmpty());
    return 0;
}
