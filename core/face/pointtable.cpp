#include "face/pointtable.h"

#include <QHash>

#include <string_view>
#include <unordered_map>

namespace toonface {

namespace {

constexpr PointGroup H = PointGroup::Hair;
constexpr PointGroup C = PointGroup::Contour;
constexpr PointGroup R = PointGroup::Ears;
constexpr PointGroup B = PointGroup::Eyebrows;
constexpr PointGroup E = PointGroup::Eyes;
constexpr PointGroup N = PointGroup::Nose;
constexpr PointGroup M = PointGroup::Mouth;

constexpr std::array<PointInfo, kPointCount> kTable = {{
    {"h.1", H, false},
    {"h.2", H, false},
    {"h.3", H, false},
    {"h.4", H, false},
    {"h.5", H, false},
    {"h.6", H, false},
    {"h.7", H, false},
    {"h.8", H, false},
    {"h.9", H, false},
    {"h.10", H, false},
    {"h.11", H, false},
    {"h.12", H, false},
    {"h.13", H, false},
    {"h.14", H, false},
    {"h.15", H, false},
    {"h.16", H, false},
    {"h.17", H, false},
    {"h.18", H, false},
    {"h.19", H, false},
    {"11.2", C, false},
    {"11.1", C, false},
    {"11.3", C, false},
    {"5.2", C, false},
    {"5.1", C, false},
    {"2.14", C, false},
    {"2.12", C, false},
    {"2.1", C, false},
    {"2.11", C, false},
    {"2.13", C, false},
    {"10.2", R, false},
    {"10.4", R, false},
    {"10.6", R, false},
    {"10.10", R, false},
    {"10.1", R, false},
    {"10.3", R, false},
    {"10.5", R, false},
    {"10.9", R, false},
    {"4.6", B, true},
    {"4.4a", B, true},
    {"4.4", B, true},
    {"4.2", B, true},
    {"4.1", B, true},
    {"4.3", B, true},
    {"4.3a", B, true},
    {"4.5", B, true},
    {"3.12", E, false},
    {"3.2", E, true},
    {"3.8", E, false},
    {"3.4", E, true},
    {"3.6", E, true},
    {"3.11", E, false},
    {"3.1", E, true},
    {"3.7", E, false},
    {"3.3", E, true},
    {"3.5", E, true},
    {"9.6", N, false},
    {"9.7", N, false},
    {"9.14", N, false},
    {"9.13", N, false},
    {"9.2", N, false},
    {"9.1", N, false},
    {"9.4", N, false},
    {"9.5", N, false},
    {"9.15", N, false},
    {"8.4", M, true},
    {"8.9", M, true},
    {"8.1", M, false},
    {"8.10", M, false},
    {"8.3", M, true},
    {"8.2", M, true},
    {"2.2", M, false},
    {"2.3", M, false},
}};

const QHash<QString, int> &indexById()
{
    static const QHash<QString, int> map = [] {
        QHash<QString, int> m;
        for (int i = 0; i < kPointCount; ++i)
            m.insert(QString::fromLatin1(kTable[i].id), i);
        return m;
    }();
    return map;
}

} // namespace

const std::array<PointInfo, kPointCount> &pointTable()
{
    return kTable;
}

int pointIndex(const QString &id)
{
    return indexById().value(id, -1);
}

int pointIndex(QLatin1StringView id)
{
    // Without a QString: the drawing's rules look points up by name hundreds of times a pose.
    static const std::unordered_map<std::string_view, int> map = [] {
        std::unordered_map<std::string_view, int> m;
        for (int i = 0; i < kPointCount; ++i)
            m.emplace(kTable[i].id, i);
        return m;
    }();
    const auto it = map.find(std::string_view(id.data(), size_t(id.size())));
    return it == map.end() ? -1 : it->second;
}

QString pointId(int index)
{
    if (index < 0 || index >= kPointCount)
        return {};
    return QString::fromLatin1(kTable[index].id);
}

QString groupName(PointGroup group)
{
    switch (group) {
    case PointGroup::Hair: return QStringLiteral("hair");
    case PointGroup::Contour: return QStringLiteral("contour");
    case PointGroup::Ears: return QStringLiteral("ears");
    case PointGroup::Eyebrows: return QStringLiteral("eyebrows");
    case PointGroup::Eyes: return QStringLiteral("eyes");
    case PointGroup::Nose: return QStringLiteral("nose");
    case PointGroup::Mouth: return QStringLiteral("mouth");
    }
    return {};
}

bool groupFromName(const QString &name, PointGroup *group)
{
    for (PointGroup g : {PointGroup::Hair, PointGroup::Contour, PointGroup::Ears, PointGroup::Eyebrows,
             PointGroup::Eyes, PointGroup::Nose, PointGroup::Mouth}) {
        if (groupName(g) == name) {
            *group = g;
            return true;
        }
    }
    return false;
}

namespace pt {
int idx(const char *id)
{
    const int i = pointIndex(QLatin1StringView(id));
    Q_ASSERT_X(i >= 0, "pt::idx", id);
    return i;
}
} // namespace pt

} // namespace toonface
