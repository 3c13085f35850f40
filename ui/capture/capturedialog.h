#pragma once

#include <QDialog>
#include <QFutureWatcher>
#include <QImage>
#include <QRectF>
#include <QString>

#include <atomic>

class QComboBox;
class QLabel;
class QPushButton;
class QTimer;
class QVideoFrame;

namespace toonface {

class CameraFeed;
class Document;
class FramePane;

// File ▸ Capture from Camera…: a camera picker (by description, remembered in the settings),
// the live view with the face the detector finds boxed, and a countdown snapshot that becomes
// the neutral photo — saved as a PNG beside the project (else in the user's Pictures folder)
// and handed on through photoTaken() for the editor to open.
//
// With no camera the dialog says so and offers nothing to take (no QCamera is made, so Qt's
// test pattern never shows); a camera unplugged while it runs stops with a message.
class CaptureDialog : public QDialog
{
    Q_OBJECT

public:
    explicit CaptureDialog(Document *document, QWidget *parent = nullptr);
    ~CaptureDialog() override;

    // Runs the dialog; the PNG written, or empty when cancelled.
    static QString run(QWidget *parent, Document *document);

    // The newest camera picture (the view shows it; the snapshot takes it).
    void showFrame(const QImage &image);
    // Starts the countdown (`seconds` 0: at once).
    void takePhoto(int seconds = 3);
    QString savedPath() const { return m_saved; }
    QString messageText() const;
    bool hasCamera() const;
    FramePane *view() const { return m_view; }
    QPushButton *takeButton() const { return m_take; }
    QRectF faceBox() const { return m_box; }

Q_SIGNALS:
    // The snapshot, written to `path`.
    void photoTaken(const QString &path, const QImage &image);

private:
    void fillCameras();
    void startCamera();
    void onVideoFrame(const QVideoFrame &frame);
    void tick();
    void snapshot();
    void scanForFace();
    void setMessage(const QString &text);

    Document *m_document;
    CameraFeed *m_feed;
    QComboBox *m_cameras;
    FramePane *m_view;
    QLabel *m_message;
    QPushButton *m_take;
    QTimer *m_countdown;
    int m_remaining = 0;
    QImage m_latest;
    QRectF m_box;
    QFutureWatcher<QRectF> m_scan;
    QString m_saved;
    std::atomic_bool m_framePending {false};
};

} // namespace toonface
