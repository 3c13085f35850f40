#include "dialogs/exportanimationdialog.h"

#include <QComboBox>
#include <QDesktopServices>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QProgressBar>
#include <QPromise>
#include <QPushButton>
#include <QSpinBox>
#include <QStyle>
#include <QToolButton>
#include <QUrl>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include <cmath>

namespace toonface {

namespace {

constexpr int kProgressSteps = 1000;
constexpr int kSizes[] = {360, 480, 720, 1080, 1440, 1920};
const QString kFramesSuffix = QStringLiteral("-frames");

QString formatName(AnimationFormat format)
{
    switch (format) {
    case AnimationFormat::SmilSvg: return ExportAnimationDialog::tr("SVG animation (SMIL)");
    case AnimationFormat::HtmlPlayer: return ExportAnimationDialog::tr("HTML player");
    case AnimationFormat::Mp4: return ExportAnimationDialog::tr("MP4 video");
    case AnimationFormat::Gif: return ExportAnimationDialog::tr("Animated GIF");
    case AnimationFormat::PngSequence: return ExportAnimationDialog::tr("PNG sequence (a folder of frames)");
    }
    return {};
}

QString fileFilter(AnimationFormat format)
{
    switch (format) {
    case AnimationFormat::SmilSvg: return ExportAnimationDialog::tr("SVG animation (*.svg)");
    case AnimationFormat::HtmlPlayer: return ExportAnimationDialog::tr("HTML page (*.html *.htm)");
    case AnimationFormat::Mp4: return ExportAnimationDialog::tr("MP4 video (*.mp4)");
    case AnimationFormat::Gif: return ExportAnimationDialog::tr("Animated GIF (*.gif)");
    case AnimationFormat::PngSequence: break;
    }
    return ExportAnimationDialog::tr("Folder for the frames (*)");
}

// `path` renamed for `format`: the suffix replaced ("talk.mp4" -> "talk.svg"), or for a PNG
// sequence a folder named after the file ("talk.mp4" -> "talk-frames/") and back.
QString pathForFormat(const QString &path, AnimationFormat format)
{
    QString p = path.trimmed();
    if (p.isEmpty())
        return p;
    const bool wasFolder = p.endsWith(QLatin1Char('/')) || p.endsWith(QDir::separator());
    while (p.size() > 1 && (p.endsWith(QLatin1Char('/')) || p.endsWith(QDir::separator())))
        p.chop(1);
    const qsizetype slash = std::max(p.lastIndexOf(QLatin1Char('/')), p.lastIndexOf(QDir::separator()));
    const QString dir = p.left(slash + 1);
    QString base = p.mid(slash + 1);
    if (wasFolder) {
        if (base.endsWith(kFramesSuffix) && base.size() > kFramesSuffix.size())
            base.chop(kFramesSuffix.size());
    } else if (animationFormatForPath(base)) {
        base = QFileInfo(base).completeBaseName();
    }
    if (format == AnimationFormat::PngSequence)
        return dir + base + kFramesSuffix + QLatin1Char('/');
    return dir + base + QLatin1Char('.') + animationFormatSuffix(format);
}

// The folder to show for an exported path: the file's, or a PNG sequence's own.
QString folderOf(const QString &path, AnimationFormat format)
{
    const QFileInfo info(QDir::cleanPath(path));
    return format == AnimationFormat::PngSequence ? info.absoluteFilePath() : info.absolutePath();
}

} // namespace

ExportAnimationDialog::ExportAnimationDialog(const ExportRequest &base, QWidget *parent)
    : QDialog(parent)
    , m_base(base)
    , m_format(new QComboBox)
    , m_path(new QLineEdit)
    , m_browse(new QToolButton)
    , m_size(new QComboBox)
    , m_fps(new QSpinBox)
    , m_framing(new QComboBox)
    , m_summary(new QLabel)
    , m_progress(new QProgressBar)
    , m_status(new QLabel)
    , m_buttons(new QDialogButtonBox)
{
    setWindowTitle(tr("Export Animation"));
    setObjectName(QStringLiteral("exportAnimationDialog"));

    m_format->setObjectName(QStringLiteral("format"));
    for (AnimationFormat format : kAllAnimationFormats)
        m_format->addItem(formatName(format), int(format));
    m_format->setCurrentIndex(m_format->findData(int(base.format)));

    m_path->setObjectName(QStringLiteral("path"));
    m_path->setClearButtonEnabled(true);
    m_path->setMinimumWidth(fontMetrics().averageCharWidth() * 48);
    QString path = base.outputPath;
    if (path.isEmpty())
        path = QDir::home().filePath(QStringLiteral("animation"));
    m_path->setText(pathForFormat(path, base.format));
    m_browse->setObjectName(QStringLiteral("browse"));
    m_browse->setText(tr("Browse…"));
    m_browse->setIcon(style()->standardIcon(QStyle::SP_DirOpenIcon));
    m_browse->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_browse->setToolTip(tr("Choose where to save the animation"));
    auto *pathRow = new QHBoxLayout;
    pathRow->addWidget(m_path, 1);
    pathRow->addWidget(m_browse);

    m_size->setObjectName(QStringLiteral("size"));
    m_size->addItem(tr("Automatic"), 0);
    for (int side : kSizes)
        m_size->addItem(tr("%1 px").arg(side), side);
    if (base.size > 0 && m_size->findData(base.size) < 0)
        m_size->addItem(tr("%1 px").arg(base.size), base.size);
    m_size->setCurrentIndex(std::max(0, m_size->findData(base.size)));
    m_size->setToolTip(tr("The longer side of the video frames; the drawing is vector, so any size is sharp"));

    m_fps->setObjectName(QStringLiteral("fps"));
    m_fps->setRange(1, 120);
    m_fps->setSuffix(tr(" fps"));
    m_fps->setValue(int(std::lround(base.fps > 0 ? base.fps : base.timeline.frameRate())));

    m_framing->setObjectName(QStringLiteral("framing"));
    m_framing->addItem(tr("The head"), int(ExportFraming::Head));
    m_framing->addItem(tr("The whole photo"), int(ExportFraming::Photo));
    m_framing->setCurrentIndex(m_framing->findData(int(base.framing)));

    m_summary->setObjectName(QStringLiteral("summary"));
    m_summary->setWordWrap(true);
    m_summary->setForegroundRole(QPalette::PlaceholderText);

    auto *form = new QFormLayout;
    form->addRow(tr("&Format:"), m_format);
    auto *pathLabel = new QLabel(tr("&Save to:"));
    pathLabel->setBuddy(m_path);
    form->addRow(pathLabel, pathRow);
    form->addRow(tr("Frame si&ze:"), m_size);
    form->addRow(tr("Frame &rate:"), m_fps);
    form->addRow(tr("Fr&aming:"), m_framing);
    form->addRow(QString(), m_summary);

    m_progress->setObjectName(QStringLiteral("progress"));
    m_progress->setRange(0, kProgressSteps);
    m_progress->setValue(0);
    m_progress->setTextVisible(true);
    m_status->setObjectName(QStringLiteral("status"));
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);

