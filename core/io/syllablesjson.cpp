#include "io/syllablesjson.h"

#include "anim/timeline.h"
#include "i18n/coretext.h"
#include "io/jsonfield.h"

#include <QJsonObject>

namespace toonface {

namespace {

// Shape starts are written to the microsecond and may sit a rounding step outside their syllable.
constexpr double kTimeSlack = 1e-6;

bool shapesFromJson(const JsonField &field, const LipsyncSyllable &syllable, QVector<ShapeKey> *out, QString *error)
{
    QJsonArray array;
    if (!field.toArray(&array, error))
        return false;
    double previous = syllable.start;
    for (qsizetype i = 0; i < array.size(); ++i) {
        const JsonField s = field.at(i);
        QJsonObject unused;
        QString name;
        ShapeKey key;
        if (!s.toObject(&unused, error) || !s.member("shape").toString(&name, error)
            || !s.member("start").toNumber(&key.start, error))
            return false;
        const std::optional<MouthShape> shape = mouthShapeFromName(name);
        if (!shape)
            return s.member("shape").fail(ProjectText::tr("unknown mouth shape '%1'").arg(name), error);
        key.shape = *shape;
        if (key.start < previous - kTimeSlack || key.start > syllable.end + kTimeSlack)
            return s.member("start").fail(
                ProjectText::tr("%1 s is outside the syllable (%2 to %3 s) or before the shape before it")
                    .arg(key.start)
                    .arg(previous)
                    .arg(syllable.end),
                error);
        previous = key.start;
        out->append(key);
    }
    return true;
}

} // namespace

QJsonArray syllablesToJson(const QVector<LipsyncSyllable> &syllables)
{
    QJsonArray array;
    for (const LipsyncSyllable &s : syllables) {
        QJsonObject o;
        o.insert(QStringLiteral("text"), s.text);
        o.insert(QStringLiteral("pinyin"), s.pinyin);
        o.insert(QStringLiteral("tone"), s.tone);
        o.insert(QStringLiteral("start"), s.start);
        o.insert(QStringLiteral("end"), s.end);
        o.insert(QStringLiteral("confidence"), s.confidence);
        QJsonArray shapes;
        for (const ShapeKey &k : s.shapes) {
            QJsonObject key;
            key.insert(QStringLiteral("shape"), mouthShapeName(k.shape));
            key.insert(QStringLiteral("start"), k.start);
            shapes.append(key);
        }
        o.insert(QStringLiteral("shapes"), shapes);
        array.append(o);
    }
    return array;
}

bool syllablesFromJson(const JsonField &field, QVector<LipsyncSyllable> *out, QString *error)
{
    QJsonArray array;
    if (!field.toArray(&array, error))
        return false;
    QVector<LipsyncSyllable> result;
    result.reserve(array.size());
    for (qsizetype i = 0; i < array.size(); ++i) {
        const JsonField f = field.at(i);
        QJsonObject unused;
        LipsyncSyllable s;
        if (!f.toObject(&unused, error) || !f.member("text").toString(&s.text, error)
            || !f.member("pinyin").toString(&s.pinyin, error) || !f.member("tone").toInt(0, 5, &s.tone, error)
            || !f.member("start").toBoundedNumber(Timeline::kMaxSeconds, &s.start, error)
            || !f.member("end").toBoundedNumber(Timeline::kMaxSeconds, &s.end, error)
            || !f.member("confidence").toNumber(&s.confidence, error))
            return false;
        if (s.start < 0)
            return f.member("start").expected(ProjectText::tr("a time of 0 s or more"), error);
        if (s.end < s.start)
            return f.member("end").expected(ProjectText::tr("a time after the start (%1 s)").arg(s.start), error);
        if (!shapesFromJson(f.member("shapes"), s, &s.shapes, error))
            return false;
        result.append(std::move(s));
    }
    *out = std::move(result);
    return true;
}

} // namespace toonface
