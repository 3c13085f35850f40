#include "testmain.h"
#include "tsfile.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
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
Run cli(const QStringList &args, const QString &lang, const QString &language = QString(),
    const QString &workingDirectory = QString())
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
    p.setWorkingDirectory(workingDirectory);
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

    void coreErrorsFollowTheLocale_data()
    {
        QTest::addColumn<QString>("lang");
        QTest::addColumn<QString>("catalogue");
        QTest::newRow("zh_TW") << QStringLiteral("zh_TW.UTF-8") << QStringLiteral("zh_TW");
        QTest::newRow("zh_CN") << QStringLiteral("zh_CN.UTF-8") << QStringLiteral("zh_CN");
        QTest::newRow("C") << QStringLiteral("C") << QString();
    }

    // The messages core builds (a damaged project, a file that is no sound, a script with
    // something unspeakable) in the user's language, naming the file, after the unchanged
    // "toonface-cli: error:" prefix; under LANG=C the English of before.
    void coreErrorsFollowTheLocale()
    {
        QFETCH(QString, lang);
        QFETCH(QString, catalogue);
        fixture::TsFile ts;
        if (!catalogue.isEmpty()) {
            ts = fixture::readTsFile(QDir(kDir).filePath(QStringLiteral("toonface_%1.ts").arg(catalogue)));
            QVERIFY2(ts.error.isEmpty(), qPrintable(ts.error));
        }
        // The source text in English, its translation in Chinese.
        const auto text = [&](const char *context, const QString &source) {
            return catalogue.isEmpty() ? source : ts.translate(QString::fromLatin1(context), source);
        };
        const auto joined = [&](const QString &where, const QString &problem) {
            return text("toonface::Problem", QStringLiteral("%1: %2")).arg(where, problem);
        };
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const auto write = [&](const QString &name, const QByteArray &bytes) {
            QFile f(dir.filePath(name));
            return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
        };
        QVERIFY(write(QStringLiteral("empty.toonface"), "{}"));
        QVERIFY(write(QStringLiteral("noise.wav"), "hello, this is no sound"));
        QVERIFY(write(QStringLiteral("good.txt"), "你好"));
        QVERIFY(write(QStringLiteral("bad.txt"), "你好 ⓧ"));

        struct Case
        {
            QStringList args;
            QString want;
        };
        const QList<Case> cases {
            {{QStringLiteral("cartoon"), QStringLiteral("empty.toonface"), QStringLiteral("-o"),
                 QStringLiteral("x.svg")},
                joined(QStringLiteral("empty.toonface"),
                    text("toonface::ProjectFile",
                        QStringLiteral("not a Toonface project (it has no \"format\" field)")))},
            {{QStringLiteral("lipsync"), QStringLiteral("--audio"), QStringLiteral("noise.wav"),
                 QStringLiteral("--script"), QStringLiteral("good.txt")},
                joined(QStringLiteral("noise.wav"),
                    text("toonface::SoundFile", QStringLiteral("not a readable sound or video file (%1)"))
                        .arg(text("toonface::Media", QStringLiteral("the data is invalid or damaged"))))},
            {{QStringLiteral("lipsync"), QStringLiteral("--audio"), QStringLiteral("noise.wav"),
                 QStringLiteral("--script"), QStringLiteral("bad.txt")},
                joined(QStringLiteral("bad.txt"),
                    text("toonface::Script", QStringLiteral("line %1, column %2: '%3' %4"))
                        .arg(QStringLiteral("1"), QStringLiteral("4"), QStringLiteral("ⓧ"),
                            text("toonface::Script", QStringLiteral("cannot be spoken"))))},
        };
        for (const Case &c : cases) {
            const Run run = cli(c.args, lang, QString(), dir.path());
            QCOMPARE(run.code, 3);
            QCOMPARE(run.err.trimmed(), QStringLiteral("toonface-cli: error: ") + c.want);
            static const QRegularExpression han(QStringLiteral("\\p{Han}"));
            const QString message = c.want.mid(c.want.indexOf(QLatin1Char('.')));
            QCOMPARE(message.contains(han), !catalogue.isEmpty());
        }
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

TOONFACE_TEST_GUILESS_MAIN(TestCliLanguage)
#include "tst_clilanguage.moc"
