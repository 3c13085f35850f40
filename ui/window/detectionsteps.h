#pragma once

#include <QImage>
#include <QMap>
#include <QObject>
#include <QString>
#include <QStringList>

namespace toonface {

// The intermediate images of the last detection of the open photo (DetectionResult::
// debugImages, by file stem: "classic-b1", "detect-landmarks", "detect-points-crop", ...),
// for showing the detection's steps over the photo. They are not part of the Document: not
// saved, not undoable; they belong to the photo they came from and are cleared when the
// photo changes or detection runs again.
//
// An image whose name ends in "-crop" is a close-up of part of the photo; every other image
// shows the whole photo's frame, possibly at a lower resolution, and is drawn stretched over
// the photo. GUI thread only.
class DetectionSteps : public QObject
{
    Q_OBJECT

public:
    explicit DetectionSteps(QObject *parent = nullptr);

    void setImages(const QMap<QString, QImage> &images);
    void clear();

    bool isEmpty() const { return m_images.isEmpty(); }
    // In the order of the pipeline for known names, then the others alphabetically.
    QStringList names() const;
    QImage image(const QString &name) const { return m_images.value(name); }

    static bool isCloseUp(const QString &name);
    // A name for the user, translated: known names get the thesis' words ("B1 – dark regions
    // (1st level)"), others a readable form of the file stem.
    static QString displayName(const QString &name);

Q_SIGNALS:
    void changed();

private:
    QMap<QString, QImage> m_images;
};

} // namespace toonface
