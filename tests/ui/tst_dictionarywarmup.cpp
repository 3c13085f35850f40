#include "testmain.h"
#include "uifixture.h"

#include "dialogs/lipsyncdialog.h"
#include "dialogs/saytextdialog.h"
#include "document/document.h"
#include "i18n/translations.h"
#include "speech/pinyindictionary.h"

#include <QDialogButtonBox>
#include <QFile>
#include <QLabel>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>

using namespace toonface;

// The editor's first use of the character dictionary: the dictionary loads (its cache built,
// here, into an empty cache folder) off the GUI thread, the dialogs say so and catch up when
// it is ready. This test runs alone in its process: nothing has loaded the dictionary before.
class TestDictionaryWarmUp : public QObject
{
    Q_OBJECT

    QTemporaryDir m_cache;

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_cache.isValid());
        // As the editor starts: English with its plural forms ("15 syllables").
        QVERIFY(installTranslations(QCoreApplication::instance(), QString()));
        qputenv("TOONFACE_CACHE_DIR", m_cache.path().toLocal8Bit());
        QVERIFY(!PinyinDictionary::isLoaded());
    }

    void lipSyncDialogDoesNotWaitForTheDictionary()
    {
        Document doc;
        fixture::fill(doc);
        LipSyncDialog dialog(&doc);
        const QString path = m_cache.filePath(QStringLiteral("script.txt"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QStringLiteral("经广州日报报道后成为了社会热点").toUtf8());
        f.close();
        auto *state = dialog.findChild<QLabel *>(QStringLiteral("scriptState"));
        QVERIFY(state);
        const bool loadedBefore = PinyinDictionary::isLoaded();
        // Reading the script checks it at once, on this thread.
        QVERIFY(dialog.openScript(path));
        if (loadedBefore)
            QSKIP("the dictionary loaded before the script was checked: nothing to wait for");
        QVERIFY2(state->text().contains(QStringLiteral("Loading")), qPrintable(state->text()));
        QTRY_VERIFY_WITH_TIMEOUT(state->text().contains(QStringLiteral("15 syllables")), 60000);
        QVERIFY(PinyinDictionary::isLoaded());
    }
};

TOONFACE_TEST_MAIN(TestDictionaryWarmUp)
#include "tst_dictionarywarmup.moc"
