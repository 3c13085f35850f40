#include "speech/samplerelay.h"

namespace toonface {

namespace {

constexpr size_t kMaxQueued = 16; // blocks; the synthesiser's are 200 ms

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
        m_changed.wait(lock, [this] { return m_done || !m_queue.empty(); });
        if (m_queue.empty())
            return; // done, and nothing left
        std::vector<float> block = std::move(m_queue.front());
        m_queue.pop_front();
        m_changed.notify_all();
        lock.unlock();
        m_sink(block.data(), qsizetype(block.size()));
        lock.lock();
        m_spare.push_back(std::move(block));
    }
}

} // namespace toonface
