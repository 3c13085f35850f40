#include "speech/samplerelay.h"

namespace toonface {

namespace {

constexpr size_t kMaxQueued = 16; // blocks; the synthesiser's are 60 ms
// The sink's thread is woken once this many blocks wait (or at the end), not for every block:
// a wake-up per block cost more than the blocks' hand-over.
constexpr size_t kWakeAt = 8;

} // namespace

SampleRelay::SampleRelay(AudioSink sink)
    : m_sink(std::move(sink))
    , m_thread([this] { run(); })
{ }

SampleRelay::~SampleRelay()
{
    finish();
}

void SampleRelay::push(const float *samples, qsizetype count)
{
    if (count <= 0)
        return;
    std::unique_lock lock(m_mutex);
    m_changed.wait(lock, [this] { return m_queue.size() < kMaxQueued; });
    std::vector<float> block;
    if (!m_spare.empty()) {
        block = std::move(m_spare.back());
        m_spare.pop_back();
    }
    block.assign(samples, samples + count);
    m_queue.push_back(std::move(block));
    if (m_queue.size() >= kWakeAt)
        m_changed.notify_all();
}

void SampleRelay::finish()
{
    {
        std::lock_guard lock(m_mutex);
        m_done = true;
        m_changed.notify_all();
    }
    if (m_thread.joinable())
        m_thread.join();
}

void SampleRelay::run()
{
    std::unique_lock lock(m_mutex);
    for (;;) {
        m_changed.wait(lock, [this] { return m_done || m_queue.size() >= kWakeAt; });
        if (m_queue.empty())
            return; // done, and nothing left
        while (!m_queue.empty()) {
            std::vector<float> block = std::move(m_queue.front());
            m_queue.pop_front();
            // A producer waits only on a full queue: it is woken once half of it is free.
            if (m_queue.size() == kMaxQueued - kWakeAt)
                m_changed.notify_all();
            lock.unlock();
            m_sink(block.data(), qsizetype(block.size()));
            lock.lock();
            m_spare.push_back(std::move(block));
        }
    }
}

} // namespace toonface
