#pragma once

#include <QVector>

#include <compare>

namespace toonface {

// The kinds of items on the timeline's rows: the script's syllables, the tracks' keys and clips,
// and the audio track's clips (on the waveform row; last, so older kinds keep their values).
enum class ItemKind { Syllable, Mouth, Emotion, Blink, Head, Gaze, Pose, Audio };
inline constexpr int kItemKindCount = 8;

// One item on the timeline: the index of a syllable, key or clip in its (time-sorted) list.
struct ItemRef
{
    ItemKind kind = ItemKind::Mouth;
    int index = 0;
    auto operator<=>(const ItemRef &) const = default;
};

// The selected items, sorted and without repeats. A plain value.
class Selection
{
public:
    Selection() = default;
    Selection(std::initializer_list<ItemRef> items);

    bool isEmpty() const { return m_items.isEmpty(); }
    qsizetype size() const { return m_items.size(); }
    const QVector<ItemRef> &items() const { return m_items; }
    bool contains(const ItemRef &item) const;
    // The indices of the selected items of one kind, ascending.
    QVector<int> indices(ItemKind kind) const;
    bool hasKind(ItemKind kind) const;

    void insert(const ItemRef &item);
    void remove(const ItemRef &item);
    void toggle(const ItemRef &item);
    void clear() { m_items.clear(); }
    // Leaves out items whose index is not below count(kind).
    template<class Count>
    void clip(Count count)
    {
        m_items.removeIf([&](const ItemRef &r) { return r.index < 0 || r.index >= count(r.kind); });
    }

    bool operator==(const Selection &) const = default;

private:
    QVector<ItemRef> m_items;
};

} // namespace toonface
