#include "timeline/timelineicons.h"

namespace toonface {

QIcon timelineIcon(const QString &themeName, const QString &resourceName)
{
    const QIcon bundled(QStringLiteral(":/toonface/icons/%1.svg").arg(resourceName));
    return themeName.isEmpty() ? bundled : QIcon::fromTheme(themeName, bundled);
}

QIcon emotionIcon(Emotion emotion)
{
    return QIcon(QStringLiteral(":/toonface/icons/emotion-%1.svg").arg(emotionName(emotion)));
}

} // namespace toonface
