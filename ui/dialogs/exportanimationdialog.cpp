#include "dialogs/exportanimationdialog.h"

#include "dialogs/exportpreview.h"
#include "export/framerenderer.h"
#include "render/svgface.h"

#include <QColorDialog>
#include <QComboBox>
#include <QDesktopServices>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
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
    case AnimationFormat::WebM: return ExportAnimationDialog::tr("WebM video (with transparency)");
    case AnimationFormat::Mov:
        return ExportAnimationDialog::tr("MOV ProRes 4444 (with transparency, for video editors)");
    case AnimationFormat::Apng: return ExportAnimationDialog::tr("Animated PNG");
    case AnimationFormat::WebP: return ExportAnimationDialog::tr("Animated WebP");
    }
    return {};
}

QString presetName(const QString &name)
{
    if (name == u"telegram-sticker")
        return ExportAnimationDialog::tr("Telegram sticker (512 px, up to 3 s and 256 KB)");
    if (name == u"emoji")
        return ExportAnimationDialog::tr("Emoji (100 px, up to 3 s and 64 KB)");
    if (name == u"slide-overlay")
        return ExportAnimationDialog::tr("Slide overlay (1080 px, with sound)");
    return name;
}

// The Background box's choices.
const QString kAutomatic = QStringLiteral("auto");
const QString kTransparent = QStringLiteral("transparent");
const QString kColour = QStringLiteral("colour");
const QString kPhoto = QStringLiteral("photo");

