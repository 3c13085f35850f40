#include "window/detectionsteps.h"

#include <QCoreApplication>

#include <algorithm>

namespace toonface {

namespace {

const QLatin1StringView kCloseUpSuffix("-crop");

struct KnownStep
{
    const char *name;
    const char *text;
};

// The steps the detectors name today, in the order they happen; the texts follow the thesis
// (chapter 3, figures 3.6–3.18) so that the user can compare.
const KnownStep kKnownSteps[] = {
    {"classic-b1", QT_TRANSLATE_NOOP("DetectionSteps", "B1 – dark regions (1st level, intensity)")},
    {"classic-b2", QT_TRANSLATE_NOOP("DetectionSteps", "B2 – face regions (2nd level, hue)")},
    {"classic-b3", QT_TRANSLATE_NOOP("DetectionSteps", "B3 – B1 and B2 (for the hair region)")},
    {"classic-face-hair", QT_TRANSLATE_NOOP("DetectionSteps", "Face and hair regions")},
    {"classic-eye-pairs", QT_TRANSLATE_NOOP("DetectionSteps", "Eye-pair candidates and the chosen pair")},
    {"classic-eyeballs", QT_TRANSLATE_NOOP("DetectionSteps", "Eyeballs and the 2d square")},
    {"classic-edges", QT_TRANSLATE_NOOP("DetectionSteps", "Edges and division lines")},
    {"classic-feature-regions", QT_TRANSLATE_NOOP("DetectionSteps", "Feature regions")},
    {"classic-points", QT_TRANSLATE_NOOP("DetectionSteps", "Feature points (thesis pipeline)")},
    {"detect-landmarks", QT_TRANSLATE_NOOP("DetectionSteps", "Landmarks")},
    {"detect-hair-region", QT_TRANSLATE_NOOP("DetectionSteps", "Hair region")},
    {"detect-points-crop", QT_TRANSLATE_NOOP("DetectionSteps", "Points, close-up")},
};

int knownRank(const QString &name)
{
    for (int i = 0; i < int(std::size(kKnownSteps)); ++i) {
        if (name == QLatin1StringView(kKnownSteps[i].name))
            return i;
    }
    return -1;
}

} // namespace

DetectionSteps::DetectionSteps(QObject *parent)
    : QObject(parent)
{ }

void DetectionSteps::setImages(const QMap<QString, QImage> &images)
{
    m_images.clear();
    for (auto it = images.cbegin(); it != images.cend(); ++it) {
        if (!it.value().isNull())
            m_images.insert(it.key(), it.value());
    }
    Q_EMIT changed();
}

void DetectionSteps::clear()
{
    if (m_images.isEmpty())
        return;
    m_images.clear();
    Q_EMIT changed();
}

QStringList DetectionSteps::names() const
{
    QStringList names = m_images.keys(); // sorted
    std::stable_sort(names.begin(), names.end(), [](const QString &a, const QString &b) {
        const int ra = knownRank(a);
        const int rb = knownRank(b);
        if (ra >= 0 && rb >= 0)
            return ra < rb;
        return ra >= 0 && rb < 0; // known steps first; the rest keep their alphabetical order
    });
    return names;
}

bool DetectionSteps::isCloseUp(const QString &name)
{
    return name.endsWith(kCloseUpSuffix);
}

QString DetectionSteps::displayName(const QString &name)
{
    const int rank = knownRank(name);
    if (rank >= 0)
        return QCoreApplication::translate("DetectionSteps", kKnownSteps[rank].text);

    // "classic-mouth-cut" -> "Mouth cut (classic)", "detect-ears-crop" -> "Ears, close-up".
    QString stem = name;
    const bool closeUp = isCloseUp(stem);
    if (closeUp)
        stem.chop(kCloseUpSuffix.size());
    QString method;
    const qsizetype dash = stem.indexOf(QLatin1Char('-'));
    if (dash > 0 && dash + 1 < stem.size()) {
        const QString prefix = stem.left(dash);
        if (prefix == QLatin1StringView("classic"))
            method = QCoreApplication::translate("DetectionSteps", "thesis pipeline");
        else if (prefix != QLatin1StringView("detect"))
            method = prefix;
        stem = stem.mid(dash + 1);
    }
    stem.replace(QLatin1Char('-'), QLatin1Char(' ')).replace(QLatin1Char('_'), QLatin1Char(' '));
    stem = stem.simplified();
    if (stem.isEmpty())
        return name;
    stem[0] = stem[0].toUpper();
    if (closeUp)
        stem = QCoreApplication::translate("DetectionSteps", "%1, close-up").arg(stem);
    if (!method.isEmpty())
        stem = QCoreApplication::translate("DetectionSteps", "%1 (%2)").arg(stem, method);
    return stem;
}

} // namespace toonface
