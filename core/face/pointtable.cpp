#include "face/pointtable.h"

#include <QHash>

#include <string_view>

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

namespace {

// An id's slot in the lookup table: its group ("h" or a number below 16) and its number (below
// 32), or -1 for an id of another form.
int slotOf(std::string_view id)
{
    const size_t dot = id.find('.');
    if (dot == std::string_view::npos || dot == 0 || dot > 2 || dot + 1 >= id.size() || id.size() - dot > 3)
        return -1;
    auto number = [](std::string_view digits) {
        int n = 0;
        for (const char c : digits) {
            if (c < '0' || c > '9')
                return -1;
            n = n * 10 + (c - '0');
        }
        return n;
    };
    const int group = id.substr(0, dot) == "h" ? 0 : number(id.substr(0, dot));
    const int n = number(id.substr(dot + 1));
    return group < 0 || group >= 16 || n < 0 || n >= 32 ? -1 : group * 32 + n;
}

} // namespace

int pointIndex(QLatin1StringView id)
{
    // Without a QString or a hash: the drawing's rules look points up by name hundreds of
    // times a pose, and the SMIL export draws tens of thousands of poses.
    static const std::array<int, 16 * 32> table = [] {
        std::array<int, 16 * 32> t;
        t.fill(-1);
        for (int i = 0; i < kPointCount; ++i) {
            if (const int slot = slotOf(kTable[i].id); slot >= 0)
                t[size_t(slot)] = i;
        }
        return t;
    }();
    const std::string_view view(id.data(), size_t(id.size()));
    const int slot = slotOf(view);
    const int i = slot < 0 ? -1 : table[size_t(slot)];
    // The slot ignores leading zeros ("8.09"): only the id as written matches.
    if (i >= 0 && view == kTable[i].id)
        return i;
    // Ids of another form ("4.4a") and unknown ones: by comparison with every id.
    for (int k = 0; k < kPointCount; ++k) {
        if (view == kTable[k].id)
            return k;
    }
    return -1;
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
