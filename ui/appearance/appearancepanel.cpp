#include "appearance/appearancepanel.h"

#include "appearance/layerseditor.h"
#include "detect/photocolours.h"
#include "views/displaynames.h"

#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>

namespace toonface {

namespace {

constexpr int kCaricatureSteps = 100; // slider units per 1.0 of the factor

// The component keys that share one colour in the panel: the skin is the face, jaw and ears.
QStringList keysOf(const QString &key)
{
    if (key == QLatin1StringView("face"))
        return {QStringLiteral("face"), QStringLiteral("jaw"), QStringLiteral("ears")};
    return {key};
}

ComponentStyle componentOf(const Style &style, const QString &key)
{
    auto it = style.components.constFind(key);
    if (it != style.components.constEnd())
        return *it;
    return Style::preset(QStringLiteral("normal")).components.value(key);
}

void setSwatch(QPushButton *button, const QColor &c)
{
    button->setText(c.isValid() ? c.name() : AppearancePanel::tr("none"));
    button->setStyleSheet(c.isValid()
            ? QStringLiteral("background:%1;color:%2")
                  .arg(c.name(), c.lightness() > 128 ? QStringLiteral("black") : QStringLiteral("white"))
            : QString());
}

} // namespace

QList<std::pair<QString, QString>> AppearancePanel::componentKeys()
{
    return {{QStringLiteral("face"), tr("Skin")}, {QStringLiteral("hair"), tr("Hair")},
        {QStringLiteral("eyebrows"), tr("Brows")}, {QStringLiteral("eyes"), tr("Eyes")},
        {QStringLiteral("eyeballs"), tr("Irises")}, {QStringLiteral("lips"), tr("Lips")},
        {QStringLiteral("nose"), tr("Nose")}, {QStringLiteral("cheeks"), tr("Cheeks")},
        {QStringLiteral("glasses"), tr("Glasses")}, {QStringLiteral("moustache"), tr("Moustache")},
        {QStringLiteral("beard"), tr("Beard")}, {QStringLiteral("hat"), tr("Hat")},
        {QStringLiteral("body"), tr("Neck and shoulders")}, {QStringLiteral("creases"), tr("Expression lines")},
        {QStringLiteral("blush"), tr("Smile blush")}};
}

AppearancePanel::AppearancePanel(Document *document, QWidget *parent)
    : QWidget(parent)
    , m_document(document)
{
    auto *layout = new QVBoxLayout(this);

    auto *drawing = new QGroupBox(tr("Drawing"));
    auto *form = new QFormLayout(drawing);
    m_eyebrows = new QComboBox;
    m_eyebrows->setObjectName(QStringLiteral("eyebrowVariant"));
    for (EyebrowVariant v : {EyebrowVariant::Polyline, EyebrowVariant::Bezier, EyebrowVariant::Thick})
        m_eyebrows->addItem(variantTitle(eyebrowVariantName(v)), int(v));
    m_nose = new QComboBox;
    m_nose->setObjectName(QStringLiteral("noseVariant"));
    for (NoseVariant v : {NoseVariant::Full, NoseVariant::Simple, NoseVariant::Tip})
        m_nose->addItem(variantTitle(noseVariantName(v)), int(v));
    m_cute = new QCheckBox(tr("Cute proportions"));
    m_cute->setObjectName(QStringLiteral("cute"));
    m_caricature = new QSlider(Qt::Horizontal);
    m_caricature->setObjectName(QStringLiteral("caricature"));
    m_caricature->setRange(0, int(kMaxCaricature * kCaricatureSteps));
    m_caricature->setToolTip(tr("How much the drawing exaggerates what makes this face its own (0 = exact)"));
    m_caricatureValue = new QLabel;
    auto *caricatureRow = new QHBoxLayout;
    caricatureRow->addWidget(m_caricature, 1);
    caricatureRow->addWidget(m_caricatureValue);
    form->addRow(tr("Eyebrows:"), m_eyebrows);
    form->addRow(tr("Nose:"), m_nose);
    form->addRow(QString(), m_cute);
    form->addRow(tr("Caricature:"), caricatureRow);
    layout->addWidget(drawing);

    auto *worn = new QGroupBox(tr("Worn and grown"));
    auto *wornForm = new QFormLayout(worn);
    m_glasses = new QComboBox;
    m_glasses->setObjectName(QStringLiteral("glasses"));
    for (GlassesShape g : {GlassesShape::None, GlassesShape::Round, GlassesShape::Rectangular, GlassesShape::Rimless})
        m_glasses->addItem(variantTitle(glassesShapeName(g)), int(g));
    m_moustache = new QCheckBox(tr("Moustache"));
    m_moustache->setObjectName(QStringLiteral("moustache"));
    m_beard = new QCheckBox(tr("Beard"));
    m_beard->setObjectName(QStringLiteral("beard"));
    m_goatee = new QCheckBox(tr("Goatee"));
    m_goatee->setObjectName(QStringLiteral("goatee"));
    m_goatee->setToolTip(tr("Hair on the chin only (drawn when there is no beard)"));
    m_hat = new QCheckBox(tr("Hat"));
    m_hat->setObjectName(QStringLiteral("hat"));
    m_bald = new QCheckBox(tr("Bald head"));
    m_bald->setObjectName(QStringLiteral("bald"));
    m_age = new QComboBox;
    m_age->setObjectName(QStringLiteral("age"));
    m_age->setToolTip(tr("A child is drawn with thin light brows, unpainted lips, a rounder jaw and larger eyes; "
                         "an elderly person with fine age lines"));
    m_age->addItem(tr("Adult"), int(AgeGroup::Adult));
    m_age->addItem(tr("Child"), int(AgeGroup::Child));
    m_age->addItem(tr("Elderly"), int(AgeGroup::Elderly));
    wornForm->addRow(tr("Age:"), m_age);
    wornForm->addRow(tr("Glasses:"), m_glasses);
    for (QCheckBox *box : {m_moustache, m_beard, m_goatee, m_hat, m_bald})
        wornForm->addRow(QString(), box);
    layout->addWidget(worn);

    m_resample = new QPushButton(tr("Resample colours from the photo"));
    m_resample->setObjectName(QStringLiteral("resample"));
    m_resample->setToolTip(tr("Skin, hair, eyes and lips from the photo (its colour cast taken out), and what "
                              "the person wears"));
    layout->addWidget(m_resample);
    auto *layers = new QGroupBox(tr("Your layers"));
    (new QVBoxLayout(layers))->addWidget(new LayersEditor(document));
    layout->addWidget(layers);
    layout->addWidget(buildComponents(), 1);

    connect(m_eyebrows, &QComboBox::activated, this, [this](int i) {
        change(tr("Eyebrows"), [&](Style &s) { s.eyebrows = EyebrowVariant(m_eyebrows->itemData(i).toInt()); });
    });
    connect(m_nose, &QComboBox::activated, this,
        [this](int i) { change(tr("Nose"), [&](Style &s) { s.nose = NoseVariant(m_nose->itemData(i).toInt()); }); });
    connect(m_cute, &QCheckBox::clicked, this, [this](bool on) { change(tr("Cute"), [&](Style &s) { s.cute = on; }); });
    // One drag is one step: the value is taken when the slider is released (or moved by keys).
    auto caricatureChanged = [this] {
        m_caricatureValue->setText(QString::number(m_caricature->value() / double(kCaricatureSteps), 'f', 2));
        if (m_caricature->isSliderDown())
            return;
        const double factor = m_caricature->value() / double(kCaricatureSteps);
        change(tr("Caricature"), [&](Style &s) { s.caricature = factor; });
    };
    connect(m_caricature, &QSlider::valueChanged, this, caricatureChanged);
    connect(m_caricature, &QSlider::sliderReleased, this, caricatureChanged);
    connect(m_glasses, &QComboBox::activated, this, [this](int i) {
        change(tr("Glasses"), [&](Style &s) { s.appearance.glasses = GlassesShape(m_glasses->itemData(i).toInt()); });
    });
    connect(m_age, &QComboBox::activated, this, [this](int i) {
        change(tr("Age"), [&](Style &s) { s.appearance.age = AgeGroup(m_age->itemData(i).toInt()); });
    });
    const std::pair<QCheckBox *, bool Appearance::*> flags[]
        = {{m_moustache, &Appearance::moustache}, {m_beard, &Appearance::beard}, {m_goatee, &Appearance::goatee},
            {m_hat, &Appearance::hat}, {m_bald, &Appearance::bald}};
    for (const auto &[box, member] : flags) {
        connect(box, &QCheckBox::clicked, this, [this, box = box, member = member](bool on) {
            change(box->text(), [&](Style &s) { s.appearance.*member = on; });
        });
    }
    connect(m_resample, &QPushButton::clicked, this, [this] {
        change(tr("Resample colours"), [&](Style &s) { sampleColours(m_document->photo(), m_document->face(), &s); });
    });
    connect(m_document, &Document::changed, this, &AppearancePanel::onDocumentChanged);
    sync();
}

QWidget *AppearancePanel::buildComponents()
{
    auto *box = new QGroupBox(tr("Colours and lines"));
    auto *grid = new QGridLayout(box);
    grid->addWidget(new QLabel(tr("Shown")), 0, 0);
    grid->addWidget(new QLabel(tr("Fill")), 0, 1);
    grid->addWidget(new QLabel(tr("Line")), 0, 2);
    grid->addWidget(new QLabel(tr("Weight")), 0, 3);
    int r = 1;
    for (const auto &[key, label] : componentKeys()) {
        Row row {key, new QCheckBox(label), new QPushButton, new QPushButton, new QDoubleSpinBox};
        row.visible->setObjectName(QStringLiteral("visible-") + key);
        row.fill->setObjectName(QStringLiteral("fill-") + key);
        row.stroke->setObjectName(QStringLiteral("stroke-") + key);
        row.width->setObjectName(QStringLiteral("width-") + key);
        row.width->setRange(0, 20);
        row.width->setSingleStep(0.2);
        row.width->setToolTip(tr("Line weight in hundredths of the eye distance"));
        grid->addWidget(row.visible, r, 0);
        grid->addWidget(row.fill, r, 1);
        grid->addWidget(row.stroke, r, 2);
        grid->addWidget(row.width, r, 3);
        connect(row.visible, &QCheckBox::clicked, this, [this, key = key, label = label](bool on) {
            change(tr("Show %1").arg(label), [&](Style &s) {
                for (const QString &k : keysOf(key)) {
                    ComponentStyle c = componentOf(s, k);
                    c.visible = on;
                    s.components.insert(k, c);
                }
            });
        });
        connect(row.fill, &QPushButton::clicked, this, [this, key = key] { pickColour(key, false); });
        connect(row.stroke, &QPushButton::clicked, this, [this, key = key] { pickColour(key, true); });
        connect(row.width, &QDoubleSpinBox::editingFinished, this, [this, key = key, spin = row.width] {
            const double w = spin->value();
            if (componentOf(m_document->style(), key).strokeWidth == w)
                return;
            change(tr("Line weight"), [&](Style &s) {
                for (const QString &k : keysOf(key)) {
                    ComponentStyle c = componentOf(s, k);
                    c.strokeWidth = w;
                    s.components.insert(k, c);
                }
            });
        });
        m_rows.append(row);
        ++r;
    }
    grid->setRowStretch(r, 1); // the rows stay together at the top of a tall dock
    auto *scroll = new QScrollArea;
    scroll->setWidget(box);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    return scroll;
}

void AppearancePanel::pickColour(const QString &key, bool stroke)
{
    const ComponentStyle current = componentOf(m_document->style(), key);
    const QColor start = stroke ? current.stroke : current.fill;
    const QColor chosen = QColorDialog::getColor(start.isValid() ? start : QColor(Qt::black), this,
        stroke ? tr("Line colour") : tr("Fill colour"), QColorDialog::ShowAlphaChannel);
    if (!chosen.isValid() || chosen == start)
        return;
    change(stroke ? tr("Line colour") : tr("Fill colour"), [&](Style &s) {
        for (const QString &k : keysOf(key)) {
            ComponentStyle c = componentOf(s, k);
            (stroke ? c.stroke : c.fill) = chosen;
            s.components.insert(k, c);
        }
    });
}

void AppearancePanel::change(const QString &text, const std::function<void(Style &)> &edit)
{
    if (m_syncing || !m_document->hasFace())
        return;
    Style style = m_document->style();
    edit(style);
    if (style == m_document->style())
        return;
    m_document->changeStyle(style, text);
}

void AppearancePanel::onDocumentChanged(ChangeFlags what)
{
    if (what & (Change::Style | Change::Face | Change::Photo))
        sync();
}

void AppearancePanel::sync()
{
    m_syncing = true;
    const Style &s = m_document->style();
    const bool enabled = m_document->hasFace();
    setEnabled(enabled);
    m_eyebrows->setCurrentIndex(m_eyebrows->findData(int(s.eyebrows)));
    m_nose->setCurrentIndex(m_nose->findData(int(s.nose)));
    m_cute->setChecked(s.cute);
    if (!m_caricature->isSliderDown()) {
        const QSignalBlocker blocker(m_caricature);
        m_caricature->setValue(int(std::lround(s.caricature * kCaricatureSteps)));
    }
    m_caricatureValue->setText(QString::number(s.caricature, 'f', 2));
    m_glasses->setCurrentIndex(m_glasses->findData(int(s.appearance.glasses)));
    m_age->setCurrentIndex(m_age->findData(int(s.appearance.age)));
    m_moustache->setChecked(s.appearance.moustache);
    m_beard->setChecked(s.appearance.beard);
    m_goatee->setChecked(s.appearance.goatee);
    m_goatee->setEnabled(!s.appearance.beard);
    m_hat->setChecked(s.appearance.hat);
    m_bald->setChecked(s.appearance.bald);
    m_resample->setEnabled(!m_document->photo().isNull());
    for (const Row &row : std::as_const(m_rows)) {
        const ComponentStyle c = componentOf(s, row.key);
        row.visible->setChecked(c.visible);
        setSwatch(row.fill, c.fill);
        setSwatch(row.stroke, c.stroke);
        const QSignalBlocker blocker(row.width);
        row.width->setValue(c.strokeWidth);
    }
    m_syncing = false;
}

} // namespace toonface
