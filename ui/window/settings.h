#pragma once

#include <QByteArray>
#include <QSettings>
#include <QString>
#include <QStringList>

namespace toonface {

// The editor's persistent settings, typed, with every key in settings.cpp. QSettings
// underneath (the application's organisation and name pick the file); cheap to construct,
// so code makes one where it needs it. GUI thread only.
class Settings
{
public:
    Settings();

    static constexpr int kMaxRecentFiles = 10;

    QByteArray windowGeometry() const;
    void setWindowGeometry(const QByteArray &geometry);
    QByteArray windowState() const;
    void setWindowState(const QByteArray &state);
    QByteArray splitterState() const;
    void setSplitterState(const QByteArray &state);
    // Live Mode's own window (QWidget::saveGeometry()); empty before it was first closed.
    QByteArray liveWindowGeometry() const;
    void setLiveWindowGeometry(const QByteArray &geometry);

    // Most recent first, absolute paths, no duplicates, at most kMaxRecentFiles.
    QStringList recentFiles() const;
    void addRecentFile(const QString &path);
    void removeRecentFile(const QString &path);
    void clearRecentFiles();

    // The folder the file dialogs open in.
    QString lastDirectory() const;
    void setLastDirectory(const QString &directory);

    // Seconds between autosaves of a modified project; 0 turns autosave off.
    int autosaveInterval() const;
    void setAutosaveInterval(int seconds);

    bool showPointIds() const;
    void setShowPointIds(bool show);

    // Whether the cartoon preview leaves out the background (over a checkerboard); default off.
    bool transparentPreview() const;
    void setTransparentPreview(bool transparent);

    // The method the editor detects faces with: "auto" (default), "classic" or "landmarks"
    // (detectionMethodName()); an unknown stored name reads as "auto".
    QString detectionMethod() const;
    void setDetectionMethod(const QString &name);

    // Opacity of the detection-step overlay on the photo, 0..1 (default 0.6).
    double overlayOpacity() const;
    void setOverlayOpacity(double opacity);

    // The camera last used, by its description (Qt 6.4's device ids are not stable); empty: the
    // system's default camera.
    QString cameraDescription() const;
    void setCameraDescription(const QString &description);

    // The interface's language (languageSettingNames() of i18n/translations.h): "" follows the
    // system, "en", "zh_TW" or "zh_CN"; an unknown stored name reads as "". Read at start-up.
    QString language() const;
    void setLanguage(const QString &language);

    void sync() { m_settings.sync(); }

private:
    QSettings m_settings;
};

} // namespace toonface
