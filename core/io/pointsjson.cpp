#include "io/pointsjson.h"

#include "i18n/coretext.h"

#include <QJsonObject>

namespace toonface {

QJsonArray pointsToJson(const FaceModel &face, bool withGroups)
{
    const auto &table = pointTable();
    QJsonArray points;
    for (int i = 0; i < kPointCount; ++i) {
        QJsonObject p;
        p.insert(QStringLiteral("id"), QString::fromLatin1(table[i].id));
        p.insert(QStringLiteral("x"), face.point(i).x());
        p.insert(QStringLiteral("y"), face.point(i).y());
        if (withGroups) {
            p.insert(QStringLiteral("group"), groupName(table[i].group));
            p.insert(QStringLiteral("control"), table[i].control);
        }
        p.insert(QStringLiteral("handPlaced"), face.isHandPlaced(i));
        points.append(p);
    }
    return points;
}

bool pointsFromJson(const JsonField &points, FaceModel *face, QString *error)
{
    QJsonArray array;
    if (!points.toArray(&array, error))
        return false;
    if (array.size() != kPointCount) {
        return points.fail(ProjectText::tr("expected %1 points, found %2").arg(kPointCount).arg(array.size()), error);
    }
    const auto &table = pointTable();
    for (int i = 0; i < kPointCount; ++i) {
        const JsonField p = points.at(i);
        QJsonObject unused;
        if (!p.toObject(&unused, error))
            return false;
        const QString wantId = QString::fromLatin1(table[i].id);
        QString id;
        if (!p.member("id").toString(&id, error))
            return false;
        if (id != wantId)
            return p.member("id").expected(
                QStringLiteral("\"%1\" (points are listed in the order of the face model)").arg(wantId), error);
        double x = 0;
        double y = 0;
        if (!p.member("x").toBoundedNumber(kMaxCoordinate, &x, error)
            || !p.member("y").toBoundedNumber(kMaxCoordinate, &y, error))
            return false;
        const JsonField group = p.member("group");
        if (!group.isMissing()) {
            QString name;
            if (!group.toString(&name, error))
                return false;
            if (name != groupName(table[i].group))
                return group.expected(QStringLiteral("\"%1\"").arg(groupName(table[i].group)), error);
        }
        const JsonField control = p.member("control");
        if (!control.isMissing()) {
            bool c = false;
            if (!control.toBool(&c, error))
                return false;
            if (c != table[i].control)
                return control.expected(table[i].control ? QStringLiteral("true") : QStringLiteral("false"), error);
        }
        bool handPlaced = false;
        const JsonField hand = p.member("handPlaced");
        if (!hand.isMissing() && !hand.toBool(&handPlaced, error))
            return false;
        face->setPoint(i, QPointF(x, y), handPlaced);
    }
    return true;
}

} // namespace toonface
