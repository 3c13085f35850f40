#include "i18n/translations.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QStringList>
#include <QTranslator>

namespace toonface {

QStringList languageSettingNames()
{
    return {QString(), QStringLiteral("en"), QStringLiteral("zh_TW"), QStringLiteral("zh_CN")};
}

QString translationForLocale(const QLocale &locale)
{
    if (locale.language() != QLocale::Chinese)
        return {};
    if (locale.script() == QLocale::TraditionalChineseScript)
        return QStringLiteral("zh_TW");
    if (locale.script() == QLocale::SimplifiedChineseScript)
        return QStringLiteral("zh_CN");
    switch (locale.territory()) {
    case QLocale::Taiwan:
    case QLocale::HongKong:
    case QLocale::Macao: return QStringLiteral("zh_TW");
    default: return QStringLiteral("zh_CN");
    }
}

QLocale systemUiLocale()
{
    const QStringList languages = QLocale::system().uiLanguages();
    return languages.isEmpty() ? QLocale::system() : QLocale(languages.constFirst());
}

QString translationForSetting(const QString &setting, const QLocale &system)
{
    if (setting == QLatin1StringView("en"))
        return {};
    if (setting == QLatin1StringView("zh_TW") || setting == QLatin1StringView("zh_CN"))
        return setting;
    return translationForLocale(system);
}

namespace {
QString &installed()
{
    static QString name;
    return name;
}
} // namespace

QString installedTranslation()
{
    return installed();
}

bool installTranslations(QCoreApplication *app, const QString &translation)
{
    if (translation.isEmpty()) {
        // English is the source language; its catalogue gives the plural forms of "%n" messages.
        auto *plurals = new QTranslator(app);
        if (!plurals->load(QStringLiteral("toonface_en"), QStringLiteral(":/i18n"))) {
            delete plurals;
            return false;
        }
        QCoreApplication::installTranslator(plurals);
        installed().clear();
        return true;
    }
    // Qt's catalogue "qt_<lang>" pulls in qtbase's and qtmultimedia's.
    auto *qt = new QTranslator(app);
    if (qt->load(QStringLiteral("qt_") + translation, QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(qt);
    else
        delete qt;
    auto *own = new QTranslator(app);
    if (!own->load(QStringLiteral("toonface_") + translation, QStringLiteral(":/i18n"))) {
        delete own;
        return false;
    }
    QCoreApplication::installTranslator(own);
    installed() = translation;
    // Dates and numbers as the language writes them (a Preferences choice may differ from the
    // system's locale).
    QLocale::setDefault(QLocale(translation));
    return true;
}

} // namespace toonface
