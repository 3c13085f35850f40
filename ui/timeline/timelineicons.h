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
// An emotion preset's name as the interface shows it (translated; emotionName() is the file's).
QString emotionTitle(Emotion emotion);
// A drawing style preset's name (Style::presetNames()) as the interface shows it.
QString styleTitle(const QString &preset);

} // namespace toonface
