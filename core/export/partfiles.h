#pragma once

#include <QString>

namespace toonface {

// Exports write beside their target under a hidden name, ".NAME.PID-N.part" (a file, or a
// folder of PNG frames), and rename it over the target at the end. A process that was killed
// before it could clean up leaves its part behind; the next export of the same target removes
// the parts whose process is gone (a running export's parts are left alone).
void removeStaleParts(const QString &target);

} // namespace toonface
