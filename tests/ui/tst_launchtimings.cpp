#include "testmain.h"
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QImage>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

namespace {

const QString kPortrait = QStringLiteral("/usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg");

} // namespace

// The editor's start-up timings (TOONFACE_TIMINGS, app/launchtimings.h), which
// bench/bench_startup.cpp reads: every event printed once, in the order it happens.
class TestLaunchTimings : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void eventsInOrder_data();
    void eventsInOrder();
};

void TestLaunchTimings::eventsInOrder_data()
{
    QTest::addColumn<int>("delayMs");
    QTest::newRow("photo at launch") << 0;
    QTest::newRow("photo after launch") << 300;
}

void TestLaunchTimings::eventsInOrder()
{
    QFETCH(int, delayMs);
    if (!QFile::exists(kPortrait))
        QSKIP("grace_hopper.jpg is not installed (package python-matplotlib-data)");
    QTemporaryDir home;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    env.insert(QStringLiteral("TOONFACE_TIMINGS"), QStringLiteral("1"));
    env.insert(QStringLiteral("TOONFACE_TIMINGS_OPEN_DELAY_MS"), QString::number(delayMs));
    env.insert(QStringLiteral("HOME"), home.path());
    env.insert(QStringLiteral("XDG_CONFIG_HOME"), home.filePath(QStringLiteral("config")));
    env.insert(QStringLiteral("XDG_DATA_HOME"), home.filePath(QStringLiteral("data")));
    QProcess editor;
    editor.setProcessEnvironment(env);
    editor.start(QStringLiteral(TOONFACE_EDITOR_PATH), {kPortrait});
    QVERIFY(editor.waitForStarted());
    static const QRegularExpression line(QStringLiteral("^toonface: timing: ([a-z-]+) ([0-9.]+)$"));
    QStringList events;
    QList<double> times;
    QByteArray pending;
    QElapsedTimer clock;
    clock.start();
    while (!events.contains(QStringLiteral("points-shown")) && clock.elapsed() < 120000) {
        editor.waitForReadyRead(1000);
        pending += editor.readAllStandardError();
        while (pending.contains('\n')) {
            const QString text = QString::fromUtf8(pending.left(pending.indexOf('\n')));
            pending.remove(0, pending.indexOf('\n') + 1);
            const auto m = line.match(text);
            if (m.hasMatch()) {
                events << m.captured(1);
                times << m.captured(2).toDouble();
            }
        }
        if (editor.state() != QProcess::Running)
            break;
    }
    editor.kill();
    editor.waitForFinished();
    QStringList sorted = events;
    sorted.sort();
    QCOMPARE(sorted,
        QStringList({QStringLiteral("open"), QStringLiteral("photo-opened"), QStringLiteral("points-shown"),
            QStringLiteral("window-shown"), QStringLiteral("window-usable")}));
    auto at = [&](const char *event) { return times[events.indexOf(QLatin1StringView(event))]; };
    QVERIFY(at("window-shown") <= at("window-usable"));
    QVERIFY(at("open") <= at("photo-opened"));
    QVERIFY(at("photo-opened") <= at("points-shown"));
    // Held back as asked, counted from the window being usable.
    if (delayMs > 0)
        QVERIFY(at("open") - at("window-usable") >= delayMs);
}

TOONFACE_TEST_GUILESS_MAIN(TestLaunchTimings)
#include "tst_launchtimings.moc"
