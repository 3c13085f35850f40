#pragma once

#include <QString>

#include <atomic>
#include <functional>

namespace toonface {

// Long speech work reports how far it got (0..1) and what it is doing; it polls `cancel`
// and stops early with a "cancelled" status when it becomes true.
using SpeechProgressFn = std::function<void(double fraction, const QString &stage)>;

inline bool isCancelled(const std::atomic_bool *cancel)
{
    return cancel && cancel->load(std::memory_order_relaxed);
}

} // namespace toonface
