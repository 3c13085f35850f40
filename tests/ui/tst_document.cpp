#include "testmain.h"
#include "uifixture.h"

#include "document/changestylecommand.h"
#include "document/companionfile.h"
#include "document/document.h"
#include "document/loadedfile.h"
#include "document/movepointcommand.h"
#include "io/project.h"

#include <QDir>
#include <QFile>
#include <QLineF>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace toonface;

Q_DECLARE_METATYPE(toonface::ChangeFlags)

namespace {

bool near(QPointF a, QPointF b, double tol = 1e-9)
{
    return QLineF(a, b).length() <= tol;
}

ChangeFlags allChanges(const QSignalSpy &spy)
{
    ChangeFlags all;
    for (const QList<QVariant> &args : spy)
        all |= args.first().value<ChangeFlags>();
    return all;
}

ChangeFlags lastChange(const QSignalSpy &spy)
{
    return spy.isEmpty() ? ChangeFlags() : spy.last().first().value<ChangeFlags>();
}

} // namespace

class TestDocument : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private Q_SLOTS:
    void initTestCase()
    {
        qRegisterMetaType<ChangeFlags>();
        QVERIFY(m_dir.isValid());
    }

    void newDocumentIsEmptyAndUnmodified()
    {
        Document doc;
        QVERIFY(!doc.hasFace());
        QVERIFY(doc.photo().isNull());
        QVERIFY(!doc.isModified());
        QVERIFY(doc.filePath().isEmpty());
        QCOMPARE(doc.displayName(), QStringLiteral("Untitled"));
    }

    void movePointMarksHandPlacedAndUndoes()
    {
        Document doc;
        fixture::fill(doc);
        const int i = pt::idx("8.9");
        const QPointF before = doc.face().point(i);
        QSignalSpy spy(&doc, &Document::changed);

        doc.movePoint(i, before + QPointF(5, -3), true);
        QVERIFY(near(doc.face().point(i), before + QPointF(5, -3)));
        QVERIFY(doc.face().isHandPlaced(i));
        QVERIFY(doc.isModified());
        QVERIFY(allChanges(spy).testFlag(Change::Points));
        QCOMPARE(doc.undoStack()->undoText(), QStringLiteral("Move Upper lip, left peak"));

        spy.clear();
        doc.undoStack()->undo();
        QVERIFY(near(doc.face().point(i), before));
        QVERIFY(!doc.face().isHandPlaced(i));
        QVERIFY(!doc.isModified());
        QVERIFY(allChanges(spy).testFlag(Change::Points));
        QVERIFY(allChanges(spy).testFlag(Change::FileState));

        doc.undoStack()->redo();
        QVERIFY(near(doc.face().point(i), before + QPointF(5, -3)));
        QVERIFY(doc.face().isHandPlaced(i));
    }

    // Another editor writing the project file is noticed before this one overwrites it; this
    // document's own saves are not.
    void changedOnDiskIsNoticed()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("shared.toonface"));
        Document doc;
        fixture::fill(doc);
        QString error;
        QVERIFY2(doc.save(path, &error), qPrintable(error));
        QVERIFY(!doc.changedOnDisk());
        Document other;
        QVERIFY2(other.load(path, &error), qPrintable(error));
        other.movePoint(0, QPointF(51, 61), true);
        QTest::qWait(20); // a later modification time on file systems that keep milliseconds
        QVERIFY2(other.save(path, &error), qPrintable(error));
        QVERIFY(!other.changedOnDisk());
        QVERIFY(doc.changedOnDisk());
        QVERIFY2(doc.save(path, &error), qPrintable(error)); // the user chose to overwrite
        QVERIFY(!doc.changedOnDisk());
    }

    void changeFlagsNameWhatChanged()
    {
        Document doc;
        fixture::fill(doc);
        QSignalSpy spy(&doc, &Document::changed);

        doc.movePoint(0, QPointF(1, 2), false);
        // The first edit also leaves the clean state: a Points change and a FileState change.
        const ChangeFlags all = allChanges(spy);
        QVERIFY(all.testFlag(Change::Points));
        QVERIFY(all.testFlag(Change::FileState));
        QVERIFY(!all.testFlag(Change::Style));
        QVERIFY(!all.testFlag(Change::Photo));

        spy.clear();
        doc.changeStyle(Style::preset(QStringLiteral("normal")), QStringLiteral("style"));
        QCOMPARE(spy.size(), 1);
        QCOMPARE(lastChange(spy), ChangeFlags(Change::Style));
    }

    void oneDragIsOneUndoStep()
    {
        Document doc;
        fixture::fill(doc);
        const int i = pt::idx("3.6");
        const QPointF start = doc.face().point(i);

        for (int step = 1; step <= 10; ++step)
            doc.movePoint(i, start + QPointF(step, step), false);
        doc.movePoint(i, start + QPointF(12, 11), true);
        QCOMPARE(doc.undoStack()->count(), 1);
        QVERIFY(near(doc.face().point(i), start + QPointF(12, 11)));

        // A second drag of the same point is a second step.
        doc.movePoint(i, start + QPointF(20, 20), false);
        doc.movePoint(i, start + QPointF(21, 20), true);
        QCOMPARE(doc.undoStack()->count(), 2);

        doc.undoStack()->undo();
        QVERIFY(near(doc.face().point(i), start + QPointF(12, 11)));
        doc.undoStack()->undo();
        QVERIFY(near(doc.face().point(i), start));
        QVERIFY(!doc.face().isHandPlaced(i));
    }

    void dragsOfDifferentPointsDoNotMerge()
    {
        Document doc;
        fixture::fill(doc);
        doc.movePoint(pt::idx("8.4"), QPointF(150, 330), false);
        doc.movePoint(pt::idx("8.3"), QPointF(250, 330), false);
        QCOMPARE(doc.undoStack()->count(), 2);
    }

    void replaceFaceKeepsHandPlacedPoints_data()
    {
        QTest::addColumn<bool>("keepHandPlaced");
        QTest::newRow("keep my points") << true;
        QTest::newRow("replace all") << false;
    }

    void replaceFaceKeepsHandPlacedPoints()
    {
        QFETCH(bool, keepHandPlaced);
        Document doc;
        fixture::fill(doc);
        const int moved = pt::idx("2.1");
        const QPointF placed = doc.face().point(moved) + QPointF(0, 15);
        doc.movePoint(moved, placed, true);
        const FaceModel beforeDetection = doc.face();

        // A "detection" that puts every point somewhere else.
        const FaceModel detected = averageFace(QRectF(120, 160, 180, 220), fixture::kPhotoSize);
        doc.replaceFace(detected, keepHandPlaced, QStringLiteral("Re-detect"));
        QCOMPARE(doc.undoStack()->count(), 2);

        for (int i = 0; i < kPointCount; ++i) {
            if (i == moved && keepHandPlaced) {
                QVERIFY(near(doc.face().point(i), placed));
                QVERIFY(doc.face().isHandPlaced(i));
            } else {
                QVERIFY2(near(doc.face().point(i), detected.point(i)), qPrintable(pointId(i)));
                QVERIFY(!doc.face().isHandPlaced(i));
            }
        }

        doc.undoStack()->undo();
        QCOMPARE(doc.face(), beforeDetection);
    }

    void replaceFaceOnEmptyDocumentIsUndoable()
    {
        Document doc;
        Project project;
        project.face = FaceModel(fixture::kPhotoSize);
        doc.reset(project, fixture::photo(), {}, false);
        QVERIFY(!doc.hasFace());

        doc.replaceFace(fixture::face(), true, QStringLiteral("Detect face"));
        QVERIFY(doc.hasFace());
        QCOMPARE(doc.face(), fixture::face());
        QVERIFY(doc.isModified());

        doc.undoStack()->undo();
        QVERIFY(!doc.hasFace());
        QVERIFY(!doc.isModified());
    }

    void changeStyleIsUndoable()
    {
        Document doc;
        fixture::fill(doc);
        const Style before = doc.style();
        Style after = before;
        after.name = QStringLiteral("other");
        after.cornerCutDepth = before.cornerCutDepth + 1;
        doc.changeStyle(after, QStringLiteral("Style"));
        QCOMPARE(doc.style(), after);
        doc.undoStack()->undo();
        QCOMPARE(doc.style(), before);
    }

    void changeAnimationIsOneUndoStepAndRestoresExactly()
    {
        Document doc;
        fixture::fill(doc);
        QSignalSpy spy(&doc, &Document::changed);
        const Animation before = doc.animation();

        Animation after = before;
        after.timeline.addMouthKey(MouthKey {0.5, MouthShape::A, 1.0, 0.2});
        after.timeline.addEmotionClip(EmotionClip {0.2, 1.4, Emotion::Sad, 0.7, 0.1, 0.2});
        LipsyncSyllable ma {QStringLiteral("妈"), QStringLiteral("ma"), 1, 0.5, 0.7, 1.0, {}};
        ma.shapes = {{MouthShape::M, 0.5}, {MouthShape::A, 0.5 + 0.8095 * 0.2}};
        after.syllables = {ma};
        AudioClip clip {m_dir.filePath(QStringLiteral("ma.wav")), 0.4, 0.5};
        clip.script = QStringLiteral("妈");
        clip.language = QStringLiteral("cmn");
        after.timeline.setAudioClips({clip});
        doc.changeAnimation(after, QStringLiteral("Lip Sync"));
        QCOMPARE(doc.animation(), after);
        QCOMPARE(doc.timeline(), after.timeline);
        QCOMPARE(doc.syllables(), after.syllables);
        QVERIFY(allChanges(spy).testFlag(Change::Animation));
        QVERIFY(doc.isModified());
        QCOMPARE(doc.undoStack()->undoText(), QStringLiteral("Lip Sync"));

        doc.undoStack()->undo();
        QCOMPARE(doc.animation(), before);
        QVERIFY(!doc.isModified());
        doc.undoStack()->redo();
        QCOMPARE(doc.animation(), after);

        // The same value again is no step.
        doc.changeAnimation(after, QStringLiteral("Nothing"));
        QCOMPARE(doc.undoStack()->count(), 1);
    }

    void animationDragIsOneUndoStep()
    {
        Document doc;
        fixture::fill(doc);
        Animation a = doc.animation();
        a.timeline.addMouthKey(MouthKey {1.0, MouthShape::O, 1.0, 0.3});
        doc.changeAnimation(a, QStringLiteral("Insert"));
        const Animation beforeDrag = doc.animation();

        constexpr int kDrag = 7;
        for (int step = 1; step <= 5; ++step) {
            Animation moved = beforeDrag;
            QVector<MouthKey> keys = moved.timeline.mouthKeys();
            keys[0].time = 1.0 + 0.01 * step;
            moved.timeline.setMouthKeys(keys);
            doc.changeAnimation(moved, QStringLiteral("Move Key"), kDrag, step == 5);
        }
        QCOMPARE(doc.undoStack()->count(), 2);
        QCOMPARE(doc.timeline().mouthKeys().constFirst().time, 1.05);
        // A later drag with the same id is a step of its own: the first one was committed.
        Animation again = doc.animation();
        QVector<MouthKey> keys = again.timeline.mouthKeys();
        keys[0].time = 1.2;
        again.timeline.setMouthKeys(keys);
        doc.changeAnimation(again, QStringLiteral("Move Key"), kDrag, false);
        doc.changeAnimation(again, QStringLiteral("Move Key"), kDrag, true);
        QCOMPARE(doc.undoStack()->count(), 3);

        doc.undoStack()->undo();
        QCOMPARE(doc.timeline().mouthKeys().constFirst().time, 1.05);
        doc.undoStack()->undo();
        QCOMPARE(doc.animation(), beforeDrag);
    }

    void changeMouthShapesIsUndoable()
    {
        Document doc;
        fixture::fill(doc);
        QSignalSpy spy(&doc, &Document::changed);
        const MouthShapeSet before = doc.mouthShapes();
        MouthShapeSet after = before;
        MouthShapePreset a = after.preset(MouthShape::A);
        a.offsets[1].dy.mns = 0.95;
        after.setPreset(MouthShape::A, a);
        doc.changeMouthShapes(after, QStringLiteral("Edit Mouth Shape a"));
        QCOMPARE(doc.mouthShapes(), after);
        QVERIFY(allChanges(spy).testFlag(Change::MouthShapes));
        doc.undoStack()->undo();
        QCOMPARE(doc.mouthShapes(), before);
    }

    void animationSavesAndLoads()
    {
        const QString photoPath = m_dir.filePath(QStringLiteral("talker.png"));
        QVERIFY(fixture::photo().save(photoPath));
        Document doc;
        fixture::fill(doc, photoPath);
        Animation a = doc.animation();
        a.timeline.addMouthKey(MouthKey {0.25, MouthShape::U, 0.8, 0.15});
        a.timeline.generateBlinks(7, 4.0);
        a.timeline.addNod(1.0, 2.0);
        AudioClip clip {m_dir.filePath(QStringLiteral("sound/voice.wav")), 0.5, 3.5};
        clip.script = QStringLiteral("我");
        clip.language = QStringLiteral("cmn");
        a.timeline.setAudioClips({clip});
        LipsyncSyllable wo {QStringLiteral("我"), QStringLiteral("wo"), 3, 0.25, 0.4, 0.75, {}};
        wo.shapes = {{MouthShape::U, 0.25}, {MouthShape::O, 0.25 + 0.8095 * 0.15}};
        a.syllables = {wo};
        doc.changeAnimation(a, QStringLiteral("Animate"));

        const QString projectPath = m_dir.filePath(QStringLiteral("talker.toonface"));
        QString error;
        QVERIFY2(doc.save(projectPath, &error), qPrintable(error));
        Document loaded;
        QVERIFY2(loaded.load(projectPath, &error), qPrintable(error));
        QCOMPARE(loaded.animation(), doc.animation());
        // The sound is referred to relative to the project, so the pair can move together.
        QFile file(projectPath);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray text = file.readAll();
        QVERIFY(text.contains("\"sound/voice.wav\""));
        QVERIFY(!text.contains(m_dir.path().toUtf8()));
    }

    void saveLoadRoundTrip()
    {
        const QString photoPath = m_dir.filePath(QStringLiteral("portrait.png"));
        QVERIFY(fixture::photo().save(photoPath));
        Document doc;
        fixture::fill(doc, photoPath);
        doc.movePoint(pt::idx("8.2"), QPointF(205, 345), true);
        QVERIFY(doc.isModified());
        QCOMPARE(doc.displayName(), QStringLiteral("portrait.png"));

        const QString projectPath = m_dir.filePath(QStringLiteral("round.toonface"));
        QSignalSpy spy(&doc, &Document::changed);
        QString error;
        QVERIFY2(doc.save(projectPath, &error), qPrintable(error));
        QVERIFY(!doc.isModified());
        QCOMPARE(doc.filePath(), projectPath);
        QCOMPARE(doc.displayName(), QStringLiteral("round.toonface"));
        QVERIFY(lastChange(spy).testFlag(Change::FileState));

        Document loaded;
        QString photoWarning;
        QVERIFY2(loaded.load(projectPath, &error, &photoWarning), qPrintable(error));
        QVERIFY2(photoWarning.isEmpty(), qPrintable(photoWarning));
        Project expected = doc.project();
        QVERIFY(loaded.style() == expected.style);
        expected.style = loaded.style();
        QCOMPARE(loaded.project(), expected);
        QVERIFY(loaded.face().isHandPlaced(pt::idx("8.2")));
        QCOMPARE(loaded.photo().size(), fixture::kPhotoSize);
        QVERIFY(loaded.hasFace());
        QVERIFY(!loaded.isModified());
        QCOMPARE(loaded.undoStack()->count(), 0);

        // Saving again to the same path after an edit clears the modified flag again.
        loaded.movePoint(0, QPointF(10, 10), true);
        QVERIFY(loaded.isModified());
        QVERIFY(loaded.save(projectPath, &error));
        QVERIFY(!loaded.isModified());
    }

    void markModifiedWithoutHistory()
    {
        Document doc;
        fixture::fill(doc);
        QVERIFY(!doc.isModified());
        doc.markModified();
        QVERIFY(doc.isModified());
        QCOMPARE(doc.undoStack()->count(), 0);
    }

    void projectWithMissingPhotoStillOpens()
    {
        const QString photoPath = m_dir.filePath(QStringLiteral("gone.png"));
        QVERIFY(fixture::photo().save(photoPath));
        Document doc;
        fixture::fill(doc, photoPath);
        const QString projectPath = m_dir.filePath(QStringLiteral("gone.toonface"));
        QString error;
        QVERIFY2(doc.save(projectPath, &error), qPrintable(error));
        QVERIFY(QFile::remove(photoPath));

        Document loaded;
        QString photoWarning;
        QVERIFY2(loaded.load(projectPath, &error, &photoWarning), qPrintable(error));
        QVERIFY(loaded.photo().isNull());
        QVERIFY2(photoWarning.contains(QStringLiteral("gone.png")), qPrintable(photoWarning));
        QCOMPARE(loaded.face(), doc.face());
        QCOMPARE(loaded.canvasSize(), fixture::kPhotoSize);
    }

    void loadFileErrorsNameTheFile_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QByteArray>("content");
        QTest::newRow("missing photo") << QStringLiteral("absent.jpg") << QByteArray();
        QTest::newRow("not an image") << QStringLiteral("notes.png") << QByteArray("these are not pixels");
        QTest::newRow("broken project") << QStringLiteral("broken.toonface") << QByteArray("{\"format\": 3");
        QTest::newRow("wrong project field") << QStringLiteral(
            "field.toonface") << QByteArray("{\"format\": \"toonface.project\", \"version\": 1, \"face\": 12}");
    }

    void loadFileErrorsNameTheFile()
    {
        QFETCH(QString, name);
        QFETCH(QByteArray, content);
        const QString path = m_dir.filePath(name);
        if (!content.isEmpty()) {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(content);
        }
        const LoadedFile file = loadFile(path);
        QVERIFY(!file.ok());
        QVERIFY2(file.error.contains(name), qPrintable(file.error));

        Document doc;
        fixture::fill(doc);
        QString error;
        QVERIFY(!doc.load(path, &error));
        QVERIFY2(error.contains(name), qPrintable(error));
        QVERIFY(doc.hasFace()); // a failed load leaves the document alone
    }

    void loadPhotoStartsUntitledWithoutFace()
    {
        const QString photoPath = m_dir.filePath(QStringLiteral("fresh.png"));
        QVERIFY(fixture::photo().save(photoPath));
        Document doc;
        QString error;
        QVERIFY2(doc.load(photoPath, &error), qPrintable(error));
        QVERIFY(!doc.hasFace());
        QVERIFY(doc.filePath().isEmpty());
        QCOMPARE(doc.project().photoPath, photoPath);
        QCOMPARE(doc.photo().size(), fixture::kPhotoSize);
        QCOMPARE(doc.displayName(), QStringLiteral("fresh.png"));
        QVERIFY(!doc.isModified());
    }

    // An export is offered beside the project, else beside its photo; where that folder cannot
    // be written to (here: a card taken out since the photo was opened) in the user's folder.
    void exportsAreOfferedWhereTheyCanBeWritten()
    {
        QTemporaryDir card, documents;
        const QString photoPath = card.filePath(QStringLiteral("hopper.png"));
        QVERIFY(fixture::photo().save(photoPath));
        Document doc;
        QString error;
        QVERIFY2(doc.load(photoPath, &error), qPrintable(error));
        QCOMPARE(exportFile(doc, QStringLiteral("mp4"), QStringLiteral("animation"), documents.path()),
            card.filePath(QStringLiteral("hopper.mp4")));
        QVERIFY(card.remove());
        QCOMPARE(exportFile(doc, QStringLiteral("mp4"), QStringLiteral("animation"), documents.path()),
            QDir(documents.path()).filePath(QStringLiteral("hopper.mp4")));
        QCOMPARE(companionFile(doc, QStringLiteral("speech"), QStringLiteral("wav"), documents.path()),
            QDir(documents.path()).filePath(QStringLiteral("hopper-speech.wav")));

        // Saved as a project: beside the project.
        const QString otherPhoto = m_dir.filePath(QStringLiteral("other.png"));
        QVERIFY(fixture::photo().save(otherPhoto));
        Document saved;
        QVERIFY2(saved.load(otherPhoto, &error), qPrintable(error));
        QVERIFY2(saved.save(m_dir.filePath(QStringLiteral("talk.toonface")), &error), qPrintable(error));
        QCOMPARE(exportFile(saved, QStringLiteral("epub"), QStringLiteral("book"), documents.path()),
            m_dir.filePath(QStringLiteral("talk.epub")));
        // Neither: the untitled name in the user's folder.
        QCOMPARE(exportFile(Document(), QStringLiteral("mp4"), QStringLiteral("animation"), documents.path()),
            QDir(documents.path()).filePath(QStringLiteral("animation.mp4")));
    }
};

TOONFACE_TEST_MAIN(TestDocument)
#include "tst_document.moc"
