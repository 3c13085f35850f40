#pragma once

#include "face/mouthshape.h"

#include <QToolButton>
#include <QWidget>

#include <array>

namespace toonface {

class MouthIcons;

// The nine mouth shapes as buttons showing this character's lips: a click replaces the shape
// of the selected mouth keys (or inserts one at the playhead).
class ShapePalette : public QWidget
{
    Q_OBJECT

public:
    explicit ShapePalette(QWidget *parent = nullptr);
    // Shows the pictures of `icons` (call again after they were rebuilt).
    void setIcons(const MouthIcons &icons);

Q_SIGNALS:
    void shapeChosen(toonface::MouthShape shape);

private:
    std::array<QToolButton *, kMouthShapeCount> m_buttons {};
};

} // namespace toonface
