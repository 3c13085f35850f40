#include "window/questions.h"

#include "document/autosaver.h"
#include "document/document.h"
#include "face/averageface.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>

#include <algorithm>

namespace toonface {

namespace {

// The context of this file's strings in the translations.
struct Questions
{
    Q_DECLARE_TR_FUNCTIONS(toonface::Questions)
};

} // namespace

bool askToRestore(QWidget *parent, const RecoveryFile &kept)
{
    const QString name
        = kept.originalPath.isEmpty() ? Questions::tr("an untitled project") : QFileInfo(kept.originalPath).fileName();
    QMessageBox box(QMessageBox::Question, Questions::tr("Restore Unsaved Work"),
        Questions::tr("Toonface did not close properly. Unsaved work on %1 from %2 was kept.")
            .arg(name,
                // The time in 24 hours: Qt 6.4 prints the Taiwanese short format's day period
                // ("Bh:mm") as a letter B.
                QLocale().toString(kept.written.date(), QLocale::ShortFormat) + QLatin1Char(' ')
                    + kept.written.time().toString(QStringLiteral("HH:mm"))),
        QMessageBox::NoButton, parent);
    box.setInformativeText(Questions::tr("Restore it? Discarding deletes the kept copy."));
    QPushButton *restore = box.addButton(Questions::tr("&Restore"), QMessageBox::AcceptRole);
    box.addButton(Questions::tr("&Discard"), QMessageBox::DestructiveRole);
    box.setDefaultButton(restore);
    box.exec();
    return box.clickedButton() == restore;
}

void offerAverageFace(QWidget *parent, Document *document, const QString &reason)
{
    // The detector's reason already says what was missing: say it once, naming the file.
    const QString text = reason.isEmpty() ? Questions::tr("No face was found in %1.").arg(document->displayName())
                                          : Questions::tr("%1: %2").arg(document->displayName(), reason);
    QMessageBox box(QMessageBox::Information, Questions::tr("No Face Found"), text, QMessageBox::NoButton, parent);
    box.setInformativeText(
        Questions::tr("You can place an average face on the photo and drag its points into place by hand."));
    QPushButton *place = box.addButton(Questions::tr("&Place Average Face"), QMessageBox::AcceptRole);
    box.addButton(QMessageBox::Cancel);
    box.setDefaultButton(place);
    box.exec();
    if (box.clickedButton() != place)
        return;
    const QSizeF size = document->canvasSize();
    const double width = 0.4 * std::min(size.width(), size.height());
    QRectF faceBox(0, 0, width, 1.2 * width);
    faceBox.moveCenter(QPointF(size.width() / 2, size.height() / 2));
    document->replaceFace(averageFace(faceBox, document->canvasSize()), false, Questions::tr("Place average face"));
}

void showOutsideFiles(QWidget *parent, const QString &project, const QStringList &files)
{
    auto *box = new QMessageBox(QMessageBox::Information, Questions::tr("Files Outside the Project"),
        Questions::tr("%1 uses files outside its folder. Its sound, photo, video and layers are read from there "
                      "when you play or export it:")
            .arg(QFileInfo(project).fileName()),
        QMessageBox::Ok, parent);
    box->setObjectName(QStringLiteral("outsideFiles"));
    box->setInformativeText(files.join(QLatin1Char('\n')));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

DiskConflict askOverwriteChanged(QWidget *parent, const QString &project)
{
    QMessageBox box(QMessageBox::Warning, Questions::tr("Project Changed on Disk"),
        Questions::tr("%1 was changed by another program since you opened it.").arg(QFileInfo(project).fileName()),
        QMessageBox::NoButton, parent);
    box.setInformativeText(Questions::tr("Overwriting it loses the other program's changes."));
    QPushButton *saveAs = box.addButton(Questions::tr("Save &As…"), QMessageBox::AcceptRole);
    QPushButton *overwrite = box.addButton(Questions::tr("&Overwrite"), QMessageBox::DestructiveRole);
    box.addButton(QMessageBox::Cancel);
    box.setDefaultButton(saveAs);
    box.exec();
    if (box.clickedButton() == saveAs)
        return DiskConflict::SaveAs;
    return box.clickedButton() == overwrite ? DiskConflict::Overwrite : DiskConflict::Cancel;
}

} // namespace toonface
