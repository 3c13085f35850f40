#pragma once

#include "speech/features.h"
#include "speech/script.h"
#include "speech/tts.h"

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace toonface {

// espeak-ng's rate the script's pace is measured at.
inline constexpr int kDefaultReferenceRate = 175;

// The first rendering alignScript makes of a script when it matches the reference's rate to
// the speaker's: (at most) its first kProbeSyllables syllables at kDefaultReferenceRate, to
// measure the script's pace; when they are the whole script, with its features, as it may
// serve as the reference itself. It does not depend on the recording: a PaceProbe renders it
// on a thread of its own from the moment it is made, so that lipsyncRecording has it made
// while the recording is decoded.
class PaceProbe
{
public:
    static constexpr int kProbeSyllables = 120;

    // Starts rendering, unless `reference` fixes the rate (rate > 0: no probe is needed).
    PaceProbe(const Script &script, const TtsOptions &reference);
    ~PaceProbe(); // abandons the rendering if it is still running
    PaceProbe(const PaceProbe &) = delete;
    PaceProbe &operator=(const PaceProbe &) = delete;

    bool needed() const { return m_needed; }
    int syllables() const { return m_syllables; } // how many were rendered
    bool whole() const { return m_whole; } // all the script's

    // Waits for the rendering, abandoning it if `cancel` becomes true meanwhile. `features`
    // are set when whole().
    const TtsResult &sample(const std::atomic_bool *cancel);
    const SpeechFeatures &features() const { return m_features; }

private:
    void join();

    std::atomic_bool m_stop {false};
    std::mutex m_mutex;
    std::condition_variable m_doneChanged;
    bool m_done = false; // under m_mutex
    bool m_needed = false;
    int m_syllables = 0;
    bool m_whole = false;
    TtsResult m_sample;
    SpeechFeatures m_features;
    std::thread m_thread;
};

} // namespace toonface