    m_export = m_buttons->addButton(tr("&Export"), QDialogButtonBox::AcceptRole);
    m_export->setObjectName(QStringLiteral("export"));
    m_export->setIcon(style()->standardIcon(QStyle::SP_DialogSaveButton));
    m_export->setDefault(true);
    m_show = m_buttons->addButton(tr("&Show in Folder"), QDialogButtonBox::ActionRole);
    m_show->setObjectName(QStringLiteral("showInFolder"));
    m_show->setIcon(style()->standardIcon(QStyle::SP_DirIcon));
    m_show->setVisible(false);
    QPushButton *close = m_buttons->addButton(QDialogButtonBox::Close);
    close->setObjectName(QStringLiteral("close"));

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addSpacing(6);
    layout->addWidget(m_progress);
    layout->addWidget(m_status);
    layout->addStretch(1);
    layout->addWidget(m_buttons);

    connect(m_format, &QComboBox::currentIndexChanged, this, &ExportAnimationDialog::formatChanged);
    connect(m_browse, &QToolButton::clicked, this, &ExportAnimationDialog::browse);
    connect(m_path, &QLineEdit::textChanged, this, &ExportAnimationDialog::updateSummary);
    connect(m_size, &QComboBox::currentIndexChanged, this, &ExportAnimationDialog::updateSummary);
    connect(m_fps, &QSpinBox::valueChanged, this, &ExportAnimationDialog::updateSummary);
    connect(m_framing, &QComboBox::currentIndexChanged, this, &ExportAnimationDialog::updateSummary);
    connect(m_export, &QPushButton::clicked, this, [this] {
        const QString target = QDir::cleanPath(m_path->text().trimmed());
        const QFileInfo info(target);
        const bool replaces
            = info.exists() && (request().format != AnimationFormat::PngSequence || !QDir(target).isEmpty());
        if (replaces
            && QMessageBox::question(this, tr("Export Animation"),
                   tr("%1 already exists. Replace it?").arg(QDir::toNativeSeparators(target)),
                   QMessageBox::Yes | QMessageBox::No, QMessageBox::No)
                != QMessageBox::Yes)
            return;
        start();
    });
    connect(m_show, &QPushButton::clicked, this, &ExportAnimationDialog::showInFolder);
    connect(close, &QPushButton::clicked, this, &ExportAnimationDialog::reject);
    connect(&m_watcher, &QFutureWatcher<ExportResult>::progressValueChanged, m_progress, &QProgressBar::setValue);
    connect(&m_watcher, &QFutureWatcher<ExportResult>::finished, this, &ExportAnimationDialog::exportFinished);

