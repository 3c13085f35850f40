#include "views/displaynames.h"

#include <QCoreApplication>

namespace toonface {

namespace {

// A name and its title with the translators' comment (QT_TRANSLATE_NOOP3 gives both).
struct Title
{
    const char *name;
    struct
    {
        const char *source;
        const char *comment;
    } text;
};

QString lookUp(const QString &name, std::initializer_list<Title> titles)
{
    for (const Title &t : titles) {
        if (name == QLatin1StringView(t.name))
            return QCoreApplication::translate("toonface::Names", t.text.source, t.text.comment);
    }
    return name;
}

} // namespace

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
    return lookUp(preset,
        {{"normal", QT_TRANSLATE_NOOP3("toonface::Names", "Normal", "drawing style")},
            {"soft", QT_TRANSLATE_NOOP3("toonface::Names", "Soft", "drawing style")},
            {"bold", QT_TRANSLATE_NOOP3("toonface::Names", "Bold", "drawing style")},
            {"cute", QT_TRANSLATE_NOOP3("toonface::Names", "Cute", "drawing style")}});
}

QString variantTitle(const QString &name)
{
    return lookUp(name,
        {{"polyline", QT_TRANSLATE_NOOP3("toonface::Names", "Angular", "eyebrow variant")},
            {"bezier", QT_TRANSLATE_NOOP3("toonface::Names", "Curved", "eyebrow variant")},
            {"thick", QT_TRANSLATE_NOOP3("toonface::Names", "Thick", "eyebrow variant")},
            {"full", QT_TRANSLATE_NOOP3("toonface::Names", "Full", "nose variant")},
            {"simple", QT_TRANSLATE_NOOP3("toonface::Names", "Simple", "nose variant")},
            {"tip", QT_TRANSLATE_NOOP3("toonface::Names", "Tip only", "nose variant")},
            {"none", QT_TRANSLATE_NOOP3("toonface::Names", "None", "glasses")},
            {"round", QT_TRANSLATE_NOOP3("toonface::Names", "Round", "glasses")},
            {"rectangular", QT_TRANSLATE_NOOP3("toonface::Names", "Rectangular", "glasses")},
            {"rimless", QT_TRANSLATE_NOOP3("toonface::Names", "Rimless", "glasses")},
            {"landmarks", QT_TRANSLATE_NOOP3("toonface::Names", "landmark", "detection method")},
            {"classic", QT_TRANSLATE_NOOP3("toonface::Names", "classic", "detection method")}});
}

} // namespace toonface
