#include "animationfixture.h"
#include "testmain.h"
#include "translators.h"
#include "uifixture.h"

#include "capture/capturedialog.h"
#include "capture/importvideodialog.h"
#include "capture/livewindow.h"
#include "dialogs/blinksdialog.h"
#include "dialogs/emotiondialog.h"
#include "dialogs/exportanimationdialog.h"
#include "dialogs/lipsyncdialog.h"
#include "dialogs/mouthshapesdialog.h"
#include "dialogs/preferencesdialog.h"
#include "dialogs/saytextdialog.h"
#include "document/autosaver.h"
#include "document/document.h"
#include "i18n/translations.h"
#include "io/project.h"
#include "playback/playhead.h"
#include "window/mainwindow.h"
#include "window/questions.h"
#include "window/studio.h"

#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QDateTime>
#include <QDialog>
#include <QDir>
#include <QFileDialog>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QTranslator>

#include <functional>
#include <memory>

using namespace toonface;

namespace {

// Texts of the widgets that show less than their text needs: a label without word wrap, a
// button or a combo box narrower than its size hint (Chinese text is wider per character than
// the English the layouts were first tried with).
QStringList clipped(QWidget *root)
{
    QStringList problems;
    for (QWidget *w : root->findChildren<QWidget *>()) {
        if (!w->isVisibleTo(root) || w->width() <= 0)
            continue;
        QString text;
        int needed = 0;
        if (auto *label = qobject_cast<QLabel *>(w)) {
            if (label->wordWrap() || label->text().isEmpty() || label->hasScaledContents()
                || label->textFormat() == Qt::RichText || label->text().contains(QLatin1Char('<')))
                continue;
            text = label->text();
            needed = label->sizeHint().width();
        } else if (auto *button = qobject_cast<QAbstractButton *>(w)) {
            if (button->text().isEmpty())
                continue;
            text = button->text();
            needed = button->sizeHint().width();
        } else if (auto *combo = qobject_cast<QComboBox *>(w)) {
            text = combo->currentText();
            needed = combo->minimumSizeHint().width();
        } else {
            continue;
        }
        if (w->width() + 1 < needed)
            problems << QStringLiteral("%1 \"%2\": %3 px of %4")
                            .arg(QString::fromLatin1(w->metaObject()->className()), text)
                            .arg(w->width())
                            .arg(needed);
    }
    return problems;
}

// Lays the widget out (at its own size, as it opens, unless `keepSize`) and looks for clipped
// text; saves it as <language>-<name>.png in TOONFACE_GRAB_DIR when that is set.
QStringList lookAt(QWidget *widget, const QString &name, bool keepSize = false)
{
    widget->show();
    QApplication::processEvents();
    if (!keepSize)
        widget->adjustSize();
    QApplication::processEvents();
    const QString dir = qEnvironmentVariable("TOONFACE_GRAB_DIR");
    if (!dir.isEmpty())
        widget->grab().save(
            QDir(dir).filePath(installedTranslation() + QLatin1Char('-') + name + QStringLiteral(".png")));
    QStringList problems = clipped(widget);
    for (QString &p : problems)
        p.prepend(name + QStringLiteral(": "));
    return problems;
}

using fixture::removeTranslators;

} // namespace

