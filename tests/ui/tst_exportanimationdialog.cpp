#include "animationfixture.h"
#include "testmain.h"

#include "dialogs/exportanimationdialog.h"
#include "dialogs/exportpreview.h"
#include "i18n/translations.h"
#include "media/mediareader.h"
#include "render/style.h"

#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QProcess>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace toonface;

namespace {

QStringList entries(const QString &dir)
{
    return QDir(dir).entryList(QDir::AllEntries | QDir::Hidden | QDir::System | QDir::NoDotAndDotDot, QDir::Name);
}

void choose(QComboBox *combo, AnimationFormat format)
{
    combo->setCurrentIndex(combo->findData(int(format)));
}

} // namespace

class TestExportAnimationDialog : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    QString m_tone;

    // The editor's animation as the main window hands it over: 2 s of talk with its sound.
    ExportRequest base(const QString &outputPath) const
    {
        ExportRequest r;
        r.format = AnimationFormat::SmilSvg;
        r.outputPath = outputPath;
        r.face = test::animationFace();
        r.style = Style::preset(QStringLiteral("normal"));
        Timeline t;
        t.setFrameRate(25);
        t.addMouthCues({{0.2, 0.5, MouthShape::A}, {0.5, 0.9, MouthShape::U}, {1.0, 1.6, MouthShape::E}});
        t.addBlink({1.2, 0.18});
        t.setAudioClips({AudioClip {m_tone, 0.0, 2.0}});
        r.timeline = t;
        return r;
    }

    QString newFolder(const QString &name) const
    {
        const QString path = m_dir.filePath(name);
        QDir(path).removeRecursively();
        QDir().mkpath(path);
        return path;
    }

