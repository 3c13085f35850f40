#include "io/facejson.h"

#include "detect/detector.h"
#include "face/fapu.h"
#include "io/jsonfield.h"
#include "io/pointsjson.h"

#include <QJsonArray>
#include <QRegularExpression>

namespace toonface {

namespace {

QJsonObject mapToJson(const QMap<QString, double> &map)
{
    QJsonObject o;
    for (auto it = map.cbegin(); it != map.cend(); ++it)
        o.insert(it.key(), it.value());
    return o;
}

} // namespace

QJsonObject faceToJson(const FaceModel &face, const QString &imagePath, const DetectionResult *detection)
{
    QJsonObject json;
    json.insert(QStringLiteral("format"), QLatin1StringView(kFaceFormat));
    json.insert(QStringLiteral("points"), pointsToJson(face, true));

    const Fapu f = face.fapu();
    QJsonObject fapu;
    fapu.insert(QStringLiteral("ES0"), f.es0);
    fapu.insert(QStringLiteral("ENS0"), f.ens0);
    fapu.insert(QStringLiteral("MNS0"), f.mns0);
    fapu.insert(QStringLiteral("MW0"), f.mw0);
    fapu.insert(QStringLiteral("LeftEyeH"), f.leftEyeH);
    fapu.insert(QStringLiteral("RightEyeH"), f.rightEyeH);
    fapu.insert(QStringLiteral("UpperLipH"), f.upperLipH);
    fapu.insert(QStringLiteral("LowerLipH"), f.lowerLipH);
    fapu.insert(QStringLiteral("JawH"), f.jawH);
    json.insert(QStringLiteral("fapu"), fapu);

    QJsonObject image;
    image.insert(QStringLiteral("path"), imagePath);
    if (face.imageSize().isValid()) {
        image.insert(QStringLiteral("width"), face.imageSize().width());
        image.insert(QStringLiteral("height"), face.imageSize().height());
    }
    json.insert(QStringLiteral("image"), image);

    if (detection) {
        json.insert(QStringLiteral("method"), detection->method);
        json.insert(QStringLiteral("timingMs"), mapToJson(detection->timingMs));
        json.insert(QStringLiteral("faceCount"), detection->faceCount);
        const QRect box = detection->faceBox;
        QJsonObject faceBox;
        faceBox.insert(QStringLiteral("x"), box.x());
        faceBox.insert(QStringLiteral("y"), box.y());
        faceBox.insert(QStringLiteral("width"), box.width());
        faceBox.insert(QStringLiteral("height"), box.height());
        json.insert(QStringLiteral("faceBox"), faceBox);
        json.insert(QStringLiteral("groupConfidence"), mapToJson(detection->groupConfidence));
    } else {
        json.insert(QStringLiteral("method"), QStringLiteral("none"));
    }
    return json;
}

std::optional<FaceModel> faceFromJson(const QJsonObject &json, QString *error, QString *imagePath)
{
    QString scratch;
    if (!error)
        error = &scratch;
    const JsonField root(json, QString());

    const JsonField formatField = root.member("format");
    QString format;
    if (!formatField.toString(&format, error))
        return std::nullopt;
    const QString want = QLatin1StringView(kFaceFormat);
    if (format != want) {
        static const QRegularExpression versioned(QStringLiteral("^toonface\\.face/(\\d+)$"));
        const auto m = versioned.match(format);
        if (m.hasMatch() && m.captured(1).toInt() > 1) {
            formatField.fail(
                QStringLiteral("%1 was made by a newer Toonface (this version reads %2)").arg(format, want), error);
        } else {
            formatField.expected(QStringLiteral("\"%1\"").arg(want), error);
        }
        return std::nullopt;
    }

    FaceModel face;
    if (!pointsFromJson(root.member("points"), &face, error))
        return std::nullopt;

    const JsonField image = root.member("image");
    QJsonObject unused;
    if (!image.toObject(&unused, error))
        return std::nullopt;
    QString path;
    if (!image.member("path").toString(&path, error))
        return std::nullopt;
    const JsonField width = image.member("width");
    const JsonField height = image.member("height");
    if (!width.isMissing() || !height.isMissing()) {
        int w = 0;
        int h = 0;
        if (!width.toInt(0, 1000000, &w, error) || !height.toInt(0, 1000000, &h, error))
            return std::nullopt;
        face.setImageSize(QSize(w, h));
    }
    if (imagePath)
        *imagePath = path;
    return face;
}

} // namespace toonface