    formatChanged();
}

ExportAnimationDialog::~ExportAnimationDialog()
{
    if (isRunning()) {
        m_cancel->store(true);
        m_watcher.waitForFinished();
    }
}

QString ExportAnimationDialog::run(QWidget *parent, const ExportRequest &base)
{
    ExportAnimationDialog dialog(base, parent);
    dialog.exec();
    return dialog.exportedPath();
}

ExportRequest ExportAnimationDialog::request() const
{
    ExportRequest r = m_base;
    r.format = AnimationFormat(m_format->currentData().toInt());
    r.outputPath = m_path->text().trimmed();
    r.size = m_size->currentData().toInt();
    r.fps = m_fps->value();
    r.framing = ExportFraming(m_framing->currentData().toInt());
    return r;
}

bool ExportAnimationDialog::isRunning() const
{
    return !m_running.isEmpty();
}

bool ExportAnimationDialog::start()
{
    const ExportRequest r = request();
    if (isRunning() || r.outputPath.isEmpty())
        return false;
    m_cancel = std::make_shared<std::atomic_bool>(false);
    m_running = r.outputPath;
    m_runningFormat = r.format;
    m_progress->setValue(0);
    m_status->setText(tr("Exporting to %1…").arg(QDir::toNativeSeparators(r.outputPath)));
    m_show->setVisible(false);
    setRunning(true);
    const std::shared_ptr<std::atomic_bool> cancel = m_cancel;
    m_watcher.setFuture(QtConcurrent::run(
        [cancel](QPromise<ExportResult> &promise, const ExportRequest &request) {
            promise.setProgressRange(0, kProgressSteps);
            promise.addResult(exportAnimation(
                request,
                [&promise](double fraction) { promise.setProgressValue(int(std::lround(fraction * kProgressSteps))); },
                cancel.get()));
        },
        r));
    return true;
}

void ExportAnimationDialog::cancel()
{
    if (!isRunning())
        return;
    m_cancel->store(true);
    m_status->setText(tr("Cancelling…"));
}

void ExportAnimationDialog::reject()
{
    if (isRunning()) {
        cancel();
        return;
    }
    QDialog::reject();
}

