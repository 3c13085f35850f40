#include "dialogfixture.h"
#include "testmain.h"
#include "uifixture.h"

#include "dialogs/mouthshapesdialog.h"
#include "dialogs/posepreview.h"
#include "document/document.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineF>
#include <QListWidget>
#include <QTest>
#include <QToolButton>
#include <QUndoStack>

using namespace toonface;
using namespace toonface::dialogfixture;

namespace {

FapuOffset termsOf(const MouthShapePreset &preset, int control)
{
    return preset.offsets[control];
}

} // namespace

class TestMouthShapesDialog : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void editResetAndUndo()
    {
        Document doc;
        fixture::fill(doc);
        // A project whose presets are already edited: undo must give back exactly these.
        MouthShapeSet custom;
        MouthShapePreset i = custom.preset(MouthShape::I);
        i.offsets[Down].dy.mns = 0.2;
        custom.setPreset(MouthShape::I, i);
        doc.changeMouthShapes(custom, QStringLiteral("setup"));
        doc.undoStack()->clear();
        const MouthShapeSet before = doc.mouthShapes();

        MouthShapesDialog dialog(&doc);
        dialog.resize(dialog.sizeHint());
        dialog.show();
        auto *list = dialog.findChild<QListWidget *>(QStringLiteral("shapes"));
        auto *preview = dialog.findChild<PosePreview *>(QStringLiteral("preview"));
        QCOMPARE(list->count(), kMouthShapeCount);
        QTest::mouseClick(dialog.findChild<QToolButton *>(QStringLiteral("advanced")), Qt::LeftButton);

        // Choosing a shape in the list shows it; m (shut) and a (wide open) look different.
        list->setCurrentRow(int(MouthShape::M));
        const QImage shut = preview->image();
        list->setCurrentRow(int(MouthShape::A));
        QCOMPARE(dialog.currentShape(), MouthShape::A);
        const QImage open = preview->image();
        QVERIFY(open != shut);
        // The editor shows the preset's terms: a's lower lip drops 0.8 MNS0.
        QCOMPARE(dialog.termBox(Down, 1, 0)->value(), 0.8);

        // Edit a's lower lip by typing into its MNS0 box: the preview follows at once.
        QDoubleSpinBox *drop = dialog.termBox(Down, 1, 0);
        drop->selectAll();
        QTest::keyClicks(drop, QStringLiteral("1.2"));
        QCOMPARE(dialog.shapes().preset(MouthShape::A).offsets[Down].dy.mns, 1.2);
        QVERIFY(!dialog.shapes().isDefault(MouthShape::A));
        QVERIFY(preview->image() != open);
        QVERIFY(list->item(int(MouthShape::A))->font().bold()); // marked as edited
        grab(&dialog, QStringLiteral("mouthshapes"));
        // The document is untouched until OK.
        QVERIFY(doc.mouthShapes() == before);

        // Reset Shape gives a back its default (and the edited `i` stays edited).
        QVERIFY(click(&dialog, "resetShape"));
        QVERIFY(dialog.shapes().isDefault(MouthShape::A));
        QCOMPARE(dialog.termBox(Down, 1, 0)->value(), 0.8);
        QVERIFY(preview->image() == open);
        QVERIFY(!dialog.shapes().isDefault(MouthShape::I));

        // Edit again, tick o's corner rule on a, and press OK: one undo step.
        drop->selectAll();
        QTest::keyClicks(drop, QStringLiteral("0.6"));
        QTest::mouseClick(dialog.findChild<QCheckBox *>(QStringLiteral("cornersAtLipMiddle")), Qt::LeftButton);
        QVERIFY(dialog.shapes().preset(MouthShape::A).cornersAtLipMiddle);
        dialog.accept();
        QCOMPARE(doc.mouthShapes().preset(MouthShape::A).offsets[Down].dy.mns, 0.6);
        QVERIFY(doc.mouthShapes().preset(MouthShape::A).cornersAtLipMiddle);
        for (MouthShape s : kAllMouthShapes)
            if (s != MouthShape::A)
                QVERIFY(doc.mouthShapes().preset(s) == before.preset(s));
        QCOMPARE(doc.undoStack()->count(), 1);
        doc.undoStack()->undo();
        QVERIFY(doc.mouthShapes() == before);
        doc.undoStack()->redo();

        // Reset All restores face-model.md's whole table.
        MouthShapesDialog again(&doc);
        QVERIFY(!(again.shapes() == MouthShapeSet()));
        again.resetAll();
        QVERIFY(again.shapes() == MouthShapeSet());
        again.accept();
        QVERIFY(doc.mouthShapes() == MouthShapeSet());
        QCOMPARE(doc.undoStack()->count(), 2);
    }

    void draggingAPointOnThePreviewEditsTheShape()
    {
        Document doc;
        fixture::fill(doc);
        MouthShapesDialog dialog(&doc);
        dialog.resize(dialog.sizeHint());
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        dialog.setCurrentShape(MouthShape::A);
        auto *preview = dialog.findChild<PosePreview *>(QStringLiteral("preview"));
        const FaceModel &face = doc.face();
        const QPointF lowerLip = face.point("8.2") + dialog.shapes().displacements(MouthShape::A, face)[Down];
        const QPoint from = preview->toWidget(lowerLip).toPoint();
        const QPoint to = from + QPoint(6, 25);
        QTest::mousePress(preview, Qt::LeftButton, {}, from);
        QTest::mouseMove(preview, from + QPoint(3, 10));
        QTest::mouseMove(preview, to);
        QTest::mouseRelease(preview, Qt::LeftButton, {}, to);
        // The lower lip is where it was dropped: lower in MNS0, sideways in ES0/100.
        const QPointF moved = face.point("8.2") + dialog.shapes().displacements(MouthShape::A, face)[Down];
        const QPointF dropped = preview->toPhoto(to);
        QVERIFY2(QLineF(moved, dropped).length() < 0.1,
            qPrintable(
                QStringLiteral("%1,%2 vs %3,%4").arg(moved.x()).arg(moved.y()).arg(dropped.x()).arg(dropped.y())));
        const MouthShapePreset a = dialog.shapes().preset(MouthShape::A);
        QVERIFY(a.offsets[Down].dy.mns > 0.8);
        QVERIFY(a.offsets[Down].dx.px > 0);
        QCOMPARE(a.offsets[Down].dx.mw, 0.0);
        QCOMPARE(termsOf(a, Up), termsOf(MouthShapeSet::defaultPreset(MouthShape::A), Up));
        // A press away from every point moves nothing.
        const MouthShapeSet before = dialog.shapes();
        QTest::mousePress(preview, Qt::LeftButton, {}, QPoint(2, 2));
        QTest::mouseRelease(preview, Qt::LeftButton, {}, QPoint(40, 40));
        QVERIFY(dialog.shapes() == before);
    }

    void unchangedValuesKeepTheirExactDefaults()
    {
        // i's corners move by MW0/12, which no spin box shows exactly: editing another term
        // must leave it the exact default.
        Document doc;
        fixture::fill(doc);
        MouthShapesDialog dialog(&doc);
        dialog.setCurrentShape(MouthShape::I);
        dialog.termBox(Up, 1, 3)->setValue(2.0);
        dialog.termBox(Up, 1, 3)->setValue(0.0);
        QVERIFY(dialog.shapes().isDefault(MouthShape::I));
    }

    void cancelChangesNothing()
    {
        Document doc;
        fixture::fill(doc);
        const MouthShapeSet before = doc.mouthShapes();
        MouthShapesDialog dialog(&doc);
        dialog.show();
        dialog.setCurrentShape(MouthShape::O);
        dialog.termBox(Left, 0, 1)->setValue(0.4);
        QVERIFY(!dialog.shapes().isDefault(MouthShape::O));
        dialog.reject();
        QVERIFY(doc.mouthShapes() == before);
        QCOMPARE(doc.undoStack()->count(), 0);
    }

    // The dialog shows the shape to drag; the numbers in the face's measures (MNS0, MW0, …) wait
    // behind Advanced, and even there each column says in words what it measures.
    void numbersWaitBehindAdvanced()
    {
        Document doc;
        fixture::fill(doc);
        MouthShapesDialog dialog(&doc);
        dialog.resize(dialog.sizeHint());
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        QVERIFY(dialog.findChild<PosePreview *>(QStringLiteral("preview"))->isVisible());
        QVERIFY(!dialog.termBox(0, 0, 0)->isVisible());
        const auto shownText = [&dialog] {
            QStringList texts;
            for (const QLabel *label : dialog.findChildren<QLabel *>())
                if (label->isVisible())
                    texts << label->text();
            return texts.join(QLatin1Char('|'));
        };
        for (const char *unit : {"MNS0", "MW0", "ES0", "LowerLipH", "8.9", "8.4"})
            QVERIFY2(!shownText().contains(QLatin1String(unit)), qPrintable(shownText()));

        QTest::mouseClick(dialog.findChild<QToolButton *>(QStringLiteral("advanced")), Qt::LeftButton);
        QVERIFY(dialog.termBox(0, 0, 0)->isVisible());
        QVERIFY(shownText().contains(QStringLiteral("× mouth width")));
        QVERIFY(!shownText().contains(QStringLiteral("× MW0")));
    }
};

TOONFACE_TEST_MAIN(TestMouthShapesDialog)
#include "tst_mouthshapesdialog.moc"
