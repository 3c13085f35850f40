#include "dialogfixture.h"
#include "testmain.h"
#include "timelinefixture.h"
#include "uifixture.h"

#include "dialogs/emotiondialog.h"
#include "dialogs/exportanimationdialog.h"
#include "dialogs/lipsyncdialog.h"
#include "media/mediareader.h"
#include "playback/playbackcontroller.h"
#include "playback/playhead.h"
#include "speech/tts.h"
#include "timeline/emotionpalette.h"
#include "timeline/timelineview.h"
#include "timeline/timelinewidget.h"
#include "views/previewview.h"
#include "window/mainwindow.h"
#include "window/studio.h"

#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QLineEdit>
#include <QMimeData>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <cmath>
#include <memory>

using namespace toonface;
using namespace toonface::dialogfixture;

// The studio's "done when", as a new user would go through it in one window: open a photo, lip
// sync a Mandarin recording with its script, drag one syllable to fix it, replace one shape,
// drop a smile over a phrase, play it back, export an MP4 and an SVG, save, reopen. Each step is
// checked on the document and on the files; with TOONFACE_SCREENSHOTS set, the window is saved
// as a PNG after each step, to look at.
namespace {

const QString kPortrait = QStringLiteral("/usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg");
constexpr int kLongMs = 180000;

// Runs `handle` on the next modal dialog of type T that comes up (polling, as a user would wait
// for it); `handled` turns true once it ran.
template<typename T>
std::shared_ptr<bool> onNextDialog(std::function<void(T *)> handle)
{
    auto handled = std::make_shared<bool>(false);
    auto *timer = new QTimer;
    timer->setInterval(20);
    QObject::connect(timer, &QTimer::timeout, timer, [timer, handle, handled] {
        auto *dialog = qobject_cast<T *>(QApplication::activeModalWidget());
        if (!dialog || !dialog->isVisible())
            return;
        timer->stop();
        timer->deleteLater();
        *handled = true;
        handle(dialog);
    });
    timer->start();
    return handled;
}

void drag(QWidget *viewport, QPoint from, QPoint to, int steps = 6)
{
    QTest::mousePress(viewport, Qt::LeftButton, Qt::NoModifier, from);
    for (int s = 1; s <= steps; ++s)
        QTest::mouseMove(viewport, from + (to - from) * s / steps);
    QTest::mouseRelease(viewport, Qt::LeftButton, Qt::NoModifier, to);
}

void shoot(QWidget *window, const QString &name)
{
    const QString dir = qEnvironmentVariable("TOONFACE_SCREENSHOTS");
    if (!dir.isEmpty())
        window->grab().save(QDir(dir).filePath(QStringLiteral("studioflow-") + name + QStringLiteral(".png")));
}

} // namespace

class TestStudioFlow : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    QTemporaryDir m_recovery;

    // The real recording when the research data is here, else the same script spoken by the
    // built-in voice in another voice than the aligner's, with silence around it.
    QString recording()
    {
        const QString real = realRecording();
        if (!real.isEmpty())
            return real;
        TtsOptions o;
        o.voice = QStringLiteral("cmn-latn-pinyin+f2");
        o.rate = 150;
        const TtsResult r = synthesize(parseScript(kRealScript).script, o);
        if (!r.ok())
            return {};
        Audio a = resampled(r.audio, kSpeechSampleRate);
        a.samples = QVector<float>(8000, 0.0f) + a.samples + QVector<float>(8000, 0.0f);
        QString error;
        const QString path = m_dir.filePath(QStringLiteral("spoken.wav"));
        return writeAudio(path, a, &error) ? path : QString();
    }

    // Exports through File ▸ Export Animation… in `format` to `path`; the dialog's result.
    ExportResult exportAs(MainWindow *window, AnimationFormat format, const QString &path)
    {
        auto result = std::make_shared<ExportResult>();
        auto handled = onNextDialog<ExportAnimationDialog>([format, path, result](ExportAnimationDialog *dialog) {
            auto *formats = dialog->findChild<QComboBox *>(QStringLiteral("format"));
            formats->setCurrentIndex(formats->findData(int(format)));
            auto *pathEdit = dialog->findChild<QLineEdit *>(QStringLiteral("path"));
            pathEdit->setText(path);
            auto *size = dialog->findChild<QComboBox *>(QStringLiteral("size"));
            if (size->findData(360) >= 0)
                size->setCurrentIndex(size->findData(360));
            QSignalSpy finished(dialog, &ExportAnimationDialog::finished);
            QTest::mouseClick(dialog->findChild<QPushButton *>(QStringLiteral("export")), Qt::LeftButton);
            if (finished.wait(kLongMs))
                *result = dialog->lastResult();
            else
                result->error = QStringLiteral("the export did not end");
            QTest::mouseClick(dialog->findChild<QPushButton *>(QStringLiteral("close")), Qt::LeftButton);
        });
        window->studio()->exportAnimationAction()->trigger();
        if (!*handled)
            result->error = QStringLiteral("no export dialog came up");
        return *result;
    }

