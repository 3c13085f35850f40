#pragma once

#include "face/emotion.h"

#include <QIcon>
#include <QString>

namespace toonface {

// An icon of the desktop theme when it has one by `themeName`, else the project's own
// resources/icons/<resourceName>.svg.
QIcon timelineIcon(const QString &themeName, const QString &resourceName);
// The project's face for an emotion preset (resources/icons/emotion-<name>.svg).
QIcon emotionIcon(Emotion emotion);

} // namespace toonface
