#pragma once

#include "face/mouthshape.h"
#include "render/svgface.h"

#include <QDialog>

#include <array>

class QCheckBox;
class QDoubleSpinBox;
class QGridLayout;
class QLabel;
class QListWidget;
class QPushButton;

namespace toonface {

class Document;
class PosePreview;

// Mouth Shapes…: the character's nine mouth-shape presets (face-model.md's table by default),
// each edited with a live preview of this character's mouth. A shape is the displacement of
// the four mouth control points (8.9, 8.2, 8.4, 8.3), each coordinate a sum of FAPU terms
// (MNS0, MW0, LowerLipH, ES0/100) so that it fits any face; the preview marks where each
// control point moves from and to; dragging a marker there moves that control (corners
// sideways in MW0, lips up and down in MNS0, the other axis in ES0/100). The shape and its four
// points are what the dialog shows; the table of terms (its columns named in words: nose to
// mouth, mouth width, lower lip, eye distance/100) waits behind "Advanced: the numbers".
// Reset Shape / Reset All restore the defaults.
// The edits reach the project on OK as one undo step (undo restores the exact previous presets); Cancel changes
// nothing.
class MouthShapesDialog : public QDialog
{
    Q_OBJECT

public:
    // Opens the dialog modally; true when the presets were changed.
    static bool run(QWidget *parent, Document *document);

    explicit MouthShapesDialog(Document *document, QWidget *parent = nullptr);

    // The presets as edited so far.
    const MouthShapeSet &shapes() const { return m_shapes; }
    MouthShape currentShape() const { return m_current; }
    void setCurrentShape(MouthShape shape);

    // The spin box of one FAPU term: control 0..3 (MouthControl), axis 0 = x, 1 = y,
    // term 0..3 = MNS0, MW0, LowerLipH, ES0/100. Object name "term-<control>-<axis>-<term>".
    QDoubleSpinBox *termBox(int control, int axis, int term) const;

public Q_SLOTS:
    void resetShape();
    void resetAll();
    void accept() override;

private:
    void buildEditor(QGridLayout *grid);
    void loadShape();
    void readEditor();
    void refresh();
    void refreshIcon(MouthShape shape);
    void dragControl(int control, QPointF photoPos);

    Document *m_document;
    MouthShapeSet m_shapes;
    MouthShape m_current = MouthShape::M;
    SvgFace m_face;
    QRectF m_mouthFrame;
    QListWidget *m_list;
    PosePreview *m_preview;
    std::array<QDoubleSpinBox *, 32> m_terms {};
    std::array<QLabel *, 8> m_pixels {};
    QCheckBox *m_cornersAtLipMiddle;
    QCheckBox *m_cornersFromPrevious;
    QLabel *m_shapeTitle;
    QPushButton *m_resetShape;
    bool m_loading = false;
};

} // namespace toonface
