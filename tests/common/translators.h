#pragma once

// For the translation tests: takes every installed catalogue out again (the application's
// translators are its children) and returns the default locale to the system's.
#include <QCoreApplication>
#include <QLocale>
#include <QTranslator>

namespace toonface::fixture {

inline void removeTranslators()
{
    for (QTranslator *t : QCoreApplication::instance()->findChildren<QTranslator *>()) {
        QCoreApplication::removeTranslator(t);
        delete t;
    }
    QLocale::setDefault(QLocale::system());
}

} // namespace toonface::fixture
