#include "io/jsonfield.h"

#include "i18n/coretext.h"

#include <QLocale>

#include <cmath>

namespace toonface {

namespace {

QString joinKey(const QString &path, const QString &key)
{
    return path.isEmpty() ? key : path + QLatin1Char('.') + key;
}

} // namespace

JsonField JsonField::member(const char *key) const
{
    return member(QString::fromLatin1(key));
}

JsonField JsonField::member(const QString &key) const
{
    const QJsonValue v = m_value.isObject() ? m_value.toObject().value(key) : QJsonValue(QJsonValue::Undefined);
    return JsonField(v, joinKey(m_path, key));
}

JsonField JsonField::at(qsizetype index) const
{
    QJsonValue v(QJsonValue::Undefined);
    if (m_value.isArray()) {
        const QJsonArray a = m_value.toArray();
        if (index >= 0 && index < a.size())
            v = a.at(index);
    }
    return JsonField(v, m_path + QLatin1Char('[') + QString::number(index) + QLatin1Char(']'));
}

bool JsonField::toNumber(double *out, QString *error) const
{
    if (!m_value.isDouble())
        return expected(ProjectText::tr("a number"), error);
    const double d = m_value.toDouble();
    if (!std::isfinite(d))
        return expected(ProjectText::tr("a finite number"), error);
    *out = d;
    return true;
}

bool JsonField::toBoundedNumber(double limit, double *out, QString *error) const
{
    double d = 0;
    if (!toNumber(&d, error))
        return false;
    if (std::abs(d) > limit)
        return expected(
            ProjectText::tr("a number between %1 and %2").arg(-limit, 0, 'g', 12).arg(limit, 0, 'g', 12), error);
    *out = d;
    return true;
}

bool JsonField::toInt(int min, int max, int *out, QString *error) const
{
    const QString what = ProjectText::tr("an integer from %1 to %2").arg(min).arg(max);
    if (!m_value.isDouble())
        return expected(what, error);
    const double d = m_value.toDouble();
    if (!std::isfinite(d) || d != std::floor(d) || d < min || d > max)
        return expected(what, error);
    *out = int(d);
    return true;
}

bool JsonField::toBool(bool *out, QString *error) const
{
    if (!m_value.isBool())
        return expected(ProjectText::tr("true or false"), error);
    *out = m_value.toBool();
    return true;
}

bool JsonField::toString(QString *out, QString *error) const
{
    if (!m_value.isString())
        return expected(ProjectText::tr("a string"), error);
    *out = m_value.toString();
    return true;
}

bool JsonField::toObject(QJsonObject *out, QString *error) const
{
    if (!m_value.isObject())
        return expected(ProjectText::tr("an object"), error);
    *out = m_value.toObject();
    return true;
}

bool JsonField::toArray(QJsonArray *out, QString *error) const
{
    if (!m_value.isArray())
        return expected(ProjectText::tr("an array"), error);
    *out = m_value.toArray();
    return true;
}

bool JsonField::fail(const QString &problem, QString *error) const
{
    if (error)
        *error = m_path.isEmpty() ? problem : withProblem(m_path, problem);
    return false;
}

bool JsonField::expected(const QString &expected, QString *error) const
{
    return fail(ProjectText::tr("expected %1, %2").arg(expected, describe(m_value)), error);
}

QString JsonField::describe(const QJsonValue &value)
{
    switch (value.type()) {
    case QJsonValue::Undefined: return ProjectText::tr("it is missing");
    case QJsonValue::Null: return ProjectText::tr("found null");
    case QJsonValue::Bool: return value.toBool() ? ProjectText::tr("found true") : ProjectText::tr("found false");
    case QJsonValue::Double:
        return ProjectText::tr("found %1").arg(QString::number(value.toDouble(), 'g', QLocale::FloatingPointShortest));
    case QJsonValue::String: {
        QString s = value.toString();
        if (s.size() > 40)
            s = s.left(37) + QStringLiteral("...");
        return ProjectText::tr("found the string \"%1\"").arg(s);
    }
    case QJsonValue::Array: return ProjectText::tr("found an array");
    case QJsonValue::Object: return ProjectText::tr("found an object");
    }
    return {};
}

} // namespace toonface
