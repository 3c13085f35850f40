#include "views/displaynames.h"

#include "face/pointtable.h"

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

QString pointTitle(int index)
{
    const QString id = pointId(index);
    if (id.isEmpty())
        return {};
    if (id.startsWith(QLatin1String("h.")))
        return QCoreApplication::translate("toonface::Names", "Hair outline, point %1", "a point of the face")
            .arg(id.mid(2));
    return lookUp(id,
        {
            {"11.2", QT_TRANSLATE_NOOP3("toonface::Names", "Left temple", "a point of the face")},
            {"11.1", QT_TRANSLATE_NOOP3("toonface::Names", "Hairline, centre", "a point of the face")},
            {"11.3", QT_TRANSLATE_NOOP3("toonface::Names", "Right temple", "a point of the face")},
            {"5.2", QT_TRANSLATE_NOOP3("toonface::Names", "Left cheek", "a point of the face")},
            {"5.1", QT_TRANSLATE_NOOP3("toonface::Names", "Right cheek", "a point of the face")},
            {"2.14", QT_TRANSLATE_NOOP3("toonface::Names", "Jaw, left, at the mouth", "a point of the face")},
            {"2.12", QT_TRANSLATE_NOOP3("toonface::Names", "Lower jaw, left", "a point of the face")},
            {"2.1", QT_TRANSLATE_NOOP3("toonface::Names", "Chin", "a point of the face")},
            {"2.11", QT_TRANSLATE_NOOP3("toonface::Names", "Lower jaw, right", "a point of the face")},
            {"2.13", QT_TRANSLATE_NOOP3("toonface::Names", "Jaw, right, at the mouth", "a point of the face")},
            {"10.2", QT_TRANSLATE_NOOP3("toonface::Names", "Left ear, top", "a point of the face")},
            {"10.4", QT_TRANSLATE_NOOP3("toonface::Names", "Left ear, outermost point", "a point of the face")},
            {"10.6", QT_TRANSLATE_NOOP3("toonface::Names", "Left ear, bottom of the lobe", "a point of the face")},
            {"10.10",
                QT_TRANSLATE_NOOP3(
                    "toonface::Names", "Left ear, where the lobe meets the cheek", "a point of the face")},
            {"10.1", QT_TRANSLATE_NOOP3("toonface::Names", "Right ear, top", "a point of the face")},
            {"10.3", QT_TRANSLATE_NOOP3("toonface::Names", "Right ear, outermost point", "a point of the face")},
            {"10.5", QT_TRANSLATE_NOOP3("toonface::Names", "Right ear, bottom of the lobe", "a point of the face")},
            {"10.9",
                QT_TRANSLATE_NOOP3(
                    "toonface::Names", "Right ear, where the lobe meets the cheek", "a point of the face")},
            {"4.6", QT_TRANSLATE_NOOP3("toonface::Names", "Left eyebrow, outer end", "a point of the face")},
            {"4.4a", QT_TRANSLATE_NOOP3("toonface::Names", "Left eyebrow, outer arch", "a point of the face")},
            {"4.4", QT_TRANSLATE_NOOP3("toonface::Names", "Left eyebrow, inner arch", "a point of the face")},
            {"4.2", QT_TRANSLATE_NOOP3("toonface::Names", "Left eyebrow, inner end", "a point of the face")},
            {"4.1", QT_TRANSLATE_NOOP3("toonface::Names", "Right eyebrow, inner end", "a point of the face")},
            {"4.3", QT_TRANSLATE_NOOP3("toonface::Names", "Right eyebrow, inner arch", "a point of the face")},
            {"4.3a", QT_TRANSLATE_NOOP3("toonface::Names", "Right eyebrow, outer arch", "a point of the face")},
            {"4.5", QT_TRANSLATE_NOOP3("toonface::Names", "Right eyebrow, outer end", "a point of the face")},
            {"3.12", QT_TRANSLATE_NOOP3("toonface::Names", "Left eye, outer corner", "a point of the face")},
            {"3.2", QT_TRANSLATE_NOOP3("toonface::Names", "Left eye, upper lid", "a point of the face")},
            {"3.8", QT_TRANSLATE_NOOP3("toonface::Names", "Left eye, inner corner", "a point of the face")},
            {"3.4", QT_TRANSLATE_NOOP3("toonface::Names", "Left eye, lower lid", "a point of the face")},
            {"3.6", QT_TRANSLATE_NOOP3("toonface::Names", "Left eye, centre of the eyeball", "a point of the face")},
            {"3.11", QT_TRANSLATE_NOOP3("toonface::Names", "Right eye, inner corner", "a point of the face")},
            {"3.1", QT_TRANSLATE_NOOP3("toonface::Names", "Right eye, upper lid", "a point of the face")},
            {"3.7", QT_TRANSLATE_NOOP3("toonface::Names", "Right eye, outer corner", "a point of the face")},
            {"3.3", QT_TRANSLATE_NOOP3("toonface::Names", "Right eye, lower lid", "a point of the face")},
            {"3.5", QT_TRANSLATE_NOOP3("toonface::Names", "Right eye, centre of the eyeball", "a point of the face")},
            {"9.6", QT_TRANSLATE_NOOP3("toonface::Names", "Bridge of the nose, left", "a point of the face")},
            {"9.7", QT_TRANSLATE_NOOP3("toonface::Names", "Bridge of the nose, right", "a point of the face")},
            {"9.14", QT_TRANSLATE_NOOP3("toonface::Names", "Nose, top left", "a point of the face")},
            {"9.13", QT_TRANSLATE_NOOP3("toonface::Names", "Nose, top right", "a point of the face")},
            {"9.2", QT_TRANSLATE_NOOP3("toonface::Names", "Nose, left wing", "a point of the face")},
            {"9.1", QT_TRANSLATE_NOOP3("toonface::Names", "Nose, right wing", "a point of the face")},
            {"9.4", QT_TRANSLATE_NOOP3("toonface::Names", "Left nostril, bottom", "a point of the face")},
            {"9.5", QT_TRANSLATE_NOOP3("toonface::Names", "Right nostril, bottom", "a point of the face")},
            {"9.15", QT_TRANSLATE_NOOP3("toonface::Names", "Tip of the nose", "a point of the face")},
            {"8.4", QT_TRANSLATE_NOOP3("toonface::Names", "Mouth, left corner", "a point of the face")},
            {"8.9", QT_TRANSLATE_NOOP3("toonface::Names", "Upper lip, left peak", "a point of the face")},
            {"8.1", QT_TRANSLATE_NOOP3("toonface::Names", "Upper lip, top centre", "a point of the face")},
            {"8.10", QT_TRANSLATE_NOOP3("toonface::Names", "Upper lip, right peak", "a point of the face")},
            {"8.3", QT_TRANSLATE_NOOP3("toonface::Names", "Mouth, right corner", "a point of the face")},
            {"8.2", QT_TRANSLATE_NOOP3("toonface::Names", "Lower lip, bottom centre", "a point of the face")},
            {"2.2", QT_TRANSLATE_NOOP3("toonface::Names", "Upper lip, inner edge", "a point of the face")},
            {"2.3", QT_TRANSLATE_NOOP3("toonface::Names", "Lower lip, inner edge", "a point of the face")},
        });
}

} // namespace toonface
