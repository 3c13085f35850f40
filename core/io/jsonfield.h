#pragma once

#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QString>

namespace toonface {

// One value of a parsed JSON document together with its path from the root
// ("points[12].x", "style.components.hair.fill"), for readers that validate every field and
// report the first bad one by its path.
//
// Each to*() returns true and sets *out when the value has the expected type (and range);
// otherwise it returns false and sets *error to "<path>: expected <what>, found <what was there>".
// A plain value type; copying it is cheap (QJsonValue is implicitly shared).
class JsonField
{
public:
    JsonField(const QJsonValue &value, const QString &path)
        : m_value(value)
        , m_path(path)
    { }

    const QString &path() const { return m_path; }
    const QJsonValue &value() const { return m_value; }
    bool isMissing() const { return m_value.isUndefined(); }

    // The member `key` of this object (missing when this is not an object or has no such key).
    JsonField member(const char *key) const;
    JsonField member(const QString &key) const;
    // The element `index` of this array (missing when out of range).
    JsonField at(qsizetype index) const;

    // A finite number.
    bool toNumber(double *out, QString *error) const;
    // A finite number with |value| <= limit.
    bool toBoundedNumber(double limit, double *out, QString *error) const;
    // An integral number in [min, max].
    bool toInt(int min, int max, int *out, QString *error) const;
    bool toBool(bool *out, QString *error) const;
    bool toString(QString *out, QString *error) const;
    bool toObject(QJsonObject *out, QString *error) const;
    bool toArray(QJsonArray *out, QString *error) const;

    // Sets *error to "<path>: <problem>" and returns false.
    bool fail(const QString &problem, QString *error) const;
    // Sets *error to "<path>: expected <expected>, <what was found>" and returns false.
    bool expected(const QString &expected, QString *error) const;

    // "it is missing", "found null", "found the string \"abc\"", "found an object", ...
    static QString describe(const QJsonValue &value);

private:
    QJsonValue m_value;
    QString m_path;
};

} // namespace toonface
