#include "dialogs/mouthshapesdialog.h"

#include "dialogs/posepreview.h"
#include "document/document.h"
#include "face/fapu.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QToolButton>
#include <QVBoxLayout>

#include <cmath>

namespace toonface {

namespace {

constexpr int kThumbnailSize = 56;
constexpr int kAxisCount = 2;
constexpr int kTermCount = 4;

QString shapeDescription(MouthShape shape)
{
    switch (shape) {
    case MouthShape::M: return MouthShapesDialog::tr("lips shut (b p m, rest)");
    case MouthShape::F: return MouthShapesDialog::tr("lower lip under the upper (f)");
    case MouthShape::H: return MouthShapesDialog::tr("open (most initials, ng, er)");
    case MouthShape::A: return MouthShapesDialog::tr("wide open (a)");
    case MouthShape::I: return MouthShapesDialog::tr("spread (i, y)");
    case MouthShape::U: return MouthShapesDialog::tr("rounded (u, w)");
    case MouthShape::E: return MouthShapesDialog::tr("half open, spread (e)");
    case MouthShape::O: return MouthShapesDialog::tr("round open (o)");
    case MouthShape::N: return MouthShapesDialog::tr("tongue up (n)");
    }
    return QString();
}

QString controlTitle(int control)
{
    switch (control) {
    case Up: return MouthShapesDialog::tr("Upper lip");
    case Down: return MouthShapesDialog::tr("Lower lip");
    case Left: return MouthShapesDialog::tr("Left corner");
    case Right: return MouthShapesDialog::tr("Right corner");
    }
    return QString();
}

FapuTerm &axisTerm(FapuOffset &offset, int axis)
{
    return axis == 0 ? offset.dx : offset.dy;
}

double &termValue(FapuTerm &term, int which)
{
    switch (which) {
    case 0: return term.mns;
    case 1: return term.mw;
    case 2: return term.lowerLip;
    default: return term.px;
    }
}

int termIndex(int control, int axis, int term)
{
    return (control * kAxisCount + axis) * kTermCount + term;
}

// The mouth and what moves around it: from the nose tip to the chin, 4:3 about the mouth.
QRectF mouthFrame(const FaceModel &face)
{
    const QRectF mouth = face.bounds(PointGroup::Mouth);
    const double top = face.point("9.15").y();
    const double bottom = face.point("2.1").y();
    const double height = std::abs(bottom - top) * 1.1;
    const double width = std::max(height * 4.0 / 3.0, mouth.width() * 1.8);
    QRectF frame(0, 0, width, height);
    frame.moveCenter(QPointF(mouth.center().x(), (top + bottom) / 2));
    return frame;
}

} // namespace

bool MouthShapesDialog::run(QWidget *parent, Document *document)
{
    MouthShapesDialog dialog(document, parent);
    return dialog.exec() == QDialog::Accepted;
}

MouthShapesDialog::MouthShapesDialog(Document *document, QWidget *parent)
    : QDialog(parent)
    , m_document(document)
    , m_shapes(document->mouthShapes())
    , m_face(document->face(), document->style())
    , m_mouthFrame(mouthFrame(document->face()))
    , m_list(new QListWidget(this))
    , m_preview(new PosePreview(this))
    , m_cornersAtLipMiddle(new QCheckBox(tr("Corners at the height &midway between the lips (as o)"), this))
    , m_cornersFromPrevious(new QCheckBox(tr("Corners stay where the shape &before put them (as n)"), this))
    , m_shapeTitle(new QLabel(this))
    , m_resetShape(new QPushButton(tr("&Reset Shape"), this))
{
    setWindowTitle(tr("Mouth Shapes"));

    m_list->setObjectName(QStringLiteral("shapes"));
    m_list->setIconSize(QSize(kThumbnailSize, kThumbnailSize));
    m_list->setSpacing(1);
    for (MouthShape shape : kAllMouthShapes) {
        auto *item = new QListWidgetItem(m_list);
        item->setData(Qt::UserRole, int(shape));
    }
    m_list->setMinimumWidth(kThumbnailSize + fontMetrics().horizontalAdvance(shapeDescription(MouthShape::H)) / 2 + 60);
    m_list->setWordWrap(true);

    m_preview->setObjectName(QStringLiteral("preview"));
    m_preview->setMinimumSize(360, 240);
    m_preview->setMarkersDraggable(true);
    m_preview->setMouseTracking(true);
    m_preview->setToolTip(tr("Drag a point to move it"));
    if (m_document->hasFace()) {
        m_preview->setFace(m_face);
        m_preview->setFrame(m_mouthFrame);
    }
    QFont titleFont = m_shapeTitle->font();
    titleFont.setPointSizeF(titleFont.pointSizeF() * 1.3);
    titleFont.setBold(true);
    m_shapeTitle->setFont(titleFont);

    // The shape is what the user sees and drags; the numbers behind it (in the face's own
    // measures, so that a shape fits any face) wait behind Advanced.
    auto *hint = new QLabel(tr("Drag the four points of the mouth in the picture to change the shape. Each shape "
                               "fits every face: it moves the lips in proportion to this face's mouth."),
        this);
    hint->setObjectName(QStringLiteral("hint"));
    hint->setWordWrap(true);
    auto *advanced = new QToolButton(this);
    advanced->setObjectName(QStringLiteral("advanced"));
    advanced->setText(tr("Ad&vanced: the numbers"));
    advanced->setCheckable(true);
    advanced->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    advanced->setArrowType(Qt::RightArrow);
    advanced->setAutoRaise(true);
    auto *advancedPart = new QWidget(this);
    advancedPart->setObjectName(QStringLiteral("advancedPart"));
    auto *advancedLayout = new QVBoxLayout(advancedPart);
    advancedLayout->setContentsMargins(0, 0, 0, 0);

    auto *editorBox = new QGroupBox(tr("How the four mouth control points move"), this);
    auto *grid = new QGridLayout(editorBox);
    buildEditor(grid);
    m_cornersAtLipMiddle->setObjectName(QStringLiteral("cornersAtLipMiddle"));
    m_cornersFromPrevious->setObjectName(QStringLiteral("cornersFromPrevious"));
    grid->addWidget(m_cornersAtLipMiddle, grid->rowCount(), 0, 1, grid->columnCount());
    grid->addWidget(m_cornersFromPrevious, grid->rowCount(), 0, 1, grid->columnCount());

    const Fapu f = m_document->face().fapu();
    auto *units = new QLabel(tr("On this face MNS0 (nose to mouth) = %1 px, MW0 (mouth width) = %2 px, LowerLipH = %3 "
                                "px, ES0/100 = %4 px. y grows downwards.")
                                 .arg(f.mns0, 0, 'f', 1)
                                 .arg(f.mw0, 0, 'f', 1)
                                 .arg(f.lowerLipH, 0, 'f', 1)
                                 .arg(f.pixel(), 0, 'f', 2),
        this);
    units->setWordWrap(true);
    units->setEnabled(false); // a secondary note

    auto *right = new QVBoxLayout;
    right->addWidget(m_shapeTitle);
    right->addWidget(m_preview, 1);
    right->addWidget(hint);
    right->addWidget(advanced, 0, Qt::AlignLeft);
    advancedLayout->addWidget(editorBox);
    advancedLayout->addWidget(units);
    right->addWidget(advancedPart);
    advancedPart->setVisible(false);
    connect(advanced, &QToolButton::toggled, this, [this, advanced, advancedPart](bool on) {
        advanced->setArrowType(on ? Qt::DownArrow : Qt::RightArrow);
        advancedPart->setVisible(on);
        adjustSize();
    });

    auto *body = new QHBoxLayout;
    body->addWidget(m_list);
    body->addLayout(right, 1);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    m_resetShape->setObjectName(QStringLiteral("resetShape"));
    auto *resetAllButton = new QPushButton(tr("Reset &All"), this);
    resetAllButton->setObjectName(QStringLiteral("resetAll"));
    buttons->addButton(m_resetShape, QDialogButtonBox::ResetRole);
    buttons->addButton(resetAllButton, QDialogButtonBox::ResetRole);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(body, 1);
    layout->addWidget(buttons);

    connect(m_list, &QListWidget::currentRowChanged, this, [this](int row) {
        if (row >= 0)
            setCurrentShape(kAllMouthShapes[row]);
    });
    for (QDoubleSpinBox *box : m_terms)
        connect(box, &QDoubleSpinBox::valueChanged, this, &MouthShapesDialog::readEditor);
    connect(m_preview, &PosePreview::markerDragged, this,
        [this](int control, QPointF photoPos, bool) { dragControl(control, photoPos); });
    connect(m_cornersAtLipMiddle, &QCheckBox::toggled, this, &MouthShapesDialog::readEditor);
    connect(m_cornersFromPrevious, &QCheckBox::toggled, this, &MouthShapesDialog::readEditor);
    connect(m_resetShape, &QPushButton::clicked, this, &MouthShapesDialog::resetShape);
    connect(resetAllButton, &QPushButton::clicked, this, &MouthShapesDialog::resetAll);
    connect(buttons, &QDialogButtonBox::accepted, this, &MouthShapesDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &MouthShapesDialog::reject);

    for (MouthShape shape : kAllMouthShapes)
        refreshIcon(shape);
    m_list->setCurrentRow(0);
    loadShape();
}

void MouthShapesDialog::buildEditor(QGridLayout *grid)
{
    const QStringList heads = {
        tr("× nose to mouth"), tr("× mouth width"), tr("× lower lip"), tr("× eye distance/100"), tr("= pixels here")};
    const QStringList tips = {tr("MNS0: the height from the tip of the nose to the lips"),
        tr("MW0: the width of the mouth, corner to corner"), tr("LowerLipH: the height of the lower lip"),
        tr("ES0/100: a hundredth of the distance between the eyes"), tr("The move on this face, in pixels")};
    for (int c = 0; c < heads.size(); ++c) {
        auto *head = new QLabel(heads[c], this);
        head->setToolTip(tips[c]);
        head->setAlignment(Qt::AlignCenter);
        grid->addWidget(head, 0, 2 + c);
    }
    int row = 1;
    for (int control = 0; control < 4; ++control) {
        for (int axis = 0; axis < kAxisCount; ++axis, ++row) {
            if (axis == 0)
                grid->addWidget(new QLabel(controlTitle(control), this), row, 0);
            grid->addWidget(new QLabel(axis == 0 ? tr("x") : tr("y"), this), row, 1);
            for (int term = 0; term < kTermCount; ++term) {
                auto *box = new QDoubleSpinBox(this);
                box->setObjectName(QStringLiteral("term-%1-%2-%3").arg(control).arg(axis).arg(term));
                const bool pixels = term == 3;
                box->setRange(pixels ? -100 : -3, pixels ? 100 : 3);
                box->setDecimals(pixels ? 2 : 4);
                box->setSingleStep(pixels ? 0.5 : 0.01);
                box->setAccelerated(true);
                grid->addWidget(box, row, 2 + term);
                m_terms[termIndex(control, axis, term)] = box;
            }
            auto *pixels = new QLabel(this);
            pixels->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
            pixels->setMinimumWidth(fontMetrics().horizontalAdvance(QStringLiteral("−000.0 px")));
            grid->addWidget(pixels, row, 2 + kTermCount);
            m_pixels[control * kAxisCount + axis] = pixels;
        }
    }
}

QDoubleSpinBox *MouthShapesDialog::termBox(int control, int axis, int term) const
{
    return m_terms[termIndex(control, axis, term)];
}

void MouthShapesDialog::setCurrentShape(MouthShape shape)
{
    m_current = shape;
    if (m_list->currentRow() != int(shape))
        m_list->setCurrentRow(int(shape));
    loadShape();
}

void MouthShapesDialog::loadShape()
{
    m_loading = true;
    MouthShapePreset preset = m_shapes.preset(m_current);
    for (int control = 0; control < 4; ++control)
        for (int axis = 0; axis < kAxisCount; ++axis)
            for (int term = 0; term < kTermCount; ++term)
                termBox(control, axis, term)->setValue(termValue(axisTerm(preset.offsets[control], axis), term));
    m_cornersAtLipMiddle->setChecked(preset.cornersAtLipMiddle);
    m_cornersFromPrevious->setChecked(preset.cornersFromPrevious);
    m_loading = false;
    refresh();
}

void MouthShapesDialog::readEditor()
{
    if (m_loading)
        return;
    MouthShapePreset preset = m_shapes.preset(m_current);
    for (int control = 0; control < 4; ++control)
        for (int axis = 0; axis < kAxisCount; ++axis)
            for (int term = 0; term < kTermCount; ++term) {
                double &value = termValue(axisTerm(preset.offsets[control], axis), term);
                // Keep the exact stored value unless the user changed what the box shows.
                const QDoubleSpinBox *box = termBox(control, axis, term);
                if (box->textFromValue(value) != box->textFromValue(box->value()))
                    value = box->value();
            }
    preset.cornersAtLipMiddle = m_cornersAtLipMiddle->isChecked();
    preset.cornersFromPrevious = m_cornersFromPrevious->isChecked();
    m_shapes.setPreset(m_current, preset);
    refresh();
}

void MouthShapesDialog::refresh()
{
    const FaceModel &face = m_document->face();
    const std::array<QPointF, 4> d = m_shapes.displacements(m_current, face);
    QVector<PosePreview::Marker> markers;
    for (int control = 0; control < 4; ++control) {
        const QPointF from = face.point(kMouthControlIds[control]);
        markers.append({from, from + d[control], controlTitle(control)});
        m_pixels[control * kAxisCount]->setText(tr("%1 px").arg(d[control].x(), 0, 'f', 1));
        m_pixels[control * kAxisCount + 1]->setText(tr("%1 px").arg(d[control].y(), 0, 'f', 1));
    }
    if (m_document->hasFace()) {
        m_preview->setPose(mouthPose(face, m_shapes, m_current));
        m_preview->setMarkers(markers);
    }
    m_shapeTitle->setText(tr("%1 — %2%3")
                              .arg(mouthShapeName(m_current), shapeDescription(m_current),
                                  m_shapes.isDefault(m_current) ? QString() : tr(" (edited)")));
    m_resetShape->setEnabled(!m_shapes.isDefault(m_current));
    refreshIcon(m_current);
}

void MouthShapesDialog::refreshIcon(MouthShape shape)
{
    QListWidgetItem *item = m_list->item(int(shape));
    const bool edited = !m_shapes.isDefault(shape);
    item->setText(
        QStringLiteral("%1  %2%3").arg(mouthShapeName(shape), shapeDescription(shape), edited ? tr(" •") : QString()));
    QFont font = m_list->font();
    font.setBold(edited);
    item->setFont(font);
    if (m_document->hasFace())
        item->setIcon(QIcon(QPixmap::fromImage(renderPose(m_face, mouthPose(m_document->face(), m_shapes, shape),
            m_mouthFrame, QSize(kThumbnailSize, kThumbnailSize)))));
}

// A coordinate's displacement is affine in each of its terms, whatever the face's resting
// mouth adds: moving one term by (wanted - now) / unit brings the point where it is dragged.
// A coordinate a corner rule sets (o's corner height, n's corners) does not follow the drag.
void MouthShapesDialog::dragControl(int control, QPointF photoPos)
{
    const FaceModel &face = m_document->face();
    const Fapu f = face.fapu();
    const QPointF now = m_shapes.displacements(m_current, face)[control];
    const QPointF wanted = photoPos - face.point(kMouthControlIds[control]);
    const bool corner = control == Left || control == Right;
    // x: corners in MW0, lips in ES0/100; y: lips in MNS0, corners in ES0/100.
    const int xTerm = corner ? 1 : 3;
    const int yTerm = corner ? 3 : 0;
    const auto unit = [&f](int term) { return term == 0 ? f.mns0 : term == 1 ? f.mw0 : f.pixel(); };
    QDoubleSpinBox *xBox = termBox(control, 0, xTerm);
    QDoubleSpinBox *yBox = termBox(control, 1, yTerm);
    m_loading = true; // one update for both boxes
    xBox->setValue(xBox->value() + (wanted.x() - now.x()) / unit(xTerm));
    yBox->setValue(yBox->value() + (wanted.y() - now.y()) / unit(yTerm));
    m_loading = false;
    readEditor();
}

void MouthShapesDialog::resetShape()
{
    m_shapes.setPreset(m_current, MouthShapeSet::defaultPreset(m_current));
    loadShape();
}

void MouthShapesDialog::resetAll()
{
    m_shapes = MouthShapeSet();
    for (MouthShape shape : kAllMouthShapes)
        refreshIcon(shape);
    loadShape();
}

void MouthShapesDialog::accept()
{
    m_document->changeMouthShapes(m_shapes, tr("Edit Mouth Shapes"));
    QDialog::accept();
}

} // namespace toonface
