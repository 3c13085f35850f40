#pragma once

#include "export/animationexport.h"
#include "export/exportpreset.h"

#include <QDialog>
#include <QFutureWatcher>

#include <atomic>
#include <memory>
#include <optional>

class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QToolButton;

namespace toonface {

class ExportPreview;

// Export Animation…: the format (SMIL SVG, HTML player, MP4, GIF, PNG sequence, WebM, MOV,
// APNG, WebP) with the file name's suffix following it, a preset for stickers and overlays
// (which fixes the format, size and limits), the frames' size, frame rate, framing, background
// (automatic, transparent, a colour or a photo) and the stretch exported, with a still of the
// result over a checkerboard where it is transparent; the export runs in the
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

    // The request the controls describe now (a preset's format, size and limits applied).
    ExportRequest request() const;
    // The preset chosen, if any.
    std::optional<ExportPreset> preset() const;
    // The background chosen; setBackground() selects it as the Background box's choices do.
    ExportBackground background() const;
    void setBackground(const ExportBackground &background);
    // Why the export cannot start as the controls stand (a preset's limit, MP4 asked to be
    // transparent), shown under the summary; empty when it can.
    QString problem() const;
    const ExportPreview *preview() const { return m_preview; }
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
    void presetChanged();
    void backgroundChosen();
    void updatePreview();
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
    QComboBox *m_preset;
    QComboBox *m_background;
    QDoubleSpinBox *m_start;
    QDoubleSpinBox *m_length;
    ExportPreview *m_preview;
    QColor m_colour = Qt::white; // the Background box's colour choice
    QString m_photo; // and its photo
    QLabel *m_summary;
    QProgressBar *m_progress;
    QLabel *m_status;
    QDialogButtonBox *m_buttons;
    QPushButton *m_export = nullptr;
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
