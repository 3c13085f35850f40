#include "io/textgrid.h"

#include "i18n/coretext.h"

#include <QFile>
#include <QRegularExpression>
#include <QStringList>

namespace toonface {

QVector<TextGridInterval> readTextGridTier(const QString &path, const QString &tier, QString *error)
{
    auto fail = [&](const QString &why) {
        if (error)
            *error = withProblem(path, why);
        return QVector<TextGridInterval> {};
    };
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return fail(f.errorString());
    // Both text formats hold the same sequence of strings and numbers once the long format's
    // "name = " labels and "[n]" indices are set aside: a tier is its class, name, xmin, xmax,
    // count, then xmin xmax text per interval.
    QString text = QString::fromUtf8(f.readAll());
    static const QRegularExpression index(QStringLiteral("\\[\\d+\\]"));
    text.remove(index);
    static const QRegularExpression token(
        QStringLiteral("\"((?:[^\"]|\"\")*)\"|(-?\\d+(?:\\.\\d+)?(?:[eE][-+]?\\d+)?)"));
    QStringList tokens;
    for (auto it = token.globalMatch(text); it.hasNext();) {
        const auto m = it.next();
        tokens.append(m.capturedStart(1) >= 0 ? QStringLiteral("\"") + m.captured(1) : m.captured(2));
    }
    for (qsizetype i = 0; i + 4 < tokens.size(); ++i) {
        if (tokens[i] != QLatin1String("\"IntervalTier") || tokens[i + 1].mid(1) != tier)
            continue;
        const int count = tokens[i + 4].toInt();
        QVector<TextGridInterval> out;
        for (qsizetype k = 0; k < count && i + 5 + 3 * k + 2 < tokens.size(); ++k) {
            const qsizetype at = i + 5 + 3 * k;
            out.append({tokens[at].toDouble(), tokens[at + 1].toDouble(), tokens[at + 2].mid(1)});
        }
        return out;
    }
    return fail(LipSyncText::tr("no interval tier named '%1'").arg(tier));
}

} // namespace toonface