QString fileFilter(AnimationFormat format)
{
    switch (format) {
    case AnimationFormat::SmilSvg: return ExportAnimationDialog::tr("SVG animation (*.svg)");
    case AnimationFormat::HtmlPlayer: return ExportAnimationDialog::tr("HTML page (*.html *.htm)");
    case AnimationFormat::Mp4: return ExportAnimationDialog::tr("MP4 video (*.mp4)");
    case AnimationFormat::Gif: return ExportAnimationDialog::tr("Animated GIF (*.gif)");
    case AnimationFormat::WebM: return ExportAnimationDialog::tr("WebM video (*.webm)");
    case AnimationFormat::Mov: return ExportAnimationDialog::tr("MOV video (*.mov)");
    case AnimationFormat::Apng: return ExportAnimationDialog::tr("Animated PNG (*.apng)");
    case AnimationFormat::WebP: return ExportAnimationDialog::tr("Animated WebP (*.webp)");
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
    , m_preset(new QComboBox)
    , m_background(new QComboBox)
    , m_start(new QDoubleSpinBox)
    , m_length(new QDoubleSpinBox)
    , m_preview(new ExportPreview)
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

    m_preset->setObjectName(QStringLiteral("preset"));
    m_preset->addItem(tr("None"), QString());
    for (const ExportPreset &p : exportPresets())
        m_preset->addItem(presetName(p.name), p.name);
    m_preset->setToolTip(tr("Ready-made settings for a place where talking faces are shared; the export "
                            "keeps to its limits or says why it cannot"));

    m_background->setObjectName(QStringLiteral("background"));
    m_background->addItem(tr("Automatic"), kAutomatic);
    m_background->addItem(tr("Transparent"), kTransparent);
    m_background->addItem(tr("Colour…"), kColour);
    m_background->addItem(tr("Photo…"), kPhoto);
    m_background->setToolTip(tr("Automatic: transparent for WebM, MOV, APNG, WebP and PNG frames, white for "
                                "MP4 and GIF"));
    setBackground(base.background);

    const double length = base.timeline.frameCount() / std::max(1.0, base.timeline.frameRate());
    m_start->setObjectName(QStringLiteral("start"));
    m_start->setRange(0, std::max(0.0, length));
    m_start->setDecimals(2);
    m_start->setSingleStep(0.5);
    m_start->setSuffix(tr(" s"));
    m_start->setValue(base.start);
    m_length->setObjectName(QStringLiteral("length"));
    m_length->setRange(0, std::max(0.0, length));
    m_length->setDecimals(2);
    m_length->setSingleStep(0.5);
    m_length->setSuffix(tr(" s"));
    m_length->setSpecialValueText(tr("To the end"));
    m_length->setValue(base.duration);
    auto *stretchRow = new QHBoxLayout;
    stretchRow->addWidget(m_start);
    stretchRow->addWidget(new QLabel(tr("for")));
    stretchRow->addWidget(m_length);
    stretchRow->addStretch(1);

    m_summary->setObjectName(QStringLiteral("summary"));
    m_summary->setWordWrap(true);
    m_summary->setForegroundRole(QPalette::PlaceholderText);

    auto *form = new QFormLayout;
    form->addRow(tr("&Preset:"), m_preset);
    form->addRow(tr("&Format:"), m_format);
    auto *pathLabel = new QLabel(tr("&Save to:"));
    pathLabel->setBuddy(m_path);
    form->addRow(pathLabel, pathRow);
    form->addRow(tr("Frame si&ze:"), m_size);
    form->addRow(tr("Frame &rate:"), m_fps);
    form->addRow(tr("Fr&aming:"), m_framing);
    form->addRow(tr("&Background:"), m_background);
    auto *stretchLabel = new QLabel(tr("Fro&m:"));
    stretchLabel->setBuddy(m_start);
    form->addRow(stretchLabel, stretchRow);
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
    // Its room is kept while it is hidden: Export and Close stay where they are, so a second
    // click where Export was never lands on Show in Folder (or on nothing).
    QSizePolicy keepRoom = m_show->sizePolicy();
    keepRoom.setRetainSizeWhenHidden(true);
    m_show->setSizePolicy(keepRoom);
    QPushButton *close = m_buttons->addButton(QDialogButtonBox::Close);
    close->setObjectName(QStringLiteral("close"));

    auto *top = new QHBoxLayout;
    top->addLayout(form, 1);
    top->addWidget(m_preview, 0, Qt::AlignTop);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(top);
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
    connect(m_framing, &QComboBox::currentIndexChanged, this, &ExportAnimationDialog::updatePreview);
    connect(m_preset, &QComboBox::currentIndexChanged, this, &ExportAnimationDialog::presetChanged);
    connect(m_background, &QComboBox::activated, this, &ExportAnimationDialog::backgroundChosen);
    connect(m_start, &QDoubleSpinBox::valueChanged, this, &ExportAnimationDialog::updateSummary);
    connect(m_start, &QDoubleSpinBox::valueChanged, this, &ExportAnimationDialog::updatePreview);
    connect(m_length, &QDoubleSpinBox::valueChanged, this, &ExportAnimationDialog::updateSummary);
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
    r.background = background();
    r.start = m_start->value();
    r.duration = m_length->value();
    if (const std::optional<ExportPreset> p = preset())
        r = withPreset(r, *p);
    return r;
}

std::optional<ExportPreset> ExportAnimationDialog::preset() const
{
    return exportPresetNamed(m_preset->currentData().toString());
}

ExportBackground ExportAnimationDialog::background() const
{
    const QString choice = m_background->currentData().toString();
    if (choice == kTransparent)
        return ExportBackground::transparent();
    if (choice == kColour)
        return ExportBackground::ofColour(m_colour);
    if (choice == kPhoto)
        return ExportBackground::ofPhoto(m_photo);
    return {};
}

void ExportAnimationDialog::setBackground(const ExportBackground &background)
{
    QString choice = kAutomatic;
    switch (background.kind) {
    case ExportBackground::Kind::Automatic: break;
    case ExportBackground::Kind::Transparent: choice = kTransparent; break;
    case ExportBackground::Kind::Colour:
        choice = kColour;
        m_colour = background.colour;
        break;
    case ExportBackground::Kind::Photo:
        choice = kPhoto;
        m_photo = background.photoPath;
        break;
    }
    const int colourRow = m_background->findData(kColour);
    m_background->setItemText(colourRow, choice == kColour ? tr("Colour: %1").arg(m_colour.name()) : tr("Colour…"));
    m_background->setItemIcon(colourRow, QIcon());
    if (choice == kColour) {
        QPixmap swatch(16, 16);
        swatch.fill(m_colour);
        m_background->setItemIcon(colourRow, QIcon(swatch));
    }
    const int photoRow = m_background->findData(kPhoto);
    m_background->setItemText(
        photoRow, choice == kPhoto ? tr("Photo: %1").arg(QFileInfo(m_photo).fileName()) : tr("Photo…"));
    m_background->setCurrentIndex(m_background->findData(choice));
    if (m_export) { // built
        updateSummary();
        updatePreview();
    }
}

QString ExportAnimationDialog::problem() const
{
    const ExportRequest r = request();
    if (const std::optional<ExportPreset> p = preset()) {
        if (const QString why = presetProblem(r, *p); !why.isEmpty())
            return why;
    }
    return backgroundProblem(r.format, r.background);
}

bool ExportAnimationDialog::isRunning() const
{
    return !m_running.isEmpty();
}

bool ExportAnimationDialog::start()
{
    const ExportRequest r = request();
    if (isRunning() || r.outputPath.isEmpty() || !problem().isEmpty())
        return false;
    m_cancel = std::make_shared<std::atomic_bool>(false);
    m_running = r.outputPath;
    m_runningFormat = r.format;
    m_progress->setValue(0);
    m_status->setText(tr("Exporting to %1…").arg(QDir::toNativeSeparators(r.outputPath)));
    m_show->setVisible(false);
    setRunning(true);
    const std::shared_ptr<std::atomic_bool> cancel = m_cancel;
    const std::optional<ExportPreset> preset = this->preset();
    m_watcher.setFuture(QtConcurrent::run(
        [cancel, preset](QPromise<ExportResult> &promise, const ExportRequest &request) {
            promise.setProgressRange(0, kProgressSteps);
            const auto report = [&promise](double fraction) {
                promise.setProgressValue(int(std::lround(fraction * kProgressSteps)));
            };
            promise.addResult(preset ? exportWithPreset(request, *preset, report, cancel.get())
                                     : exportAnimation(request, report, cancel.get()));
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
    m_size->setEnabled(isRasterFormat(format) && !preset());
    m_background->setEnabled(isRasterFormat(format));
    m_start->setEnabled(isRasterFormat(format));
    m_length->setEnabled(isRasterFormat(format));
    updateSummary();
    updatePreview();
}

void ExportAnimationDialog::presetChanged()
{
    const std::optional<ExportPreset> p = preset();
    if (p) {
        m_format->setCurrentIndex(m_format->findData(int(p->format)));
        if (p->maxSeconds > 0 && (m_length->value() == 0 || m_length->value() > p->maxSeconds))
            m_length->setValue(std::min(p->maxSeconds, m_length->maximum()));
    }
    m_format->setEnabled(!p && !isRunning());
    formatChanged();
}

void ExportAnimationDialog::backgroundChosen()
{
    const QString choice = m_background->currentData().toString();
    if (choice == kColour) {
        const QColor colour = QColorDialog::getColor(m_colour, this, tr("Background Colour"));
        if (colour.isValid())
            m_colour = colour;
    } else if (choice == kPhoto) {
        const QString photo = QFileDialog::getOpenFileName(this, tr("Background Photo"),
            m_photo.isEmpty() ? QFileInfo(m_path->text()).absolutePath() : m_photo,
            tr("Images (*.png *.jpg *.jpeg *.webp *.bmp)"));
        if (!photo.isEmpty())
            m_photo = photo;
        else if (m_photo.isEmpty()) { // nothing chosen: back to automatic
            setBackground({});
            return;
        }
    }
    setBackground(background());
}

// A still of the export's first frame, small: drawn as the export draws it (background
// included), over the checkerboard where it stays transparent.
void ExportAnimationDialog::updatePreview()
{
    const ExportRequest r = request();
    SvgFace face(r.face, r.style);
    face.setFrame(r.framing == ExportFraming::Head ? headFrame(r.face) : QRectF());
    for (const QString &layer : r.layerFiles)
        face.addLayerFile(layer);
    const QSize size = exportFrameSize(r).scaled(m_preview->sizeHint(), Qt::KeepAspectRatio);
    const ExportBackground b = effectiveBackground(r);
    QImage backdrop;
    if (b.kind == ExportBackground::Kind::Photo)
        backdrop = backgroundPicture(b.photoPath, size, nullptr);
    const QColor colour = b.kind == ExportBackground::Kind::Colour ? b.colour : QColor(Qt::transparent);
    // An MP4 asked to be transparent is refused: its still shows it white, as it was.
    const FrameRenderer renderer(face, r.timeline, r.mouthShapes, size,
        b.kind == ExportBackground::Kind::Transparent && !animationFormatCanBeTransparent(r.format) ? QColor(Qt::white)
                                                                                                    : colour,
        backdrop);
    m_preview->setFrame(renderer.renderAt(r.start));
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
    const bool hasSound = !r.audioPath.isEmpty() || !r.timeline.audioClips().isEmpty();
    if (!animationFormatHasSound(r.format) || r.silent)
        parts << tr("silent");
    else
        parts << (hasSound ? tr("with sound") : tr("no sound"));
    const QString why = problem();
    if (!why.isEmpty())
        parts << tr("cannot export: %1").arg(why);
    m_summary->setText(parts.join(QStringLiteral(" · ")));
    m_export->setEnabled(!isRunning() && !r.outputPath.isEmpty() && why.isEmpty());
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
    case ExportStatus::OverLimit:
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
    for (QWidget *w :
        {static_cast<QWidget *>(m_format), static_cast<QWidget *>(m_path), static_cast<QWidget *>(m_browse),
            static_cast<QWidget *>(m_fps), static_cast<QWidget *>(m_framing), static_cast<QWidget *>(m_preset),
            static_cast<QWidget *>(m_background), static_cast<QWidget *>(m_start), static_cast<QWidget *>(m_length)})
        w->setEnabled(!running);
    const bool raster = isRasterFormat(request().format);
    m_format->setEnabled(!running && !preset());
    m_size->setEnabled(!running && raster && !preset());
    for (QWidget *w :
        {static_cast<QWidget *>(m_background), static_cast<QWidget *>(m_start), static_cast<QWidget *>(m_length)})
        w->setEnabled(!running && raster);
    m_export->setEnabled(!running);
    if (QPushButton *close = m_buttons->button(QDialogButtonBox::Close))
        close->setText(running ? tr("Cancel") : tr("Close"));
}

} // namespace toonface
