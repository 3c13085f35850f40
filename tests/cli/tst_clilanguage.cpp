#include "tsfile.h"

#include <QDir>
#include <QProcess>
#include <QTest>

using namespace toonface;

namespace {

const QString kDir = QStringLiteral(TOONFACE_TRANSLATIONS_DIR);
const QString kContext = QStringLiteral("toonface::cli::Cli");

struct Run
{
    int code = -1;
    QString out;
    QString err;
};

// Runs the CLI with the locale variables of a user whose language is `lang`.
Run cli(const QStringList &args, const QString &lang, const QString &language = QString())
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove(QStringLiteral("LC_ALL"));
    env.remove(QStringLiteral("LC_MESSAGES"));
    env.remove(QStringLiteral("LANGUAGE"));
    env.insert(QStringLiteral("LANG"), lang);
    if (!language.isEmpty())
        env.insert(QStringLiteral("LANGUAGE"), language);
    QProcess p;
    p.setProcessEnvironment(env);
    p.start(QStringLiteral(TOONFACE_CLI_PATH), args);
    if (!p.waitForFinished(60000))
        return {};
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, QString::fromUtf8(p.readAllStandardOutput()),
        QString::fromUtf8(p.readAllStandardError())};
}

} // namespace

class TestCliLanguage : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void usageFollowsTheLocale_data()
    {
        QTest::addColumn<QString>("lang");
        QTest::addColumn<QString>("catalogue");
        QTest::newRow("zh_TW") << QStringLiteral("zh_TW.UTF-8") << QStringLiteral("zh_TW");
        QTest::newRow("zh_HK") << QStringLiteral("zh_HK.UTF-8") << QStringLiteral("zh_TW");
        QTest::newRow("zh_CN") << QStringLiteral("zh_CN.UTF-8") << QStringLiteral("zh_CN");
        QTest::newRow("zh_SG") << QStringLiteral("zh_SG.UTF-8") << QStringLiteral("zh_CN");
    }

    // --help in Chinese: its headings, every command's summary and the exit codes, from the
    // .ts file; the command lines themselves (names, options) stay as typed.
    void usageFollowsTheLocale()
    {
        QFETCH(QString, lang);
        QFETCH(QString, catalogue);
        const fixture::TsFile ts
            = fixture::readTsFile(QDir(kDir).filePath(QStringLiteral("toonface_%1.ts").arg(catalogue)));
        QVERIFY2(ts.error.isEmpty(), qPrintable(ts.error));
        const Run run = cli({QStringLiteral("--help")}, lang);
        QCOMPARE(run.code, 0);
        const QStringList wanted {QStringLiteral("Commands:"), QStringLiteral("options of one command"),
            QStringLiteral("Find the face in a photo and write its 72 points as JSON (toonface.face/1)."),
            QStringLiteral(
                "Track the face of a video frame by frame and write its motion as JSON (toonface.track/1).")};
        for (const QString &source : wanted) {
            const QString translated = ts.translate(kContext, source);
            QVERIFY2(!translated.isEmpty() && translated != source, qPrintable(source));
            QVERIFY2(run.out.contains(translated), qPrintable(run.out));
            QVERIFY2(!run.out.contains(source), qPrintable(source));
        }
        const QString usage = ts.translate(kContext, QStringLiteral("Usage: %1"));
        QVERIFY(run.out.startsWith(usage.arg(QStringLiteral("toonface-cli COMMAND [OPTIONS]"))));
        QVERIFY(run.out.contains(QStringLiteral("detect IMAGE [--method auto|classic|landmarks]")));
        const QString exitCodes = ts.translate(kContext,
            QStringLiteral("Exit codes: 0 success, 2 usage, 3 unreadable or invalid input, 4 no face found,\n5 the "
                           "audio and the script could not be aligned, 1 other failures."));
        QVERIFY(run.out.contains(exitCodes));
    }

    // A command's options and a usage error in Chinese, with the option names and the
    // "toonface-cli: error:" prefix (what scripts look for) unchanged.
    void commandHelpAndErrors()
    {
        const fixture::TsFile ts = fixture::readTsFile(QDir(kDir).filePath(QStringLiteral("toonface_zh_TW.ts")));
        const Run help = cli({QStringLiteral("cartoon"), QStringLiteral("--help")}, QStringLiteral("zh_TW.UTF-8"));
        QCOMPARE(help.code, 0);
        QVERIFY(help.out.contains(ts.translate(kContext, QStringLiteral("The cartoon SVG to write."))));
        QVERIFY(help.out.contains(ts.translate(kContext, QStringLiteral("Show this help."))));
        QVERIFY(help.out.contains(QStringLiteral("--caricature")));

        const Run wrong = cli({QStringLiteral("frobnicate")}, QStringLiteral("zh_TW.UTF-8"));
        QCOMPARE(wrong.code, 2);
        QVERIFY2(wrong.err.startsWith(QStringLiteral("toonface-cli: error: ")), qPrintable(wrong.err));
        QVERIFY2(
            wrong.err.contains(ts.translate(kContext, QStringLiteral("unknown command '%1'; try 'toonface-cli --help'"))
                                   .arg(QStringLiteral("frobnicate"))),
            qPrintable(wrong.err));
    }

    // LANGUAGE's first choice wins over LANG (as in gettext); other languages read English.
    void languageListAndEnglish()
    {
        const fixture::TsFile cn = fixture::readTsFile(QDir(kDir).filePath(QStringLiteral("toonface_zh_CN.ts")));
        const Run listed
            = cli({QStringLiteral("--help")}, QStringLiteral("zh_TW.UTF-8"), QStringLiteral("zh_CN:zh_TW"));
        QVERIFY(listed.out.contains(cn.translate(kContext, QStringLiteral("Commands:"))));
        for (const QString &lang : {QStringLiteral("C.UTF-8"), QStringLiteral("fr_FR.UTF-8")}) {
            const Run english = cli({QStringLiteral("--help")}, lang);
            QCOMPARE(english.code, 0);
            QVERIFY2(english.out.startsWith(QStringLiteral("Usage: toonface-cli COMMAND [OPTIONS]")), qPrintable(lang));
            QVERIFY(english.out.contains(QStringLiteral("Commands:")));
        }
    }
};

QTEST_GUILESS_MAIN(TestCliLanguage)
#include "tst_clilanguage.moc"