private Q_SLOTS:
    void initTestCase()
    {
        fixture::isolateSettings();
        QSettings().clear();
        QVERIFY(m_dir.isValid() && m_recovery.isValid());
    }

    void photoToExportedAnimationAndBack()
    {
        if (!QFile::exists(kPortrait))
            QSKIP("grace_hopper.jpg is not installed (package python-matplotlib-data)");
        const QString wav = recording();
        QVERIFY2(!wav.isEmpty(), "no recording: neither the research data nor the built-in voice");

        MainWindow::Options options;
        options.recoveryDirectory = m_recovery.path();
        auto window = std::make_unique<MainWindow>(options);
        window->resize(1600, 1000);
        window->show();
        QVERIFY(QTest::qWaitForWindowExposed(window.get()));
        Document *doc = window->document();
        Studio *studio = window->studio();

        // 1. Open a photo: its points are detected.
        QSignalSpy detected(window.get(), &MainWindow::detectionDone);
        window->openFile(kPortrait);
        QVERIFY(QTest::qWaitFor([&] { return detected.size() == 1; }, kLongMs));
        QVERIFY(doc->hasFace());
        QVERIFY(studio->lipSyncAction()->isEnabled());
        shoot(window.get(), QStringLiteral("1-photo"));

        // 2. Lip sync the recording with its script, through the dialog: one undo step.
        const int stepsBefore = doc->undoStack()->count();
        auto synced = onNextDialog<LipSyncDialog>([wav](LipSyncDialog *dialog) {
            auto *path = dialog->findChild<QLineEdit *>(QStringLiteral("recording"));
            path->clear();
            QTest::keyClicks(path, wav);
            QVERIFY(typeScript(dialog, kRealScript));
            QVERIFY(click(dialog, "start"));
        });
        studio->lipSyncAction()->trigger(); // returns when the dialog closes
        QVERIFY(*synced);
        QCOMPARE(doc->undoStack()->count(), stepsBefore + 1);
        QCOMPARE(doc->syllables().size(), kRealScript.size());
        QVERIFY(!doc->timeline().audioClips().isEmpty());
        QCOMPARE(doc->timeline().audioClips().first().path, wav);
        QVERIFY(doc->timeline().mouthKeys().size() >= doc->syllables().size());
        shoot(window.get(), QStringLiteral("2-lipsynced"));

        // The timeline, zoomed so that a syllable is wide enough to grab.
        TimelineView *view = studio->timelineDock()->findChild<TimelineView *>();
        QVERIFY(view);
        view->setPixelsPerSecond(300, TimelineLayout::kLabelWidth);
        QWidget *viewport = view->viewport();

        // 3. Drag one syllable's end later: its shapes re-time, its neighbour gives way.
        const int fix = 3;
        const LipsyncSyllable syllable = doc->syllables()[fix];
        const QRectF rect = view->itemRect({ItemKind::Syllable, fix});
        QVERIFY(rect.right() < viewport->width());
        const QPoint grab(int(std::lround(rect.right())) - 1, int(rect.center().y()));
        QCOMPARE(view->hitAt(grab).part, HitPart::EndEdge);
        drag(viewport, grab, grab + QPoint(18, 0));
        const LipsyncSyllable moved = doc->syllables()[fix];
        QVERIFY2(moved.end > syllable.end + 0.03, qPrintable(QString::number(moved.end - syllable.end)));
        QCOMPARE(moved.start, syllable.start);
        QCOMPARE(doc->syllables()[fix + 1].start, moved.end);
        QCOMPARE(doc->undoStack()->count(), stepsBefore + 2);

        // 4. Replace one shape from the keyboard.
        int key = -1;
        const QVector<MouthKey> keys = doc->timeline().mouthKeys();
        for (int i = 0; i < keys.size() && key < 0; ++i)
            if (keys[i].shape != MouthShape::O && keys[i].time > 0.5)
                key = i;
        QVERIFY(key >= 0);
        QTest::mouseClick(
            viewport, Qt::LeftButton, Qt::NoModifier, view->itemRect({ItemKind::Mouth, key}).center().toPoint());
        QTest::keyClick(view, Qt::Key_O);
        QCOMPARE(doc->timeline().mouthKeys()[key].shape, MouthShape::O);
        QCOMPARE(doc->undoStack()->count(), stepsBefore + 3);

        // 5. Select a phrase (its first syllable, Shift+click its fourth) and drop a smile from
        // the palette into it: the smile covers the phrase.
        const int phraseEnd = 3;
        QTest::mouseClick(
            viewport, Qt::LeftButton, Qt::NoModifier, view->itemRect({ItemKind::Syllable, 0}).center().toPoint());
        QTest::mouseClick(viewport, Qt::LeftButton, Qt::ShiftModifier,
            view->itemRect({ItemKind::Syllable, phraseEnd}).center().toPoint());
        QCOMPARE(view->selection().indices(ItemKind::Syllable).size(), phraseEnd + 1);
        const double phraseStart = doc->syllables()[0].start;
        const double phraseStop = doc->syllables()[phraseEnd].end;
        const QRect emotionRow = view->timelineLayout().rowRect(RowKind::Emotion, viewport->width());
        const QPoint drop(int(std::lround(view->xOf((phraseStart + phraseStop) / 2))), emotionRow.center().y());
        std::unique_ptr<QMimeData> mime(emotionMimeData(Emotion::Smile));
        QDragEnterEvent enter(drop, Qt::CopyAction, mime.get(), Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(viewport, &enter);
        QDragMoveEvent move(drop, Qt::CopyAction, mime.get(), Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(viewport, &move);
        QDropEvent dropEvent(QPointF(drop), Qt::CopyAction, mime.get(), Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(viewport, &dropEvent);
        QCOMPARE(doc->timeline().emotionClips().size(), 1);
        const EmotionClip smile = doc->timeline().emotionClips().first();
        QCOMPARE(smile.emotion, Emotion::Smile);
        QVERIFY(std::abs(smile.start - phraseStart) < 1e-6 && std::abs(smile.end - phraseStop) < 1e-6);
        QCOMPARE(doc->undoStack()->count(), stepsBefore + 4);
        // The preview follows the playhead into the phrase.
        const QImage beforeScrub = window->previewView()->image();
        studio->playhead()->setTime((phraseStart + phraseStop) / 2);
        QTRY_VERIFY(window->previewView()->image() != beforeScrub);
        shoot(window.get(), QStringLiteral("3-edited"));

        // 6. Play for a second (on the wall clock here, with sound where a device exists): the
        // playhead moves about a second, the preview draws the frames on the way.
        PlaybackController *playback = studio->playback();
        playback->goToFirstFrame();
        const QImage still = window->previewView()->image();
        QElapsedTimer wall;
        wall.start();
        playback->playPauseAction()->trigger();
        QVERIFY(playback->isPlaying());
        // Until a second has played, waited on rather than timed: a loaded machine makes it
        // slower, not wrong.
        QTRY_VERIFY_WITH_TIMEOUT(studio->playhead()->time() >= 1.0 && playback->framesPlayed() >= 15, kLongMs);
        playback->playPauseAction()->trigger();
        const double played = studio->playhead()->time();
        const double waited = wall.nsecsElapsed() / 1e9;
        // On the clock: never ahead of the time that passed.
        QVERIFY2(played >= 1.0 && played <= waited + 0.05,
            qPrintable(QStringLiteral("played %1 s in %2 s").arg(played).arg(waited)));
        QVERIFY(window->previewView()->image() != still); // the mouth moved
        shoot(window.get(), QStringLiteral("4-played"));

        // 7. Export an MP4 (every frame and the sound) and a SMIL SVG.
        const double duration = doc->timeline().duration();
        const QString mp4 = m_dir.filePath(QStringLiteral("talk.mp4"));
        const ExportResult video = exportAs(window.get(), AnimationFormat::Mp4, mp4);
        QVERIFY2(video.ok(), qPrintable(video.error));
        QString error;
        const std::optional<MediaInfo> info = probeMedia(mp4, &error);
        QVERIFY2(info, qPrintable(error));
        const int fps = int(std::lround(doc->timeline().frameRate()));
        QVERIFY2(std::abs(info->frameCount - duration * fps) <= 1.0, qPrintable(QString::number(info->frameCount)));
        QVERIFY(info->hasAudio);
        const QString svg = m_dir.filePath(QStringLiteral("talk.svg"));
        const ExportResult smil = exportAs(window.get(), AnimationFormat::SmilSvg, svg);
        QVERIFY2(smil.ok(), qPrintable(smil.error));
        QFile svgFile(svg);
        QVERIFY(svgFile.open(QIODevice::ReadOnly));
        const QByteArray svgText = svgFile.readAll();
        QVERIFY(svgText.contains("<animate"));
        QVERIFY(svgText.contains("<audio") || svgText.contains("audio"));

        // 8. Save, close, reopen: the whole animation comes back.
        const Animation saved = doc->animation();
        const MouthShapeSet shapes = doc->mouthShapes();
        const QString project = m_dir.filePath(QStringLiteral("talk.toonface"));
        QVERIFY(window->saveTo(project));
        QVERIFY(!window->isWindowModified());
        window.reset();

        auto reopened = std::make_unique<MainWindow>(options);
        reopened->resize(1600, 1000);
        reopened->show();
        QSignalSpy opened(reopened.get(), &MainWindow::fileOpened);
        reopened->openFile(project);
        QTRY_COMPARE_WITH_TIMEOUT(opened.size(), 1, 30000);
        QCOMPARE(reopened->document()->animation(), saved);
        QCOMPARE(reopened->document()->mouthShapes(), shapes);
        QCOMPARE(reopened->document()->undoStack()->count(), 0);
        QTRY_VERIFY(!reopened->previewView()->image().isNull()); // the cartoon is drawn
        shoot(reopened.get(), QStringLiteral("5-reopened"));
        reopened->document()->undoStack()->setClean();
    }

    // Add Emotion… offers the timeline's selected range, else two seconds from the playhead.
    void addEmotionStartsAtTheSelectionOrThePlayhead()
    {
        MainWindow::Options options;
        options.preloadLandmarkModel = false;
        options.recoveryDirectory = m_recovery.path();
        MainWindow window(options);
        window.show();
        fixture::fillTalking(*window.document());
        const Animation a = window.document()->animation();
        auto *addEmotion = window.findChild<QAction *>(QStringLiteral("actionAddEmotion"));
        QVERIFY(addEmotion && addEmotion->isEnabled());
        const auto offered = [addEmotion] {
            auto clip = std::make_shared<EmotionClip>();
            auto seen = onNextDialog<EmotionDialog>([clip](EmotionDialog *dialog) {
                *clip = dialog->clip();
                dialog->reject();
            });
            addEmotion->trigger();
            return *seen ? std::optional<EmotionClip>(*clip) : std::nullopt;
        };

        TimelineView *view = window.studio()->timelineDock()->findChild<TimelineView *>();
        view->setSelection({{ItemKind::Syllable, 1}, {ItemKind::Syllable, 3}});
        std::optional<EmotionClip> clip = offered();
        QVERIFY(clip);
        QCOMPARE(clip->start, a.syllables[1].start);
        QCOMPARE(clip->end, a.syllables[3].end);

        view->setSelection({});
        window.studio()->playhead()->setTime(0.4);
        clip = offered();
        QVERIFY(clip);
        QVERIFY(std::abs(clip->start - 0.4) < 1e-6 && std::abs(clip->end - 2.4) < 1e-6);
        QCOMPARE(window.document()->undoStack()->count(), 0); // cancelled: nothing added
        window.document()->undoStack()->setClean();
    }
};

TOONFACE_TEST_MAIN(TestStudioFlow)
#include "tst_studioflow.moc"
