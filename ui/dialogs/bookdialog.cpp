#include "dialogs/bookdialog.h"

#include "dialogs/jobstatus.h"
#include "document/companionfile.h"
#include "document/document.h"
#include "export/animationexport.h"
#include "media/audiomix.h"

#include <QAction>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QStandardPaths>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

namespace toonface {

BookDialog::BookDialog(const BookRequest &base, QWidget *parent)
    : QDialog(parent)
    , m_base(base)
{
    setWindowTitle(tr("Export Read-aloud Book"));
    auto *form = new QFormLayout;
    auto row = [this](QLineEdit *edit, QPushButton **button, const QString &filter, bool save) {
        auto *box = new QHBoxLayout;
        box->addWidget(edit, 1);
        auto *pick = new QPushButton(tr("Browse…"));
        connect(pick, &QPushButton::clicked, this, [this, edit, filter, save]() { browse(edit, filter, save); });
        box->addWidget(pick);
        if (button)
            *button = pick;
        return box;
    };
    m_text = new QLineEdit(base.textPath);
    m_text->setObjectName(QStringLiteral("bookText"));
    form->addRow(tr("&Text:"), row(m_text, nullptr, tr("Text (*.txt *.md *.markdown)"), false));
    m_source = new QComboBox;
    m_source->setObjectName(QStringLiteral("bookSource"));
    m_source->addItem(tr("A recording of the text"), QStringLiteral("file"));
    m_source->addItem(tr("The built-in voice"), QStringLiteral("voice"));
    m_source->setCurrentIndex(base.audioPath.isEmpty() ? 1 : 0);
    form->addRow(tr("&Read by:"), m_source);
    m_audio = new QLineEdit(base.audioPath);
    m_audio->setObjectName(QStringLiteral("bookAudio"));
    form->addRow(
        tr("&Recording:"), row(m_audio, &m_audioBrowse, tr("Sound (*.wav *.flac *.mp3 *.ogg *.opus *.m4a)"), false));
    m_language = new QComboBox;
    m_language->addItem(tr("As the text reads"), QString());
    m_language->addItem(tr("Chinese (Traditional)"), QStringLiteral("zh-Hant"));
    m_language->addItem(tr("Chinese (Simplified)"), QStringLiteral("zh-Hans"));
    m_language->addItem(tr("English"), QStringLiteral("en"));
    m_language->setCurrentIndex(std::max(0, m_language->findData(base.language)));
    form->addRow(tr("&Language:"), m_language);
    m_title = new QLineEdit(base.title);
    m_title->setPlaceholderText(tr("The first heading, or the text's file name"));
    form->addRow(tr("T&itle:"), m_title);
    m_author = new QLineEdit(base.author);
    form->addRow(tr("&Author:"), m_author);
    m_highlight = new QComboBox;
    m_highlight->addItem(tr("Each sentence"));
    m_highlight->addItem(tr("Each character or word"));
    m_highlight->setCurrentIndex(base.highlight == BookHighlight::Syllable ? 1 : 0);
    form->addRow(tr("&Highlight:"), m_highlight);
    m_faceMedia = new QComboBox;
    m_faceMedia->setObjectName(QStringLiteral("bookFaceMedia"));
    m_faceMedia->addItem(tr("An animated drawing"), int(BookFaceMedia::Svg));
    m_faceMedia->addItem(tr("A video of each page"), int(BookFaceMedia::Video));
    m_faceMedia->setCurrentIndex(base.faceMedia == BookFaceMedia::Video ? 1 : 0);
    m_faceMedia->setToolTip(tr("A video of each page read aloud plays in reading systems that neither read "
                               "aloud nor animate drawings; it takes longer to make"));
    form->addRow(tr("&Face:"), m_faceMedia);
    m_output = new QLineEdit(base.outputPath);
    m_output->setObjectName(QStringLiteral("bookOutput"));
    form->addRow(tr("&Book:"), row(m_output, nullptr, tr("EPUB book (*.epub)"), true));

    m_status = new JobStatus;
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    m_export = m_buttons->addButton(tr("&Export"), QDialogButtonBox::AcceptRole);
    m_export->setDefault(true);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &BookDialog::start);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &BookDialog::reject);
    connect(m_source, &QComboBox::currentIndexChanged, this, &BookDialog::updateControls);
    connect(m_text, &QLineEdit::textChanged, this, &BookDialog::updateControls);
    connect(m_output, &QLineEdit::textChanged, this, &BookDialog::updateControls);
    connect(m_audio, &QLineEdit::textChanged, this, &BookDialog::updateControls);
    connect(&m_watcher, &QFutureWatcher<BookResult>::finished, this, &BookDialog::bookFinished);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_status);
    layout->addWidget(m_buttons);
    setMinimumWidth(520);
    updateControls();
}

BookDialog::~BookDialog()
{
    if (isRunning()) {
        m_cancel->store(true);
        m_watcher.waitForFinished();
    }
}

QString BookDialog::run(QWidget *parent, const BookRequest &base)
{
    BookDialog dialog(base, parent);
    dialog.exec();
    return dialog.exportedPath();
}

QAction *BookDialog::createAction(QWidget *window, Document *document)
{
    auto *action = new QAction(tr("Export Read-aloud &Book…"), window);
    action->setObjectName(QStringLiteral("actionExportBook"));
    connect(action, &QAction::triggered, window, [window, document]() {
        const Project &project = document->project();
        const ExportRequest animation = exportRequestFor(project);
        BookRequest base;
        base.face = animation.face;
        base.style = animation.style;
        base.mouthShapes = animation.mouthShapes;
        base.layerFiles = animation.layerFiles;
        base.audioPath = project.audioPath();
        base.outputPath = exportFile(*document, QStringLiteral("epub"), QStringLiteral("book"),
            QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation));
        BookDialog dialog(base, window);
        dialog.setProjectTrack(project.timeline.audioClips());
        dialog.exec();
    });
    return action;
}

