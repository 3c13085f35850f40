#include "appearance/appearancepanel.h"
#include "testmain.h"
#include "uifixture.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QSlider>
#include <QTest>
#include <QUndoStack>

using namespace toonface;

class TestAppearancePanel : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void showsTheDocumentsStyle()
    {
        Document doc;
        fixture::fill(doc);
        Style s = doc.style();
        s.caricature = 0.6;
        s.appearance.beard = true;
        s.appearance.glasses = GlassesShape::Round;
        s.eyebrows = EyebrowVariant::Thick;
        doc.changeStyle(s, QStringLiteral("set"));
        AppearancePanel panel(&doc);
        QCOMPARE(panel.findChild<QSlider *>(QStringLiteral("caricature"))->value(), 60);
        QVERIFY(panel.findChild<QCheckBox *>(QStringLiteral("beard"))->isChecked());
        QVERIFY(!panel.findChild<QCheckBox *>(QStringLiteral("moustache"))->isChecked());
        QCOMPARE(
            panel.findChild<QComboBox *>(QStringLiteral("glasses"))->currentData().toInt(), int(GlassesShape::Round));
        QCOMPARE(panel.findChild<QComboBox *>(QStringLiteral("eyebrowVariant"))->currentData().toInt(),
            int(EyebrowVariant::Thick));
        // Shown by their titles, not the file's names.
        QCOMPARE(panel.findChild<QComboBox *>(QStringLiteral("glasses"))->currentText(), QStringLiteral("Round"));
        // Undo shows the change going back.
        doc.undoStack()->undo();
        QVERIFY(!panel.findChild<QCheckBox *>(QStringLiteral("beard"))->isChecked());
        QCOMPARE(panel.findChild<QSlider *>(QStringLiteral("caricature"))->value(),
            int(std::lround(kDefaultCaricature * 100)));
    }

    // Every control is one undo step that changes just its part of the style.
    void eachChangeIsOneStep()
    {
        Document doc;
        fixture::fill(doc);
        AppearancePanel panel(&doc);
        QUndoStack *undo = doc.undoStack();

        panel.findChild<QCheckBox *>(QStringLiteral("moustache"))->click();
        QCOMPARE(undo->count(), 1);
        QVERIFY(doc.style().appearance.moustache);

        auto *glasses = panel.findChild<QComboBox *>(QStringLiteral("glasses"));
        glasses->setCurrentIndex(glasses->findData(int(GlassesShape::Rectangular)));
        Q_EMIT glasses->activated(glasses->currentIndex());
        QCOMPARE(undo->count(), 2);
        QCOMPARE(doc.style().appearance.glasses, GlassesShape::Rectangular);

        // A slider drag: many values while down, one step on release.
        auto *slider = panel.findChild<QSlider *>(QStringLiteral("caricature"));
        slider->setSliderDown(true);
        for (int v : {10, 20, 30, 80})
            slider->setValue(v);
        QCOMPARE(undo->count(), 2);
        slider->setSliderDown(false);
        QCOMPARE(undo->count(), 3);
        QCOMPARE(doc.style().caricature, 0.8);

        auto *hideHair = panel.findChild<QCheckBox *>(QStringLiteral("visible-hair"));
        hideHair->click();
        QCOMPARE(undo->count(), 4);
        QVERIFY(!doc.style().components.value(QStringLiteral("hair")).visible);

        // The skin's weight changes face, jaw and ears together, in one step.
        auto *width = panel.findChild<QDoubleSpinBox *>(QStringLiteral("width-face"));
        width->setValue(5.0);
        Q_EMIT width->editingFinished();
        QCOMPARE(undo->count(), 5);
        for (const char *key : {"face", "jaw", "ears"})
            QCOMPARE(doc.style().components.value(QLatin1StringView(key)).strokeWidth, 5.0);

        // Resampling from the photo is one step too.
        panel.findChild<QPushButton *>(QStringLiteral("resample"))->click();
        QVERIFY(undo->count() <= 6);

        for (int i = undo->count(); i > 0; --i)
            undo->undo();
        QCOMPARE(doc.style(), Style::preset(QStringLiteral("normal")));
        QVERIFY(!panel.findChild<QCheckBox *>(QStringLiteral("moustache"))->isChecked());
    }

    // The goatee is its own switch, one undo step, and stands aside (disabled) while a beard,
    // which covers the chin, is on.
    void goateeSwitch()
    {
        Document doc;
        fixture::fill(doc);
        AppearancePanel panel(&doc);
        auto *goatee = panel.findChild<QCheckBox *>(QStringLiteral("goatee"));
        auto *beard = panel.findChild<QCheckBox *>(QStringLiteral("beard"));
        QVERIFY(goatee && goatee->isEnabled() && !goatee->isChecked());
        goatee->click();
        QCOMPARE(doc.undoStack()->count(), 1);
        QVERIFY(doc.style().appearance.goatee);
        beard->click();
        QCOMPARE(doc.undoStack()->count(), 2);
        QVERIFY(!goatee->isEnabled() && goatee->isChecked());
        doc.undoStack()->undo();
        QVERIFY(goatee->isEnabled());
        doc.undoStack()->undo();
        QVERIFY(!goatee->isChecked() && !doc.style().appearance.goatee);
    }

    // The age group drawn is the user's to choose: one step, shown back, undone.
    void ageChoice()
    {
        Document doc;
        fixture::fill(doc);
        AppearancePanel panel(&doc);
        auto *age = panel.findChild<QComboBox *>(QStringLiteral("age"));
        QVERIFY(age);
        QCOMPARE(age->count(), 3);
        QCOMPARE(age->currentData().toInt(), int(doc.style().appearance.age));
        const AgeGroup before = doc.style().appearance.age;
        const AgeGroup chosen = before == AgeGroup::Child ? AgeGroup::Elderly : AgeGroup::Child;
        age->setCurrentIndex(age->findData(int(chosen)));
        Q_EMIT age->activated(age->currentIndex());
        QCOMPARE(doc.undoStack()->count(), 1);
        QCOMPARE(doc.style().appearance.age, chosen);
        doc.undoStack()->undo();
        QCOMPARE(doc.style().appearance.age, before);
        QCOMPARE(age->currentData().toInt(), int(before));
    }

    void disabledWithoutAFace()
    {
        Document doc;
        AppearancePanel panel(&doc);
        QVERIFY(!panel.isEnabled());
        panel.findChild<QCheckBox *>(QStringLiteral("beard"))->click();
        QCOMPARE(doc.undoStack()->count(), 0);
    }
};

TOONFACE_TEST_MAIN(TestAppearancePanel)
#include "tst_appearancepanel.moc"
