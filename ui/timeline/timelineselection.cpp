#include "timeline/timelineselection.h"

#include <algorithm>

namespace toonface {

Selection::Selection(std::initializer_list<ItemRef> items)
{
    for (const ItemRef &r : items)
        insert(r);
}

bool Selection::contains(const ItemRef &item) const
{
    return std::binary_search(m_items.begin(), m_items.end(), item);
}

QVector<int> Selection::indices(ItemKind kind) const
{
    QVector<int> out;
    for (const ItemRef &r : m_items)
        if (r.kind == kind)
            out.append(r.index);
    return out;
}

bool Selection::hasKind(ItemKind kind) const
{
    return std::any_of(m_items.begin(), m_items.end(), [&](const ItemRef &r) { return r.kind == kind; });
}

void Selection::insert(const ItemRef &item)
{
    const auto at = std::lower_bound(m_items.begin(), m_items.end(), item);
    if (at == m_items.end() || *at != item)
        m_items.insert(at, item);
}

void Selection::remove(const ItemRef &item)
{
    const auto at = std::lower_bound(m_items.begin(), m_items.end(), item);
    if (at != m_items.end() && *at == item)
        m_items.erase(at);
}

void Selection::toggle(const ItemRef &item)
{
    if (contains(item))
        remove(item);
    else
        insert(item);
}

} // namespace toonface
