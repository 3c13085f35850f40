#include "mainwindowfixture.h"
#include "testmain.h"

using namespace toonface;
using namespace toonface::mainwindowfixture;

// Detecting the photo from the main window: the method, the fallback, several faces, no face,
// cancelling, the detection steps over the photo, re-detecting over points placed by hand.
class TestDetectionFlow : public MainWindowTestBase
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { setUpCase(); }
    void init() { setUpTest(); }
    void cleanup() { tearDown(); }

    // Without the landmark model, auto's fallback to the thesis' pipeline is said in the status
    // bar, which keeps it up.
    void fallbackToClassicIsShown()
    {
        const QByteArray saved = qgetenv("TOONFACE_LANDMARK_MODEL");
        const bool had = qEnvironmentVariableIsSet("TOONFACE_LANDMARK_MODEL");
        qputenv("TOONFACE_LANDMARK_MODEL", "/nonexistent/toonface-ui-test/landmarks.dat");
        makeWindow();
        const bool ok = openPortrait();
        const QString message = m_window->statusBar()->currentMessage();
        if (had)
            qputenv("TOONFACE_LANDMARK_MODEL", saved);
        else
            qunsetenv("TOONFACE_LANDMARK_MODEL");
        if (!ok)
            return;
        QVERIFY(m_window->document()->hasFace());
        QVERIFY2(message.contains(QStringLiteral("classic")), qPrintable(message));
        QVERIFY2(message.contains(QStringLiteral("/nonexistent/toonface-ui-test/landmarks.dat")), qPrintable(message));
    }

    // A photo of two people: the status bar says how many faces there were and which was used.
    void severalFacesAreCounted()
    {
        if (!QFile::exists(kPortrait))
            QSKIP("grace_hopper.jpg is not installed (package python-matplotlib-data)");
        const QImage one(kPortrait);
        const QImage both = testing::twoPeople(one);
        const QString photo = m_dir.filePath(QStringLiteral("two people.png"));
        QVERIFY(both.save(photo));
        makeWindow();
        QSignalSpy done(m_window.get(), &MainWindow::detectionDone);
        m_window->openFile(photo);
        QVERIFY(QTest::qWaitFor([&] { return done.size() == 1; }, 120000));
        QVERIFY(m_window->document()->hasFace());
        const QString message = m_window->statusBar()->currentMessage();
        QVERIFY2(message.contains(QStringLiteral("2 faces found: using the largest, most central one")),
            qPrintable(message));
        // The whole photo is shown, so that the other face can be seen and chosen.
        QCOMPARE(m_window->photoView()->fitMode(), PhotoView::Fit::Photo);
        QVERIFY(m_window->document()->face().point("2.1").x() < one.width());

        // The other face's box is on the photo; a click in it detects that face, one undo step.
        PhotoView *view = m_window->photoView();
        QCOMPARE(view->otherFaces().size(), 1);
        const QRect other = view->otherFaces().constFirst();
        QVERIFY(other.left() >= one.width() - 5);
        const int undoBefore = m_window->document()->undoStack()->count();
        done.clear();
        const QPoint click = view->mapFromScene(QPointF(other.center()));
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, click);
        QVERIFY(QTest::qWaitFor([&] { return done.size() == 1; }, 120000));
        QVERIFY(other.contains(m_window->document()->face().point("2.1").toPoint()));
        QCOMPARE(m_window->document()->undoStack()->count(), undoBefore + 1);
        QCOMPARE(m_window->document()->undoStack()->undoText(), QStringLiteral("Use another face"));
        QVERIFY2(m_window->statusBar()->currentMessage().contains(QStringLiteral("using the one you chose")),
            qPrintable(m_window->statusBar()->currentMessage()));
        // Now the first portrait's face is the other one.
        QCOMPARE(view->otherFaces().size(), 1);
        QVERIFY(view->otherFaces().constFirst().right() < one.width() + 5);
        m_window->document()->undoStack()->undo();
        QVERIFY(m_window->document()->face().point("2.1").x() < one.width());
    }

    void cancelledDetectionLeavesNoFace()
    {
        makeWindow();
        QSignalSpy opened(m_window.get(), &MainWindow::fileOpened);
        QSignalSpy done(m_window.get(), &MainWindow::detectionDone);
        m_window->openFile(m_photoPath);
        QTRY_COMPARE(opened.size(), 1);
        QVERIFY(m_window->isBusy()); // detecting
        auto *cancel = m_window->findChild<QAbstractButton *>(QStringLiteral("cancelButton"));
        QVERIFY(cancel && cancel->isVisible());
        cancel->click();
        QTRY_VERIFY_WITH_TIMEOUT(done.size() == 1, 60000);
        QVERIFY(!m_window->isBusy());
        QVERIFY(!cancel->isVisible());
        QVERIFY(!m_window->document()->hasFace());
        QCOMPARE(m_window->document()->undoStack()->count(), 0);
    }

    void photoWithoutFaceOffersTheAverageFace()
    {
        QImage blank(320, 240, QImage::Format_RGB32);
        blank.fill(QColor(128, 128, 128));
        const QString blankPath = m_dir.filePath(QStringLiteral("blank.png"));
        QVERIFY(blank.save(blankPath));

        makeWindow();
        QSignalSpy done(m_window.get(), &MainWindow::detectionDone);
        const auto answered = answerNextMessageBox(QStringLiteral("Place Average Face"));
        m_window->openFile(blankPath);
        QTRY_VERIFY_WITH_TIMEOUT(done.size() == 1, 60000);
        QVERIFY(*answered);
        Document *doc = m_window->document();
        QVERIFY(doc->hasFace());
        QVERIFY(doc->filePath().isEmpty());
        QCOMPARE(doc->displayName(), QStringLiteral("blank.png"));
        QCOMPARE(doc->undoStack()->count(), 1);
        QCOMPARE(doc->undoStack()->undoText(), QStringLiteral("Place average face"));
        QVERIFY(QRectF(0, 0, 320, 240).contains(doc->face().bounds(PointGroup::Mouth)));
    }

    // The points are placed as soon as they are found, before the detection's steps (drawn
    // after, in the background); the face then stays as it was placed, in one undo step.
    void pointsComeBeforeTheSteps()
    {
        makeWindow();
        if (!QFile::exists(kPortrait))
            QSKIP("grace_hopper.jpg is not installed (package python-matplotlib-data)");
        QStringList order;
        FaceModel placed;
        int stepsWhenPlaced = -1;
        connect(m_window.get(), &MainWindow::pointsPlaced, this, [&] {
            order << QStringLiteral("points");
            placed = m_window->document()->face();
            stepsWhenPlaced = int(m_window->detectionSteps()->names().size());
        });
        connect(m_window.get(), &MainWindow::detectionDone, this, [&] { order << QStringLiteral("done"); });
        m_window->openFile(kPortrait);
        QVERIFY(QTest::qWaitFor([&] { return order.contains(QStringLiteral("done")); }, 120000));
        QCOMPARE(order, QStringList({QStringLiteral("points"), QStringLiteral("done")}));
        QCOMPARE(stepsWhenPlaced, 0);
        QVERIFY(!m_window->detectionSteps()->names().isEmpty());
        const FaceModel &final = m_window->document()->face();
        for (int i = 0; i < kPointCount; ++i)
            QCOMPARE(final.point(i), placed.point(i));
        QCOMPARE(m_window->document()->undoStack()->count(), 1);
    }

    void detectionStepsNeedADetection()
    {
        makeWindow();
        QVERIFY(!stepsMenu()->menuAction()->isEnabled());
        QVERIFY(stepsMenu()->menuAction()->toolTip().contains(QStringLiteral("Open a photo")));
        openProject();
        // A project keeps no steps: the menu says so and how to get them.
        QVERIFY(m_window->detectionSteps()->isEmpty());
        QVERIFY(!stepsMenu()->menuAction()->isEnabled());
        QVERIFY(!stepsCombo()->isEnabled());
        QVERIFY(stepsMenu()->menuAction()->toolTip().contains(QStringLiteral("Re-detect")));
        QCOMPARE(stepsCombo()->toolTip(), stepsMenu()->menuAction()->toolTip());
        QVERIFY(!m_window->photoView()->hasOverlay());
    }

    void detectionStepsOfThePortraitShowOverThePhoto()
    {
        makeWindow();
        // The photo at the size this check was made for: the docks closed, so that the view does
        // not shrink the photo (a shrunk photo shows only some of its pixels).
        for (QDockWidget *dock : m_window->findChildren<QDockWidget *>())
            dock->close();
        if (!openPortrait())
            return;
        Document *doc = m_window->document();
        QVERIFY(doc->hasFace());
        DetectionSteps *steps = m_window->detectionSteps();
        QVERIFY(!steps->isEmpty());

        // The menu and the combo list every step by its name for people, None first and checked.
        QVERIFY(stepsMenu()->menuAction()->isEnabled());
        QVERIFY(stepsCombo()->isEnabled());
        QStringList overlays;
        QStringList closeUps;
        for (const QString &name : steps->names())
            (DetectionSteps::isCloseUp(name) ? closeUps : overlays) << name;
        QVERIFY(!overlays.isEmpty());
        QCOMPARE(listedSteps(false), overlays);
        QCOMPARE(listedSteps(true), closeUps);
        QVERIFY(action("actionStepNone")->isChecked());
        QCOMPARE(stepsCombo()->count(), overlays.size() + 1);
        QCOMPARE(stepsCombo()->currentIndex(), 0);
        for (int i = 0; i < overlays.size(); ++i) {
            QCOMPARE(
                action(QStringLiteral("actionStep-") + overlays[i])->text(), DetectionSteps::displayName(overlays[i]));
            QCOMPARE(stepsCombo()->itemText(i + 1), DetectionSteps::displayName(overlays[i]));
        }
        QVERIFY(!m_window->photoView()->hasOverlay());

        // Choosing one lays it over the whole photo, with the slider's opacity.
        PhotoView *view = m_window->photoView();
        view->fitToWindow();
        opacitySlider()->setValue(100);
        QCoreApplication::processEvents();
        const QImage plain = view->viewport()->grab().toImage();
        // Photo pixels (on a grid) where a step's picture is opaque and clearly not the photo.
        const QRectF photoRect(QPointF(), QSizeF(doc->photo().size()));
        auto differing = [&](const QString &name) {
            const QImage picture = steps->image(name).scaled(doc->photo().size());
            QList<QPoint> points;
            for (int y = 4; y < photoRect.height() - 4; y += 7) {
                for (int x = 4; x < photoRect.width() - 4; x += 7) {
                    const QRgb over = picture.pixel(x, y);
                    const QRgb under = doc->photo().pixel(x, y);
                    const int contrast = std::abs(qRed(over) - qRed(under)) + std::abs(qGreen(over) - qGreen(under))
                        + std::abs(qBlue(over) - qBlue(under));
                    if (qAlpha(over) == 255 && contrast >= 60)
                        points.append(QPoint(x, y));
                }
            }
            return points;
        };
        QString step = overlays.first(); // the step that differs most from the photo
        QList<QPoint> stepDiffers = differing(step);
        for (const QString &name : std::as_const(overlays)) {
            const QList<QPoint> points = differing(name);
            if (points.size() > stepDiffers.size()) {
                step = name;
                stepDiffers = points;
            }
        }
        action(QStringLiteral("actionStep-") + step)->trigger();
        QCOMPARE(m_window->overlayStep(), step);
        QVERIFY(view->hasOverlay());
        QCOMPARE(stepsCombo()->currentData().toString(), step);
        QVERIFY(action(QStringLiteral("actionStep-") + step)->isChecked());
        QCOMPARE(view->overlayItem()->sceneBoundingRect(), photoRect);
        QCOMPARE(view->overlayItem()->opacity(), 1.0);

        // Where the step's picture is opaque and differs from the photo, the view shows it.
        QCoreApplication::processEvents();
        const QImage covered = view->viewport()->grab().toImage();
        int opaque = 0;
        int changed = 0;
        for (const QPoint &p : std::as_const(stepDiffers)) {
            const QPoint v = view->mapFromScene(QPointF(p) + QPointF(0.5, 0.5));
            if (!view->viewport()->rect().contains(v))
                continue;
            ++opaque;
            changed += covered.pixel(v) != plain.pixel(v);
        }
        QVERIFY2(opaque > 100, qPrintable(QString::number(opaque)));
        QVERIFY2(changed >= opaque * 0.95, qPrintable(QStringLiteral("%1 of %2").arg(changed).arg(opaque)));

        opacitySlider()->setValue(35);
        QCOMPARE(view->overlayItem()->opacity(), 0.35);
        QCOMPARE(Settings().overlayOpacity(), 0.35);

        // The combo chooses too, and None takes the overlay away.
        if (overlays.size() > 1) {
            stepsCombo()->setCurrentIndex(2);
            Q_EMIT stepsCombo()->activated(2);
            QCOMPARE(m_window->overlayStep(), overlays[1]);
            QVERIFY(action(QStringLiteral("actionStep-") + overlays[1])->isChecked());
        }
        action("actionStepNone")->trigger();
        QVERIFY(!view->hasOverlay());
        QVERIFY(m_window->overlayStep().isEmpty());
        QVERIFY(!opacitySlider()->isEnabled());
        m_window->showDetectionStep(step);
        QVERIFY(opacitySlider()->isEnabled());

        // Points still drag with the overlay shown, one undo step each.
        const int i = pt::idx("8.4");
        const QPointF before = doc->face().point(i);
        const int undoCount = doc->undoStack()->count();
        const QPoint from = view->mapFromScene(before);
        QTest::mousePress(view->viewport(), Qt::LeftButton, Qt::NoModifier, from);
        for (int s = 1; s <= 6; ++s)
            QTest::mouseMove(view->viewport(), from + QPoint(2 * s, 3 * s));
        QTest::mouseRelease(view->viewport(), Qt::LeftButton, Qt::NoModifier, from + QPoint(12, 18));
        QVERIFY(QLineF(doc->face().point(i), before + QPointF(12, 18) / view->zoom()).length() < 1.5 / view->zoom());
        QCOMPARE(doc->undoStack()->count(), undoCount + 1);
        QVERIFY(view->hasOverlay());

        // A close-up opens in a window of its own and leaves the overlay as it was.
        if (!closeUps.isEmpty()) {
            action(QStringLiteral("actionStep-") + closeUps.first())->trigger();
            auto *dialog = m_window->findChild<StepImageDialog *>(QStringLiteral("closeUp-") + closeUps.first());
            QVERIFY(dialog);
            QVERIFY(dialog->isVisible());
            QCOMPARE(dialog->windowTitle(), DetectionSteps::displayName(closeUps.first()));
            QVERIFY(!dialog->shownPixmap().isNull());
            QCOMPARE(m_window->overlayStep(), step);
        }

        // Undoing the drag and the detection keeps the steps (they belong to the photo, not the points).
        while (doc->undoStack()->canUndo())
            doc->undoStack()->undo();
        QVERIFY(!doc->hasFace());
        QVERIFY(!steps->isEmpty());
        QVERIFY(view->hasOverlay());
        doc->undoStack()->setClean();

        // Another photo (here a project's) drops them, the close-ups with them.
        openProject();
        QVERIFY(steps->isEmpty());
        QVERIFY(!view->hasOverlay());
        QVERIFY(m_window->overlayStep().isEmpty());
        QVERIFY(!stepsMenu()->menuAction()->isEnabled());
        QCOMPARE(listedSteps(false), QStringList());
        QCOMPARE(stepsCombo()->count(), 1);
        QTRY_VERIFY(m_window->findChildren<StepImageDialog *>().isEmpty());
    }

    void detectionMethodComesFromTheSettings()
    {
        Settings().setDetectionMethod(QStringLiteral("landmarks"));
        makeWindow();
        QVERIFY(action("actionMethodLandmarks")->isChecked());
        QVERIFY(!action("actionMethodAuto")->isChecked());
        QCOMPARE(m_window->detectionMethod(), DetectionMethod::Landmarks);
        action("actionMethodClassic")->trigger();
        QCOMPARE(Settings().detectionMethod(), QStringLiteral("classic"));
    }

    void detectionMethodChoosesTheSteps()
    {
        makeWindow();
        QVERIFY(action("actionMethodAuto")->isChecked());
        m_window->setDetectionMethod(DetectionMethod::Classic);
        QVERIFY(action("actionMethodClassic")->isChecked());
        QCOMPARE(m_window->detectionMethod(), DetectionMethod::Classic);
        QCOMPARE(Settings().detectionMethod(), QStringLiteral("auto")); // this session only
        const MessageBoxAnswerer answerer({QStringLiteral("OK"), QStringLiteral("Cancel")});
        if (!openPortrait())
            return;
        // The thesis pipeline may or may not place a face on this photo; its steps show how far it got.
        const QStringList classic = m_window->detectionSteps()->names();
        QVERIFY(!classic.isEmpty());
        for (const QString &name : classic)
            QVERIFY2(name.startsWith(QStringLiteral("classic-")), qPrintable(name));
        QVERIFY(classic.contains(QStringLiteral("classic-b1")));
        m_window->showDetectionStep(QStringLiteral("classic-b1"));
        QCOMPARE(m_window->overlayStep(), QStringLiteral("classic-b1"));

        // The menu switches the method; re-detection replaces the steps and keeps the chosen
        // one when the new run has it too.
        action("actionMethodLandmarks")->trigger();
        QCOMPARE(m_window->detectionMethod(), DetectionMethod::Landmarks);
        QCOMPARE(Settings().detectionMethod(), QStringLiteral("landmarks"));
        QVERIFY(action("actionRedetect")->isEnabled()); // with or without a face from the classic run
        QVERIFY(redetect());
        const QStringList landmarks = m_window->detectionSteps()->names();
        QVERIFY(!landmarks.isEmpty());
        for (const QString &name : landmarks)
            QVERIFY2(!name.startsWith(QStringLiteral("classic-")), qPrintable(name));
        QVERIFY(m_window->overlayStep().isEmpty()); // B1 is not a landmark step

        m_window->showDetectionStep(landmarks.first());
        const QString shown = m_window->overlayStep();
        QVERIFY(!shown.isEmpty());
        QVERIFY(redetect());
        QCOMPARE(m_window->overlayStep(), shown);
    }

    void photoIsDetectedInTheBackground()
    {
        if (!QFile::exists(kPortrait))
            QSKIP("grace_hopper.jpg is not installed (package python-matplotlib-data)");
        makeWindow();
        QSignalSpy done(m_window.get(), &MainWindow::detectionDone);
        m_window->openFile(kPortrait);
        QTRY_VERIFY(m_window->isBusy() || done.size() == 1);
        QTRY_VERIFY_WITH_TIMEOUT(done.size() == 1, 120000);
        QVERIFY(!m_window->isBusy());
        Document *doc = m_window->document();
        if (!doc->hasFace())
            QFAIL("no face found on the portrait");
        // Points and sampled colours arrive as one undoable step.
        QCOMPARE(doc->undoStack()->count(), 1);
        QCOMPARE(doc->undoStack()->undoText(), QStringLiteral("Detect face"));
        QVERIFY(doc->isModified());
        doc->undoStack()->undo();
        QVERIFY(!doc->hasFace());

        // Re-detection keeping a hand-placed point.
        doc->undoStack()->redo();
        const int i = pt::idx("9.15");
        const QPointF placed = doc->face().point(i) + QPointF(7, 0);
        doc->movePoint(i, placed, true);
        action("actionRedetectKeep")->trigger();
        QVERIFY(m_window->isBusy());
        QTRY_VERIFY_WITH_TIMEOUT(done.size() == 2, 120000);
        QCOMPARE(doc->undoStack()->count(), 3);
        QCOMPARE(doc->face().point(i), placed);

        // Re-detect Points over a point moved by hand asks first: Cancel does nothing,
        // Keep My Points keeps it.
        auto answered = answerNextMessageBox(QStringLiteral("Cancel"));
        action("actionRedetect")->trigger();
        QVERIFY(*answered);
        QVERIFY(!m_window->isBusy());
        QCOMPARE(doc->undoStack()->count(), 3);
        answered = answerNextMessageBox(QStringLiteral("Keep My Points"));
        action("actionRedetect")->trigger();
        QVERIFY(*answered);
        QTRY_VERIFY_WITH_TIMEOUT(done.size() == 3, 120000);
        QCOMPARE(doc->face().point(i), placed);
    }

    // A face turned or tilted beyond what the cartoon draws well is said after detection (the
    // cartoon came out twisted with no word); a face looking into the camera is not.
    void turnedFaceIsSaid()
    {
        DetectionResult result;
        result.faceCount = 1;
        result.method = QStringLiteral("landmarks");
        result.face = fixture::face();
        QVERIFY(!detectionSummary(result, false).contains(QStringLiteral("twisted")));
        QTransform rotation;
        rotation.translate(200, 250).rotate(22).translate(-200, -250);
        const FaceModel front = result.face;
        for (int i = 0; i < kPointCount; ++i)
            result.face.setPoint(i, rotation.map(front.point(i)));
        const QString said = detectionSummary(result, false);
        QVERIFY2(said.contains(QStringLiteral("tilted about 22°")), qPrintable(said));
        QVERIFY(said.contains(QStringLiteral("twisted")));
    }
};

TOONFACE_TEST_MAIN(TestDetectionFlow)
#include "tst_detectionflow.moc"
