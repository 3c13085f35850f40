#pragma once

#include "export/animationexport.h"

#include <QDialog>
#include <QFutureWatcher>

#include <atomic>
#include <memory>

class QComboBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QToolButton;

namespace toonface {

// Export Animation…: the format (SMIL SVG, HTML player, MP4, GIF, PNG sequence) with the file
// name's suffix following it, the frames' size, frame rate and framing; the export runs in the
// background (exportAnimation through QtConcurrent) with a progress bar and Cancel, and leaves
// no file behind when cancelled or failed; at the end the dialog offers to show the file in its
// folder.
//
// Takes everything by value (an ExportRequest: the face, style, timeline, mouth shapes, layers
// and sound of the animation, and the initial format, file, size, rate and framing), so it
// depends on no document.
class ExportAnimationDialog : public QDialog
{
    Q_OBJECT

public:
    explicit ExportAnimationDialog(const ExportRequest &base, QWidget *parent = nullptr);
    ~ExportAnimationDialog() override;

    // Shows the dialog modally; returns the path written, or an empty string when nothing was.
    static QString run(QWidget *parent, const ExportRequest &base);

    // The request the controls describe now.
    ExportRequest request() const;
    bool isRunning() const;
    // The path of the last successful export (empty before one) and the folder Show in Folder
    // opens.
    QString exportedPath() const { return m_exported; }
    QString exportedFolder() const { return m_exportedFolder; }
    // The last export's outcome (status Failed with an empty error before any).
    const ExportResult &lastResult() const { return m_result; }

    // Starts the export as the Export button does; false when one is running or the request
    // lacks a file name.
    bool start();
    // Stops a running export (as Cancel does while one runs).
    void cancel();

    void reject() override;

Q_SIGNALS:
    // After each export, with its outcome.
    void finished(const toonface::ExportResult &result);

private:
    void formatChanged();
    void browse();
    void updateSummary();
    void exportFinished();
    void showInFolder();
    void setRunning(bool running);

    ExportRequest m_base;
    QComboBox *m_format;
    QLineEdit *m_path;
    QToolButton *m_browse;
    QComboBox *m_size;
    QSpinBox *m_fps;
    QComboBox *m_framing;
    QLabel *m_summary;
    QProgressBar *m_progress;
    QLabel *m_status;
    QDialogButtonBox *m_buttons;
    QPushButton *m_export;
    QPushButton *m_show;
    QFutureWatcher<ExportResult> m_watcher;
    std::shared_ptr<std::atomic_bool> m_cancel;
    ExportResult m_result;
    QString m_running; // the path being written
    AnimationFormat m_runningFormat = AnimationFormat::Mp4;
    QString m_exported;
    QString m_exportedFolder;
};

} // namespace toonface
