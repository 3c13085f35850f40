#pragma once

#include "speech/audio.h"

#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>
#include <vector>

namespace toonface {

// Hands blocks of samples on to a sink that runs on a thread of its own, so that whoever makes
// the samples (the synthesiser, a decoder) and whoever consumes them (the features) work on two
// cores at once. The sink sees the same blocks in the same order as if it were called directly.
// At most a few blocks wait: a producer faster than its sink waits for it.
class SampleRelay
{
public:
    explicit SampleRelay(AudioSink sink);
    ~SampleRelay(); // finish()
    SampleRelay(const SampleRelay &) = delete;
    SampleRelay &operator=(const SampleRelay &) = delete;

    void push(const float *samples, qsizetype count); // copies the block
    void finish(); // returns once the sink has had every block; push no more after it

private:
    void run();

    AudioSink m_sink;
    std::mutex m_mutex;
    std::condition_variable m_changed;
    std::deque<std::vector<float>> m_queue;
    std::vector<std::vector<float>> m_spare; // blocks handed back for reuse
    bool m_done = false;
    std::thread m_thread;
};

} // namespace toonface
