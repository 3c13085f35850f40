#include "testmain.h"
#include "translators.h"
#include "tsfile.h"
#include "uifixture.h"

#include "dialogs/preferencesdialog.h"
#include "i18n/translations.h"
#include "window/mainwindow.h"
#include "window/settings.h"
#include "window/studio.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QTest>
#include <QTranslator>

using namespace toonface;

namespace {

const QString kDir = QStringLiteral(TOONFACE_TRANSLATIONS_DIR);

using fixture::removeTranslators;

QStringList menuTitles(const QMainWindow &window)
{
    QStringList titles;
    for (QAction *a : window.menuBar()->actions()) {
        if (a->menu())
            titles << a->text();
    }
    return titles;
}

QMenu *menuTitled(const QMainWindow &window, const QString &title)
{
    for (QAction *a : window.menuBar()->actions()) {
        if (a->menu() && a->text() == title)
            return a->menu();
    }
    return nullptr;
}

} // namespace

class TestLocalizedUi : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { fixture::isolateSettings(); }
    void init() { QSettings().clear(); }
    void cleanup() { removeTranslators(); }

    void menusAreTranslated_data()
    {
        QTest::addColumn<QString>("translation");
        QTest::newRow("zh_TW") << QStringLiteral("zh_TW");
        QTest::newRow("zh_CN") << QStringLiteral("zh_CN");
    }

    // The editor in Chinese: every menu title of the menu bar is the .ts file's translation,
    // and Edit ends with Preferences… in Chinese.
    void menusAreTranslated()
    {
        QFETCH(QString, translation);
        const fixture::TsFile ts
            = fixture::readTsFile(QDir(kDir).filePath(QStringLiteral("toonface_%1.ts").arg(translation)));
        QVERIFY2(ts.error.isEmpty(), qPrintable(ts.error));
        QVERIFY(installTranslations(QCoreApplication::instance(), translation));

        MainWindow window;
        window.show();
        const QString mainWindow = QStringLiteral("toonface::MainWindow");
        const QString studio = QStringLiteral("toonface::Studio");
        const QStringList expected {ts.translate(mainWindow, QStringLiteral("&File")),
            ts.translate(mainWindow, QStringLiteral("&Edit")), ts.translate(mainWindow, QStringLiteral("&View")),
            ts.translate(studio, QStringLiteral("&Animation")), ts.translate(studio, QStringLiteral("&Playback")),
            ts.translate(mainWindow, QStringLiteral("&Help"))};
        QVERIFY(!expected.contains(QString()));
        QCOMPARE(menuTitles(window), expected);

        QMenu *edit = menuTitled(window, expected[1]);
        QVERIFY(edit);
        QAction *preferences = window.studio()->preferencesAction();
        QVERIFY(preferences);
        QVERIFY(edit->actions().contains(preferences));
        QCOMPARE(preferences->text(), ts.translate(studio, QStringLiteral("Pre&ferences…")));
        QCOMPARE(preferences->shortcut(), QKeySequence(QKeySequence::Preferences));
        // The video dock's toggle found the View menu by its translated title.
        QMenu *view = menuTitled(window, expected[2]);
        QVERIFY(view);
        bool videoToggle = false;
        for (QAction *a : view->actions())
            videoToggle = videoToggle || a->objectName() == QLatin1StringView("showVideo");
        QVERIFY(videoToggle);
    }

    void preferencesStoreTheLanguage()
    {
        QVERIFY(installTranslations(QCoreApplication::instance(), QStringLiteral("zh_TW")));
        PreferencesDialog dialog(QStringLiteral("zh_TW"));
        dialog.show();
        auto *combo = dialog.findChild<QComboBox *>(QStringLiteral("language"));
        auto *note = dialog.findChild<QLabel *>(QStringLiteral("restartNote"));
        QVERIFY(combo && note);
        QCOMPARE(combo->count(), 4);
        QCOMPARE(dialog.language(), QString()); // nothing stored: the system's
        combo->setCurrentIndex(combo->findData(QStringLiteral("zh_TW")));
        QVERIFY(!dialog.restartNeeded());
        QVERIFY(!note->isVisible());
        combo->setCurrentIndex(combo->findData(QStringLiteral("zh_CN")));
        QVERIFY(dialog.restartNeeded());
        QVERIFY(note->isVisible());
        // Qt's own buttons speak Chinese too when its catalogue is installed.
        auto *buttons = dialog.findChild<QDialogButtonBox *>();
        QVERIFY(buttons);
        const QString cancel = buttons->button(QDialogButtonBox::Cancel)->text();
        if (QCoreApplication::translate("QPlatformTheme", "Cancel") != QLatin1StringView("Cancel"))
            QCOMPARE(cancel, QCoreApplication::translate("QPlatformTheme", "Cancel"));
        dialog.accept();
        QCOMPARE(Settings().language(), QStringLiteral("zh_CN"));

        PreferencesDialog again(QStringLiteral("zh_TW"));
        QCOMPARE(again.language(), QStringLiteral("zh_CN"));
        again.setLanguage(QString());
        again.accept();
        QCOMPARE(Settings().language(), QString());
    }

    void unknownStoredLanguageFollowsTheSystem()
    {
        QSettings().setValue(QStringLiteral("interface/language"), QStringLiteral("tlh"));
        QCOMPARE(Settings().language(), QString());
        Settings settings;
        settings.setLanguage(QStringLiteral("en"));
        QCOMPARE(Settings().language(), QStringLiteral("en"));
        settings.setLanguage(QStringLiteral("xx"));
        QCOMPARE(Settings().language(), QString());
    }
};

TOONFACE_TEST_MAIN(TestLocalizedUi)
#include "tst_localizedui.moc"
