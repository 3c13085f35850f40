#include "dialogs/emotiondialog.h"

#include "dialogs/animationedits.h"
#include "dialogs/posepreview.h"
#include "dialogs/secondsbox.h"
#include "document/document.h"
#include "face/emotion.h"
#include "views/displaynames.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QVBoxLayout>

#include <cmath>

namespace toonface {

namespace {

constexpr int kThumbnailSize = 40;
constexpr double kFrameMargin = 0.06; // of the face's size
// A clip for an animation with nothing on it yet.
constexpr double kEmptyAnimationRange = 2.0;

QRectF faceFrame(const FaceModel &face)
{
    const QRectF bounds = face.bounds();
    const double margin = kFrameMargin * std::max(bounds.width(), bounds.height());
    return bounds.adjusted(-margin, -margin, margin, margin);
}

} // namespace

bool EmotionDialog::run(QWidget *parent, Document *document, double start, double end)
{
    EmotionDialog dialog(document, parent);
    if (end >= 0 && end > start) {
        EmotionClip clip = dialog.clip();
        clip.start = start;
        clip.end = end;
        dialog.setClip(clip);
    }
    return dialog.exec() == QDialog::Accepted;
}

EmotionDialog::EmotionDialog(Document *document, QWidget *parent)
    : QDialog(parent)
    , m_document(document)
    , m_emotion(new QComboBox(this))
    , m_start(new SecondsBox(this))
    , m_end(new SecondsBox(this))
    , m_intensity(new QSlider(Qt::Horizontal, this))
    , m_intensityValue(new QSpinBox(this))
    , m_fadeIn(new SecondsBox(this, 60))
    , m_fadeOut(new SecondsBox(this, 60))
    , m_replace(new QCheckBox(tr("The emotions already there &give way"), this))
    , m_preview(new PosePreview(this))
{
    setWindowTitle(tr("Add Emotion"));

    const bool hasFace = m_document->hasFace();
    const SvgFace svgFace(m_document->face(), m_document->style());
    m_emotion->setObjectName(QStringLiteral("emotion"));
    m_emotion->setIconSize(QSize(kThumbnailSize, kThumbnailSize));
    for (Emotion e : kAllEmotions) {
        QIcon icon;
        if (hasFace)
            icon = QIcon(QPixmap::fromImage(renderPose(svgFace, stillEmotionPose(m_document->face(), e, 1.0),
                faceFrame(m_document->face()), QSize(kThumbnailSize, kThumbnailSize))));
        m_emotion->addItem(icon, emotionTitle(e), int(e));
    }

    m_start->setObjectName(QStringLiteral("start"));
    m_end->setObjectName(QStringLiteral("end"));
    auto *rangeRow = new QHBoxLayout;
    rangeRow->addWidget(m_start);
    rangeRow->addWidget(new QLabel(tr("to"), this));
    rangeRow->addWidget(m_end);
    rangeRow->addStretch(1);

    m_intensity->setObjectName(QStringLiteral("intensity"));
    m_intensity->setRange(0, 100);
    m_intensityValue->setObjectName(QStringLiteral("intensityValue"));
    m_intensityValue->setRange(0, 100);
    m_intensityValue->setSuffix(tr(" %"));
    auto *intensityRow = new QHBoxLayout;
    intensityRow->addWidget(m_intensity, 1);
    intensityRow->addWidget(m_intensityValue);

    m_fadeIn->setObjectName(QStringLiteral("fadeIn"));
    m_fadeOut->setObjectName(QStringLiteral("fadeOut"));
    auto *fadeRow = new QHBoxLayout;
    fadeRow->addWidget(new QLabel(tr("in"), this));
    fadeRow->addWidget(m_fadeIn);
    fadeRow->addSpacing(8);
    fadeRow->addWidget(new QLabel(tr("out"), this));
    fadeRow->addWidget(m_fadeOut);
    fadeRow->addStretch(1);

    m_replace->setObjectName(QStringLiteral("replace"));
    m_replace->setChecked(true);
    m_replace->setToolTip(tr("Otherwise the new emotion adds to the ones under it"));

    auto *form = new QFormLayout;
    form->addRow(tr("&Emotion:"), m_emotion);
    form->addRow(tr("&From:"), rangeRow);
    form->addRow(tr("&Intensity:"), intensityRow);
    form->addRow(tr("Fade:"), fadeRow);
    form->addRow(QString(), m_replace);
    static_cast<QLabel *>(form->labelForField(rangeRow))->setBuddy(m_start);
    static_cast<QLabel *>(form->labelForField(intensityRow))->setBuddy(m_intensity);

    m_preview->setObjectName(QStringLiteral("preview"));
    m_preview->setMinimumSize(200, 220);
    if (hasFace) {
        m_preview->setFace(svgFace);
        m_preview->setFrame(faceFrame(m_document->face()));
    }

    auto *buttons = new QDialogButtonBox(this);
    buttons->addButton(tr("Add Emotion"), QDialogButtonBox::AcceptRole)->setObjectName(QStringLiteral("ok"));
    buttons->addButton(QDialogButtonBox::Cancel);

    auto *body = new QHBoxLayout;
    body->addLayout(form, 1);
    body->addWidget(m_preview);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(body, 1);
    layout->addWidget(buttons);

    connect(m_intensity, &QSlider::valueChanged, m_intensityValue, &QSpinBox::setValue);
    connect(m_intensityValue, &QSpinBox::valueChanged, m_intensity, &QSlider::setValue);

    EmotionClip initial;
    initial.emotion = Emotion::Smile;
    initial.intensity = 0.8;
    const double duration = m_document->timeline().duration();
    initial.end = duration > 0 ? duration : kEmptyAnimationRange;
    setClip(initial);

    connect(m_intensity, &QSlider::valueChanged, this, &EmotionDialog::updatePreview);
    connect(m_emotion, &QComboBox::currentIndexChanged, this, &EmotionDialog::updatePreview);
    connect(buttons, &QDialogButtonBox::accepted, this, &EmotionDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &EmotionDialog::reject);
    updatePreview();
}

void EmotionDialog::setClip(const EmotionClip &clip)
{
    m_emotion->setCurrentIndex(std::max(0, m_emotion->findData(int(clip.emotion))));
    m_start->setValue(clip.start);
    m_end->setValue(clip.end);
    m_intensity->setValue(int(std::lround(clip.intensity * 100)));
    m_fadeIn->setValue(clip.fadeIn);
    m_fadeOut->setValue(clip.fadeOut);
}

EmotionClip EmotionDialog::clip() const
{
    EmotionClip clip;
    clip.emotion = Emotion(m_emotion->currentData().toInt());
    clip.start = m_start->value();
    clip.end = m_end->value();
    clip.intensity = m_intensity->value() / 100.0;
    clip.fadeIn = m_fadeIn->value();
    clip.fadeOut = m_fadeOut->value();
    return clip;
}

bool EmotionDialog::replacesOthers() const
{
    return m_replace->isChecked();
}

void EmotionDialog::updatePreview()
{
    if (m_document->hasFace())
        m_preview->setPose(stillEmotionPose(m_document->face(), clip().emotion, clip().intensity));
}

void EmotionDialog::accept()
{
    const EmotionClip c = clip();
    if (c.end <= c.start) {
        m_end->setFocus();
        return;
    }
    m_document->changeAnimation(
        withEmotion(m_document->animation(), c, replacesOthers()), tr("Add Emotion (%1)").arg(emotionTitle(c.emotion)));
    QDialog::accept();
}

} // namespace toonface
