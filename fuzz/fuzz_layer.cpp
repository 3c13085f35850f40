// A user's SVG layer (clothing, accessories) added to a face. Whatever the file holds, the
// drawing written is well-formed XML and runs nothing: no script, foreignObject, iframe or
// handler elements, no on* attributes, no javascript: URL in any value (white space inside
// the scheme too, as browsers skip it).

#include "fuzzinput.h"

#include "face/averageface.h"
#include "render/svgface.h"

#include <QRegularExpression>
#include <QXmlStreamReader>

using namespace toonface;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const FaceModel face = averageFace(QRectF(100, 100, 200, 260), QSize(400, 480));
    SvgFace drawing(face, Style());
    drawing.addLayer(fuzz::bytes(data, size));
    QXmlStreamReader reader(drawing.svg());
    while (!reader.atEnd()) {
        if (reader.readNext() != QXmlStreamReader::StartElement)
            continue;
        const QStringView name = reader.name();
        TOONFACE_FUZZ_CHECK(name.compare(QLatin1StringView("script"), Qt::CaseInsensitive) != 0);
        TOONFACE_FUZZ_CHECK(name.compare(QLatin1StringView("foreignObject"), Qt::CaseInsensitive) != 0);
        TOONFACE_FUZZ_CHECK(name.compare(QLatin1StringView("iframe"), Qt::CaseInsensitive) != 0);
        TOONFACE_FUZZ_CHECK(name.compare(QLatin1StringView("handler"), Qt::CaseInsensitive) != 0);
        for (const QXmlStreamAttribute &a : reader.attributes()) {
            TOONFACE_FUZZ_CHECK(!a.name().startsWith(QLatin1StringView("on"), Qt::CaseInsensitive));
            QString value = a.value().toString().toLower();
            value.remove(QRegularExpression(QStringLiteral("[\\x00-\\x20]")));
            TOONFACE_FUZZ_CHECK(!value.contains(QLatin1StringView("javascript:")));
        }
    }
    TOONFACE_FUZZ_CHECK(!reader.hasError());
    return 0;
}