void ExportAnimationDialog::formatChanged()
{
    const AnimationFormat format = AnimationFormat(m_format->currentData().toInt());
    const QString renamed = pathForFormat(m_path->text(), format);
    if (renamed != m_path->text())
        m_path->setText(renamed);
    // The last export's outcome was of another file: it would read as this one's.
    if (!isRunning()) {
        m_status->clear();
        m_progress->setValue(0);
        m_show->setVisible(false);
    }
    m_size->setEnabled(isRasterFormat(format));
    updateSummary();
}

void ExportAnimationDialog::browse()
{
    const ExportRequest r = request();
    QString chosen = QFileDialog::getSaveFileName(this, tr("Export Animation"), r.outputPath, fileFilter(r.format),
        nullptr, r.format == AnimationFormat::PngSequence ? QFileDialog::ShowDirsOnly : QFileDialog::Options());
    if (chosen.isEmpty())
        return;
    if (r.format == AnimationFormat::PngSequence)
        chosen = QDir::cleanPath(chosen) + QLatin1Char('/');
    else if (animationFormatForPath(chosen) != r.format)
        chosen += QLatin1Char('.') + animationFormatSuffix(r.format);
    m_path->setText(chosen);
}

void ExportAnimationDialog::updateSummary()
{
    const ExportRequest r = request();
    const int frames = exportFrameCount(r);
    QStringList parts;
    parts << tr("%n frame(s)", nullptr, frames) << tr("%1 s").arg(frames / double(r.fps), 0, 'f', 1);
    if (isRasterFormat(r.format)) {
        const QSize size = exportFrameSize(r);
        parts << tr("%1 × %2 px").arg(size.width()).arg(size.height());
    } else {
        parts << tr("vector drawing");
    }
    const bool hasSound = !r.audioPath.isEmpty() || (r.timeline.audio() && !r.timeline.audio()->path.isEmpty());
    if (r.format == AnimationFormat::Gif || r.format == AnimationFormat::PngSequence)
        parts << tr("silent");
    else
        parts << (hasSound ? tr("with sound") : tr("no sound"));
    m_summary->setText(parts.join(QStringLiteral(" · ")));
    m_export->setEnabled(!isRunning() && !r.outputPath.isEmpty());
}

void ExportAnimationDialog::exportFinished()
{
    const QString path = m_running;
    m_running.clear();
    m_result = m_watcher.future().resultCount() > 0
        ? m_watcher.result()
        : ExportResult {ExportStatus::Failed, tr("%1: the export stopped").arg(QDir::toNativeSeparators(path))};
    setRunning(false);
    switch (m_result.status) {
    case ExportStatus::Done:
        m_exported = path;
        m_exportedFolder = folderOf(path, m_runningFormat);
        m_progress->setValue(kProgressSteps);
        m_status->setText(tr("Exported to %1.").arg(QDir::toNativeSeparators(path)));
        m_show->setVisible(true);
        m_show->setFocus();
        break;
    case ExportStatus::Cancelled:
        m_progress->setValue(0);
        m_status->setText(tr("Cancelled: nothing was written."));
        break;
    case ExportStatus::BadInput:
    case ExportStatus::Failed:
        m_progress->setValue(0);
        m_status->setText(tr("Not exported: %1").arg(m_result.error));
        break;
    }
    Q_EMIT finished(m_result);
}

void ExportAnimationDialog::showInFolder()
{
    if (!m_exportedFolder.isEmpty())
        QDesktopServices::openUrl(QUrl::fromLocalFile(m_exportedFolder));
}

void ExportAnimationDialog::setRunning(bool running)
{
    for (QWidget *w : {static_cast<QWidget *>(m_format), static_cast<QWidget *>(m_path),
             static_cast<QWidget *>(m_browse), static_cast<QWidget *>(m_fps), static_cast<QWidget *>(m_framing)})
        w->setEnabled(!running);
    m_size->setEnabled(!running && isRasterFormat(request().format));
    m_export->setEnabled(!running);
    if (QPushButton *close = m_buttons->button(QDialogButtonBox::Close))
        close->setText(running ? tr("Cancel") : tr("Close"));
}

} // namespace toonface
