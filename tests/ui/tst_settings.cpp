#include "testmain.h"
#include "uifixture.h"

#include "window/settings.h"

#include <QDir>
#include <QTest>

using namespace toonface;

class TestSettings : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { fixture::isolateSettings(); }

    void init() { QSettings().clear(); }

    void recentFilesPersistMostRecentFirst()
    {
        {
            Settings settings;
            settings.addRecentFile(QStringLiteral("/photos/a.jpg"));
            settings.addRecentFile(QStringLiteral("/photos/b.toonface"));
            settings.addRecentFile(QStringLiteral("/photos/a.jpg"));
            settings.sync();
        }
        Settings reread;
        QCOMPARE(
            reread.recentFiles(), QStringList({QStringLiteral("/photos/a.jpg"), QStringLiteral("/photos/b.toonface")}));
        reread.removeRecentFile(QStringLiteral("/photos/a.jpg"));
        QCOMPARE(Settings().recentFiles(), QStringList({QStringLiteral("/photos/b.toonface")}));
        reread.clearRecentFiles();
        QVERIFY(Settings().recentFiles().isEmpty());
    }

    void recentFilesAreAbsoluteAndBounded()
    {
        Settings settings;
        for (int i = 0; i < Settings::kMaxRecentFiles + 5; ++i)
            settings.addRecentFile(QStringLiteral("photo%1.jpg").arg(i));
        const QStringList files = Settings().recentFiles();
        QCOMPARE(files.size(), Settings::kMaxRecentFiles);
        QCOMPARE(files.first(),
            QDir::current().absoluteFilePath(QStringLiteral("photo%1.jpg").arg(Settings::kMaxRecentFiles + 4)));
    }

    void valuesRoundTripWithDefaults()
    {
        Settings settings;
        QCOMPARE(settings.autosaveInterval(), 60);
        QCOMPARE(settings.showPointIds(), false);
        QCOMPARE(settings.transparentPreview(), false);
        QCOMPARE(settings.lastDirectory(), QDir::homePath());
        QVERIFY(settings.windowGeometry().isEmpty());

        settings.setAutosaveInterval(15);
        settings.setShowPointIds(true);
        settings.setTransparentPreview(true);
        settings.setLastDirectory(QStringLiteral("/photos"));
        settings.setWindowGeometry(QByteArray("geometry"));
        settings.setWindowState(QByteArray("state"));
        settings.setSplitterState(QByteArray("splitter"));

        Settings reread;
        QCOMPARE(reread.autosaveInterval(), 15);
        QCOMPARE(reread.showPointIds(), true);
        QCOMPARE(reread.transparentPreview(), true);
        QCOMPARE(reread.lastDirectory(), QStringLiteral("/photos"));
        QCOMPARE(reread.windowGeometry(), QByteArray("geometry"));
        QCOMPARE(reread.windowState(), QByteArray("state"));
        QCOMPARE(reread.splitterState(), QByteArray("splitter"));
    }

    void badAutosaveIntervalFallsBackToDefault()
    {
        QSettings().setValue(QStringLiteral("autosave/intervalSeconds"), QStringLiteral("soon"));
        QCOMPARE(Settings().autosaveInterval(), 60);
    }

    void detectionMethodAndOverlayOpacityRoundTrip()
    {
        Settings settings;
        QCOMPARE(settings.detectionMethod(), QStringLiteral("auto"));
        QCOMPARE(settings.overlayOpacity(), 0.6);
        settings.setDetectionMethod(QStringLiteral("classic"));
        settings.setOverlayOpacity(0.25);
        Settings reread;
        QCOMPARE(reread.detectionMethod(), QStringLiteral("classic"));
        QCOMPARE(reread.overlayOpacity(), 0.25);
    }

    void badDetectionValuesFallBack()
    {
        QSettings().setValue(QStringLiteral("detection/method"), QStringLiteral("magic"));
        QCOMPARE(Settings().detectionMethod(), QStringLiteral("auto"));
        QSettings().setValue(QStringLiteral("view/overlayOpacity"), QStringLiteral("half"));
        QCOMPARE(Settings().overlayOpacity(), 0.6);
        QSettings().setValue(QStringLiteral("view/overlayOpacity"), 3.0);
        QCOMPARE(Settings().overlayOpacity(), 1.0);
    }

    void settingsStayInTheTestSandbox()
    {
        QVERIFY2(QSettings().fileName().contains(QStringLiteral(".qttest")), qPrintable(QSettings().fileName()));
    }
};

TOONFACE_TEST_MAIN(TestSettings)
#include "tst_settings.moc"
