#pragma once

#include "speech/onsetsignals.h"

#include <vector>

namespace toonface {

// Onset frames of the n syllables: the best chain of boundaries near the warped estimates
// `prior`, each where the signal shows the syllable's kind of onset, each syllable holding a
// voiced nucleus and lasting about as long as in the reference (`expected`, frames of speech,
// scaled to the speaker's rate) and never less than its minimum (`minFrames`, frames of speech:
// the duration model's, a hard limit of the search). Returns the evidence of each chosen onset
// in `evidence`.
std::vector<int> segmentSyllables(const OnsetSignals &sig, const std::vector<int> &prior,
    const std::vector<double> &expected, const std::vector<int> &minFrames, const std::vector<OnsetKind> &kinds,
    const std::vector<double> &priorWeight, int speechEnd, std::vector<double> *evidence);

} // namespace toonface
