#include "speech/paceprobe.h"

#include "speech/referencefeatures.h"
#include "speech/stagetimes.h"

#include <chrono>

namespace toonface {

PaceProbe::PaceProbe(const Script &script, const TtsOptions &reference)
{
    if (reference.rate > 0 || script.syllables.isEmpty())
        return;
    Script probe = script;
    if (probe.syllables.size() > kProbeSyllables)
        probe.syllables.resize(kProbeSyllables);
    m_needed = true;
    m_syllables = int(probe.syllables.size());
    m_whole = probe.syllables.size() == script.syllables.size();
    TtsOptions tts = reference;
    tts.rate = kDefaultReferenceRate;
    m_thread = std::thread([this, probe = std::move(probe), tts] {
        // Only the syllables' times are needed of a part of the script: its samples are dropped.
        m_sample = m_whole ? renderReference(probe, tts, &m_features, &m_stop)
                           : synthesize(
                               probe, tts, [](const float *, qsizetype) {}, {}, &m_stop);
        markStage("probed");
        std::lock_guard lock(m_mutex);
        m_done = true;
        m_doneChanged.notify_all();
    });
}

PaceProbe::~PaceProbe()
{
    m_stop = true;
    join();
}

void PaceProbe::join()
{
    if (m_thread.joinable())
        m_thread.join();
}

const TtsResult &PaceProbe::sample(const std::atomic_bool *cancel)
{
    if (m_thread.joinable()) {
        // The user's cancel is a flag to poll, not a signal to wait on.
        std::unique_lock lock(m_mutex);
        while (!m_doneChanged.wait_for(lock, std::chrono::milliseconds(20), [this] { return m_done; })) {
            if (isCancelled(cancel))
                m_stop = true;
        }
    }
    join();
    return m_sample;
}

} // namespace toonface
