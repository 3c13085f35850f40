#pragma once

#include <QLocale>
#include <QString>

class QCoreApplication;

namespace toonface {

// The languages of the interface: Toonface's own strings (resources/translations, compiled into
// the program) and Qt's (the qt_*.qm catalogues of qt6-translations-l10n).
//
// A setting names the language: "" follows the system, "en" English, "zh_TW" Traditional
// Chinese, "zh_CN" Simplified Chinese (languageSettingNames()).
QStringList languageSettingNames();

// The translation a locale reads: "zh_TW" for Chinese in Traditional characters (Taiwan, Hong
// Kong, Macau, or the Hant script), "zh_CN" for other Chinese (China, Singapore, Hans), and ""
// (English, the source language) for every other language.
QString translationForLocale(const QLocale &locale);

// The translation a setting asks for; "" or an unknown setting follows `system` (the first of
// the system's interface languages: LANGUAGE, LC_ALL, LC_MESSAGES, LANG).
QLocale systemUiLocale();
QString translationForSetting(const QString &setting, const QLocale &system = systemUiLocale());

// Installs Toonface's and Qt's translators for `translation` ("zh_TW", "zh_CN"; "" English:
// only the plural forms of Toonface's "%n" messages) on the application, which owns them.
// A Chinese translation also becomes the default QLocale (dates, numbers). Returns false when
// Toonface's catalogue is missing (Qt's is optional: the dialogs' buttons stay English without
// it). Call it once.
bool installTranslations(QCoreApplication *app, const QString &translation);
// The translation installTranslations() installed last ("" before, or for English).
QString installedTranslation();

} // namespace toonface
