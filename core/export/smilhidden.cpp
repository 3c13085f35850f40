#include "export/smilhidden.h"

#include <QHash>

namespace toonface::smil {

bool isRadius(const Channel &c)
{
    return c.part >= 0 && c.kind == ChannelKind::Number
        && (c.attribute == QLatin1StringView("r") || c.attribute == QLatin1StringView("rx")
            || c.attribute == QLatin1StringView("ry"));
}

QVector<std::pair<qint64, qint64>> zeroSpans(const Channel &radius, const ChannelKeys &keys)
{
    // Between two keys the value stays between theirs (keySplines' progress is within [0, 1]),
    // so an interval whose ends are both 0 or less is 0 or less throughout.
    const double base = radius.base.value(0);
    const double unit = 1.0 / double(kPow10[radius.decimals]);
    auto hidden = [&](qsizetype k) { return base + double(keys.values[k]) * unit <= 0; };
    QVector<std::pair<qint64, qint64>> spans;
    for (qsizetype i = 0; i + 1 < keys.times.size(); ++i) {
        if (!hidden(i) || !hidden(i + 1))
            continue;
        if (!spans.isEmpty() && spans.last().second == keys.times[i])
            spans.last().second = keys.times[i + 1];
        else
            spans.append({keys.times[i], keys.times[i + 1]});
    }
    return spans;
}

void dropHiddenKeys(const QVector<Channel> &channels, QVector<ChannelKeys> &keys)
{
    QHash<int, QVector<std::pair<qint64, qint64>>> hiddenOf; // part -> where it draws nothing
    for (const ChannelKeys &k : keys) {
        const Channel &c = channels[k.channel];
        if (isRadius(c))
            hiddenOf[c.part] += zeroSpans(c, k);
    }
    for (ChannelKeys &k : keys) {
        const Channel &c = channels[k.channel];
        const auto found = hiddenOf.constFind(c.part);
        if (c.part < 0 || found == hiddenOf.constEnd() || isRadius(c))
            continue;
        auto inside = [&](qint64 a, qint64 b) {
            return std::any_of(
                found->cbegin(), found->cend(), [&](const auto &s) { return s.first <= a && b <= s.second; });
        };
        // Key i goes when the interval from the last key kept to key i + 1 is all hidden; the
        // interval that then ends at the next key kept is linear (its shape is never seen).
        ChannelKeys kept;
        kept.channel = k.channel;
        const int size = c.size;
        auto keep = [&](qsizetype i, std::optional<Timing> timing) {
            kept.times.append(k.times[i]);
            kept.values.append(k.values.mid(i * size, size));
            if (i > 0)
                kept.timings.append(timing);
        };
        keep(0, std::nullopt);
        qsizetype last = 0; // index in k of the last key kept
        for (qsizetype i = 1; i < k.times.size(); ++i) {
            if (i + 1 < k.times.size() && inside(k.times[last], k.times[i + 1]))
                continue;
            keep(i, i == last + 1 ? k.timings[i - 1] : std::optional<Timing>(Timing {}));
            last = i;
        }
        k = std::move(kept);
    }
}

} // namespace toonface::smil
