#pragma once

namespace toonface {

// With TOONFACE_TIMINGS set, prints on stderr "toonface: timing: STAGE MS" when a stage of
// the speech work ends, MS being the monotonic clock (CLOCK_MONOTONIC, ms with three decimals)
// so that a parent that read the clock when it started the process can tell the process's
// start-up from its work (bench speech.lipsyncCli). Without it, does nothing.
void markStage(const char *stage);

} // namespace toonface