void BookDialog::setProjectTrack(const QVector<AudioClip> &clips)
{
    const QVector<AudioClip> sounding = soundingClips(clips);
    const bool whole = sounding.size() == 1 && sounding.first().trimIn == 0 && sounding.first().trimOut == 0;
    const int at = m_source->findData(QStringLiteral("track"));
    if (at >= 0)
        m_source->removeItem(at);
    m_trackClips.clear();
    if (sounding.isEmpty() || whole)
        return;
    m_trackClips = sounding;
    m_source->insertItem(0, tr("The project's audio track (%n recording(s), mixed)", nullptr, int(sounding.size())),
        QStringLiteral("track"));
    m_source->setCurrentIndex(0);
    updateControls();
}

QString BookDialog::mixedTrackPath() const
{
    return m_mixDir.isValid() ? m_mixDir.filePath(QStringLiteral("track.wav")) : QString();
}

bool BookDialog::readByTrack() const
{
    return m_source->currentData().toString() == QLatin1String("track");
}

bool BookDialog::readByRecording() const
{
    return m_source->currentData().toString() == QLatin1String("file");
}

BookRequest BookDialog::request() const
{
    BookRequest r = m_base;
    r.textPath = m_text->text().trimmed();
    r.audioPath = readByRecording() ? m_audio->text().trimmed() : readByTrack() ? mixedTrackPath() : QString();
    r.language = m_language->currentData().toString();
    r.title = m_title->text().trimmed();
    r.author = m_author->text().trimmed();
    r.highlight = m_highlight->currentIndex() == 1 ? BookHighlight::Syllable : BookHighlight::Sentence;
    r.faceMedia = BookFaceMedia(m_faceMedia->currentData().toInt());
    r.outputPath = m_output->text().trimmed();
    return r;
}

bool BookDialog::isRunning() const
{
    return m_watcher.isRunning();
}

void BookDialog::updateControls()
{
    const bool recording = readByRecording();
    m_audio->setEnabled(recording && !isRunning());
    m_audioBrowse->setEnabled(recording && !isRunning());
    const BookRequest r = request();
    m_export->setEnabled(
        !isRunning() && !r.textPath.isEmpty() && !r.outputPath.isEmpty() && (!recording || !r.audioPath.isEmpty()));
    m_buttons->button(QDialogButtonBox::Close)->setText(isRunning() ? tr("Cancel") : tr("Close"));
}

void BookDialog::browse(QLineEdit *edit, const QString &filter, bool save)
{
    const QString chosen = save ? QFileDialog::getSaveFileName(this, windowTitle(), edit->text(), filter)
                                : QFileDialog::getOpenFileName(this, windowTitle(), edit->text(), filter);
    if (chosen.isEmpty())
        return;
    edit->setText(save && QFileInfo(chosen).suffix().isEmpty() ? chosen + QStringLiteral(".epub") : chosen);
}

bool BookDialog::start()
{
    const BookRequest r = request();
    if (isRunning() || !m_export->isEnabled())
        return false;
    m_cancel = std::make_shared<std::atomic_bool>(false);
    m_status->showProgress(0, tr("Starting…"));
    const std::shared_ptr<std::atomic_bool> cancel = m_cancel;
    // Progress comes from the worker thread: shown on the dialog's (dropped if it is gone).
    const QVector<AudioClip> track = readByTrack() ? m_trackClips : QVector<AudioClip> {};
    m_watcher.setFuture(QtConcurrent::run(
        [this, cancel, track](const BookRequest &request) {
            if (!track.isEmpty()) {
                // The whole audio track as one recording, the clips mixed at their places.
                QMetaObject::invokeMethod(
                    this, [this]() { m_status->showProgress(0, tr("Mixing the recordings…")); }, Qt::QueuedConnection);
                QString error;
                const QFileInfo mix(request.audioPath);
                const std::optional<TrackSound> sound
                    = trackSoundFile(track, mix.absolutePath(), mix.fileName(), &error, cancel.get());
                if (!sound || sound->path.isEmpty()) {
                    BookResult failed;
                    failed.status = cancel->load() ? BookStatus::Cancelled : BookStatus::BadInput;
                    failed.error = error;
                    return failed;
                }
            }
            return exportBook(
                request,
                [this](double fraction, const QString &stage) {
                    QMetaObject::invokeMethod(
                        this, [this, fraction, stage]() { m_status->showProgress(fraction, stage); },
                        Qt::QueuedConnection);
                },
                cancel.get());
        },
        r));
    updateControls();
    return true;
}

void BookDialog::cancel()
{
    if (isRunning())
        m_cancel->store(true);
}

void BookDialog::reject()
{
    if (isRunning()) {
        cancel();
        return;
    }
    QDialog::reject();
}

void BookDialog::bookFinished()
{
    m_result = m_watcher.result();
    switch (m_result.status) {
    case BookStatus::Done:
        m_exported = request().outputPath;
        m_status->showNote(
            tr("Wrote %1: %n page(s)", nullptr, m_result.pages).arg(QDir::toNativeSeparators(m_exported)));
        break;
    case BookStatus::Cancelled: m_status->showNote(tr("Cancelled; nothing was written.")); break;
    default: m_status->showError(m_result.error); break;
    }
    updateControls();
    Q_EMIT finished();
}

} // namespace toonface
