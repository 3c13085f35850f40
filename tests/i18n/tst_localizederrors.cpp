#include "testmain.h"
#include "translators.h"
#include "tsfile.h"
#include "uifixture.h"

#include "dialogs/lipsyncdialog.h"
#include "document/document.h"
#include "i18n/translations.h"
#include "io/imageio.h"
#include "io/project.h"
#include "speech/audio.h"
#include "speech/script.h"
#include "window/mainwindow.h"

#include <QAbstractButton>
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QTranslator>

using namespace toonface;

namespace {

const QString kDir = QStringLiteral(TOONFACE_TRANSLATIONS_DIR);

using fixture::removeTranslators;

bool hasHan(const QString &text)
{
    static const QRegularExpression han(QStringLiteral("\\p{Han}"));
    return text.contains(han);
}

// The messages a test expects, read from the committed catalogue of `translation` ("" for the
// English sources): what a user of that language should read.
class Expected
{
public:
    explicit Expected(const QString &translation)
    {
        if (!translation.isEmpty())
            m_ts = fixture::readTsFile(QDir(kDir).filePath(QStringLiteral("toonface_%1.ts").arg(translation)));
        m_english = translation.isEmpty();
    }
    QString error() const { return m_ts.error; }
    QString text(const char *context, const QString &source) const
    {
        return m_english ? source : m_ts.translate(QStringLiteral("toonface::") + QLatin1StringView(context), source);
    }
    // "WHERE: problem" as core joins it.
    QString joined(const QString &where, const QString &problem) const
    {
        return text("Problem", QStringLiteral("%1: %2")).arg(where, problem);
    }

private:
    fixture::TsFile m_ts;
    bool m_english = true;
};

bool writeFile(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

// Answers the next modal message box: keeps its text, saves it as TOONFACE_GRAB_DIR/<name>.png
// when that is set, and closes it.
void answerNextBox(QString *text, QSize *size, bool *wide, const QString &name)
{
    auto *timer = new QTimer;
    timer->setInterval(50);
    QObject::connect(timer, &QTimer::timeout, timer, [=] {
        auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
        if (!box)
            return;
        QApplication::processEvents();
        *text = box->text();
        *size = box->size();
        // The text's label shows it whole: wrapped, and as wide as its longest unbreakable run.
        auto *label = box->findChild<QLabel *>(QStringLiteral("qt_msgbox_label"));
        *wide = label && label->isVisible() && label->height() >= label->heightForWidth(label->width());
        const QString dir = qEnvironmentVariable("TOONFACE_GRAB_DIR");
        if (!dir.isEmpty())
            box->grab().save(QDir(dir).filePath(name + QStringLiteral(".png")));
        box->done(QMessageBox::Ok);
        timer->deleteLater();
    });
    timer->start();
}

} // namespace

class TestLocalizedErrors : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        fixture::isolateSettings();
        QVERIFY(m_dir.isValid());
        QVERIFY(writeFile(path("empty.toonface"), "{}"));
        QVERIFY(writeFile(path("oldversion.toonface"), R"({"format": "toonface.project", "version": "1"})"));
        QVERIFY(writeFile(path("noise.wav"), "hello, this is no sound"));
        QVERIFY(writeFile(path("paper.png"), "%PDF-1.4\n%\xe2\xe3\xcf\xd3\n1 0 obj\n"));
        QVERIFY(writeFile(path("bad.txt"), "你好 ⓧ"));
    }
    void cleanup() { removeTranslators(); }

    void coreMessagesFollowTheLanguage_data()
    {
        QTest::addColumn<QString>("translation");
        QTest::newRow("zh_TW") << QStringLiteral("zh_TW");
        QTest::newRow("zh_CN") << QStringLiteral("zh_CN");
        QTest::newRow("English") << QString();
    }

    // Each reader of core says what is wrong in the installed language and names the file;
    // messages built of parts (a field, what it should be, what it is) are translated part by part.
    void coreMessagesFollowTheLanguage()
    {
        QFETCH(QString, translation);
        QVERIFY(installTranslations(QCoreApplication::instance(), translation));
        const Expected want(translation);
        QVERIFY2(want.error().isEmpty(), qPrintable(want.error()));
        const bool chinese = !translation.isEmpty();
        QStringList got;

        QString error;
        QVERIFY(!loadProject(path("empty.toonface"), &error));
        QCOMPARE(error,
            want.joined(QDir::toNativeSeparators(path("empty.toonface")),
                want.text("ProjectFile", QStringLiteral("not a Toonface project (it has no \"format\" field)"))));
        got << error;

        QVERIFY(!loadProject(path("oldversion.toonface"), &error));
        const QString field = want.joined(QStringLiteral("version"),
            want.text("ProjectFile", QStringLiteral("expected %1, %2"))
                .arg(want.text("ProjectFile", QStringLiteral("a version number (1 or more)")),
                    want.text("ProjectFile", QStringLiteral("found the string \"%1\"")).arg(QStringLiteral("1"))));
        QCOMPARE(error, want.joined(QDir::toNativeSeparators(path("oldversion.toonface")), field));
        got << error;

        QVERIFY(loadPhoto(path("paper.png"), &error).isNull());
        QCOMPARE(error,
            want.joined(QDir::toNativeSeparators(path("paper.png")),
                want.text("ImageFile", QStringLiteral("a PDF document, not an image"))));
        got << error;

        const AudioResult sound = loadAudio(path("noise.wav"));
        QVERIFY(sound.status == AudioStatus::Unreadable);
        QCOMPARE(sound.error,
            want.joined(path("noise.wav"),
                want.text("SoundFile", QStringLiteral("not a readable sound or video file (%1)"))
                    .arg(want.text("Media", QStringLiteral("the data is invalid or damaged")))));
        got << sound.error;

        const ScriptParse script = readScriptFile(path("bad.txt"), Language::Mandarin);
        QVERIFY(!script.ok());
        QCOMPARE(script.error,
            want.joined(path("bad.txt"),
                want.text("Script", QStringLiteral("line %1, column %2: '%3' %4"))
                    .arg(QStringLiteral("1"), QStringLiteral("4"), QStringLiteral("ⓧ"),
                        want.text("Script", QStringLiteral("cannot be spoken")))));
        got << script.error;

        for (const QString &message : std::as_const(got)) {
            // The file's name, and the problem in the language (the name itself is Latin).
            QVERIFY2(message.contains(m_dir.path()) || message.contains(QDir::toNativeSeparators(m_dir.path())),
                qPrintable(message));
            QVERIFY2(hasHan(message.mid(m_dir.path().size())) == chinese, qPrintable(message));
        }
        if (!chinese) // English as before the translations, word for word
            QCOMPARE(got.first(),
                path("empty.toonface") + QStringLiteral(": not a Toonface project (it has no \"format\" field)"));
    }

    void editorSaysWhyAProjectCannotOpen_data()
    {
        QTest::addColumn<QString>("translation");
        QTest::newRow("zh_TW") << QStringLiteral("zh_TW");
        QTest::newRow("zh_CN") << QStringLiteral("zh_CN");
    }

    // A damaged project opened in the Chinese editor: the message box gives the problem in
    // Chinese, names the file, and shows its whole text.
    void editorSaysWhyAProjectCannotOpen()
    {
        QFETCH(QString, translation);
        QVERIFY(installTranslations(QCoreApplication::instance(), translation));
        const Expected want(translation);
        const QString broken = path("broken.toonface");
        QVERIFY(writeFile(broken, R"({"format": "toonface.project", "version": 1, "face": {"points": )"));
        MainWindow window;
        window.resize(1280, 800);
        window.show();
        QSignalSpy failed(&window, &MainWindow::openFailed);
        QString text;
        QSize size;
        bool wide = false;
        answerNextBox(&text, &size, &wide, translation + QStringLiteral("-cannotopen"));
        window.startup(broken);
        QTRY_VERIFY_WITH_TIMEOUT(failed.count() == 1, 30000);
        QTRY_VERIFY(!text.isEmpty());
        QCOMPARE(text, failed.first().first().toString());
        QVERIFY2(text.startsWith(QDir::toNativeSeparators(broken)), qPrintable(text));
        const QString problem = text.mid(QDir::toNativeSeparators(broken).size());
        QVERIFY2(problem.startsWith(QStringLiteral("：")), qPrintable(text)); // a full-width colon
        QVERIFY2(
            problem.contains(
                want.text("ProjectFile", QStringLiteral("not a Toonface project: %1 at offset %2 (line %3, column %4)"))
                    .section(QLatin1Char('%'), 0, 0)),
            qPrintable(text));
        QVERIFY2(hasHan(problem), qPrintable(text));
        QVERIFY2(wide, qPrintable(QStringLiteral("%1 x %2").arg(size.width()).arg(size.height())));
    }

    // Lip sync with a file that is no sound: the dialog says so in Chinese, naming the file.
    void lipSyncSaysTheRecordingIsNoSound()
    {
        QVERIFY(installTranslations(QCoreApplication::instance(), QStringLiteral("zh_TW")));
        const Expected want(QStringLiteral("zh_TW"));
        Document document;
        fixture::fill(document);
        LipSyncDialog dialog(&document);
        dialog.show();
        auto *recording = dialog.findChild<QLineEdit *>(QStringLiteral("recording"));
        QTest::keyClicks(recording, path("noise.wav"));
        dialog.findChild<QPlainTextEdit *>(QStringLiteral("script"))->setPlainText(QStringLiteral("你好"));
        auto *start = dialog.findChild<QAbstractButton *>(QStringLiteral("start"));
        QTRY_VERIFY_WITH_TIMEOUT(start->isEnabled(), 30000);
        QSignalSpy failed(&dialog, &LipSyncDialog::failed);
        QTest::mouseClick(start, Qt::LeftButton);
        QVERIFY(failed.wait(30000));
        const QString sound = want.joined(path("noise.wav"),
            want.text("SoundFile", QStringLiteral("not a readable sound or video file (%1)"))
                .arg(want.text("Media", QStringLiteral("the data is invalid or damaged"))));
        QVERIFY2(dialog.message().contains(sound), qPrintable(dialog.message()));
        QApplication::processEvents();
        const QString dir = qEnvironmentVariable("TOONFACE_GRAB_DIR");
        if (!dir.isEmpty())
            dialog.grab().save(QDir(dir).filePath(QStringLiteral("zh_TW-lipsync-nosound.png")));
    }

private:
    QString path(const char *name) const { return m_dir.filePath(QString::fromUtf8(name)); }

    QTemporaryDir m_dir;
};

TOONFACE_TEST_MAIN(TestLocalizedErrors)
#include "tst_localizederrors.moc"
