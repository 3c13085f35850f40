#include "timeline/timelineicons.h"

#include <QCoreApplication>

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

QString emotionTitle(Emotion emotion)
{
    switch (emotion) {
    case Emotion::Neutral: return QCoreApplication::translate("toonface::Names", "Neutral");
    case Emotion::Smile: return QCoreApplication::translate("toonface::Names", "Smile");
    case Emotion::Sad: return QCoreApplication::translate("toonface::Names", "Sad");
    case Emotion::Angry: return QCoreApplication::translate("toonface::Names", "Angry");
    case Emotion::Surprise: return QCoreApplication::translate("toonface::Names", "Surprise");
    }
    return emotionName(emotion);
}

QString styleTitle(const QString &preset)
{
    if (preset == QLatin1StringView("normal"))
        return QCoreApplication::translate("toonface::Names", "Normal", "drawing style");
    if (preset == QLatin1StringView("soft"))
        return QCoreApplication::translate("toonface::Names", "Soft", "drawing style");
    if (preset == QLatin1StringView("bold"))
        return QCoreApplication::translate("toonface::Names", "Bold", "drawing style");
    if (preset == QLatin1StringView("cute"))
        return QCoreApplication::translate("toonface::Names", "Cute", "drawing style");
    QString label = preset;
    if (!label.isEmpty())
        label[0] = label[0].toUpper();
    return label;
}

} // namespace toonface
