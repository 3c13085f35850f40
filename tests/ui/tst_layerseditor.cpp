// The user's SVG layers in the appearance dock (appearance/layerseditor.h): each change one undo
// step, drawn in the live preview, a bad file refused by name.

#include "appearance/appearancepanel.h"
#include "appearance/layerseditor.h"
#include "testmain.h"
#include "uifixture.h"
#include "views/previewview.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QListWidget>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace toonface;

namespace {

QString writeFile(const QTemporaryDir &dir, const QString &name, const QByteArray &content)
{
    const QString path = dir.filePath(name);
    QFile f(path);
    if (f.open(QIODevice::WriteOnly))
        f.write(content);
    return path;
}

QByteArray drawing(const char *colour)
{
    return QByteArray("<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 10 10\"><rect id=\"r\" width=\"10\" "
                      "height=\"10\" fill=\"")
        + colour + "\"/></svg>";
}

} // namespace

class TestLayersEditor : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void eachChangeIsOneStep()
    {
        QTemporaryDir dir;
        Document doc;
        fixture::fill(doc);
        AppearancePanel panel(&doc); // the editor as the dock holds it
        auto *editor = panel.findChild<LayersEditor *>();
        QVERIFY(editor);
        auto *list = panel.findChild<QListWidget *>(QStringLiteral("layers"));
        QUndoStack *undo = doc.undoStack();

        QString error;
        QVERIFY2(editor->addFile(writeFile(dir, QStringLiteral("shirt.svg"), drawing("#112233")), &error),
            qPrintable(error));
        QVERIFY2(editor->addFile(writeFile(dir, QStringLiteral("badge.svg"), drawing("#ffcc00")), &error),
            qPrintable(error));
        QCOMPARE(undo->count(), 2);
        QCOMPARE(list->count(), 2);
        QCOMPARE(doc.style().layers[0].name, QStringLiteral("shirt.svg"));
        QCOMPARE(editor->currentLayer(), 1); // the one just added

        // Reorder: the badge goes first.
        panel.findChild<QPushButton *>(QStringLiteral("layerUp"))->click();
        QCOMPARE(undo->count(), 3);
        QCOMPARE(doc.style().layers[0].name, QStringLiteral("badge.svg"));
        QCOMPARE(editor->currentLayer(), 0);

        // Place it: each field one step.
        auto *x = panel.findChild<QDoubleSpinBox *>(QStringLiteral("layerX"));
        x->setValue(0.75);
        Q_EMIT x->editingFinished();
        auto *width = panel.findChild<QDoubleSpinBox *>(QStringLiteral("layerWidth"));
        width->setValue(0.5);
        Q_EMIT width->editingFinished();
        QCOMPARE(undo->count(), 5);
        QCOMPARE(doc.style().layers[0].offset.x(), 0.75);
        QCOMPARE(doc.style().layers[0].width, 0.5);

        // Behind the face, then hidden.
        panel.findChild<QCheckBox *>(QStringLiteral("layerFront"))->click();
        QCOMPARE(undo->count(), 6);
        QVERIFY(!doc.style().layers[0].front);
        QVERIFY(list->item(0)->text().contains(QStringLiteral("behind")));
        list->item(0)->setCheckState(Qt::Unchecked);
        QCOMPARE(undo->count(), 7);
        QVERIFY(!doc.style().layers[0].visible);
        // Made to move with the head: one step.
        QVERIFY(!doc.style().layers[0].followsHead);
        panel.findChild<QCheckBox *>(QStringLiteral("layerFollowsHead"))->click();
        QCOMPARE(undo->count(), 8);
        QVERIFY(doc.style().layers[0].followsHead);

        // Remove the shirt.
        editor->setCurrentLayer(1);
        panel.findChild<QPushButton *>(QStringLiteral("removeLayer"))->click();
        QCOMPARE(undo->count(), 9);
        QCOMPARE(doc.style().layers.size(), 1);

        // Undo walks back through every step to no layers.
        undo->undo();
        QCOMPARE(doc.style().layers.size(), 2);
        QCOMPARE(list->count(), 2);
        while (undo->canUndo())
            undo->undo();
        QVERIFY(doc.style().layers.isEmpty());
        QCOMPARE(list->count(), 0);
        QVERIFY(!panel.findChild<QPushButton *>(QStringLiteral("removeLayer"))->isEnabled());
    }

    void badFileNamedNothingChanged()
    {
        QTemporaryDir dir;
        Document doc;
        fixture::fill(doc);
        LayersEditor editor(&doc);
        const QString bad = writeFile(dir, QStringLiteral("scarf.svg"), "<svg><g></svg>");
        QString error;
        QVERIFY(!editor.addFile(bad, &error));
        QVERIFY2(error.contains(bad) && error.contains(QStringLiteral("not a valid SVG")), qPrintable(error));
        QVERIFY(!editor.addFile(dir.filePath(QStringLiteral("gone.svg")), &error));
        QVERIFY2(error.contains(QStringLiteral("gone.svg")), qPrintable(error));
        QCOMPARE(doc.undoStack()->count(), 0);
        QVERIFY(doc.style().layers.isEmpty());
    }

    // The live preview draws the layers as the exports do (both are SvgFace::svg()).
    void drawnInThePreview()
    {
        QTemporaryDir dir;
        Document doc;
        fixture::fill(doc);
        PreviewView preview(&doc);
        preview.resize(300, 300);
        LayersEditor editor(&doc);
        QString error;
        QVERIFY(editor.addFile(writeFile(dir, QStringLiteral("badge.svg"), drawing("#00ff00")), &error));
        QVERIFY(preview.svg().contains("style-layer-1-r"));
        // In front of the face's centre, 1 ES0 wide: the middle of the preview turns green.
        const QImage image = preview.image();
        const QColor middle = image.pixelColor(image.width() / 2, image.height() / 2);
        QVERIFY2(middle.green() > 230 && middle.red() < 30, qPrintable(middle.name()));
        doc.undoStack()->undo();
        QVERIFY(!preview.svg().contains("style-layer-1"));
    }
};

TOONFACE_TEST_MAIN(TestLayersEditor)
#include "tst_layerseditor.moc"
