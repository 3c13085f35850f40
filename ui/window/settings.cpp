#include "window/settings.h"

#include "detect/detector.h"
#include "i18n/translations.h"

#include <QDir>
#include <QFileInfo>

#include <algorithm>

namespace toonface {

namespace {

namespace key {
const QString windowGeometry = QStringLiteral("window/geometry");
const QString windowState = QStringLiteral("window/state");
const QString splitterState = QStringLiteral("window/splitter");
const QString liveWindowGeometry = QStringLiteral("liveWindow/geometry");
const QString recentFiles = QStringLiteral("files/recent");
const QString lastDirectory = QStringLiteral("files/lastDirectory");
const QString autosaveInterval = QStringLiteral("autosave/intervalSeconds");
const QString showPointIds = QStringLiteral("view/showPointIds");
const QString transparentPreview = QStringLiteral("view/transparentPreview");
const QString detectionMethod = QStringLiteral("detection/method");
const QString overlayOpacity = QStringLiteral("view/overlayOpacity");
const QString cameraDescription = QStringLiteral("capture/camera");
const QString language = QStringLiteral("interface/language");
} // namespace key

constexpr int kDefaultAutosaveInterval = 60;
constexpr double kDefaultOverlayOpacity = 0.6;

} // namespace

Settings::Settings() = default;

QByteArray Settings::windowGeometry() const
{
    return m_settings.value(key::windowGeometry).toByteArray();
}

void Settings::setWindowGeometry(const QByteArray &geometry)
{
    m_settings.setValue(key::windowGeometry, geometry);
}

QByteArray Settings::windowState() const
{
    return m_settings.value(key::windowState).toByteArray();
}

void Settings::setWindowState(const QByteArray &state)
{
    m_settings.setValue(key::windowState, state);
}

QByteArray Settings::liveWindowGeometry() const
{
    return m_settings.value(key::liveWindowGeometry).toByteArray();
}

void Settings::setLiveWindowGeometry(const QByteArray &geometry)
{
    m_settings.setValue(key::liveWindowGeometry, geometry);
}

QByteArray Settings::splitterState() const
{
    return m_settings.value(key::splitterState).toByteArray();
}

void Settings::setSplitterState(const QByteArray &state)
{
    m_settings.setValue(key::splitterState, state);
}

QStringList Settings::recentFiles() const
{
    return m_settings.value(key::recentFiles).toStringList();
}

void Settings::addRecentFile(const QString &path)
{
    const QString absolute = QFileInfo(path).absoluteFilePath();
    QStringList files = recentFiles();
    files.removeAll(absolute);
    files.prepend(absolute);
    while (files.size() > kMaxRecentFiles)
        files.removeLast();
    m_settings.setValue(key::recentFiles, files);
}

void Settings::removeRecentFile(const QString &path)
{
    QStringList files = recentFiles();
    files.removeAll(QFileInfo(path).absoluteFilePath());
    m_settings.setValue(key::recentFiles, files);
}

void Settings::clearRecentFiles()
{
    m_settings.remove(key::recentFiles);
}

QString Settings::lastDirectory() const
{
    return m_settings.value(key::lastDirectory, QDir::homePath()).toString();
}

void Settings::setLastDirectory(const QString &directory)
{
    m_settings.setValue(key::lastDirectory, directory);
}

int Settings::autosaveInterval() const
{
    bool ok = false;
    const int seconds = m_settings.value(key::autosaveInterval, kDefaultAutosaveInterval).toInt(&ok);
    return ok && seconds >= 0 ? seconds : kDefaultAutosaveInterval;
}

void Settings::setAutosaveInterval(int seconds)
{
    m_settings.setValue(key::autosaveInterval, seconds);
}

bool Settings::showPointIds() const
{
    return m_settings.value(key::showPointIds, false).toBool();
}

void Settings::setShowPointIds(bool show)
{
    m_settings.setValue(key::showPointIds, show);
}

bool Settings::transparentPreview() const
{
    return m_settings.value(key::transparentPreview, false).toBool();
}

void Settings::setTransparentPreview(bool transparent)
{
    m_settings.setValue(key::transparentPreview, transparent);
}

QString Settings::detectionMethod() const
{
    DetectionMethod method = DetectionMethod::Auto;
    if (!detectionMethodFromName(m_settings.value(key::detectionMethod).toString(), &method))
        method = DetectionMethod::Auto;
    return detectionMethodName(method);
}

void Settings::setDetectionMethod(const QString &name)
{
    m_settings.setValue(key::detectionMethod, name);
}

double Settings::overlayOpacity() const
{
    bool ok = false;
    const double opacity = m_settings.value(key::overlayOpacity, kDefaultOverlayOpacity).toDouble(&ok);
    return ok ? std::clamp(opacity, 0.0, 1.0) : kDefaultOverlayOpacity;
}

void Settings::setOverlayOpacity(double opacity)
{
    m_settings.setValue(key::overlayOpacity, std::clamp(opacity, 0.0, 1.0));
}

QString Settings::cameraDescription() const
{
    return m_settings.value(key::cameraDescription).toString();
}

void Settings::setCameraDescription(const QString &description)
{
    m_settings.setValue(key::cameraDescription, description);
}

QString Settings::language() const
{
    const QString name = m_settings.value(key::language).toString();
    return languageSettingNames().contains(name) ? name : QString();
}

void Settings::setLanguage(const QString &language)
{
    if (languageSettingNames().contains(language))
        m_settings.setValue(key::language, language);
    else
        m_settings.remove(key::language);
}

} // namespace toonface