class TestLocalizedDialogs : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { fixture::isolateSettings(); }
    void cleanup() { removeTranslators(); }

    // The check itself sees a label or a button squeezed below its text's width.
    void clippingIsSeen()
    {
        QWidget box;
        auto *label = new QLabel(QStringLiteral("一段相當長的中文說明文字，不會自動換行"), &box);
        auto *button = new QPushButton(QStringLiteral("在資料夾中顯示"), &box);
        label->setGeometry(0, 0, 60, 20);
        button->setGeometry(0, 30, 40, 20);
        box.show();
        QCOMPARE(clipped(&box).size(), 2);
        label->setGeometry(0, 0, label->sizeHint().width(), 20);
        button->setGeometry(0, 30, button->sizeHint().width(), 20);
        QCOMPARE(clipped(&box).size(), 0);
    }

    void dialogsShowTheirText_data()
    {
        QTest::addColumn<QString>("translation");
        QTest::newRow("zh_TW") << QStringLiteral("zh_TW");
        QTest::newRow("zh_CN") << QStringLiteral("zh_CN");
        QTest::newRow("English") << QString();
    }

    // Every dialog of the editor, in each language, opens wide enough for its text.
    void dialogsShowTheirText()
    {
        QFETCH(QString, translation);
        QVERIFY(installTranslations(QCoreApplication::instance(), translation));
        QTemporaryDir dir;
        Document document;
        fixture::fill(document);
        Animation animation = document.animation();
        animation.timeline = test::animationTimeline();
        document.changeAnimation(animation, QStringLiteral("timeline"));
        Playhead playhead;
        QStringList problems;

        const std::vector<std::pair<QString, std::function<QWidget *()>>> dialogs {
            {QStringLiteral("preferences"), [] { return new PreferencesDialog(QStringLiteral("zh_TW")); }},
            {QStringLiteral("blinks"), [&] { return new BlinksDialog(&document); }},
            {QStringLiteral("emotion"), [&] { return new EmotionDialog(&document); }},
            {QStringLiteral("lipsync"), [&] { return new LipSyncDialog(&document); }},
            {QStringLiteral("saytext"), [&] { return new SayTextDialog(&document); }},
            {QStringLiteral("mouthshapes"), [&] { return new MouthShapesDialog(&document); }},
            {QStringLiteral("importvideo"), [&] { return new ImportVideoDialog(&document, 0.0); }},
            {QStringLiteral("capture"), [&] { return new CaptureDialog(&document); }},
            {QStringLiteral("live"), [&] { return new LiveWindow(&document, &playhead); }},
            {QStringLiteral("exportanimation"),
                [&] {
                    ExportRequest r;
                    r.format = AnimationFormat::Mp4;
                    r.outputPath = dir.filePath(QStringLiteral("talk.mp4"));
                    r.face = document.face();
                    r.style = document.style();
                    r.timeline = test::animationTimeline();
                    return new ExportAnimationDialog(r);
                }},
        };
        for (const auto &[name, make] : dialogs) {
            std::unique_ptr<QWidget> dialog(make());
            problems << lookAt(dialog.get(), name);
        }
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
    }

    // The main window with a face open, at the size it first opens.
    void mainWindowShowsItsText_data() { dialogsShowTheirText_data(); }

    void mainWindowShowsItsText()
    {
        QFETCH(QString, translation);
        QVERIFY(installTranslations(QCoreApplication::instance(), translation));
        QTemporaryDir dir;
        // A project: its face is given, so no detection (nor its questions) runs.
        Project project;
        project.photoPath = dir.filePath(QStringLiteral("face.png"));
        project.face = fixture::face();
        project.style = Style::preset(QStringLiteral("normal"));
        project.timeline = test::animationTimeline();
        QVERIFY(fixture::photo().save(project.photoPath));
        const QString path = dir.filePath(QStringLiteral("face.toonface"));
        QString error;
        QVERIFY2(saveProject(project, path, &error), qPrintable(error));
        MainWindow window;
        window.resize(1280, 800);
        window.show();
        window.startup(path);
        QTRY_VERIFY_WITH_TIMEOUT(!window.isBusy(), 30000);
        QApplication::processEvents();
        QStringList problems = lookAt(&window, QStringLiteral("mainwindow"), true);
        // Each menu as it drops down (menus size themselves to their items: only looked at).
        int index = 0;
        for (QAction *a : window.menuBar()->actions()) {
            if (QMenu *menu = a->menu()) {
                menu->popup(window.mapToGlobal(QPoint(10 * index, 30)));
                QApplication::processEvents();
                lookAt(menu, QStringLiteral("menu%1").arg(++index), true);
                menu->hide();
            }
        }
        // The questions the editor asks, and Qt's own file dialog.
        const auto answered = [&](const QString &name) {
            QTimer::singleShot(200, [&problems, name] {
                if (QWidget *box = QApplication::activeModalWidget()) {
                    problems << lookAt(box, name, true);
                    // Dates as the language writes them, with nothing Qt cannot print.
                    static const QRegularExpression unprinted(QStringLiteral("(?<![A-Za-z])B\\d"));
                    if (auto *message = qobject_cast<QMessageBox *>(box);
                        message && message->text().contains(unprinted))
                        problems << name + QStringLiteral(": ") + message->text();
                    // A message box without an Escape button ignores close(): answer it.
                    if (auto *dialog = qobject_cast<QDialog *>(box))
                        dialog->done(QDialog::Rejected);
                    else
                        box->close();
                } else {
                    problems << name + QStringLiteral(": did not open");
                }
            });
        };
        answered(QStringLiteral("about"));
        window.findChild<QAction *>(QStringLiteral("actionAbout"))->trigger();
        answered(QStringLiteral("restore"));
        askToRestore(
            &window, RecoveryFile {dir.filePath(QStringLiteral("r.toonface")), path, QDateTime::currentDateTime()});
        Document document;
        answered(QStringLiteral("averageface"));
        offerAverageFace(&window, &document, QStringLiteral("face.png"));
        QFileDialog files(&window, QStringLiteral("Open"), dir.path());
        files.setOption(QFileDialog::DontUseNativeDialog);
        files.resize(800, 500);
        lookAt(&files, QStringLiteral("filedialog"), true);
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
    }
};

TOONFACE_TEST_MAIN(TestLocalizedDialogs)
#include "tst_localizeddialogs.moc"
