#include "testmain.h"
#include "translators.h"
#include "tsfile.h"

#include "i18n/translations.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>
#include <QTranslator>

using namespace toonface;

namespace {

const QString kDir = QStringLiteral(TOONFACE_TRANSLATIONS_DIR);

// The placeholders of a text (%1 … %99, %n), each as often as it occurs.
QStringList placeholders(const QString &text)
{
    static const QRegularExpression marker(QStringLiteral("%(\\d{1,2}|n)"));
    QStringList found;
    for (const QRegularExpressionMatch &m : marker.globalMatch(text))
        found << m.captured(0);
    found.sort();
    return found;
}

// Whether a text has a keyboard accelerator: '&' before a character ("&&" is a plain '&').
bool hasAccelerator(const QString &text)
{
    static const QRegularExpression accelerator(QStringLiteral("(?<!&)&(?!&)\\S"));
    return accelerator.match(text).hasMatch();
}

// The translators installTranslations() gave the application, removed again.
using fixture::removeTranslators;

bool hasChinese(const QString &text)
{
    return std::any_of(
        text.begin(), text.end(), [](QChar c) { return c.unicode() >= 0x4e00 && c.unicode() <= 0x9fff; });
}

} // namespace

class TestTranslations : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void catalogueIsComplete_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("forms"); // numerus forms of the language
        QTest::newRow("zh_TW") << QStringLiteral("toonface_zh_TW.ts") << 1;
        QTest::newRow("zh_CN") << QStringLiteral("toonface_zh_CN.ts") << 1;
        QTest::newRow("en plurals") << QStringLiteral("toonface_en.ts") << 2;
    }

    // No unfinished, vanished or obsolete message; every message translated, its placeholders
    // and accelerator kept; every %n message with its language's plural forms.
    void catalogueIsComplete()
    {
        QFETCH(QString, file);
        QFETCH(int, forms);
        const fixture::TsFile ts = fixture::readTsFile(QDir(kDir).filePath(file));
        QVERIFY2(ts.error.isEmpty(), qPrintable(ts.error));
        QVERIFY(!ts.messages.isEmpty());
        QStringList problems;
        for (const fixture::TsMessage &m : ts.messages) {
            const QString where = m.context + QStringLiteral(" / \"") + m.source + QLatin1Char('"');
            if (!m.type.isEmpty())
                problems << QStringLiteral("%1: %2").arg(where, m.type);
            if (m.numerus != m.source.contains(QLatin1StringView("%n")))
                problems << where + QStringLiteral(": %n without plural forms, or plural forms without %n");
            if (m.translations.size() != (m.numerus ? forms : 1))
                problems << QStringLiteral("%1: %2 forms").arg(where).arg(m.translations.size());
            for (const QString &t : m.translations) {
                if (t.trimmed().isEmpty() && !m.source.trimmed().isEmpty())
                    problems << where + QStringLiteral(": empty translation");
                // A singular English form may say "one" without %n; every other form keeps them all.
                QStringList want = placeholders(m.source);
                QStringList got = placeholders(t);
                if (forms == 2 && &t == &m.translations.first()) {
                    want.removeAll(QStringLiteral("%n"));
                    got.removeAll(QStringLiteral("%n"));
                    want.removeAll(QStringLiteral("%%1"));
                }
                if (got != want && !(forms == 2 && &t == &m.translations.first() && got.size() <= want.size()))
                    problems << QStringLiteral("%1: placeholders %2 became %3")
                                    .arg(where, want.join(QLatin1Char(' ')), got.join(QLatin1Char(' ')));
                if (hasAccelerator(m.source) && !hasAccelerator(t))
                    problems << where + QStringLiteral(": the accelerator is lost");
            }
        }
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
    }

    // The committed catalogues hold exactly the messages of today's sources (lupdate run into a
    // scratch file): a new tr() string without its translation fails here, not in front of a user.
    void cataloguesAreCurrent()
    {
        const QString lupdate = QStringLiteral(TOONFACE_LUPDATE);
        if (!QFileInfo::exists(lupdate))
            QSKIP("lupdate (qt6-l10n-tools) is not installed");
        QTemporaryDir dir;
        const QString scratch = dir.filePath(QStringLiteral("toonface_zh_TW.ts"));
        const QDir source(QStringLiteral(TOONFACE_SOURCE_DIR));
        QProcess run;
        run.setWorkingDirectory(source.path());
        run.start(lupdate,
            {QStringLiteral("-silent"), QStringLiteral("-no-obsolete"), QStringLiteral("-locations"),
                QStringLiteral("none"), QStringLiteral("-I"), QStringLiteral("ui"), QStringLiteral("-I"),
                QStringLiteral("app"), QStringLiteral("-I"), QStringLiteral("core"), QStringLiteral("ui"),
                QStringLiteral("app"), QStringLiteral("core"), QStringLiteral("-ts"), scratch});
        QVERIFY(run.waitForFinished(120000));
        QCOMPARE(run.exitCode(), 0);
        const auto keys = [](const fixture::TsFile &ts) {
            QSet<QString> set;
            for (const fixture::TsMessage &m : ts.messages)
                set << m.context + QStringLiteral(" / ") + m.source + QStringLiteral(" / ") + m.comment;
            return set;
        };
        const QSet<QString> current = keys(fixture::readTsFile(scratch));
        const QSet<QString> committed
            = keys(fixture::readTsFile(QDir(kDir).filePath(QStringLiteral("toonface_zh_TW.ts"))));
        QVERIFY(!current.isEmpty());
        QStringList news = (current - committed).values();
        QStringList gone = (committed - current).values();
        QVERIFY2(news.isEmpty() && gone.isEmpty(),
            qPrintable(QStringLiteral("run the update_translations target and translate: new %1\ngone %2")
                           .arg(news.join(QLatin1Char('\n')), gone.join(QLatin1Char('\n')))));
    }

    // Both Chinese catalogues translate the same messages, into Chinese.
    void chineseCataloguesMatch()
    {
        const fixture::TsFile tw = fixture::readTsFile(QDir(kDir).filePath(QStringLiteral("toonface_zh_TW.ts")));
        const fixture::TsFile cn = fixture::readTsFile(QDir(kDir).filePath(QStringLiteral("toonface_zh_CN.ts")));
        QCOMPARE(tw.language, QStringLiteral("zh_TW"));
        QCOMPARE(cn.language, QStringLiteral("zh_CN"));
        QSet<QString> twKeys, cnKeys;
        int chineseTw = 0, differ = 0;
        for (const fixture::TsMessage &m : tw.messages) {
            twKeys << m.context + u'\x1f' + m.source + u'\x1f' + m.comment;
            chineseTw += hasChinese(m.translations.value(0)) ? 1 : 0;
            differ += m.translations.value(0) != cn.translate(m.context, m.source) ? 1 : 0;
        }
        for (const fixture::TsMessage &m : cn.messages)
            cnKeys << m.context + u'\x1f' + m.source + u'\x1f' + m.comment;
        QCOMPARE(twKeys, cnKeys);
        // Most messages are words (a few are only symbols, numbers or option names).
        QVERIFY2(chineseTw > tw.messages.size() * 8 / 10, qPrintable(QString::number(chineseTw)));
        // Traditional is not Simplified: most texts differ in characters or usage.
        QVERIFY2(differ > tw.messages.size() / 2, qPrintable(QString::number(differ)));
    }

    // Taiwan's usage in zh_TW, the mainland's in zh_CN (GLOSSARY.md): no term of the other.
    void termsFollowTheGlossary_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QStringList>("foreign");
        QTest::newRow("zh_TW") << QStringLiteral("toonface_zh_TW.ts")
                               << QStringList {QStringLiteral("視頻"), QStringLiteral("窗口"), QStringLiteral("設置"),
                                      QStringLiteral("文件夾"), QStringLiteral("導出"), QStringLiteral("導入"),
                                      QStringLiteral("攝像頭"), QStringLiteral("音頻"), QStringLiteral("默認"),
                                      QStringLiteral("關鍵幀"), QStringLiteral("撤銷"), QStringLiteral("嘴型")};
        QTest::newRow("zh_CN") << QStringLiteral("toonface_zh_CN.ts")
                               << QStringList {QStringLiteral("影片"), QStringLiteral("档案"), QStringLiteral("视窗"),
                                      QStringLiteral("设定"), QStringLiteral("汇出"), QStringLiteral("专案"),
                                      QStringLiteral("摄影机"), QStringLiteral("音讯"), QStringLiteral("影格"),
                                      QStringLiteral("复原"), QStringLiteral("嘴型")};
    }

    void termsFollowTheGlossary()
    {
        QFETCH(QString, file);
        QFETCH(QStringList, foreign);
        const fixture::TsFile ts = fixture::readTsFile(QDir(kDir).filePath(file));
        QStringList problems;
        for (const fixture::TsMessage &m : ts.messages) {
            for (const QString &term : foreign) {
                if (m.translations.value(0).contains(term))
                    problems << QStringLiteral("%1: \"%2\" in %3").arg(term, m.source, m.translations.value(0));
            }
        }
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
    }

    void localesChooseTheirScript_data()
    {
        QTest::addColumn<QString>("locale");
        QTest::addColumn<QString>("translation");
        QTest::newRow("Taiwan") << QStringLiteral("zh_TW") << QStringLiteral("zh_TW");
        QTest::newRow("Hong Kong") << QStringLiteral("zh_HK") << QStringLiteral("zh_TW");
        QTest::newRow("Macau") << QStringLiteral("zh_MO") << QStringLiteral("zh_TW");
        QTest::newRow("Hant") << QStringLiteral("zh-Hant") << QStringLiteral("zh_TW");
        QTest::newRow("China") << QStringLiteral("zh_CN") << QStringLiteral("zh_CN");
        QTest::newRow("Singapore") << QStringLiteral("zh_SG") << QStringLiteral("zh_CN");
        QTest::newRow("Hans in Hong Kong") << QStringLiteral("zh-Hans-HK") << QStringLiteral("zh_CN");
        QTest::newRow("Chinese") << QStringLiteral("zh") << QStringLiteral("zh_CN");
        QTest::newRow("English") << QStringLiteral("en_US") << QString();
        QTest::newRow("French") << QStringLiteral("fr_FR") << QString();
        QTest::newRow("C") << QStringLiteral("C") << QString();
    }

    void localesChooseTheirScript()
    {
        QFETCH(QString, locale);
        QFETCH(QString, translation);
        QCOMPARE(translationForLocale(QLocale(locale)), translation);
    }

    void settingOverridesTheSystem()
    {
        const QLocale taiwan(QStringLiteral("zh_TW"));
        QCOMPARE(translationForSetting(QString(), taiwan), QStringLiteral("zh_TW"));
        QCOMPARE(translationForSetting(QStringLiteral("en"), taiwan), QString());
        QCOMPARE(translationForSetting(QStringLiteral("zh_CN"), taiwan), QStringLiteral("zh_CN"));
        QCOMPARE(
            translationForSetting(QStringLiteral("zh_TW"), QLocale(QStringLiteral("en_GB"))), QStringLiteral("zh_TW"));
        QCOMPARE(translationForSetting(QStringLiteral("klingon"), taiwan), QStringLiteral("zh_TW"));
        QCOMPARE(languageSettingNames().size(), 4);
    }

    // The compiled catalogues are in the program: the texts of the .ts files come back.
    void compiledCataloguesTranslate_data()
    {
        QTest::addColumn<QString>("translation");
        QTest::newRow("zh_TW") << QStringLiteral("zh_TW");
        QTest::newRow("zh_CN") << QStringLiteral("zh_CN");
    }

    void compiledCataloguesTranslate()
    {
        QFETCH(QString, translation);
        const fixture::TsFile ts
            = fixture::readTsFile(QDir(kDir).filePath(QStringLiteral("toonface_%1.ts").arg(translation)));
        QVERIFY(installTranslations(QCoreApplication::instance(), translation));
        QCOMPARE(installedTranslation(), translation);
        QCOMPARE(QLocale().name(), translation); // dates and numbers follow the language
        int checked = 0;
        for (const fixture::TsMessage &m : ts.messages) {
            const QByteArray context = m.context.toUtf8();
            const QByteArray source = m.source.toUtf8();
            const QByteArray comment = m.comment.toUtf8();
            const QString got = QCoreApplication::translate(context.constData(), source.constData(),
                m.comment.isEmpty() ? nullptr : comment.constData(), m.numerus ? 3 : -1);
            QString want = m.translations.value(0);
            if (m.numerus)
                want.replace(QStringLiteral("%n"), QStringLiteral("3"));
            QCOMPARE(got, want);
            ++checked;
        }
        QCOMPARE(checked, ts.messages.size());
        removeTranslators();
    }

    // English needs its catalogue for plurals: "1 frame", "3 frames", never "frame(s)".
    void englishPluralsRead()
    {
        QVERIFY(installTranslations(QCoreApplication::instance(), QString()));
        QCOMPARE(installedTranslation(), QString());
        QCOMPARE(QCoreApplication::translate("toonface::ExportAnimationDialog", "%n frame(s)", nullptr, 1),
            QStringLiteral("1 frame"));
        QCOMPARE(QCoreApplication::translate("toonface::ExportAnimationDialog", "%n frame(s)", nullptr, 3),
            QStringLiteral("3 frames"));
        QCOMPARE(QCoreApplication::translate("toonface::MainWindow", "&File"), QStringLiteral("&File"));
        removeTranslators();
    }

    // Qt's own strings (the platform's button texts) come from qt6-translations-l10n.
    void qtOwnStringsTranslate()
    {
        QVERIFY(installTranslations(QCoreApplication::instance(), QStringLiteral("zh_TW")));
        const QString cancel = QCoreApplication::translate("QPlatformTheme", "Cancel");
        removeTranslators();
        if (cancel == QLatin1StringView("Cancel"))
            QSKIP("Qt's zh_TW catalogue (qt6-translations-l10n) is not installed");
        QVERIFY2(hasChinese(cancel), qPrintable(cancel));
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestTranslations)
#include "tst_translations.moc"