private Q_SLOTS:
    void initTestCase()
    {
        // As the editor starts: English with its plural forms ("24 frames").
        QVERIFY(installTranslations(QCoreApplication::instance(), QString()));
        QVERIFY(m_dir.isValid());
        m_tone = m_dir.filePath(QStringLiteral("tone.wav"));
        QVERIFY(test::writeToneWav(m_tone, 2.0));
    }

    void suffixFollowsFormat()
    {
        ExportAnimationDialog dialog(base(QStringLiteral("/tmp/x/talk.svg")));
        auto *format = dialog.findChild<QComboBox *>(QStringLiteral("format"));
        auto *path = dialog.findChild<QLineEdit *>(QStringLiteral("path"));
        auto *size = dialog.findChild<QComboBox *>(QStringLiteral("size"));
        QVERIFY(format && path && size);
        QCOMPARE(path->text(), QStringLiteral("/tmp/x/talk.svg"));
        QVERIFY(!size->isEnabled()); // a vector drawing has no pixel size
        choose(format, AnimationFormat::Mp4);
        QCOMPARE(path->text(), QStringLiteral("/tmp/x/talk.mp4"));
        QVERIFY(size->isEnabled());
        choose(format, AnimationFormat::PngSequence);
        QCOMPARE(path->text(), QStringLiteral("/tmp/x/talk-frames/"));
        choose(format, AnimationFormat::Gif);
        QCOMPARE(path->text(), QStringLiteral("/tmp/x/talk.gif"));
        choose(format, AnimationFormat::HtmlPlayer);
        QCOMPARE(path->text(), QStringLiteral("/tmp/x/talk.html"));
        // A name of the user's own keeps its dots.
        path->setText(QStringLiteral("take.2"));
        choose(format, AnimationFormat::Mp4);
        QCOMPARE(path->text(), QStringLiteral("take.2.mp4"));
        QCOMPARE(dialog.request().format, AnimationFormat::Mp4);
        QCOMPARE(dialog.request().outputPath, QStringLiteral("take.2.mp4"));
    }

    void controlsMakeTheRequest()
    {
        ExportAnimationDialog dialog(base(QStringLiteral("a.svg")));
        QCOMPARE(dialog.findChild<QSpinBox *>(QStringLiteral("fps"))->value(), 25);
        choose(dialog.findChild<QComboBox *>(QStringLiteral("format")), AnimationFormat::Gif);
        auto *size = dialog.findChild<QComboBox *>(QStringLiteral("size"));
        size->setCurrentIndex(size->findData(480));
        dialog.findChild<QSpinBox *>(QStringLiteral("fps"))->setValue(12);
        auto *framing = dialog.findChild<QComboBox *>(QStringLiteral("framing"));
        framing->setCurrentIndex(framing->findData(int(ExportFraming::Photo)));
        const ExportRequest r = dialog.request();
        QCOMPARE(r.size, 480);
        QCOMPARE(r.fps, 12.0);
        QCOMPARE(r.framing, ExportFraming::Photo);
        QCOMPARE(r.timeline, base({}).timeline);
        const QString summary = dialog.findChild<QLabel *>(QStringLiteral("summary"))->text();
        QVERIFY2(summary.contains(QStringLiteral("24 frames")), qPrintable(summary)); // 2 s at 12 fps
        QVERIFY2(summary.contains(QStringLiteral("480 × 480 px")), qPrintable(summary));
        QVERIFY2(summary.contains(QStringLiteral("silent")), qPrintable(summary));
    }

    // Choose MP4, export, wait: the file has every frame and the sound; the dialog offers to
    // show it.
    void exportsMp4()
    {
        const QString dir = newFolder(QStringLiteral("mp4"));
        ExportAnimationDialog dialog(base(QDir(dir).filePath(QStringLiteral("talk.svg"))));
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        choose(dialog.findChild<QComboBox *>(QStringLiteral("format")), AnimationFormat::Mp4);
        auto *size = dialog.findChild<QComboBox *>(QStringLiteral("size"));
        size->setCurrentIndex(size->findData(360));
        QSignalSpy finished(&dialog, &ExportAnimationDialog::finished);
        auto *exportButton = dialog.findChild<QPushButton *>(QStringLiteral("export"));
        const QRect exportWhere = exportButton->geometry();
        QTest::mouseClick(exportButton, Qt::LeftButton);
        QVERIFY(dialog.isRunning());
        QVERIFY(!exportButton->isEnabled());
        QCOMPARE(dialog.findChild<QPushButton *>(QStringLiteral("close"))->text(), QStringLiteral("Cancel"));
        QVERIFY(finished.wait(120000));
        QVERIFY2(dialog.lastResult().ok(), qPrintable(dialog.lastResult().error));
        const QString mp4 = QDir(dir).filePath(QStringLiteral("talk.mp4"));
        QCOMPARE(dialog.exportedPath(), mp4);
        QCOMPARE(dialog.exportedFolder(), QFileInfo(mp4).absolutePath());
        QCOMPARE(entries(dir), QStringList {QStringLiteral("talk.mp4")});
        QCOMPARE(dialog.findChild<QProgressBar *>(QStringLiteral("progress"))->value(),
            dialog.findChild<QProgressBar *>(QStringLiteral("progress"))->maximum());
        QVERIFY(dialog.findChild<QPushButton *>(QStringLiteral("showInFolder"))->isVisible());
        QCOMPARE(dialog.findChild<QPushButton *>(QStringLiteral("close"))->text(), QStringLiteral("Close"));
        // Export stays where it was, with Show in Folder shown or hidden again by another format
        // (once the layout has had the events that lay it out again).
        QTest::qWait(50);
        QCOMPARE(exportButton->geometry(), exportWhere);
        choose(dialog.findChild<QComboBox *>(QStringLiteral("format")), AnimationFormat::HtmlPlayer);
        QVERIFY(!dialog.findChild<QPushButton *>(QStringLiteral("showInFolder"))->isVisible());
        QTest::qWait(50);
        QCOMPARE(exportButton->geometry(), exportWhere);
        choose(dialog.findChild<QComboBox *>(QStringLiteral("format")), AnimationFormat::Mp4);

        QString error;
        const std::optional<MediaInfo> info = probeMedia(mp4, &error);
        QVERIFY2(info, qPrintable(error));
        QCOMPARE(info->frameCount, 50); // 2 s at 25 fps
        QCOMPARE(std::max(info->width, info->height), 360);
        QVERIFY(info->hasAudio);
        QVERIFY2(std::abs(info->audioDurationS - 2.0) < 0.05, qPrintable(QString::number(info->audioDurationS)));

        const QString ffprobe = QStandardPaths::findExecutable(QStringLiteral("ffprobe"));
        if (!ffprobe.isEmpty()) {
            QProcess p;
            p.start(ffprobe,
                {QStringLiteral("-v"), QStringLiteral("error"), QStringLiteral("-count_frames"),
                    QStringLiteral("-show_entries"), QStringLiteral("stream=codec_type,nb_read_frames"),
                    QStringLiteral("-of"), QStringLiteral("csv=p=0"), mp4});
            QVERIFY(p.waitForFinished(60000));
            const QString streams = QString::fromUtf8(p.readAllStandardOutput());
            QVERIFY2(streams.contains(QStringLiteral("video,50")), qPrintable(streams));
            QVERIFY2(streams.contains(QStringLiteral("audio")), qPrintable(streams));
        }

        const QString shots = qEnvironmentVariable("TOONFACE_SCREENSHOTS");
        if (!shots.isEmpty())
            QVERIFY(dialog.grab().save(QDir(shots).filePath(QStringLiteral("exportanimationdialog-done.png"))));
    }

    // Cancel while it runs: no file, no temporary file; the dialog says so and stays open.
    void cancelMidway()
    {
        const QString dir = newFolder(QStringLiteral("cancel"));
        ExportRequest r = base(QDir(dir).filePath(QStringLiteral("long.mp4")));
        r.format = AnimationFormat::Mp4;
        r.timeline = test::animationTimeline(m_tone); // 10 s: 250 frames
        r.size = 1080;
        ExportAnimationDialog dialog(r);
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        QSignalSpy finished(&dialog, &ExportAnimationDialog::finished);
        QVERIFY(dialog.start());
        auto *progress = dialog.findChild<QProgressBar *>(QStringLiteral("progress"));
        QTRY_VERIFY_WITH_TIMEOUT(progress->value() > 0, 60000);
        QVERIFY(dialog.isRunning());
        const QString shots = qEnvironmentVariable("TOONFACE_SCREENSHOTS");
        if (!shots.isEmpty())
            QVERIFY(dialog.grab().save(QDir(shots).filePath(QStringLiteral("exportanimationdialog-running.png"))));
        QTest::mouseClick(dialog.findChild<QPushButton *>(QStringLiteral("close")), Qt::LeftButton);
        QVERIFY(finished.wait(60000));
        QCOMPARE(dialog.lastResult().status, ExportStatus::Cancelled);
        QVERIFY(dialog.isVisible());
        QVERIFY(dialog.exportedPath().isEmpty());
        QVERIFY(!dialog.findChild<QPushButton *>(QStringLiteral("showInFolder"))->isVisible());
        QCOMPARE(entries(dir), QStringList());
        QVERIFY(dialog.findChild<QLabel *>(QStringLiteral("status"))->text().contains(QStringLiteral("Cancelled")));
    }

    // A failed export says why in the dialog and leaves nothing.
    void failureIsShown()
    {
        const QString dir = newFolder(QStringLiteral("failure"));
        ExportRequest r = base(QDir(dir).filePath(QStringLiteral("missing/out.gif")));
        r.format = AnimationFormat::Gif;
        ExportAnimationDialog dialog(r);
        QSignalSpy finished(&dialog, &ExportAnimationDialog::finished);
        QVERIFY(dialog.start());
        QVERIFY(finished.wait(60000));
        QCOMPARE(dialog.lastResult().status, ExportStatus::Failed);
        const QString status = dialog.findChild<QLabel *>(QStringLiteral("status"))->text();
        QVERIFY2(status.contains(QStringLiteral("out.gif")) && status.contains(QStringLiteral("does not exist")),
            qPrintable(status));
        QCOMPARE(entries(dir), QStringList());
        // Another format: the message about the GIF goes.
        choose(dialog.findChild<QComboBox *>(QStringLiteral("format")), AnimationFormat::Mp4);
        QCOMPARE(dialog.findChild<QLabel *>(QStringLiteral("status"))->text(), QString());
    }

    // Closing the dialog while it exports cancels the export first.
    void closingCancels()
    {
        const QString dir = newFolder(QStringLiteral("closing"));
        ExportRequest r = base(QDir(dir).filePath(QStringLiteral("c.gif")));
        r.format = AnimationFormat::Gif;
        r.timeline = test::animationTimeline();
        {
            ExportAnimationDialog dialog(r);
            QVERIFY(dialog.start());
        } // destroyed while running: it waits for the cancelled export
        QCOMPARE(entries(dir), QStringList());
    }

    // The still beside the controls: the checkerboard shows through where the export is
    // transparent, the chosen colour where it is not.
    void previewShowsTransparency()
    {
        ExportAnimationDialog dialog(base(m_dir.filePath(QStringLiteral("still.webm"))));
        auto *format = dialog.findChild<QComboBox *>(QStringLiteral("format"));
        auto *preview = dialog.findChild<ExportPreview *>(QStringLiteral("exportPreview"));
        QVERIFY(format && preview);
        choose(format, AnimationFormat::WebM);
        QCOMPARE(dialog.request().background.kind, ExportBackground::Kind::Automatic);
        QCOMPARE(effectiveBackground(dialog.request()).kind, ExportBackground::Kind::Transparent);
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        QVERIFY(!preview->frame().isNull());
        QCOMPARE(qAlpha(preview->frame().pixel(0, 0)), 0);
        QCOMPARE(qAlpha(preview->frame().pixel(preview->frame().width() / 2, preview->frame().height() / 2)), 255);
        // On screen the corner is the checkerboard: two greys in neighbouring cells.
        QImage shown = preview->grab().toImage();
        const QSize fitted = preview->frame().size().scaled(preview->size(), Qt::KeepAspectRatio);
        const QPoint origin((preview->width() - fitted.width()) / 2, (preview->height() - fitted.height()) / 2);
        const qreal dpr = shown.devicePixelRatio();
        const auto at = [&](int x, int y) { return QColor(shown.pixel(QPoint(origin.x() + x, origin.y() + y) * dpr)); };
        QCOMPARE(at(2, 2), QColor(255, 255, 255));
        QCOMPARE(at(10, 2), QColor(204, 204, 204));

        dialog.setBackground(ExportBackground::ofColour(QColor(200, 30, 30)));
        QCOMPARE(dialog.request().background, ExportBackground::ofColour(QColor(200, 30, 30)));
        QCOMPARE(QColor(preview->frame().pixel(0, 0)), QColor(200, 30, 30));
        shown = preview->grab().toImage();
        QCOMPARE(at(10, 2), QColor(200, 30, 30));

        // MP4 asked to be transparent: the dialog says why and will not start.
        dialog.setBackground(ExportBackground::transparent());
        choose(format, AnimationFormat::Mp4);
        auto *summary = dialog.findChild<QLabel *>(QStringLiteral("summary"));
        auto *exportButton = dialog.findChild<QPushButton *>(QStringLiteral("export"));
        QVERIFY(summary->text().contains(u"MP4"));
        QVERIFY(!exportButton->isEnabled());
        QVERIFY(!dialog.start());
    }

    // A preset fixes the format and size, shortens the stretch to its limit, and exports a
    // sticker within it.
    void presetMakesASticker()
    {
        const QString dir = newFolder(QStringLiteral("sticker"));
        ExportRequest r = base(QDir(dir).filePath(QStringLiteral("hello.svg")));
        r.timeline = test::animationTimeline(m_tone); // 10 s
        ExportAnimationDialog dialog(r);
        auto *preset = dialog.findChild<QComboBox *>(QStringLiteral("preset"));
        auto *format = dialog.findChild<QComboBox *>(QStringLiteral("format"));
        auto *size = dialog.findChild<QComboBox *>(QStringLiteral("size"));
        auto *length = dialog.findChild<QDoubleSpinBox *>(QStringLiteral("length"));
        auto *path = dialog.findChild<QLineEdit *>(QStringLiteral("path"));
        auto *summary = dialog.findChild<QLabel *>(QStringLiteral("summary"));
        auto *exportButton = dialog.findChild<QPushButton *>(QStringLiteral("export"));
        QVERIFY(preset && format && size && length && path && summary && exportButton);
        QCOMPARE(preset->itemData(0).toString(), QString());
        preset->setCurrentIndex(preset->findData(QStringLiteral("emoji")));
        QCOMPARE(dialog.preset()->name, u"emoji"_qs);
        QCOMPARE(dialog.request().format, AnimationFormat::WebM);
        QVERIFY(path->text().endsWith(u"hello.webm"));
        QVERIFY(!format->isEnabled());
        QVERIFY(!size->isEnabled());
        QCOMPARE(exportFrameSize(dialog.request()), QSize(100, 100));
        QCOMPARE(length->value(), 3.0);
        QVERIFY(dialog.problem().isEmpty());
        // Longer than the preset allows: said, and not started.
        length->setValue(4.4);
        QVERIFY2(dialog.problem().contains(u"4.4 s") && dialog.problem().contains(u"allows 3 s"),
            qPrintable(dialog.problem()));
        QVERIFY(summary->text().contains(dialog.problem()));
        QVERIFY(!exportButton->isEnabled());
        length->setValue(2.0);
        QVERIFY(exportButton->isEnabled());
        QSignalSpy finished(&dialog, &ExportAnimationDialog::finished);
        QVERIFY(dialog.start());
        QVERIFY(finished.wait(120000));
        QVERIFY2(dialog.lastResult().ok(), qPrintable(dialog.lastResult().error));
        const QString out = QDir(dir).filePath(QStringLiteral("hello.webm"));
        QVERIFY(QFileInfo(out).size() <= 64 * 1024);
        QString error;
        const std::optional<MediaInfo> info = probeMedia(out, &error);
        QVERIFY2(info, qPrintable(error));
        QCOMPARE(QSize(info->width, info->height), QSize(100, 100));
        QVERIFY(info->hasAlpha);
        QVERIFY(!info->hasAudio);
        QCOMPARE(entries(dir), QStringList {u"hello.webm"_qs});
        // None again: the format is the user's to choose.
        preset->setCurrentIndex(0);
        QVERIFY(format->isEnabled());
    }
};

TOONFACE_TEST_MAIN(TestExportAnimationDialog)
#include "tst_exportanimationdialog.moc"
